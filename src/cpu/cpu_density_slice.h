#pragma once
// The viewer's density slice on the host: the model's per-pixel rule (debugDensitySlice,
// src/model/debug_view.glsl.h) over a vertical plane through the camera. Plumbing only.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <glm/vec3.hpp>

#include <vector>

namespace cloudscape::cpu {

// The slice's scale: the plane runs from the camera (the image's left edge) along its level
// heading, from the ground (the bottom row) to 15 % over the cloud layer's top or the camera,
// whichever is higher, at the same metres per pixel across and up.
struct DensitySliceFrame {
    float metresPerPixel = 0.0f;
    float topAltitude = 0.0f; // m, the top row's
};
DensitySliceFrame densitySliceFrame(const Scene& scene, int height);

// width x height display colours, row 0 at the top.
std::vector<glm::vec3> densitySlice(const Scene& scene, const SceneResources& resources, int width,
                                    int height);

} // namespace cloudscape::cpu
