// `cloudscape render`: scene -> PNG (tone-mapped sRGB) or EXR (linear layers).
#include "backend_options.h"
#include "commands.h"
#include "gpu_pass_times.h"
#include "progress.h"
#include "scene_options.h"
#include "sequence_resume.h"
#include "validate_only.h"

#include <cloudscape/atomic_files.h>
#include <cloudscape/backend.h>
#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/frame_pattern.h>
#include <cloudscape/image_io.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/memory_estimate.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/render_files.h>
#include <cloudscape/renderer.h>
#include <cloudscape/sequence_checkpoint.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

namespace cloudscape::cli {
namespace {

enum class OutputFormat { Png, Exr };

OutputFormat formatOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png")
        return OutputFormat::Png;
    if (ext == ".exr")
        return OutputFormat::Exr;
    throw Error(path + ": unsupported output extension '" + ext + "', expected .png or .exr");
}

void writeImage(const std::string& path, OutputFormat format, const RenderResult& result,
                float exposure) {
    if (format == OutputFormat::Png)
        writePng(path, result.width, result.height, toneMapToSrgb8(result, exposure));
    else
        writeRenderExr(path, result);
}

struct RenderArgs {
    SceneOptions scene;
    std::string output;
    bool stats = false;
    std::string frames; // "A:B" renders an animated sequence through the temporal path
    float fps = 24.0f;
    bool force = false;
    std::string cameraPath = "still";
    std::string keyframes; // a keyframe file animating scene keys over the sequence
    BackendArgs backend;
    int checkpointEvery = 8; // frames between checkpoints of a temporal sequence; 0: none
};

// A PNG shows only the composite, so only that is read back from the device.
Readback readbackFor(OutputFormat format) {
    return format == OutputFormat::Png ? Readback::Display : Readback::All;
}

// The median time of the frames after the first: the first pays for building the pipelines and
// for the first background, so the mean of a short sequence overstates what a running renderer
// spends a frame (the first of 12 frames at 1280x720 on lavapipe took about 1.7 s against 0.6 s).
// Comparisons with renderers measured after their warm-up use this figure.
double steadyFrameSeconds(std::vector<double> frameSeconds) {
    frameSeconds.erase(frameSeconds.begin());
    const auto middle = frameSeconds.begin() + frameSeconds.size() / 2;
    std::nth_element(frameSeconds.begin(), middle, frameSeconds.end());
    return *middle;
}

// The sequence's march per ray (density samples along the view rays, light samples toward the
// sun) and, with GPU timestamps, the passes' times and the march's time per sample: the figures
// docs/PERFORMANCE.md compares with other renderers.
struct SequenceMarch {
    uint64_t rays = 0; // marched, over the frames (a temporal frame marches some pixels)
    uint64_t density = 0, light = 0, inCloud = 0; // samples over the frames' marched rays

