#include "scene_options.h"

#include <cloudscape/error.h>

namespace cloudscape::cli {

void SceneOptions::addTo(CLI::App& command, bool withSize) {
    command.add_option("scene", scene,
                       "Scene file or preset name (default: the " + std::string(kDefaultPreset) +
                           " preset)");
    if (withSize) {
        command.add_option("--width", width, "Image width in pixels (overrides render.width)");
        command.add_option("--height", height, "Image height in pixels (overrides render.height)");
    }
    command.add_option("--seed", seed, "Seed for noise, weather and jitter (overrides seed)");
    command.add_option("--tier", tier, "Quality tier: low, high or reference (before --set)");
    command.add_option("--set", overrides, "Override a scene key: --set weather.coverage=0.3")
        ->take_all();
}

Scene SceneOptions::load() const {
    return load(Scene{});
}

Scene SceneOptions::load(const Scene& defaults) const {
    // No scene is the default preset, not the bare key defaults: the preset adds the landscape
    // under the sky (terrain, the clouds' shadows, a camera on a hill) that the key defaults
    // leave off so every other scene and test keeps its flat ground.
    const std::string name = scene.empty() ? std::string(kDefaultPreset) : scene;
    Scene s = loadScene(resolveScenePath(name), defaults);
    if (width)
        applyOverride(s, "render.width=" + std::to_string(*width), "--width");
    if (height)
        applyOverride(s, "render.height=" + std::to_string(*height), "--height");
    if (seed)
        applyOverride(s, "seed=" + std::to_string(*seed), "--seed");
    if (!tier.empty())
        applyTier(s, tier);
    for (const std::string& o : overrides)
        applyOverride(s, o);
    validateScene(s, name);
    return s;
}

} // namespace cloudscape::cli
