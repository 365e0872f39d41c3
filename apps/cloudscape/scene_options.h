#pragma once
// The scene-related options several commands share: SCENE, --width, --height, --seed, --set.
#include <cloudscape/scene.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cloudscape::cli {

// The scene a command renders when given none (a preset in scenes/).
inline constexpr const char* kDefaultPreset = "fair-weather-cumulus";

struct SceneOptions {
    std::string scene; // path or preset name; empty means kDefaultPreset
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> seed;
    std::vector<std::string> overrides;
    std::string tier; // low, high, reference; applied before --set

    void addTo(CLI::App& command, bool withSize);
    Scene load() const; // loads, applies options and overrides, validates
    // The same over other defaults than Scene{}: a key the scene file, --tier and --set leave
    // alone keeps its value in `defaults`.
    Scene load(const Scene& defaults) const;
};

} // namespace cloudscape::cli
