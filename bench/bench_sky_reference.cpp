// The real-time sky (the sky-view table, src/model/atmosphere.glsl.h) against the path-traced
// atmosphere (src/pathtrace/sky_reference.h): radiance seen from the ground at the zenith, just
// above the horizon toward, across and away from the sun, and 30 degrees up away from the sun,
// for sun elevations 90, 30, 10, 2 and -2 degrees, with the scene's default (Earth) atmosphere.
// Prints the table of docs/QUALITY.md: per RGB channel the ratio real-time / path-traced and the
// path tracer's relative standard error. Not a Google Benchmark: a measurement, run niced.
//   bench_sky_reference [paths per channel per direction (default 200000)] [seed]
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "cpu/cpu_textures.h"
#include "model/sky.glsl.h"
#include "pathtrace/sky_reference.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

namespace cm = cloudscape::model;

struct View {
    const char* name;
    float elevationDeg;
    float azimuthFromSunDeg;
};

// A direction at an elevation and an azimuth measured from the sun's.
glm::vec3 viewDirection(const View& v, glm::vec3 sun) {
    const float sunAzimuth = std::atan2(sun.z, sun.x);
    const float azimuth = sunAzimuth + glm::radians(v.azimuthFromSunDeg);
    const float e = glm::radians(v.elevationDeg);
    return glm::normalize(
        glm::vec3(std::cos(e) * std::cos(azimuth), std::sin(e), std::cos(e) * std::sin(azimuth)));
}

} // namespace

int main(int argc, char** argv) {
    const uint64_t paths = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 200000;
    const uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    if (paths < 2) {
        std::fprintf(stderr, "bench_sky_reference: paths per channel must be at least 2\n");
        return 1;
    }
    const float elevations[] = {90.0f, 30.0f, 10.0f, 2.0f, -2.0f};
    const View views[] = {{"zenith", 90.0f, 0.0f},
                          {"horizon +1, toward sun", 1.0f, 0.0f},
                          {"horizon +1, 90 deg from sun", 1.0f, 90.0f},
                          {"horizon +1, away from sun", 1.0f, 180.0f},
                          {"30 up, away from sun", 30.0f, 180.0f}};
    std::printf("paths per channel and direction: %llu, seed %llu\n\n",
                static_cast<unsigned long long>(paths), static_cast<unsigned long long>(seed));
    std::printf("| sun | view | real-time RGB | path-traced RGB | ratio R | ratio G | ratio B | "
                "rel. s.e. R/G/B |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    double seconds = 0.0;
    for (float elevation : elevations) {
        cloudscape::Scene scene;
        scene.sunElevationDeg = elevation;
        scene.sunHeadingDeg = 0.0f;
        scene.cameraPosition = glm::vec3(0.0f, 2.0f, 0.0f);
        cm::CloudParams params = cloudscape::makeCloudParams(scene, 0.0f);
        params.sky.atmosphere.enabled = 1;
        const std::vector<glm::vec4> tables = cloudscape::computeAtmosphereLuts(params.sky);
        cloudscape::cpu::TextureSet set;
        set.atmosphere = tables.data();
        cloudscape::cpu::ScopedTextureBinding binding(set);
        for (const View& v : views) {
            if (elevation == 90.0f && v.azimuthFromSunDeg != 0.0f && v.elevationDeg < 10.0f)
                continue; // the sun overhead: every azimuth is the same
            const glm::vec3 dir = viewDirection(v, params.sky.sunDirection);
            const glm::vec3 table = cm::skyBackground(dir, params.sky);
            cloudscape::pathtrace::SkyReferenceOptions options;
            options.seed = seed;
            const auto start = std::chrono::steady_clock::now();
            const cloudscape::pathtrace::SkyReferenceEstimate e =
                cloudscape::pathtrace::traceSkyReference(params.sky, scene.cameraPosition, dir,
                                                         paths, options);
            seconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::printf("| %g | %s | %.4g %.4g %.4g | %.4g %.4g %.4g |", elevation, v.name, table.x,
                        table.y, table.z, e.radiance.x, e.radiance.y, e.radiance.z);
            for (int c = 0; c < 3; ++c)
                std::printf(" %.3f |", e.radiance[c] > 0.0 ? table[c] / e.radiance[c] : 0.0);
            std::printf(" %.1f/%.1f/%.1f %% |\n", 100.0 * e.standardError.x / e.radiance.x,
                        100.0 * e.standardError.y / e.radiance.y,
                        100.0 * e.standardError.z / e.radiance.z);
            std::fflush(stdout);
        }
    }
    std::printf("\npath tracing: %.1f s\n", seconds);
    return 0;
}
