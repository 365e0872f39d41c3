#pragma once
// The atmosphere's lookup tables (src/model/atmosphere.glsl.h), filled on the host from the
// model's per-texel functions over every texel on the CPU's cores, in the model's order
// (transmittance; multiple scattering, which reads it; then the sky views and the ambient tables,
// which read both): the same code the Vulkan backend's compute pass runs
// (src/vulkan/atmosphere_tables.h), which a Renderer on that backend uses instead.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "model/params.glsl.h"

#include <glm/vec4.hpp>

#include <functional>
#include <vector>

namespace cloudscape {

// ATMOSPHERE_LUT_TEXELS texels in the model's layout, for the sky's atmosphere, sun direction,
// sun radius and sky-view radius (the camera's distance from the planet's centre).
std::vector<glm::vec4> computeAtmosphereLuts(const model::SkyParams& sky);

// What the tables depend on, as numbers: equal inputs give equal tables.
std::vector<float> atmosphereLutInputs(const model::SkyParams& sky);

// Makes the tables somewhere other than the host (a backend's device) and returns a copy of them.
using AtmosphereMaker = std::function<std::vector<glm::vec4>(const model::SkyParams& sky)>;

// Fills resources.atmosphere* for the scene (empties them for the gradient sky): the tables from
// computeAtmosphereLuts, or from `device` when given (atmosphereOnDevice).
void prepareAtmosphere(const Scene& scene, SceneResources& resources,
                       const AtmosphereMaker& device = {});

// True when the scene's atmosphere tables differ from those in the resources.
bool atmosphereChanged(const Scene& scene, const SceneResources& resources);

} // namespace cloudscape
