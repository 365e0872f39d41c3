#pragma once
// Full-frame renders (every pixel marched) on a VulkanDevice shared with the rest of a renderer:
// the per-size buffers live here and are kept between renders of the same size.
#include <cloudscape/renderer.h>

#include "vulkan/cloud_shadow_map.h"
#include "vulkan/frame_io.h"
#include "vulkan/vulkan_device.h"
#include "vulkan/vulkan_resources.h"

#include <memory>

namespace cloudscape::vulkan {

class VulkanStill {
public:
    explicit VulkanStill(std::shared_ptr<VulkanDevice> device);
    ~VulkanStill();

    // The scene over `resources` (whose textures the device holds); reduced-resolution clouds
    // are upsampled on the device; only `readback` is copied to the host.
    RenderResult render(const Scene& scene, const SceneResources& resources,
                        const ProgressCallback& progress, Readback readback);

    // The device buffer holding the last composite (vec4 per output pixel).
    const Buffer* composite() const { return outComposite_; }
    // The clouds' shadow map the last render read (CloudShadowMap::texels).
    std::vector<glm::vec4> cloudShadowMap() const { return shadow_.texels(); }

private:
    void allocate(const Scene& full, const Scene& pass);
    void writeDescriptors();

    std::shared_ptr<VulkanDevice> device_;
    Context& ctx_;
    vk::DescriptorSet marchSet_, upsampleSet_;
    vk::UniqueQueryPool queries_;
    uint64_t textureGeneration_ = 0;

    FrameBlocks blocks_; // the pass's frame in .frame, the output's in .output
    CloudShadowMap shadow_;
    std::unique_ptr<ResourceSet> sized_;
    int width_ = 0, height_ = 0, passWidth_ = 0, passHeight_ = 0;
    Buffer *passDepth_ = nullptr, *passCloud_ = nullptr, *passComposite_ = nullptr;
    Buffer *outDepth_ = nullptr, *outCloud_ = nullptr, *outComposite_ = nullptr;
    // BackgroundLight and BackgroundTexel per output pixel (reduced only).
    Buffer *outBackground_ = nullptr, *outSeen_ = nullptr;
    Buffer* noShaftGrid_ = nullptr; // the upsample's grid binding: a still makes no grid
    // The upsample's ground fallback list binding: a still's passes all have the fallback.
    Buffer* noGroundFallback_ = nullptr;
};

} // namespace cloudscape::vulkan
