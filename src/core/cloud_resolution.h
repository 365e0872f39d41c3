#pragma once
// Reduced-resolution cloud passes (render.cloud_resolution, the low tier's half resolution) and
// the scene depth buffer at the size a pass renders. Plumbing shared by the backends: a backend
// renders the pass scene as usual, and the upsample composites over the model's sky at full size.
#include <cloudscape/renderer.h>

#include <glm/vec4.hpp>

#include "model/interface.glsl.h"

#include <functional>
#include <vector>

namespace cloudscape {

// The scene a reduced-resolution pass renders: the output size times render.cloud_resolution
// (rounded up, at least 1 pixel), the same field of view, and cloud resolution 1.
Scene cloudPassScene(const Scene& full);

// The depth buffer for a render of scene.width x scene.height: empty without one; the loaded
// buffer at its own size; for a reduced-resolution pass, each pass pixel takes the farthest depth
// of the output pixels it covers, so the pass marches every cloud some output pixel can see (the
// upsample then removes cloud from the pixels whose own geometry is nearer). Throws for any other
// size.
std::vector<float> sceneDepthFor(const Scene& scene, const SceneResources& resources);

// What a reduced pass made that its upsample reads too: the clouds' shadow map (the full
// scene's as well: the map does not depend on the image's size), and the light shafts' grid
// over the pass's image when a temporal pass made one (shaft_grid.glsl.h). Empty: not made.
struct PassProducts {
    std::vector<glm::vec4> shadowMap;
    std::vector<model::ShaftTexel> shafts;
};

// A reduced-resolution pass brought to full size: the premultiplied cloud layer bilinearly, where
// a tap whose first cloud lies behind this pixel's geometry counts as clear sky (depth-aware), the
// cloud depth from the nearest tap, then composited over the full-resolution sky, with the
// pass's shafts' grid when it made one (else every pixel's own shafts). Statistics are the
// pass's (rays are the pass's rays). The shadow map is made here when the pass did not hand it
// over.
// backgroundFromPass: the background too is the pass's brought up (upsampledBackground; a
// moving camera with render.moving_background_reduced, decided by the caller), made here for the
// pass's pixels, instead of each output pixel's own.
RenderResult upsampleCloudPass(const RenderResult& pass, const Scene& full,
                               const SceneResources& resources,
                               const PassProducts* products = nullptr,
                               bool backgroundFromPass = false);

// pass(cloudPassScene(full)), upsampled; the backends' entry points call this when
// render.cloud_resolution < 1. The pass hands out what it made that the upsample reads.
using CloudPass = std::function<RenderResult(const Scene&, PassProducts& products)>;
RenderResult renderAtCloudResolution(const Scene& full, const SceneResources& resources,
                                     const CloudPass& pass, bool backgroundFromPass = false);

} // namespace cloudscape
