#include "vulkan/compute_pass.h"

#include <cloudscape/error.h>

#include <atomic>
#include <map>
#include <string>

namespace cloudscape::vulkan {

vk::DescriptorType descriptorTypeOf(model::DescriptorKind kind) {
    switch (kind) {
    case model::DescriptorKind::UniformBuffer:
        return vk::DescriptorType::eUniformBuffer;
    case model::DescriptorKind::StorageBuffer:
        return vk::DescriptorType::eStorageBuffer;
    case model::DescriptorKind::CombinedImageSampler:
        return vk::DescriptorType::eCombinedImageSampler;
    case model::DescriptorKind::UniformTexelBuffer:
        return vk::DescriptorType::eUniformTexelBuffer;
    case model::DescriptorKind::StorageTexelBuffer:
        return vk::DescriptorType::eStorageTexelBuffer;
    }
    throw Error("unknown descriptor kind");
}

std::vector<vk::DescriptorSetLayoutBinding> layoutBindingsOf(const model::PassInterface& pass) {
    std::vector<vk::DescriptorSetLayoutBinding> out;
    for (int i = 0; i < pass.bindingCount; ++i)
        out.emplace_back(static_cast<uint32_t>(pass.bindings[i].binding),
                         descriptorTypeOf(pass.bindings[i].kind), 1,
                         vk::ShaderStageFlagBits::eCompute);
    return out;
}

std::vector<vk::DescriptorPoolSize>
descriptorPoolSizes(std::initializer_list<std::pair<const model::PassInterface*, uint32_t>> sets) {
    std::map<vk::DescriptorType, uint32_t> counts;
    for (const auto& [pass, count] : sets)
        for (int i = 0; i < pass->bindingCount; ++i)
            counts[descriptorTypeOf(pass->bindings[i].kind)] += count;
    std::vector<vk::DescriptorPoolSize> out;
    for (const auto& [type, count] : counts)
        out.emplace_back(type, count);
    return out;
}

ComputePass::ComputePass(const Context& ctx, const model::PassInterface& pass,
                         const uint32_t* spirv, size_t bytes, uint32_t maxSets)
    : pass_(pass), device_(ctx.device) {
    const vk::Device device = ctx.device;
    const std::vector<vk::DescriptorSetLayoutBinding> bindings = layoutBindingsOf(pass);
    setLayout_ = device.createDescriptorSetLayoutUnique({{}, bindings});
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, pass.pushConstantBytes);
    const vk::DescriptorSetLayout setLayout = *setLayout_;
    layout_ = device.createPipelineLayoutUnique({{}, setLayout, push});
    module_ = device.createShaderModuleUnique({{}, bytes, spirv});
    // Pipelines are built on first use, for the feature set asked for (pipelineFor): building
    // one here as well would double the compile time of every one-off render on lavapipe.
    const auto sizes = descriptorPoolSizes({{&pass, maxSets}});
    pool_ = device.createDescriptorPoolUnique({vk::DescriptorPoolCreateFlags{}, maxSets, sizes});
}

vk::DescriptorSet ComputePass::allocateSet() const {
    const vk::DescriptorSetLayout layout = *setLayout_;
    return device_.allocateDescriptorSets({*pool_, layout})[0];
}

namespace {
std::atomic<uint64_t> pipelinesBuiltCount{0};
} // namespace

uint64_t ComputePass::pipelinesBuilt() {
    return pipelinesBuiltCount.load();
}

