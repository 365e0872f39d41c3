// `cloudscape pathtrace [SCENE] -o OUT.exr --spp N`: the path-traced ground truth, progressive
// and resumable. The running estimate is written every --checkpoint seconds (atomically), with
// its sample count and a fingerprint of the scene in the EXR header, so `--resume` continues an
// interrupted or too-noisy render instead of starting again.
#include "commands.h"
#include "progress.h"
#include "scene_options.h"
#include "validate_only.h"

#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/memory_estimate.h>
#include <cloudscape/pathtrace.h>
#include <cloudscape/render_files.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace cloudscape::cli {
namespace {

struct PathTraceArgs {
    SceneOptions scene;
    std::string output;
    int samples = 64;
    bool resume = false;
    bool force = false;
    double checkpointSeconds = 60.0;
    bool stats = false;
    std::string preview;
    uint64_t stream = 0;
};

void runPathTrace(const PathTraceArgs& args) {
    namespace fs = std::filesystem;
    if (fs::path(args.output).extension() != ".exr")
        throw Error(args.output + ": the path tracer writes linear HDR: expected a .exr output");
    if (args.samples < 1)
        throw Error("--spp " + std::to_string(args.samples) + ": expected at least 1");
    const bool exists = fs::exists(args.output);
    if (exists && !args.resume && !args.force)
        throw Error(args.output + ": exists; pass --resume to add samples to it or --force to "
                                  "replace it");
    if (args.resume && args.force)
        throw Error("--resume and --force: choose one");
    const Scene scene = args.scene.load();
    checkOutputWritable(args.output);
    if (!args.preview.empty())
        checkOutputWritable(args.preview);
    requireHostMemory(scene, RenderJob::PathTrace, availableHostMemory());
    stopIfValidatingOnly();
    removeStaleTemporaries({args.output, args.preview}); // a killed run's half-written estimate
    const SceneResources resources = prepareResources(scene);
    const std::string fingerprint =
        pathTraceFingerprint(scene, resources) + "-stream" + std::to_string(args.stream);

    PathTraceImage image;
    image.stream = args.stream;
    if (args.resume && exists) {
        image = readPathTraceCheckpoint(args.output, fingerprint);
        image.stream = args.stream;
        if (image.width != scene.width || image.height != scene.height)
            throw Error(args.output + ": is " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + ", the scene renders " +
                        std::to_string(scene.width) + "x" + std::to_string(scene.height));
        std::fprintf(stderr, "cloudscape: resuming %s at %llu samples per pixel\n",
                     args.output.c_str(), static_cast<unsigned long long>(image.samplesPerPixel));
    }
    const uint64_t target = static_cast<uint64_t>(args.samples);
    if (image.samplesPerPixel >= target) {
        std::fprintf(stderr, "cloudscape: %s already has %llu samples per pixel (asked for %d)\n",
                     args.output.c_str(), static_cast<unsigned long long>(image.samplesPerPixel),
                     args.samples);
        return;
    }

    const uint64_t startSamples = image.samplesPerPixel;
    const double toDo = static_cast<double>(target - startSamples);
    ProgressBar bar("pathtrace");
    PathTraceStats total;
    auto lastCheckpoint = std::chrono::steady_clock::now();
    while (image.samplesPerPixel < target) {
        const double before = static_cast<double>(image.samplesPerPixel - startSamples);
        const PathTraceStats s = pathTrace(scene, resources, image, 1,
                                           [&](double f) { bar.update((before + f) / toDo); });
        total.paths += s.paths;
        total.collisions += s.collisions;
        total.truncated += s.truncated;
        total.majorantViolations += s.majorantViolations;
        total.seconds += s.seconds;
        const auto now = std::chrono::steady_clock::now();
        if (image.samplesPerPixel == target ||
            std::chrono::duration<double>(now - lastCheckpoint).count() >= args.checkpointSeconds) {
            writePathTraceCheckpoint(args.output, image, fingerprint);
            lastCheckpoint = now;
        }
    }
    bar.finish();
    if (!args.preview.empty()) {
        // Tone-mapped like `render` PNGs, for looking at.
        writePng(args.preview, image.width, image.height,
                 toneMapRgbToSrgb8(image.mean, scene.exposure));
    }
    if (total.majorantViolations > 0)
        std::fprintf(stderr,
                     "cloudscape: warning: %llu extinction samples exceeded the majorant; the "
                     "image is biased (please report this scene)\n",
                     static_cast<unsigned long long>(total.majorantViolations));
    if (total.truncated > 0)
        std::fprintf(stderr,
                     "cloudscape: warning: %llu paths reached pathtrace.max_bounces and were cut "
                     "(energy lost, image darker than the truth)\n",
                     static_cast<unsigned long long>(total.truncated));
    if (args.stats) {
        std::printf("samples per pixel  %llu (%llu added)\n",
                    static_cast<unsigned long long>(image.samplesPerPixel),
                    static_cast<unsigned long long>(image.samplesPerPixel - startSamples));
        std::printf("paths              %llu\n", static_cast<unsigned long long>(total.paths));
        std::printf("scattering events  %.2f per path\n",
                    total.paths ? static_cast<double>(total.collisions) / total.paths : 0.0);
        std::printf("truncated paths    %llu\n", static_cast<unsigned long long>(total.truncated));
        std::printf("time               %.2f s (%.0f paths/s)\n", total.seconds,
                    total.seconds > 0 ? total.paths / total.seconds : 0.0);
    }
}

} // namespace

void addPathTraceCommand(CLI::App& app) {
    auto args = std::make_shared<PathTraceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "pathtrace", "Path-trace the ground truth of a scene (progressive, resumable EXR)");
    args->scene.addTo(*cmd, true);
    cmd->add_option("-o,--output", args->output, "Output image (.exr, linear radiance)")
        ->required();
    cmd->add_option("--spp", args->samples, "Total samples per pixel to reach")
        ->capture_default_str();
    cmd->add_flag("--resume", args->resume,
                  "Continue the existing output (same scene) up to --spp samples");
    cmd->add_flag("--force", args->force, "Replace an existing output");
    cmd->add_option("--checkpoint", args->checkpointSeconds,
                    "Seconds between writes of the running estimate")
        ->capture_default_str();
    cmd->add_flag("--stats", args->stats, "Print path statistics");
    cmd->add_option("--stream", args->stream,
                    "Random stream: renders with different streams are independent estimates "
                    "(two of them measure the noise)")
        ->capture_default_str();
    cmd->add_option("--preview", args->preview, "Also write a tone-mapped PNG of the result");
    cmd->callback([args] { runPathTrace(*args); });
}

} // namespace cloudscape::cli
