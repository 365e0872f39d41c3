#pragma once
// The CPU backend's shadow-map pass: the model's per-texel rule (cloudShadowMapTexel,
// src/model/cloud_shadow.glsl.h) over every texel on all cores. Plumbing only.
#include "cpu/cpu_textures.h"
#include "model/params.glsl.h"

#include <glm/glm.hpp>

#include <vector>

namespace cloudscape::cpu {

// The map of this frame's parameters (resolution^2 texels, each at its
// cloudShadowStorageIndex), made with the noise and weather of `textures`; empty when the map is
// off or the sun too low for it (cloudShadowMapUsable). Deterministic: each texel is a pure
// function of its world texel.
std::vector<glm::vec4> computeCloudShadowMap(const model::CloudParams& cloud,
                                             const TextureSet& textures);

// A stored map (computeCloudShadowMap's) in map order: row-major, row 0 at the smallest z.
std::vector<glm::vec4> cloudShadowMapInRows(const std::vector<glm::vec4>& stored,
                                            const model::CloudShadowParams& params);

// Binds `map` as the set's shadow map (nullptr when empty).
inline void bindCloudShadowMap(TextureSet& textures, const std::vector<glm::vec4>& map) {
    textures.cloudShadow = map.empty() ? nullptr : map.data();
}

} // namespace cloudscape::cpu
