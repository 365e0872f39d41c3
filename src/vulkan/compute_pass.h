#pragma once
// A compute pipeline built from one pass of src/model/interface.glsl.h: its descriptor-set layout,
// push-constant range and descriptor-pool sizes come from the pass's binding table, never from a
// hand-written list, and DescriptorWriter fills a set by binding number, taking each binding's
// descriptor type from the table and refusing to leave one out. Plumbing only.
#include "model/features.glsl.h"
#include "model/interface.glsl.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace cloudscape::vulkan {

vk::DescriptorType descriptorTypeOf(model::DescriptorKind kind);

// The set-layout bindings of a pass, in binding order.
std::vector<vk::DescriptorSetLayoutBinding> layoutBindingsOf(const model::PassInterface& pass);

// Pool sizes for the given number of descriptor sets of each pass.
std::vector<vk::DescriptorPoolSize>
descriptorPoolSizes(std::initializer_list<std::pair<const model::PassInterface*, uint32_t>> sets);

// A pass's pipeline and a pool for up to maxSets descriptor sets of its layout: one pipeline
// serves every renderer on a device, each with its own sets.
class ComputePass {
public:
    ComputePass(const Context& ctx, const model::PassInterface& pass, const uint32_t* spirv,
                size_t bytes, uint32_t maxSets = 4);

    const model::PassInterface& pass() const { return pass_; }
    vk::DescriptorSetLayout setLayout() const { return *setLayout_; }
    // A new descriptor set of this pass (throws once maxSets are taken).
    vk::DescriptorSet allocateSet() const;

    // Binds the pipeline specialised for `features` (model/features.glsl.h: modelFeaturesFor of
    // the frame's CloudParams; built on first use and kept) and a descriptor set of this pass.
    void bind(vk::CommandBuffer cmd, vk::DescriptorSet set,
              int features = model::FEATURE_ALL) const;
    // Builds the pipeline for `features` now, if it is not built yet, so that a later bind does
    // not stall on the compile (a renderer's pipelines for frames it has not met yet).
    void prepare(int features) const { (void)pipelineFor(features); }
    // Pipelines built by every ComputePass of the process (a diagnostic for tests).
    static uint64_t pipelinesBuilt();
    // Push constants: the struct must be the pass's own (interface.glsl.h), checked by size.
    template <class Push> void push(vk::CommandBuffer cmd, const Push& value) const {
        checkPushSize(sizeof(Push));
        cmd.pushConstants(*layout_, vk::ShaderStageFlagBits::eCompute, 0, sizeof(Push), &value);
    }

private:
    void checkPushSize(size_t bytes) const;
    vk::Pipeline pipelineFor(int features) const;

    const model::PassInterface& pass_;
    vk::Device device_;
    vk::UniqueDescriptorSetLayout setLayout_;
    vk::UniqueDescriptorPool pool_;
    vk::UniquePipelineLayout layout_;
    vk::UniqueShaderModule module_;
    // One pipeline per feature set a renderer has asked for (a handful: scenes switch features
    // rarely); renderers on one device share them.
    mutable std::mutex pipelinesMutex_;
    mutable std::map<int, vk::UniquePipeline> pipelines_;
};

// Writes every binding of a pass's descriptor set, by binding number.
class DescriptorWriter {
public:
    DescriptorWriter(const model::PassInterface& pass, vk::DescriptorSet set);
    DescriptorWriter& buffer(int binding, const Buffer& buffer);
    DescriptorWriter& image(int binding, vk::Sampler sampler, const Image& image);
    // Throws cloudscape::Error naming the pass and binding if any binding was left out.
    void commit(vk::Device device);

private:
    const model::BindingSpec& spec(int binding, bool wantImage) const;

    const model::PassInterface& pass_;
    vk::DescriptorSet set_;
    // Sized once, so the pointers the writes hold stay valid until commit.
    std::vector<vk::DescriptorBufferInfo> buffers_;
    std::vector<vk::DescriptorImageInfo> images_;
    std::vector<vk::WriteDescriptorSet> writes_;
    std::vector<bool> written_;
};

} // namespace cloudscape::vulkan
