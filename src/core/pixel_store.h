#pragma once
// Writing one pixel of a RenderResult, shared by the backends so that the output conventions
// (premultiplied cloud layer, +infinity depth where the model reports no cloud) live in one place.
#include <cloudscape/renderer.h>

#include "model/shell.glsl.h"

#include <glm/glm.hpp>

#include <limits>

namespace cloudscape {

inline void storePixel(RenderResult& out, size_t i, glm::vec3 cloudRadiance, float transmittance,
                       glm::vec3 composite, float depth) {
    out.cloud[i * 4 + 0] = cloudRadiance.x;
    out.cloud[i * 4 + 1] = cloudRadiance.y;
    out.cloud[i * 4 + 2] = cloudRadiance.z;
    out.cloud[i * 4 + 3] = transmittance;
    out.depth[i] = depth == model::NO_HIT ? std::numeric_limits<float>::infinity() : depth;
    out.composite[i * 4 + 0] = composite.x;
    out.composite[i * 4 + 1] = composite.y;
    out.composite[i * 4 + 2] = composite.z;
    out.composite[i * 4 + 3] = 1.0f;
}

// Allocate the planes of a result.
inline void allocateResult(RenderResult& out, int width, int height) {
    out.width = width;
    out.height = height;
    const size_t pixels = static_cast<size_t>(width) * height;
    out.cloud.assign(pixels * 4, 0.0f);
    out.depth.assign(pixels, 0.0f);
    out.composite.assign(pixels * 4, 0.0f);
}

} // namespace cloudscape
