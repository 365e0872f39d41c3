// `cloudscape render`: scene -> PNG (tone-mapped sRGB) or EXR (linear layers).
#include "commands.h"
#include "progress.h"
#include "scene_options.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/renderer.h>

#include <cstdio>
#include <filesystem>
#include <memory>

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

void writeExrLayers(const std::string& path, const RenderResult& r) {
    const size_t n = static_cast<size_t>(r.width) * r.height;
    // Planar copies: EXR channels are separate planes.
    std::vector<std::vector<float>> planes(9, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i) {
        planes[0][i] = r.composite[i * 4 + 0];
        planes[1][i] = r.composite[i * 4 + 1];
        planes[2][i] = r.composite[i * 4 + 2];
        planes[3][i] = 1.0f;
        planes[4][i] = r.cloud[i * 4 + 0];
        planes[5][i] = r.cloud[i * 4 + 1];
        planes[6][i] = r.cloud[i * 4 + 2];
        planes[7][i] = r.cloud[i * 4 + 3];
        planes[8][i] = r.depth[i];
    }
    // Premultiplied cloud layer: cloud.A = 1 - transmittance, for compositors; cloud.T is the
    // transmittance itself; cloud.Z is the distance to the first cloud (+inf where none).
    std::vector<float> alpha(n);
    for (size_t i = 0; i < n; ++i)
        alpha[i] = 1.0f - planes[7][i];
    writeExr(path, r.width, r.height,
             {{"R", planes[0].data()},
              {"G", planes[1].data()},
              {"B", planes[2].data()},
              {"A", planes[3].data()},
              {"cloud.R", planes[4].data()},
              {"cloud.G", planes[5].data()},
              {"cloud.B", planes[6].data()},
              {"cloud.A", alpha.data()},
              {"cloud.T", planes[7].data()},
              {"cloud.Z", planes[8].data()}});
}

struct RenderArgs {
    SceneOptions scene;
    std::string output;
    bool stats = false;
};

void runRender(const RenderArgs& args) {
    const OutputFormat format = formatOf(args.output);
    const Scene scene = args.scene.load();
    checkOutputWritable(args.output);

    const SceneResources resources = prepareResources(scene);
    ProgressBar bar("render");
    const RenderResult result =
        renderCpu(scene, resources, [&](double fraction) { bar.update(fraction); });
    bar.finish();

    if (format == OutputFormat::Png)
        writePng(args.output, result.width, result.height, toneMapToSrgb8(result, scene.exposure));
    else
        writeExrLayers(args.output, result);

    if (args.stats) {
        const RenderStats& s = result.stats;
        const double px = static_cast<double>(s.rays);
        std::printf("backend          cpu (%d x %d)\n", result.width, result.height);
        std::printf("rays             %llu\n", static_cast<unsigned long long>(s.rays));
        std::printf("density samples  %llu (%.1f per ray)\n",
                    static_cast<unsigned long long>(s.densitySamples), s.densitySamples / px);
        std::printf("light samples    %llu (%.1f per ray)\n",
                    static_cast<unsigned long long>(s.lightSamples), s.lightSamples / px);
        std::printf("noise textures   %.3f s\n", resources.noiseSeconds);
        std::printf("weather map      %.3f s\n", resources.weatherSeconds);
        std::printf("render time      %.3f s\n", s.seconds);
    }
}

} // namespace

void addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to a PNG or EXR image");
    args->scene.addTo(*cmd, true);
    cmd->add_option("-o,--output", args->output, "Output image (.png or .exr)")->required();
    cmd->add_flag("--stats", args->stats, "Print rays, samples and timings");
    cmd->callback([args]() { runRender(*args); });
}

} // namespace cloudscape::cli
