#pragma once
// Writing one pixel of a RenderResult, shared by the backends so that the output conventions
// (premultiplied cloud layer, +infinity depth where the model reports no cloud) live in one place.
#include <cloudscape/renderer.h>

#include "model/interface.glsl.h"
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

// Pixel i of planes of 4 floats (cloud, transmittance) and 1 float (depth, NO_HIT where none) as
// the model's CloudTexel: how the CPU backend serves the model's history and pass reads.
inline model::CloudTexel cloudTexelOf(const std::vector<float>& cloud, float depth, size_t i) {
    model::CloudTexel t{};
    t.cloud = glm::vec4(cloud[i * 4], cloud[i * 4 + 1], cloud[i * 4 + 2], cloud[i * 4 + 3]);
    t.depth = depth;
    return t;
}

// The cloud layer and depth planes from a pass's CloudTexel records (a Vulkan readback).
inline void storeCloudTexels(RenderResult& out, const model::CloudTexel* texels, size_t pixels) {
    out.cloud.resize(pixels * 4);
    out.depth.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        const model::CloudTexel& t = texels[i];
        out.cloud[i * 4 + 0] = t.cloud.x;
        out.cloud[i * 4 + 1] = t.cloud.y;
        out.cloud[i * 4 + 2] = t.cloud.z;
        out.cloud[i * 4 + 3] = t.cloud.w;
        out.depth[i] = t.depth == model::NO_HIT ? std::numeric_limits<float>::infinity() : t.depth;
    }
}

// Drops the planes a readback mode does not ask for (the CPU backend has them anyway).
inline void keepReadback(RenderResult& out, Readback readback) {
    if (readback == Readback::All)
        return;
    out.cloud.clear();
    out.depth.clear();
    if (readback == Readback::None)
        out.composite.clear();
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
