#include "vulkan/vulkan_device.h"

#include <cloudscape/error.h>
#include <cloudscape/memory_estimate.h>

#include "io/fault_injection.h"
#include "model/pixel.glsl.h"

namespace cloudscape::vulkan {
namespace {

const uint32_t kTemporalResolveSpirv[] = {
#include "shaders/temporal_resolve.spv.inc"
};
const uint32_t kUpsampleCloudsSpirv[] = {
#include "shaders/upsample_clouds.spv.inc"
};
const uint32_t kCloudShadowSpirv[] = {
#include "shaders/cloud_shadow.spv.inc"
};

} // namespace

VulkanDevice::VulkanDevice(const BackendOptions& options, const SceneResources& resources)
    : ctx_(options.device, options.validation, options.presentation.get()),
      interactive_(options.interactive) {
    translateVulkanErrors("device set-up", [&] {
        march_ = std::make_unique<MarchPass>(ctx_);
        resolve_ = std::make_unique<ComputePass>(ctx_, model::RESOLVE_PASS, kTemporalResolveSpirv,
                                                 sizeof kTemporalResolveSpirv);
        upsample_ = std::make_unique<ComputePass>(ctx_, model::UPSAMPLE_PASS, kUpsampleCloudsSpirv,
                                                  sizeof kUpsampleCloudsSpirv);
        cloudShadow_ = std::make_unique<ComputePass>(ctx_, model::SHADOW_PASS, kCloudShadowSpirv,
                                                     sizeof kCloudShadowSpirv);
        textures_ = std::make_unique<ModelTextures>(ctx_, resources);
    });
}

AtmosphereTables& VulkanDevice::atmosphereTables() {
    if (!atmosphereTables_)
        atmosphereTables_ = std::make_unique<AtmosphereTables>(ctx_, textures_->atmosphere());
    return *atmosphereTables_;
}

VulkanDevice::~VulkanDevice() {
    if (ctx_.device)
        waitIdleBeforeFreeing(ctx_.device);
}

void checkImageSize(const Context& ctx, int width, int height) {
    // The per-pixel records are texel buffers (below); what a storage-buffer binding still spans
    // per pixel is at most one vec4: the composite the viewer's present shader reads (the scene
    // depth and the ground fallback's list take 4 bytes a pixel).
    const size_t bytes = static_cast<size_t>(width) * height * 16;
    const vk::PhysicalDeviceLimits& limits = ctx.properties.limits;
    if (bytes > limits.maxStorageBufferRange)
        throw Error("image " + std::to_string(width) + "x" + std::to_string(height) + " needs a " +
                    std::to_string(bytes) + "-byte storage buffer, beyond this device's limit of " +
                    std::to_string(limits.maxStorageBufferRange) + " bytes");
    // The kept background's light is the largest record read as texels (interface.glsl.h).
    const uint64_t texels = static_cast<uint64_t>(width) * height * model::BACKGROUND_LIGHT_ROWS;
    if (texels > limits.maxTexelBufferElements)
        throw Error("image " + std::to_string(width) + "x" + std::to_string(height) + " needs " +
                    std::to_string(texels) +
                    " texels in a texel buffer, beyond this device's "
                    "limit of " +
                    std::to_string(limits.maxTexelBufferElements));
}

void checkDeviceMemory(const Context& ctx, int width, int height, uint64_t bytes) {
    // The heap of the memory type ResourceSet::hostBuffer allocates from.
    const uint32_t type = ctx.memoryTypeFor(~0u, vk::MemoryPropertyFlagBits::eHostVisible |
                                                     vk::MemoryPropertyFlagBits::eHostCoherent);
    const vk::PhysicalDeviceMemoryProperties memory = ctx.physicalDevice.getMemoryProperties();
    uint64_t heap = memory.memoryHeaps[memory.memoryTypes[type].heapIndex].size;
    if (const uint64_t injected = io::faultDeviceHeapBytes())
        heap = injected; // tests: a smaller device
    requireDeviceMemory(width, height, bytes, heap, ctx.properties.deviceName.data());
}

} // namespace cloudscape::vulkan