    void add(const RenderStats& s) {
        rays += s.rays;
        density += s.densitySamples;
        light += s.lightSamples;
        inCloud += s.cloudSamples;
    }
};

void printSequenceSamples(const SequenceMarch& march, const GpuPassTimes& gpuTimes) {
    const double perRay = 1.0 / static_cast<double>(std::max<uint64_t>(march.rays, 1));
    std::printf("samples per marched ray: %.1f density (%.2f of them in cloud), %.1f light\n",
                static_cast<double>(march.density) * perRay,
                static_cast<double>(march.inCloud) * perRay,
                static_cast<double>(march.light) * perRay);
    if (!gpuTimes.timed())
        return;
    std::printf("%s\n", gpuTimes.line().c_str());
    const uint64_t samples = march.density + march.light;
    if (samples > 0)
        std::printf("march: %.0f ns of GPU time per density or light sample\n",
                    1e6 * gpuTimes.marchMsTotal() / static_cast<double>(samples));
}

// An animation: time advances by 1/fps a frame from the scene's time_s and the clouds move with
// the wind; --keyframes animates scene keys (the frame's scene is the base with the keyframes at
// f / fps, then moved along the camera path); every frame goes through one persistent Renderer
// (device, pipelines, textures and the temporal history kept between frames). Frames already on
// disk are not written again unless --force. Every --checkpoint-every frames the temporal state is
// saved beside the frames, after the frame itself, so a rerun continues from the last checkpoint
// before its first missing frame (or from the first frame) and writes exactly the frames an
// uninterrupted run would have written (sequence_resume.h).
void runSequence(const RenderArgs& args, OutputFormat format) {
    const BackendOptions backend = args.backend.options();
    const auto colon = args.frames.find(':');
    int first = 0, last = -1;
    try {
        if (colon == std::string::npos)
            throw std::invalid_argument("no colon");
        first = std::stoi(args.frames.substr(0, colon));
        last = std::stoi(args.frames.substr(colon + 1));
    } catch (const std::exception&) {
        throw Error("--frames '" + args.frames + "': expected A:B with integers A <= B");
    }
    if (first < 0 || last < first || last - first > 1000000)
        throw Error("--frames '" + args.frames + "': expected 0 <= A <= B");
    if (!(args.fps > 0.0f && args.fps <= 1000.0f))
        throw Error("--fps " + std::to_string(args.fps) + ": expected a rate in (0, 1000]");
    if (args.checkpointEvery < 0)
        throw Error("--checkpoint-every " + std::to_string(args.checkpointEvery) +
                    ": expected a number of frames, or 0 for none");
    const FramePattern pattern(args.output); // a user's string: parsed, never a format
    const Scene base = args.scene.load();
    const CameraPath path = parseCameraPath(args.cameraPath);
    const Keyframes keyframes =
        args.keyframes.empty() ? Keyframes{} : loadKeyframes(args.keyframes, base);
    auto sceneOfFrame = [&](int f) {
        return sceneOnPath(keyframes.sceneAt(base, f / static_cast<double>(args.fps)), path, f,
                           args.fps);
    };
    sceneOfFrame(last); // its last frame is in range
    requireHostMemory(base, RenderJob::Sequence, availableHostMemory());
    checkOutputWritable(pattern.path(first));
    stopIfValidatingOnly();
    const std::string checkpoint = sequenceCheckpointPath(args.output, pattern.path(first));
    std::vector<std::string> outputs = {checkpoint};
    int firstMissing = last + 1, lastMissing = first - 1;
    for (int f = first; f <= last; ++f) {
        outputs.push_back(pattern.path(f));
        if (args.force || !std::filesystem::exists(outputs.back())) {
            firstMissing = std::min(firstMissing, f);
            lastMissing = f;
        }
    }
    removeStaleTemporaries(outputs); // left by a run killed while writing
    if (firstMissing > last) {
        std::fprintf(stderr, "cloudscape: note: all %d frames exist; --force renders them again\n",
                     last - first + 1);
        return;
    }
    // With render.temporal off every frame is a full render.
    std::string notice;
    Renderer renderer(base, backend, &notice);
    // Without the temporal path frames are independent: only the missing ones are rendered.
    SequenceResume resume{firstMissing, -1};
    std::string fingerprint;
    if (base.temporal) {
        fingerprint = sequenceFingerprint(base, renderer.resources(), args.cameraPath,
                                          keyframes.fingerprintText(), args.fps, first,
                                          renderer.backendName());
        resume = args.force
                     ? SequenceResume{first, -1}
                     : resumeSequence(renderer, checkpoint, fingerprint, first, firstMissing);
    }
    const int start = resume.start, end = lastMissing;
    ProgressBar bar("frames");
    int written = 0;
    double seconds = 0.0;
    std::vector<double> frameSeconds;
    GpuPassTimes gpuTimes; // per-pass GPU timestamps (Vulkan), summed over the frames
    SequenceMarch march;
    std::string backendName;
    for (int f = start; f <= end; ++f) {
        const Scene scene = sceneOfFrame(f);
        const RenderResult r = base.temporal ? renderer.renderFrame(scene, f, readbackFor(format))
                                             : renderer.render(scene, {}, readbackFor(format));
        for (const std::string& m : r.stats.validationMessages)
            std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());
        seconds += r.stats.seconds;
        frameSeconds.push_back(r.stats.seconds);
        gpuTimes.add(r.stats);
        march.add(r.stats);
        backendName = r.stats.backend;
        const std::string framePath = pattern.path(f);
        if (f >= firstMissing && (args.force || !std::filesystem::exists(framePath))) {
            writeImage(framePath, format, r, scene.exposure);
            ++written;
        }
        // After the frame, so a checkpoint never runs ahead of the frames on disk; never over
        // a later checkpoint of this same sequence.
        const bool due =
            f == end || (args.checkpointEvery > 0 && (f - first + 1) % args.checkpointEvery == 0);
        if (base.temporal && args.checkpointEvery > 0 && due && f > resume.checkpointFrame)
            writeCheckpoint(renderer, checkpoint, fingerprint);
        bar.update(static_cast<double>(f - start + 1) / (end - start + 1));
    }
    bar.finish();
    if (!notice.empty())
        std::fprintf(stderr, "cloudscape: note: %s\n", notice.c_str());
    else if (backend.choice == BackendChoice::Auto)
        std::fprintf(stderr, "cloudscape: note: rendered on %s\n", backendName.c_str());
    if (args.stats) {
        // What the frames marched: a temporal frame one pixel of every 4x4 or 2x2 block (at the
        // clouds' pass size), so say how many output pixels share a ray on average.
        const double pixelsPerRay = static_cast<double>(base.width) * base.height *
                                    (end - start + 1) /
                                    static_cast<double>(std::max<uint64_t>(march.rays, 1));
        char marched[64];
        std::snprintf(marched, sizeof marched, "a ray per %.1f output pixels a frame",
                      pixelsPerRay);
        std::printf("frames %d..%d, wrote %d, %.1f ms per frame (%s, %s)\n", first, last, written,
                    1000.0 * seconds / (end - start + 1),
                    base.temporal ? marched : "every pixel every frame", backendName.c_str());
        if (frameSeconds.size() >= 3)
            std::printf("steady state: %.1f ms per frame (median of frames %d..%d)\n",
                        1000.0 * steadyFrameSeconds(frameSeconds), start + 1, end);
    }
    if (args.stats)
        printSequenceSamples(march, gpuTimes);
}

