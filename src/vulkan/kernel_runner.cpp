#include "vulkan/kernel_runner.h"

#include "vulkan/submit.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <cstring>

namespace cloudscape::vulkan {

KernelRun runKernel(const uint32_t* spirv, size_t bytes,
                    const std::vector<std::vector<glm::vec4>>& buffers, uint32_t groups,
                    bool validation) {
    Context ctx(-1, validation);
    KernelRun run;
    translateVulkanErrors("a unit kernel", [&] {
        ResourceSet res(ctx);
        std::vector<Buffer*> storage;
        std::vector<vk::DescriptorSetLayoutBinding> bindings;
        for (size_t b = 0; b < buffers.size(); ++b) {
            Buffer& buf = res.hostBuffer(buffers[b].size() * sizeof(glm::vec4),
                                         vk::BufferUsageFlagBits::eStorageBuffer);
            std::memcpy(buf.mapped, buffers[b].data(), buf.size);
            storage.push_back(&buf);
            bindings.emplace_back(static_cast<uint32_t>(b), vk::DescriptorType::eStorageBuffer, 1,
                                  vk::ShaderStageFlagBits::eCompute);
        }
        const vk::Device dev = ctx.device;
        const vk::UniqueDescriptorSetLayout setLayout =
            dev.createDescriptorSetLayoutUnique({{}, bindings});
        const vk::DescriptorSetLayout layoutHandle = *setLayout;
        const vk::UniquePipelineLayout layout = dev.createPipelineLayoutUnique({{}, layoutHandle});
        const vk::UniqueShaderModule module = dev.createShaderModuleUnique({{}, bytes, spirv});
        const auto pipeline = dev.createComputePipelineUnique(
            nullptr, vk::ComputePipelineCreateInfo(
                         {}, {{}, vk::ShaderStageFlagBits::eCompute, *module, "main"}, *layout));
        const vk::DescriptorPoolSize size(vk::DescriptorType::eStorageBuffer,
                                          static_cast<uint32_t>(buffers.size()));
        const vk::UniqueDescriptorPool pool = dev.createDescriptorPoolUnique({{}, 1, size});
        const vk::DescriptorSet set = dev.allocateDescriptorSets({*pool, layoutHandle})[0];
        std::vector<vk::DescriptorBufferInfo> infos;
        for (Buffer* b : storage)
            infos.emplace_back(b->buffer, 0, VK_WHOLE_SIZE);
        std::vector<vk::WriteDescriptorSet> writes;
        for (size_t b = 0; b < infos.size(); ++b)
            writes.emplace_back(set, static_cast<uint32_t>(b), 0, 1,
                                vk::DescriptorType::eStorageBuffer, nullptr, &infos[b]);
        dev.updateDescriptorSets(writes, {});
        submitAndWait(ctx, [&](vk::CommandBuffer cmd) {
            cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline.value);
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout, 0, set, {});
            cmd.dispatch(groups, 1, 1);
            shaderWritesToHost(cmd);
        });
        for (Buffer* b : storage) {
            dev.invalidateMappedMemoryRanges(vk::MappedMemoryRange(b->memory, 0, VK_WHOLE_SIZE));
            const auto* v = static_cast<const glm::vec4*>(b->mapped);
            run.buffers.emplace_back(v, v + b->size / sizeof(glm::vec4));
        }
    });
    run.validationMessages = ctx.takeValidationMessages();
    return run;
}

} // namespace cloudscape::vulkan