vk::Pipeline ComputePass::pipelineFor(int features) const {
    const std::lock_guard<std::mutex> lock(pipelinesMutex_);
    auto found = pipelines_.find(features);
    if (found != pipelines_.end())
        return *found->second;
    // Shaders without the constant ignore it (the Vulkan rule for unused map entries).
    const vk::SpecializationMapEntry entry(static_cast<uint32_t>(model::MODEL_FEATURES_CONSTANT_ID),
                                           0, sizeof(int));
    const vk::SpecializationInfo specialisation(1, &entry, sizeof(int), &features);
    // Dispatch base: the march's tiles start at a base workgroup (march_pass.cpp).
    const vk::ComputePipelineCreateInfo info(
        vk::PipelineCreateFlagBits::eDispatchBase,
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eCompute, *module_, "main",
                                          &specialisation),
        *layout_);
    auto result = device_.createComputePipelineUnique(nullptr, info);
    if (result.result != vk::Result::eSuccess)
        throw Error(std::string("cannot create the ") + pass_.shader +
                    " pipeline: " + vk::to_string(result.result));
    ++pipelinesBuiltCount;
    return *(pipelines_[features] = std::move(result.value));
}

void ComputePass::bind(vk::CommandBuffer cmd, vk::DescriptorSet set, int features) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, pipelineFor(features));
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, set, {});
}

void ComputePass::checkPushSize(size_t bytes) const {
    if (bytes != pass_.pushConstantBytes)
        throw Error(std::string(pass_.shader) + ": push constants of " + std::to_string(bytes) +
                    " bytes, the interface declares " + std::to_string(pass_.pushConstantBytes));
}

DescriptorWriter::DescriptorWriter(const model::PassInterface& pass, vk::DescriptorSet set)
    : pass_(pass), set_(set), written_(static_cast<size_t>(pass.bindingCount), false) {
    buffers_.reserve(static_cast<size_t>(pass.bindingCount));
    images_.reserve(static_cast<size_t>(pass.bindingCount));
}

const model::BindingSpec& DescriptorWriter::spec(int binding, bool wantImage) const {
    if (binding < 0 || binding >= pass_.bindingCount)
        throw Error(std::string(pass_.shader) + " has no binding " + std::to_string(binding));
    const model::BindingSpec& s = pass_.bindings[binding];
    const bool isImage = s.kind == model::DescriptorKind::CombinedImageSampler;
    if (isImage != wantImage)
        throw Error(std::string(pass_.shader) + " binding " + std::to_string(binding) + " (" +
                    s.name + ") is " + (isImage ? "an image" : "a buffer"));
    return s;
}

DescriptorWriter& DescriptorWriter::buffer(int binding, const Buffer& buffer) {
    const model::BindingSpec& s = spec(binding, false);
    if (s.kind == model::DescriptorKind::UniformTexelBuffer ||
        s.kind == model::DescriptorKind::StorageTexelBuffer) {
        if (!buffer.texels)
            throw Error(std::string(pass_.shader) + " binding " + std::to_string(binding) + " (" +
                        s.name + ") needs a buffer made with a texel-buffer view");
        writes_.emplace_back(set_, static_cast<uint32_t>(binding), 0, 1, descriptorTypeOf(s.kind),
                             nullptr, nullptr, &buffer.texels);
    } else {
        buffers_.emplace_back(buffer.buffer, 0, VK_WHOLE_SIZE);
        writes_.emplace_back(set_, static_cast<uint32_t>(binding), 0, 1, descriptorTypeOf(s.kind),
                             nullptr, &buffers_.back());
    }
    written_[static_cast<size_t>(binding)] = true;
    return *this;
}

DescriptorWriter& DescriptorWriter::image(int binding, vk::Sampler sampler, const Image& image) {
    const model::BindingSpec& s = spec(binding, true);
    images_.emplace_back(sampler, image.view, vk::ImageLayout::eShaderReadOnlyOptimal);
    writes_.emplace_back(set_, static_cast<uint32_t>(binding), 0, 1, descriptorTypeOf(s.kind),
                         &images_.back());
    written_[static_cast<size_t>(binding)] = true;
    return *this;
}

void DescriptorWriter::commit(vk::Device device) {
    for (int b = 0; b < pass_.bindingCount; ++b)
        if (!written_[static_cast<size_t>(b)])
            throw Error(std::string(pass_.shader) + ": binding " + std::to_string(b) + " (" +
                        pass_.bindings[b].name + ") was not written");
    device.updateDescriptorSets(writes_, {});
}

} // namespace cloudscape::vulkan
