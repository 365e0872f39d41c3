#include "vulkan/submit.h"

#include <cloudscape/error.h>

#include "io/fault_injection.h"

namespace cloudscape::vulkan {

void submitAndWait(const Context& ctx, const std::function<void(vk::CommandBuffer)>& record) {
    auto buffers = ctx.device.allocateCommandBuffersUnique(
        {ctx.commandPool, vk::CommandBufferLevel::ePrimary, 1});
    const vk::CommandBuffer cmd = *buffers[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(cmd);
    cmd.end();
    const vk::UniqueFence fence = ctx.device.createFenceUnique({});
    ctx.queue.submit(vk::SubmitInfo({}, {}, cmd), *fence);
    const vk::Result waited = ctx.device.waitForFences(*fence, VK_TRUE, UINT64_MAX);
    if (io::faultDeviceLostAtSubmit()) // tests only: as vkWaitForFences reports a lost device
        throw vk::DeviceLostError("vkWaitForFences (CLOUDSCAPE_TEST_FAULT)");
    if (waited != vk::Result::eSuccess)
        throw Error("waiting for the GPU failed: " + vk::to_string(waited));
}

void shaderWritesToHost(vk::CommandBuffer cmd) {
    const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost,
                        {}, toHost, {}, {});
}

void shaderWritesToShader(vk::CommandBuffer cmd) {
    const vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite,
                                    vk::AccessFlagBits::eShaderRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eComputeShader, {}, barrier, {}, {});
}

} // namespace cloudscape::vulkan
