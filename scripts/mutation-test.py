#!/usr/bin/env python3
"""Mutation testing: does the suite catch a wrong cloud?

Each mutant is one small, plausible bug: an exact string in one source file replaced by another
(the string must occur exactly once, which is checked before anything runs). For each mutant the
script copies nothing new: it keeps one scratch copy of the repository (default
/tmp/cloudscape-mutation) with its own build directory, applies the mutant there, rebuilds
incrementally, runs the test binaries that cover the mutated layer plus the CLI tests, and
restores the file. A mutant is killed when a test fails (or crashes, or times out); it survives
when every test passes. Mutants that do not compile are reported apart and not scored.

To save time: only the CPU test binaries of the layers a mutant can reach run, with
--gtest_fail_fast, fastest first, each built only when the ones before it passed; the CLI tests
run last and only their content checks (the preset bands and cli_content_test.cpp); the GPU
tests (test_vulkan, test_cli_gpu) are not run, since the model they run is the same source as
the CPU tests', and the scratch build replaces glslc by a stub (scripts/mutation-glslc-stub.sh)
so that a model header's mutant does not recompile the shaders nobody runs. The score is
killed / (killed + survived).

    nice -n 19 scripts/mutation-test.py                 # every mutant
    nice -n 19 scripts/mutation-test.py --only wind-sign,octave-b
    scripts/mutation-test.py --list

The report (text, and JSON with --json FILE) lists the survivors. docs/TESTING.md keeps the
latest score and why each survivor is acceptable.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Test binaries by layer, fastest first. Every mutant also runs the CLI tests (last).
TESTS = {
    "model": ["test_model", "test_cpu", "test_pathtrace"],
    "metrics": ["test_core"],
    "temporal": ["test_cpu"],
    "pathtrace": ["test_pathtrace"],
    "scene": ["test_io", "test_core"],
    "params": ["test_cpu", "test_model", "test_pathtrace"],
    "weather": ["test_core", "test_cpu"],
}
CLI = "test_cli"
CLI_FILTER = "Cli.EveryPresetRendersPlausibly:CliContent.*"


@dataclass
class Mutant:
    name: str
    layer: str
    path: str
    find: str
    replace: str
    what: str


M = Mutant
MUTANTS = [
    # --- The named mutants.
    M("wind-sign", "temporal", "src/model/temporal.glsl.h",
      "vec3 scrolled = p - cloudMotion(P, dt);", "vec3 scrolled = p + cloudMotion(P, dt);",
      "reprojection moves the cloud the wrong way"),
    M("accumulation-off-by-one", "temporal", "src/model/temporal.glsl.h",
      "min(weight + 1.0f, float(max(F.temporalAccumulation, 1)))",
      "min(weight + 2.0f, float(max(F.temporalAccumulation, 1)))",
      "accumulation weight counts one march too many"),
    M("octave-b", "model", "src/model/lighting.glsl.h",
      "b *= P.octaveFactors.y;", "b *= P.octaveFactors.x;",
      "octave optical depth uses the energy factor"),
    M("cone-step-ends", "model", "src/model/lighting.glsl.h",
      "(stepLength * (float(i) + 0.5f))", "(stepLength * (float(i) + 1.0f))",
      "light cone samples at step ends instead of midpoints"),
    M("ssim-sigma", "metrics", "src/core/metrics.cpp",
      "const double sigma = 1.5 * size / 11.0;", "const double sigma = 1.65 * size / 11.0;",
      "SSIM Gaussian sigma 10% too wide"),
    M("msssim-luminance-scale", "metrics", "src/core/metrics.cpp",
      "const double term = s + 1 == scales ? parts.ssim", "const double term = s == 0 ? parts.ssim",
      "MS-SSIM takes luminance at the finest scale"),
    M("vector-range-unchecked", "scene", "src/io/scene.cpp",
      "out[i] = static_cast<float>(checkedNumber(v[i], k, where));",
      "out[i] = v[i].get<float>();",
      "vector keys skip their range check"),
    # --- Model: density.
    M("coverage-overshoot", "model", "src/model/density.glsl.h",
      "CONST_FLOAT COVERAGE_OVERSHOOT = 0.15f;", "CONST_FLOAT COVERAGE_OVERSHOOT = 0.0f;",
      "full coverage keeps the noise's holes"),
    M("height-fraction", "model", "src/model/density.glsl.h",
      "(altitude - P.layerBottom) / (P.layerTop - P.layerBottom)",
      "(altitude - P.layerBottom) / P.layerTop",
      "height fraction divided by the top altitude, not the layer depth"),
    # --- Model: phase and lighting.
    M("hg-sign", "model", "src/model/phase.glsl.h",
      "float denom = max((1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f - cosTheta), 1e-12f);\n    return (1.0f - g2)",
      "float denom = max((1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f + cosTheta), 1e-12f);\n    return (1.0f - g2)",
      "Henyey-Greenstein forward and backward swapped"),
    M("powder-fade", "model", "src/model/lighting.glsl.h",
      "strength * saturate(0.5f - 0.5f * cosTheta)", "strength * saturate(0.5f + 0.5f * cosTheta)",
      "powder strongest looking into the sun"),
    M("long-sample-weight", "model", "src/model/lighting.glsl.h",
      "depth += extinctionOf(d, P) * P.coneLength;",
      "depth += extinctionOf(d, P) * P.coneLength * P.longSampleDistance;",
      "long sample weighted by three cone lengths"),
    M("ambient-depth", "model", "src/model/lighting.glsl.h",
      "sqrt(saturate(1.0f - baseDensity))", "saturate(1.0f - baseDensity)",
      "ambient falls linearly, not as the square root"),
    M("albedo-on-sun-only", "model", "src/model/lighting.glsl.h",
      "return (sun * direct + ambient) * P.albedo;", "return sun * direct * P.albedo + ambient;",
      "albedo not applied to ambient light"),
    # --- Model: march, camera, sky.
    M("step-integration", "model", "src/model/march.glsl.h",
      "P.energyConservingSteps != 0 ? 1.0f - stepTransmittance",
      "P.energyConservingSteps == 0 ? 1.0f - stepTransmittance",
      "energy-conserving step switch inverted"),
    M("phase-angle", "model", "src/model/march.glsl.h",
      "float cosTheta = dot(dir, sunDir);", "float cosTheta = dot(-dir, sunDir);",
      "scattering angle measured from the wrong direction"),
    M("composite", "model", "src/model/output.glsl.h",
      "return cloudRadiance + background * transmittance;",
      "return cloudRadiance + background * (1.0f - transmittance);",
      "background weighted by the cloud's opacity"),
    # --- Temporal.
    M("motion-updraft", "temporal", "src/model/temporal.glsl.h",
      "return cloudDriftDirection(P) * windTravel(dt, P);",
      "return P.windDirection * windTravel(dt, P);",
      "reprojection ignores the updraft"),
    M("dt-sign", "temporal", "src/cpu/cpu_temporal.cpp",
      "const float dt = continues ? scene.timeS - s.lastTime : 0.0f;",
      "const float dt = continues ? s.lastTime - scene.timeS : 0.0f;",
      "CPU temporal renderer passes the time step negated"),
    M("project-y", "temporal", "src/model/temporal.glsl.h",
      "float py = (1.0f - sy) * 0.5f * float(F.height) - 0.5f;",
      "float py = (1.0f - sy) * 0.5f * float(F.height) + 0.5f;",
      "projection half a pixel off vertically"),
    M("still-limit", "temporal", "src/model/temporal.glsl.h",
      "CONST_FLOAT ACCUMULATION_MOTION_LIMIT = 0.25f;", "CONST_FLOAT ACCUMULATION_MOTION_LIMIT = 2.5f;",
      "moving pixels accumulate (ghosting)"),
    M("bayer-order", "temporal", "src/model/temporal.glsl.h",
      "int x = ((k >> 1) & 1) * 2 + ((k >> 3) & 1);", "int x = ((k >> 1) & 1) * 2 + ((k >> 2) & 1);",
      "block order built from the wrong bit of the frame index"),
    # --- Metrics.
    M("psnr-20", "metrics", "src/core/metrics.cpp",
      "10.0 * std::log10(p * p / mse)", "20.0 * std::log10(p * p / mse)",
      "PSNR doubled"),
    M("halve-index", "metrics", "src/core/metrics.cpp",
      "img[p] + img[p + 1] + img[p + w] + img[p + w + 1]", "img[p] + img[p + 1] + img[p + w] + img[p + w]",
      "MS-SSIM downsampling reads one pixel twice"),
    M("ssim-c2", "metrics", "src/core/metrics.cpp",
      "constexpr double kC2 = 0.03 * 0.03;", "constexpr double kC2 = 0.01 * 0.03;",
      "SSIM contrast constant wrong"),
    M("relative-error-denominator", "metrics", "src/core/metrics.cpp",
      "total += std::abs(static_cast<double>(reference[i]));",
      "total += std::abs(static_cast<double>(test[i]));",
      "relative error normalised by the test image"),
    # --- Path tracer.
    M("delta-tracking", "pathtrace", "src/pathtrace/tracking.h",
      "if (random.uniform() * majorant < sigma) {", "if (random.uniform() * majorant < 0.9f * sigma) {",
      "delta tracking accepts 10% too few collisions"),
    M("ratio-tracking", "pathtrace", "src/pathtrace/tracking.h",
      "transmittance *= std::max(1.0f - sigma / majorant, 0.0f);",
      "transmittance *= std::max(1.0f - 0.9f * sigma / majorant, 0.0f);",
      "ratio tracking 10% too transparent"),
    M("nee-phase", "pathtrace", "src/pathtrace/integrator.h",
      "model::evaluatePhase(phase, glm::dot(dir, toSun))",
      "model::evaluatePhase(phase, glm::dot(-dir, toSun))",
      "next-event estimation with the phase angle reversed"),
    M("medium-fade", "pathtrace", "src/pathtrace/cloud_medium.cpp",
      "model::distanceFade(glm::length(p - camera_), params_)", "model::distanceFade(0.0f, params_)",
      "path tracer's medium without the horizon fade"),
    M("roulette-bias", "pathtrace", "src/pathtrace/integrator.h",
      "if (random.uniform() >= survive)", "if (random.uniform() >= survive * survive)",
      "Russian roulette kills more paths than it compensates"),
    # --- Scene and parameters.
    M("int-range-unchecked", "scene", "src/io/scene.cpp",
      "scene.*std::get<0>(k.member) = static_cast<int>(checkedNumber(v, k, where));",
      "scene.*std::get<0>(k.member) = static_cast<int>(v.get<double>());",
      "integer keys skip their range check"),
    M("float-range-max", "scene", "src/io/scene.cpp",
      "x < k.min || x > k.max)", "x < k.min || x >= k.max)",
      "a number's maximum itself rejected"),
    M("layer-rule", "scene", "src/io/scene.cpp",
      "if (s.cloudTopM <= s.cloudBottomM + 10.0f)", "if (s.cloudTopM <= s.cloudBottomM)",
      "cloud layer may be thinner than 10 m"),
    M("wind-heading", "params", "src/core/model_params.cpp",
      "p.windDirection = directionFromAngles(s.windHeadingDeg, 0.0f);",
      "p.windDirection = directionFromAngles(-s.windHeadingDeg, 0.0f);",
      "wind blows toward the mirrored heading"),
    M("fov-half", "params", "src/core/model_params.cpp",
      "std::tan(glm::radians(s.cameraFovDeg) * 0.5f)", "std::tan(glm::radians(s.cameraFovDeg) * 0.45f)",
      "field of view 10% narrow"),
    M("updraft-dropped", "params", "src/core/model_params.cpp",
      "p.updraft = s.updraft;", "p.updraft = 0.0f;",
      "the updraft key is ignored"),
    # --- Atmosphere and sky (issue 11).
    M("rayleigh-phase-shape", "model", "src/model/atmosphere.glsl.h",
      "3.0f / (16.0f * PI) * (1.0f + cosTheta * cosTheta)", "3.0f / (16.0f * PI) * (1.0f + cosTheta)",
      "Rayleigh phase loses its cos^2 shape"),
    M("ozone-tent-width", "model", "src/model/atmosphere.glsl.h",
      "abs(h - A.ozoneCentre) / A.ozoneHalfWidth", "abs(h - A.ozoneCentre) / (2.0f * A.ozoneHalfWidth)",
      "ozone layer twice as thick"),
    M("mie-absorption-dropped", "model", "src/model/atmosphere.glsl.h",
      "vec3(A.mieExtinction * mie)", "vec3(A.mieScattering * mie)",
      "aerosols scatter but never absorb"),
    M("limb-normalisation", "model", "src/model/sky.glsl.h",
      "/ (1.0f - u / 3.0f);", "/ (1.0f - u / 2.0f);",
      "limb-darkened sun disc no longer delivers the sun's irradiance"),
    # --- High-altitude layer.
    M("high-cloud-erosion", "model", "src/model/high_clouds.glsl.h",
      "remap(value, 1.0f - P.highClouds.coverage, 1.0f, 0.0f, 1.0f)",
      "remap(value, P.highClouds.coverage, 1.0f, 0.0f, 1.0f)",
      "high-layer coverage works backwards"),
    M("high-cloud-sun-depth", "model", "src/model/high_clouds.glsl.h",
      "0.5f * verticalDepth / max(dot(light, up)",
      "verticalDepth / max(dot(light, up)",
      "sunlight crosses the whole high layer to reach its middle"),
    M("high-cloud-wind-sign", "model", "src/model/high_clouds.glsl.h",
      "(xz - P.highClouds.windVelocity * P.time)", "(xz + P.highClouds.windVelocity * P.time)",
      "high layer drifts against its wind"),
    # --- Storms and weather control (issue 14).
    M("storm-glow-exponent", "model", "src/model/storm.glsl.h",
      "STORM_GLOW_EXPONENT = 12.0f;", "STORM_GLOW_EXPONENT = 6.0f;",
      "storm glow falls off as the 6th power, not the 12th"),
    M("storm-light-density", "model", "src/model/storm.glsl.h",
      "pow(saturate(min(1.0f - d, 0.0f) + 1.0f), 0.5f)",
      "pow(saturate(min(1.0f - d, 0.0f) + 1.0f), 1.0f)",
      "light-march density ramp linear, not the talk's square root"),
    M("storm-motion-mask", "temporal", "src/model/storm.glsl.h",
      "STORM_MOTION_EXPONENT = 0.1f;", "STORM_MOTION_EXPONENT = 1.0f;",
      "rotational motion vectors masked by a linear ramp"),
    M("vortex-ring-speed", "model", "src/model/storm.glsl.h",
      "P.stormRotation / float(ring + 1)", "P.stormRotation / float(ring + 2)",
      "vortex rings turn at half speed"),
    M("storm-type-centre", "model", "src/model/storm.glsl.h",
      "mix(weather.z, TYPE_CUMULONIMBUS, t)", "mix(weather.z, TYPE_CUMULONIMBUS, 0.5f * t)",
      "the storm's centre never reaches cumulonimbus"),
    M("weather-build-ramp", "weather", "src/core/weather_control.cpp",
      "value = phase / b;", "value = 0.5f * phase / b;",
      "storm builds to half strength"),
    M("weather-spin-integral", "weather", "src/core/weather_control.cpp",
      "integral = 0.5f * b + (phase - b);", "integral = b + (phase - b);",
      "vortex clock jumps when the storm starts holding"),
    # --- Terrain (issue 12).
    M("terrain-normal-x", "model", "src/model/terrain.glsl.h",
      "normalize(up + vec3(-sx, 0.0f, -sz))", "normalize(up + vec3(sx, 0.0f, -sz))",
      "terrain normal tilts the wrong way along x"),
    M("terrain-bilinear", "model", "src/model/terrain.glsl.h",
      "mix(mix(a, b, f.x), mix(c, d, f.x), f.y)", "mix(mix(a, b, f.y), mix(c, d, f.x), f.y)",
      "height field interpolated with the wrong weight"),
    # --- Night sky: the moon (issue 11).
    M("moon-lit-fraction", "model", "src/model/sky.glsl.h",
      "return 0.5f * (1.0f + cos(phaseAngle));", "return 0.5f * (1.0f - cos(phaseAngle));",
      "the moon's lit fraction runs backwards (full moon dark)"),
    M("moon-irradiance-disc", "params", "src/core/model_params.cpp",
      "double(s.moonAlbedo) * sinRadius * sinRadius;", "double(s.moonAlbedo) * sinRadius;",
      "moonlight not scaled by the disc's solid angle"),
    # --- Cloud shadow map and light shafts (issue 12).
    M("shadow-map-projection", "model", "src/model/cloud_shadow.glsl.h",
      "vec2 xz = vec2(p.x - sun.x * s, p.z - sun.z * s);",
      "vec2 xz = vec2(p.x + sun.x * s, p.z + sun.z * s);",
      "points looked up in the shadow map away from the sun"),
    M("shadow-depth-partial", "model", "src/model/cloud_shadow.glsl.h",
      "record.z * saturate((record.y - s) / span)", "record.z * saturate((s - record.x) / span)",
      "a point inside the cloud gets the depth below it, not above it"),
    M("shafts-behind-cloud", "model", "src/model/light_shafts.glsl.h",
      "float throughCloud = cloudDepth == NO_HIT ? 1.0f : cloudTransmittance;",
      "float throughCloud = 1.0f;",
      "air behind a cloud scatters as if the cloud were not in front"),
    M("shafts-phase-backwards", "model", "src/model/light_shafts.glsl.h",
      "float phaseM = miePhase(cosTheta, A.mieG);", "float phaseM = miePhase(-cosTheta, A.mieG);",
      "shafts glow brightest looking away from the sun"),
    # --- Lightning (issue 14).
    M("flash-intensity-half", "model", "src/model/lightning.glsl.h",
      "return cloudRadiance + P.lightning.flashLight * (flash * P.lightning.flashIntensity);",
      "return cloudRadiance + P.lightning.flashLight * (0.5f * flash * P.lightning.flashIntensity);",
      "a masked flash composites at half its intensity"),
    M("bolt-profile-width", "model", "src/model/lightning.glsl.h",
      "float x = dist / (0.5f * spread);", "float x = dist / spread;",
      "the bolt's channel twice as wide"),
    # --- Empty-space skipping (issue 15).
    M("skip-cell-exit", "model", "src/model/cloud_bound.glsl.h",
      "return max(min(exitX, exitZ), 0.0f);", "return max(max(exitX, exitZ), 0.0f);",
      "a skip runs past the column's far side into the next column"),
    M("skip-top-margin", "model", "src/model/cloud_bound.glsl.h",
      "CLOUD_TOP_MARGIN = 20.0f;", "CLOUD_TOP_MARGIN = -200.0f;",
      "column tops 200 m below the highest cloud"),
    M("march-residue", "model", "src/model/march.glsl.h",
      "                result.transmittance = 0.0f;\n                return result;",
      "                return result;",
      "a march stopped early keeps its residual transmittance (the sun shines through)"),
    # --- The viewer's weather brush (issue 13).
    M("brush-falloff", "model", "src/model/brush.glsl.h",
      "float s = 1.0f - t * t;", "float s = 1.0f - t;",
      "brush falls off as (1 - t)^2"),
]


def log(msg):
    print(msg, flush=True)


def check_mutants(repo):
    names = set()
    for m in MUTANTS:
        assert m.name not in names, "duplicate mutant " + m.name
        names.add(m.name)
        assert m.layer in TESTS, m.name
        text = open(os.path.join(repo, m.path)).read()
        n = text.count(m.find)
        if n != 1:
            sys.exit("mutant %s: '%s' occurs %d times in %s (must be once)" % (m.name, m.find, n, m.path))


def sync_scratch(repo, scratch):
    """Copy the tracked files (as in the work tree) into the scratch copy, keeping its build/."""
    files = subprocess.run(["git", "-C", repo, "ls-files", "-co", "--exclude-standard"],
                           check=True, capture_output=True, text=True).stdout.split()
    os.makedirs(scratch, exist_ok=True)
    for f in files:
        src, dst = os.path.join(repo, f), os.path.join(scratch, f)
        if not os.path.isfile(src) or f.startswith("build/"):
            continue
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        if not os.path.exists(dst) or open(src, "rb").read() != open(dst, "rb").read():
            shutil.copy(src, dst)  # a new mtime, so the incremental build sees the change


def build(scratch, targets, log_file):
    cmd = ["cmake", "--build", os.path.join(scratch, "build"), "-j2", "--target"] + targets
    with open(log_file, "w") as out:
        return subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode == 0


def run_binary(scratch, binary, timeout):
    """Returns (passed, why)."""
    args = [os.path.join(scratch, "build", binary), "--gtest_fail_fast", "--gtest_brief=1"]
    if binary == CLI:
        args.append("--gtest_filter=" + CLI_FILTER)
    try:
        p = subprocess.run(args, cwd=os.path.join(scratch, "build"), capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, binary + ": timed out"
    if p.returncode != 0:
        failed = [l for l in p.stdout.splitlines() if l.startswith("[  FAILED  ]")]
        return False, binary + ": " + (failed[0][13:].split(" (")[0] if failed else
                                       "exit %d" % p.returncode)
    return True, ""


def build_and_run(scratch, binaries, timeout, log_file):
    """Builds and runs the binaries in order, stopping at the first failure. Returns (status,
    why) with status killed, survived or no-compile."""
    for b in binaries:
        targets = [b] + (["cloudscape_cli"] if b == CLI else [])
        if not build(scratch, targets, log_file):
            return "no-compile", b
        passed, why = run_binary(scratch, b, timeout)
        if not passed:
            return "killed", why
    return "survived", ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scratch", default="/tmp/cloudscape-mutation")
    ap.add_argument("--only", help="comma-separated mutant names")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--json", help="also write the results here")
    ap.add_argument("--skip-baseline", action="store_true",
                    help="build the unmutated copy but do not run its tests (only when the same "
                         "tree's baseline has just passed, e.g. restarting a run)")
    ap.add_argument("--timeout", type=int, default=900, help="seconds per test binary")
    args = ap.parse_args()

    check_mutants(REPO)
    if args.list:
        for m in MUTANTS:
            log("%-28s %-9s %-32s %s" % (m.name, m.layer, m.path, m.what))
        log("%d mutants" % len(MUTANTS))
        return 0
    chosen = MUTANTS
    if args.only:
        wanted = set(args.only.split(","))
        chosen = [m for m in MUTANTS if m.name in wanted]
        unknown = wanted - {m.name for m in chosen}
        if unknown:
            sys.exit("unknown mutants: " + ", ".join(sorted(unknown)))

    scratch = args.scratch
    sync_scratch(REPO, scratch)
    build_dir = os.path.join(scratch, "build")
    # With ccache (when installed), restoring a mutated file rebuilds its objects from the cache:
    # each mutant then costs one compile of what it touches, not two.
    launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
    subprocess.run(["cmake", "-S", scratch, "-B", build_dir, "-G", "Ninja",
                    "-DCMAKE_BUILD_TYPE=Release", "-DCLOUDSCAPE_BUILD_BENCH=OFF",
                    "-DGLSLC=" + os.path.join(scratch, "scripts", "mutation-glslc-stub.sh")] + launcher,
                   check=True, stdout=subprocess.DEVNULL)
    unit = sorted({b for bs in TESTS.values() for b in bs})
    t0 = time.time()
    if args.skip_baseline:
        ok = build(scratch, unit + [CLI, "cloudscape_cli"], os.path.join(scratch, "build.log"))
        if not ok:
            sys.exit("the unmutated copy does not build: fix that first")
        log("baseline: built, not run (--skip-baseline) (%.0f s)" % (time.time() - t0))
    else:
        status, why = build_and_run(scratch, unit + [CLI], args.timeout,
                                    os.path.join(scratch, "build.log"))
        if status != "survived":
            sys.exit("the unmutated copy fails (%s %s): fix that first" % (status, why))
        log("baseline: builds and passes (%.0f s)" % (time.time() - t0))

    results = []
    for n, m in enumerate(chosen, 1):
        path = os.path.join(scratch, m.path)
        original = open(path).read()
        start = time.time()
        try:
            open(path, "w").write(original.replace(m.find, m.replace, 1))
            status, killer = build_and_run(scratch, TESTS[m.layer] + [CLI], args.timeout,
                                           os.path.join(scratch, "mutant.log"))
        finally:
            open(path, "w").write(original)
        results.append({"name": m.name, "layer": m.layer, "file": m.path, "what": m.what,
                        "status": status, "by": killer, "seconds": round(time.time() - start)})
        log("[%2d/%d] %-28s %-10s %s (%.0f s)" % (n, len(chosen), m.name, status, killer,
                                                  time.time() - start))

    killed = sum(r["status"] == "killed" for r in results)
    survived = [r for r in results if r["status"] == "survived"]
    stillborn = [r for r in results if r["status"] == "no-compile"]
    scored = killed + len(survived)
    score = 100.0 * killed / scored if scored else 0.0
    log("")
    log("mutation score: %d of %d killed (%.1f%%)%s" % (
        killed, scored, score, ", %d did not compile" % len(stillborn) if stillborn else ""))
    for r in survived:
        log("  survived: %-28s %s (%s)" % (r["name"], r["what"], r["file"]))
    for r in stillborn:
        log("  did not compile: %s" % r["name"])
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"score": score, "killed": killed, "scored": scored, "results": results}, f,
                      indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
