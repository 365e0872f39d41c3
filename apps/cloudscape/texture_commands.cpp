// `cloudscape noise`, `cloudscape weather` and `cloudscape scene-doc`: the generators' outputs
// and the scene reference, for use outside the renderer.
#include "commands.h"
#include "scene_options.h"
#include "validate_only.h"

#include <cloudscape/atomic_files.h>
#include <cloudscape/backend.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/texture_export.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace cloudscape::cli {
namespace {

struct NoiseArgs {
    std::string directory;
    int seed = 1;
};

void runNoise(const NoiseArgs& args) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(args.directory))
        throw Error(args.directory + ": output directory does not exist");
    stopIfValidatingOnly();
    const auto start = std::chrono::steady_clock::now();
    // The textures a user can look at; the clearance field is the march's, not an image.
    const NoiseTextures noise = generateNoiseTextures(static_cast<uint32_t>(args.seed), false);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Sixteen files as one set: a failure (a full disk) leaves the directory as it was.
    std::vector<std::string> outputs;
    for (const char* name : {"base_noise", "detail_noise", "curl_noise", "high_clouds"})
        for (const std::string& file : textureExportFiles(args.directory, name))
            outputs.push_back(file);
    removeStaleTemporaries(outputs); // left by a run that was killed while writing
    AtomicFileSet files;
    exportTexture3D(noise.base, 4, args.directory, "base_noise", files);
    exportTexture3D(noise.detail, 3, args.directory, "detail_noise", files);
    exportTexture2D(noise.curl, 3, args.directory, "curl_noise", files);
    exportTexture2D(noise.highClouds, 3, args.directory, "high_clouds", files);
    files.commit();
    std::printf("generated base %d^3 RGBA, detail %d^3 RGB, curl %d^2 RGB, high clouds %d^2 RGB "
                "in %.2f s; wrote {base,detail,curl}_noise.{png,raw,exr,json} and "
                "high_clouds.{png,raw,exr,json} to %s\n",
                noise.base.size, noise.detail.size, noise.curl.width, noise.highClouds.width,
                seconds, args.directory.c_str());
}

struct WeatherArgs {
    SceneOptions scene;
    std::string output;
};

void runWeather(const WeatherArgs& args) {
    const Scene scene = args.scene.load();
    const std::string ext = std::filesystem::path(args.output).extension().string();
    if (ext != ".png")
        throw Error(args.output + ": unsupported output extension '" + ext + "', expected .png");
    checkOutputWritable(args.output);
    stopIfValidatingOnly();
    // As the renderer reads it: the coverage field with weather.coverage's bias and the
    // precipitation rule applied, so the image can be painted over and loaded as weather.image.
    const Texture2D w = prepareWeather(scene);
    const std::vector<float> seen = weatherAsSeen(w, CoverageField(w).biasFor(scene.coverage));
    std::vector<uint8_t> rgb(seen.size());
    for (size_t i = 0; i < seen.size(); ++i)
        rgb[i] = static_cast<uint8_t>(std::lround(seen[i] * 255.0f));
    writePngChannels(args.output, w.width, w.height, 3, rgb);
}

} // namespace

void addNoiseCommand(CLI::App& app) {
    auto args = std::make_shared<NoiseArgs>();
    CLI::App* cmd = app.add_subcommand(
        "noise", "Export the tileable noise textures (PNG slice atlas, raw UNORM8, EXR, JSON)");
    cmd->add_option("-o,--output", args->directory, "Existing output directory")->required();
    cmd->add_option("--seed", args->seed, "Noise seed")->check(CLI::Range(0, INT32_MAX));
    cmd->callback([args]() { runNoise(*args); });
}

void addWeatherCommand(CLI::App& app) {
    auto args = std::make_shared<WeatherArgs>();
    CLI::App* cmd = app.add_subcommand(
        "weather", "Write a scene's weather map as an RGB PNG (coverage, precipitation, type)");
    args->scene.addTo(*cmd, false);
    cmd->add_option("-o,--output", args->output, "Output PNG")->required();
    cmd->callback([args]() { runWeather(*args); });
}

void addDevicesCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("devices", "List the Vulkan devices with compute queues");
    cmd->callback([]() {
        stopIfValidatingOnly();
        const auto devices = listVulkanDevices();
        if (devices.empty())
            std::printf("no Vulkan devices; `render --backend auto` uses the CPU backend\n");
        for (const VulkanDeviceInfo& d : devices)
            std::printf("%d  %-40s %-10s %8.0f MB device-local  Vulkan %s\n", d.index,
                        d.name.c_str(), d.type.c_str(), d.deviceLocalBytes / 1048576.0,
                        d.apiVersion.c_str());
    });
}

void addSceneDocCommand(CLI::App& app) {
    auto path = std::make_shared<std::string>();
    CLI::App* cmd =
        app.add_subcommand("scene-doc", "Print the scene key reference (docs/SCENE.md)");
    cmd->add_option("-o,--output", *path, "Write to this file instead of stdout");
    cmd->callback([path]() {
        const std::string md = sceneDocumentationMarkdown();
        stopIfValidatingOnly();
        if (path->empty())
            std::fputs(md.c_str(), stdout);
        else
            writeFileAtomic(*path, md.data(), md.size());
    });
}

} // namespace cloudscape::cli
