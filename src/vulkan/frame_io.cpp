#include "vulkan/frame_io.h"

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "model/interface.glsl.h"
#include "model/params.glsl.h"

#include <cstring>

namespace cloudscape::vulkan {

FrameBlocks::FrameBlocks(Context& ctx) : set(std::make_unique<ResourceSet>(ctx)) {
    // Read-only storage buffers, not uniform buffers (interface.glsl.h says why).
    const auto parameters = vk::BufferUsageFlagBits::eStorageBuffer;
    cloud = &set->hostBuffer(sizeof(model::CloudParams), parameters);
    frame = &set->hostBuffer(sizeof(model::FrameParams), parameters);
    previous = &set->hostBuffer(sizeof(model::FrameParams), parameters);
    output = &set->hostBuffer(sizeof(model::FrameParams), parameters);
    counters =
        &set->hostBuffer(sizeof(model::FrameCounters), vk::BufferUsageFlagBits::eStorageBuffer |
                                                           vk::BufferUsageFlagBits::eTransferDst);
}

model::FrameParams uploadFrame(Buffer& ubo, Buffer& depth, const Scene& scene,
                               const SceneResources& resources, int jitterFrame,
                               TemporalStep step) {
    model::FrameParams frame = makeFrameParams(scene, jitterFrame);
    frame.sequenceFrame = step.sequenceFrame;
    frame.secondsSincePrevious = step.secondsSincePrevious;
    if (step.temporalBlock != 0)
        frame.temporalBlock = step.temporalBlock;
    frame.gatherValid = step.gatherValid;
    const std::vector<float> metres = sceneDepthFor(scene, resources);
    frame.hasSceneDepth = metres.empty() ? 0 : 1;
    if (!metres.empty())
        std::memcpy(depth.mapped, metres.data(), metres.size() * sizeof(float));
    std::memcpy(ubo.mapped, &frame, sizeof frame);
    return frame;
}

void readBack(const Context& ctx, const Buffer& composite, const Buffer& cloud, size_t pixels,
              Readback readback, RenderResult& out) {
    // Host memory may be non-coherent: invalidate before reading.
    if (readback != Readback::None) {
        ctx.device.invalidateMappedMemoryRanges(
            vk::MappedMemoryRange(composite.memory, 0, VK_WHOLE_SIZE));
        const auto* k = static_cast<const float*>(composite.mapped);
        out.composite.assign(k, k + pixels * 4);
    }
    if (readback == Readback::All) {
        ctx.device.invalidateMappedMemoryRanges(
            vk::MappedMemoryRange(cloud.memory, 0, VK_WHOLE_SIZE));
        storeCloudTexels(out, static_cast<const model::CloudTexel*>(cloud.mapped), pixels);
    }
}

std::vector<double> timestampsMs(const Context& ctx, vk::QueryPool queries, uint32_t count) {
    if (ctx.timestampValidBits == 0)
        return {};
    std::vector<uint64_t> ticks(count);
    const vk::Result r = ctx.device.getQueryPoolResults(
        queries, 0, count, ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
        vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    if (r != vk::Result::eSuccess)
        return {};
    std::vector<double> ms;
    for (uint64_t t : ticks)
        ms.push_back(static_cast<double>(t - ticks[0]) * ctx.properties.limits.timestampPeriod *
                     1e-6);
    return ms;
}

} // namespace cloudscape::vulkan