// A still's default samples per pixel (issue 15, item 5): at 1 the march's start-offset jitter
// shows as grain at cloud edges; each sample is a jittered march through a hashed point of the
// pixel, so their mean converges (figures and cost in docs/PERFORMANCE.md). A scene file, a
// tier or --set that names render.samples_per_pixel decides instead; sequences are unchanged
// (the temporal reconstruction averages over frames).
constexpr int kStillSamplesPerPixel = 4;

Scene stillDefaults() {
    Scene s;
    s.samplesPerPixel = kStillSamplesPerPixel;
    return s;
}

void runRender(const RenderArgs& args) {
    const OutputFormat format = formatOf(args.output);
    if (!args.frames.empty()) {
        runSequence(args, format);
        return;
    }
    if (!args.keyframes.empty())
        throw Error("--keyframes " + args.keyframes +
                    ": keyframes animate a sequence; give --frames A:B too");
    const BackendOptions backend = args.backend.options();
    const Scene scene = args.scene.load(stillDefaults());
    checkOutputWritable(args.output);
    requireHostMemory(scene,
                      format == OutputFormat::Png ? RenderJob::StillPng : RenderJob::StillExr,
                      availableHostMemory());
    stopIfValidatingOnly();

    std::string notice;
    Renderer renderer(scene, backend, &notice);
    const SceneResources& resources = renderer.resources();
    ProgressBar bar("render");
    const RenderResult result = renderer.render(
        scene, [&](double fraction) { bar.update(fraction); }, readbackFor(format));
    bar.finish();
    // With auto, say which backend ran: the fallback notice, or the device chosen.
    if (!notice.empty())
        std::fprintf(stderr, "cloudscape: note: %s\n", notice.c_str());
    else if (backend.choice == BackendChoice::Auto)
        std::fprintf(stderr, "cloudscape: note: rendered on %s\n", result.stats.backend.c_str());
    for (const std::string& m : result.stats.validationMessages)
        std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());

    if (format == OutputFormat::Png)
        writePng(args.output, result.width, result.height, toneMapToSrgb8(result, scene.exposure));
    else
        writeRenderExr(args.output, result);

    if (args.stats) {
        const RenderStats& s = result.stats;
        const double px = static_cast<double>(s.rays);
        std::printf("backend          %s (%d x %d)\n", s.backend.c_str(), result.width,
                    result.height);
        std::printf("rays             %llu (%d per pixel)\n",
                    static_cast<unsigned long long>(s.rays), scene.samplesPerPixel);
        std::printf("density samples  %llu (%.1f per ray)\n",
                    static_cast<unsigned long long>(s.densitySamples), s.densitySamples / px);
        if (s.densitySamples > 0)
            std::printf("  in cloud       %llu (%.2f per ray); empty-space skips %.1f per ray\n",
                        static_cast<unsigned long long>(s.cloudSamples), s.cloudSamples / px,
                        s.emptySkips / px);
        std::printf("light samples    %llu (%.1f per ray)\n",
                    static_cast<unsigned long long>(s.lightSamples), s.lightSamples / px);
        std::printf("noise textures   %.3f s\n", resources.noiseSeconds);
        std::printf("weather map      %.3f s\n", resources.weatherSeconds);
        if (!resources.atmosphere.empty())
            std::printf("atmosphere tables %.3f s%s\n", resources.atmosphereSeconds,
                        resources.atmosphereOnDevice ? " (on the device)" : "");
        std::printf("render time      %.3f s\n", s.seconds);
        if (s.gpuMarchMs >= 0.0) {
            std::printf("gpu upload pass  %.3f ms\n", s.gpuUploadMs);
            std::printf("gpu march pass   %.3f ms\n", s.gpuMarchMs);
            std::printf("gpu shadow map   %.3f ms\n", s.gpuShadowMs);
            if (s.gpuShaftGridMs > 0.0)
                std::printf("gpu shafts grid  %.3f ms\n", s.gpuShaftGridMs);
        }
        if (s.gpuMemoryBytes > 0)
            std::printf("gpu memory       %.2f MB (textures %.2f MB; the seeds' sky budget is "
                        "20 MB of textures)\n",
                        s.gpuMemoryBytes / 1048576.0, s.gpuTextureBytes / 1048576.0);
    }
}

} // namespace

void addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to a PNG or EXR image");
    args->scene.addTo(*cmd, true);
    cmd->add_option("-o,--output", args->output, "Output image (.png or .exr)")->required();
    cmd->add_flag("--stats", args->stats, "Print rays, samples and timings");
    cmd->add_option("--frames", args->frames,
                    "Render frames A:B of an animation (output name with %04d) through the "
                    "temporal reconstruction");
    cmd->add_option("--fps", args->fps, "Frames per second of the animation (default 24)");
    cmd->add_flag("--force", args->force, "Render frames again even if their files exist");
    cmd->add_option("--checkpoint-every", args->checkpointEvery,
                    "Frames between checkpoints of a sequence's temporal state, written beside "
                    "the frames so a rerun resumes exactly (0: none)")
        ->capture_default_str();
    cmd->add_option("--camera-path", args->cameraPath,
                    "Camera motion of a sequence: still (default), slow-pan, fast-pan, "
                    "fly-forward, fly-through (below the cloud layer to above it in 96 frames)");
    cmd->add_option("--keyframes", args->keyframes,
                    "Keyframe file (JSON) animating scene keys over a sequence, e.g. the time "
                    "of day and the coverage (docs/SCENE.md)");
    args->backend.addTo(*cmd, "auto (GPU, then lavapipe, then CPU), cpu, vulkan");
    cmd->callback([args]() {
        // --vulkan-validation: after the renderers are gone, what the layer said where no
        // render result could carry it (instance destruction), also when the render failed.
        struct ReportLateMessages {
            ~ReportLateMessages() {
                for (const std::string& m : takeVulkanValidationMessages())
                    std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());
            }
        } report;
        runRender(*args);
    });
}

} // namespace cloudscape::cli
