#pragma once
// Reduced-resolution cloud passes (render.cloud_resolution, the low tier's half resolution) and
// the scene depth buffer at the size a pass renders. Plumbing shared by the backends: a backend
// renders the pass scene as usual, and the upsample composites over the model's sky at full size.
#include <cloudscape/renderer.h>

#include <glm/vec4.hpp>

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

// A reduced-resolution pass brought to full size: the premultiplied cloud layer bilinearly, where
// a tap whose first cloud lies behind this pixel's geometry counts as clear sky (depth-aware), the
// cloud depth from the nearest tap, then composited over the full-resolution sky. Statistics are
// the pass's (rays are the pass's rays). `shadowMap`: the clouds' shadow map the pass made (the
// full scene's too: the map does not depend on the image's size), or nullptr to make it here.
RenderResult upsampleCloudPass(const RenderResult& pass, const Scene& full,
                               const SceneResources& resources,
                               const std::vector<glm::vec4>* shadowMap = nullptr);

// pass(cloudPassScene(full)), upsampled; the backends' entry points call this when
// render.cloud_resolution < 1. The pass hands out the clouds' shadow map it made (left empty,
// the upsample makes its own), so a frame makes it once.
using CloudPass = std::function<RenderResult(const Scene&, std::vector<glm::vec4>& shadowMap)>;
RenderResult renderAtCloudResolution(const Scene& full, const SceneResources& resources,
                                     const CloudPass& pass);

} // namespace cloudscape
