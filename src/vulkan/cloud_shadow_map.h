#pragma once
// A renderer's shadow map on the device: the buffer cloud_shadow.comp (the model's
// cloudShadowMapTexel) fills at the start of each frame and the march, resolve and upsample
// passes read (their *_CLOUD_SHADOW bindings), with the shadow pass's descriptor set. Each
// renderer owns one (its CloudParams buffer is its own). Plumbing only.
#include "core/kept_inputs.h"
#include "model/params.glsl.h"
#include "vulkan/compute_pass.h"
#include "vulkan/model_textures.h"
#include "vulkan/vulkan_resources.h"

#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace cloudscape::vulkan {

class CloudShadowMap {
public:
    CloudShadowMap(Context& ctx, const ComputePass& pass);

    // Texels a side this frame's parameters ask for: 0 when the map is off or the sun too low.
    static int resolutionFor(const model::CloudParams& cloud);
    // Sizes the buffer for `resolution` texels a side (one texel while 0, so the readers' binding
    // stays valid). True when the buffer was replaced: the sets that bind it must be rewritten.
    bool resize(int resolution);
    const Buffer& buffer() const { return *buffer_; }
    // Rewrites the shadow pass's set: the renderer's CloudParams buffer, the textures, the map.
    void bind(const Buffer& cloudParams, const ModelTextures& textures);
    // Records the pass and a barrier before the passes that read the map, over what the map
    // does not already hold: nothing when it holds what these inputs make (the same parameters,
    // features and texture contents: a still scene in the viewer, a still sequence), the rows
    // and columns a move brings in when only the map's place changed (a flying camera), else
    // the whole map; nothing while off. True when it recorded the pass.
    bool record(vk::CommandBuffer cmd, const model::CloudParams& cloud, int features,
                uint64_t texturesVersion);
    // The texels the last record made (resolution^2 for a whole map, 0 when it kept the map).
    int64_t texelsMade() const { return texelsMade_; }
    // The map's contents become unknown (e.g. its pass did not complete): the next record runs.
    void invalidate() { holds_.invalidate(); }
    uint64_t deviceBytes() const { return resources_->deviceBytes(); }
    // The records the map holds (resolution^2) in map order (row-major from the smallest z),
    // copied from the host-visible buffer; empty while the map is off. Call after that frame's
    // work completed.
    std::vector<glm::vec4> texels() const;

private:
    Context& ctx_;
    const ComputePass& pass_;
    vk::DescriptorSet set_;
    std::unique_ptr<ResourceSet> resources_;
    Buffer* buffer_ = nullptr;
    int resolution_ = -1;
    // What the buffer holds the map of, once a recorded pass has filled it, but for where the
    // map lies (held_ has that): every input a texel's record depends on.
    struct Inputs {
        model::CloudParams cloud;
        int features;
        int pad;
        uint64_t texturesVersion;
    };
    KeptInputs<Inputs> holds_;
    model::CloudShadowParams held_{}; // the placement of the map the buffer holds
    int64_t texelsMade_ = 0;
    void recordRegion(vk::CommandBuffer cmd, glm::ivec2 begin, glm::ivec2 end);
};

} // namespace cloudscape::vulkan
