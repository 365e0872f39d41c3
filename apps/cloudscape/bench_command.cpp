// `cloudscape bench`: a scripted camera path through the temporal renderer, measured against the
// brute-force reference rendered for the same frames: cost per pass and image quality.
#include "backend_options.h"
#include "commands.h"
#include "scene_options.h"
#include "validate_only.h"

#include <cloudscape/backend.h>
#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/memory_estimate.h>
#include <cloudscape/metrics.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/renderer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace cloudscape::cli {
namespace {

struct BenchArgs {
    SceneOptions scene;
    std::string path = "slow-pan";
    int frames = 32;
    float fps = 24.0f;
    std::string json;
    std::string keyframes; // a keyframe file animating scene keys over the frames
    std::string frameDir;  // where each frame's images go, for looking at (empty: nowhere)
    BackendArgs backend;
};

// The share of a temporal frame's pixels that had no usable history and took the upsampled
// marches instead (TemporalSource::Fallback): where the reconstruction is blurry.
double fallbackFraction(const TemporalDebugImage& debug) {
    if (debug.empty())
        return 0.0;
    const auto n = std::count(debug.source.begin(), debug.source.end(), TemporalSource::Fallback);
    return static_cast<double>(n) / static_cast<double>(debug.source.size());
}

// Colours of the temporal sources in the saved source images: marched white, reprojected
// green, fallback red.
std::vector<uint8_t> sourceImage(const TemporalDebugImage& debug) {
    std::vector<uint8_t> rgba(debug.source.size() * 4, 255);
    for (size_t i = 0; i < debug.source.size(); ++i) {
        const TemporalSource s = debug.source[i];
        rgba[i * 4 + 0] = s == TemporalSource::Reprojected ? 40 : 255;
        rgba[i * 4 + 1] = s == TemporalSource::Fallback ? 40 : 255;
        rgba[i * 4 + 2] = s == TemporalSource::Marched ? 255 : 40;
    }
    return rgba;
}

// --save-frames DIR: the temporal frame, the reference and the per-pixel source of frame f, as
// DIR/frame-NNNN-{temporal,reference,source}.png. The directory must be new or empty, so no
// earlier output is overwritten.
void prepareFrameDir(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(dir, ec)) {
        if (!fs::is_directory(dir, ec) || !fs::is_empty(dir, ec))
            throw Error("--save-frames " + dir + ": expected a new or empty directory");
        return;
    }
    if (!fs::create_directories(dir, ec))
        throw Error("--save-frames " + dir + ": cannot create the directory (" + ec.message() +
                    ")");
}

void saveFrameImages(const std::string& dir, int f, const RenderResult& temporal,
                     const RenderResult& reference, const TemporalDebugImage& debug,
                     float exposure) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame-%04d-", f);
    const std::string stem = dir + name;
    writePng(stem + "temporal.png", temporal.width, temporal.height,
             toneMapToSrgb8(temporal, exposure));
    writePng(stem + "reference.png", reference.width, reference.height,
             toneMapToSrgb8(reference, exposure));
    if (!debug.empty())
        writePng(stem + "source.png", debug.width, debug.height, sourceImage(debug));
}

// The reference: the "reference" tier (every pixel every frame, no shortcuts, many steps).
Scene referenceOf(const Scene& s) {
    Scene r = s;
    applyTier(r, "reference");
    return r;
}

