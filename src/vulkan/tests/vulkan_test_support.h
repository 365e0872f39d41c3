#pragma once
// What the GPU tests share: the Vulkan backend under the validation layers, one set of textures
// generated once per test binary, and splitting RGBA images into channel groups for metrics.
#include "core/atmosphere_luts.h"

#include <cloudscape/backend.h>
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <vector>

namespace cloudscape::testing {

inline BackendOptions vulkanWithValidation() {
    BackendOptions o;
    o.choice = BackendChoice::Vulkan;
    o.validation = true;
    return o;
}

// The default scene's textures (seed 1) and atmosphere tables, generated on first use.
inline const SceneResources& sharedResources() {
    static const SceneResources r = [] {
        SceneResources res;
        res.noise = generateNoiseTextures(1);
        res.weather = prepareWeather(Scene{});
        prepareAtmosphere(Scene{}, res);
        return res;
    }();
    return r;
}

// Channels [first, first + count) of every RGBA pixel, e.g. cloud radiance (0, 3) and
// transmittance (3, 1) as separate images.
inline std::vector<float> channels(const std::vector<float>& rgba, int first, int count) {
    std::vector<float> out;
    for (size_t i = 0; i < rgba.size(); i += 4)
        for (int c = first; c < first + count; ++c)
            out.push_back(rgba[i + c]);
    return out;
}

} // namespace cloudscape::testing
