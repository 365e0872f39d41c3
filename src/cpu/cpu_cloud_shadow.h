#pragma once
// The CPU backend's shadow-map pass: the model's per-texel rule (cloudShadowMapTexel,
// src/model/cloud_shadow.glsl.h) over the texels on all cores, made whole for a still or kept
// across a sequence's frames. Plumbing only.
#include "core/kept_inputs.h"
#include "cpu/cpu_textures.h"
#include "model/params.glsl.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace cloudscape::cpu {

// The map of this frame's parameters (resolution^2 texels, each at its
// cloudShadowStorageIndex), made with the noise and weather of `textures`; empty when the map is
// off or the sun too low for it (cloudShadowMapUsable). Deterministic: each texel is a pure
// function of its world texel.
std::vector<glm::vec4> computeCloudShadowMap(const model::CloudParams& cloud,
                                             const TextureSet& textures);

// A temporal renderer's map, kept while its inputs stay, as the Vulkan renderers keep theirs
// (src/core/cloud_shadow_update.h): update makes nothing when the map holds what these inputs
// make (the same parameters and texture contents: a still scene in the viewer), the rows and
// columns a move brings in when only the map's place changed (a flying camera with the wind's
// time held), else the whole map. Bit for bit the map computeCloudShadowMap makes.
class KeptCloudShadowMap {
public:
    // The map for `cloud` with the textures of `textures`, whose contents are those of
    // texturesVersion (a new version when they change); empty while the map is off. Stored at
    // cloudShadowStorageIndex, as computeCloudShadowMap stores it.
    const std::vector<glm::vec4>& update(const model::CloudParams& cloud,
                                         const TextureSet& textures, uint64_t texturesVersion);
    // The texels the last update made (resolution^2 for a whole map, 0 when it kept the map).
    int64_t texelsMade() const { return texelsMade_; }
    const std::vector<glm::vec4>& stored() const { return map_; }
    const model::CloudShadowParams& placement() const { return held_; }

private:
    struct Inputs {
        model::CloudParams cloud;
        uint64_t texturesVersion;
    };
    KeptInputs<Inputs> holds_;
    model::CloudShadowParams held_{}; // the placement of the map map_ holds
    std::vector<glm::vec4> map_;
    int64_t texelsMade_ = 0;
};

// A stored map (computeCloudShadowMap's) in map order: row-major, row 0 at the smallest z.
std::vector<glm::vec4> cloudShadowMapInRows(const std::vector<glm::vec4>& stored,
                                            const model::CloudShadowParams& params);

// Binds `map` as the set's shadow map (nullptr when empty).
inline void bindCloudShadowMap(TextureSet& textures, const std::vector<glm::vec4>& map) {
    textures.cloudShadow = map.empty() ? nullptr : map.data();
}

} // namespace cloudscape::cpu