void runBench(const BenchArgs& args) {
    if (args.frames < 1 || args.frames > 100000)
        throw Error("--frames " + std::to_string(args.frames) + ": expected 1 to 100000");
    if (!(args.fps > 0.0f))
        throw Error("--fps: expected a positive rate");
    if (!args.json.empty())
        checkOutputWritable(args.json);
    const Scene base = args.scene.load();
    requireHostMemory(base, RenderJob::Sequence, availableHostMemory());
    const CameraPath path = parseCameraPath(args.path);
    const Keyframes keyframes =
        args.keyframes.empty() ? Keyframes{} : loadKeyframes(args.keyframes, base);
    auto sceneOfFrame = [&](int f) {
        return sceneOnPath(keyframes.sceneAt(base, f / static_cast<double>(args.fps)), path, f,
                           args.fps);
    };
    sceneOfFrame(args.frames - 1); // its last frame is in range
    if (!args.frameDir.empty())
        prepareFrameDir(args.frameDir);
    const BackendOptions backend = args.backend.options();
    stopIfValidatingOnly();
    std::string notice;
    // The temporal renderer and the reference both run on the chosen backend, each a persistent
    // Renderer (device, pipelines and textures kept), so the time ratio compares like with like.
    Renderer temporal(base, backend, &notice);
    Renderer reference(referenceOf(base), temporal.resources(), backend);
    if (!notice.empty())
        std::fprintf(stderr, "cloudscape: note: %s\n", notice.c_str());
    std::string backendName;

    std::printf("cloudscape bench: %s, camera path %s, %d frames at %dx%d, backend %s\n",
                args.scene.scene.empty() ? "default scene" : args.scene.scene.c_str(),
                args.path.c_str(), args.frames, base.width, base.height,
                args.backend.backend.c_str());
    std::printf("%5s %8s %8s %8s %9s %7s %7s %7s %8s %7s %7s %6s\n", "frame", "march", "resolve",
                "total", "reference", "rays/px", "dens/px", "light/px", "PSNR", "SSIM", "MS-SSIM",
                "fallbk");
    nlohmann::json perFrame = nlohmann::json::array();
    struct Sum {
        double ms = 0, refMs = 0, density = 0, refDensity = 0, light = 0, refLight = 0;
        double psnr = 0, ssim = 0, msssim = 0;
        int n = 0;
    } all, converged;
    const double pixels = static_cast<double>(base.width) * base.height;
    for (int f = 0; f < args.frames; ++f) {
        const Scene scene = sceneOfFrame(f);
        // The metrics read the composite only, so only the displayed image is read back.
        const RenderResult t = temporal.renderFrame(scene, f, Readback::Display);
        const RenderResult ref = reference.render(referenceOf(scene), {}, Readback::Display);
        backendName = t.stats.backend;
        const std::vector<float> a = compositeRgb(ref), b = compositeRgb(t);
        const auto la = displayLuminance(a, 3, scene.exposure);
        const auto lb = displayLuminance(b, 3, scene.exposure);
        // PSNR of the display luminance (peak 1), like SSIM: on HDR radiance the sun disc's
        // enormous peak would make every frame look excellent.
        const ImageDifference d = compareImages(la, lb, 1, {}, 1.0);
        const double s = ssim(la, lb, scene.width, scene.height);
        const double ms = msSsim(la, lb, scene.width, scene.height);
        const double tMs = t.stats.seconds * 1000.0, refMs = ref.stats.seconds * 1000.0;
        const TemporalDebugImage debug = temporal.temporalDebug();
        const double fallback = fallbackFraction(debug);
        if (!args.frameDir.empty())
            saveFrameImages(args.frameDir, f, t, ref, debug, scene.exposure);
        std::printf("%5d %8.1f %8.1f %8.1f %9.1f %7.3f %7.2f %8.2f %8.2f %7.4f %7.4f %6.3f\n", f,
                    t.stats.marchSeconds * 1000.0, t.stats.resolveSeconds * 1000.0, tMs, refMs,
                    t.stats.rays / pixels, t.stats.densitySamples / pixels,
                    t.stats.lightSamples / pixels, d.psnr, s, ms, fallback);
        perFrame.push_back(
            {{"frame", f},
             {"march_ms", t.stats.marchSeconds * 1000.0},
             {"resolve_ms", t.stats.resolveSeconds * 1000.0},
             {"total_ms", tMs},
             {"reference_ms", refMs},
             {"rays_per_pixel", t.stats.rays / pixels},
             {"density_samples_per_pixel", t.stats.densitySamples / pixels},
             {"light_samples_per_pixel", t.stats.lightSamples / pixels},
             {"reference_density_samples_per_pixel", ref.stats.densitySamples / pixels},
             {"psnr_db", d.psnr},
             {"ssim", s},
             {"ms_ssim", ms},
             {"fallback_fraction", fallback}});
        for (Sum* sum : {&all, f >= 16 ? &converged : nullptr}) {
            if (!sum)
                continue;
            sum->ms += tMs;
            sum->refMs += refMs;
            sum->density += t.stats.densitySamples + t.stats.lightSamples;
            sum->refDensity += ref.stats.densitySamples + ref.stats.lightSamples;
            sum->psnr += d.psnr;
            sum->ssim += s;
            sum->msssim += ms;
            ++sum->n;
        }
    }
    nlohmann::json summary;
    for (const auto& [name, sum] : {std::pair<const char*, const Sum&>{"all", all},
                                    std::pair<const char*, const Sum&>{"converged", converged}}) {
        if (sum.n == 0)
            continue;
        const double timeRatio = sum.refMs / sum.ms;
        const double sampleRatio = sum.refDensity / sum.density;
        std::printf("%-9s frames %3d: %.1f ms/frame (reference %.1f): %.1fx cheaper in time, "
                    "%.1fx in density+light samples; PSNR %.2f dB, SSIM %.4f, MS-SSIM %.4f\n",
                    name, sum.n, sum.ms / sum.n, sum.refMs / sum.n, timeRatio, sampleRatio,
                    sum.psnr / sum.n, sum.ssim / sum.n, sum.msssim / sum.n);
        summary[name] = {{"frames", sum.n},
                         {"ms_per_frame", sum.ms / sum.n},
                         {"reference_ms_per_frame", sum.refMs / sum.n},
                         {"time_ratio", timeRatio},
                         {"sample_ratio", sampleRatio},
                         {"psnr_db", sum.psnr / sum.n},
                         {"ssim", sum.ssim / sum.n},
                         {"ms_ssim", sum.msssim / sum.n}};
    }
    if (!args.json.empty()) {
        const nlohmann::json doc = {
            {"scene", args.scene.scene.empty() ? "default" : args.scene.scene},
            {"camera_path", args.path},
            {"frames", args.frames},
            {"width", base.width},
            {"height", base.height},
            {"backend", backendName},
            {"per_frame", perFrame},
            {"summary", summary}};
        const std::string text = doc.dump(2) + "\n";
        writeFileAtomic(args.json, text.data(), text.size());
    }
}

} // namespace

void addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Run a camera path through the temporal renderer and measure cost and quality "
                 "against the reference");
    args->scene.addTo(*cmd, true);
    cmd->add_option("--camera-path", args->path,
                    "still, slow-pan, fast-pan, fly-forward or fly-through");
    cmd->add_option("--frames", args->frames, "Number of frames (default 32)");
    cmd->add_option("--fps", args->fps, "Frames per second: time step of the animation");
    cmd->add_option("--json", args->json, "Also write the results as JSON");
    cmd->add_option("--save-frames", args->frameDir,
                    "Also write each frame's temporal image, reference and per-pixel source "
                    "(marched white, reprojected green, fallback red) as PNGs into this new or "
                    "empty directory");
    cmd->add_option("--keyframes", args->keyframes,
                    "Keyframe file (JSON) animating scene keys over the frames (docs/SCENE.md)");
    // The CPU backend unless asked: the documented figures (docs/PERFORMANCE.md) are CPU ones.
    args->backend.backend = "cpu";
    args->backend.addTo(*cmd, "cpu (default), vulkan, or auto (GPU, then lavapipe, then CPU): "
                              "where both the temporal renderer and the reference run");
    cmd->callback([args]() { runBench(*args); });
}

} // namespace cloudscape::cli
