#pragma once
// The parts of prepareResources (include/cloudscape/renderer.h), for a persistent Renderer that
// regenerates only what a scene change touches.
#include <cloudscape/renderer.h>

namespace cloudscape {

void prepareNoise(const Scene& scene, SceneResources& resources);
// The weather map and its coverage-field distribution.
void prepareWeather(const Scene& scene, SceneResources& resources);
void prepareDepth(const Scene& scene, SceneResources& resources);

// Which resources a change from `before` to `after` invalidates. Everything a scene holds that is
// not listed here (coverage included) reaches the model as a uniform.
struct ResourceChanges {
    bool noise = false;   // seed
    bool weather = false; // the procedural generator's keys and seed, or weather.image
    bool depth = false;   // render.depth_file, or the size it must match
};
ResourceChanges resourceChanges(const Scene& before, const Scene& after);

} // namespace cloudscape
