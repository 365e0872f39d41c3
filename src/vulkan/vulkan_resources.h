#pragma once
// Buffers and sampled images for the Vulkan backend, each owning its memory. Plumbing only.
#include <cloudscape/texture.h>

#include "vulkan/vulkan_context.h"

#include <cstdint>
#include <vector>

namespace cloudscape::vulkan {

// Handles for use, owned by the RAII members (declared so that the memory is freed last).
struct Buffer {
    vk::Buffer buffer;
    vk::DeviceMemory memory;
    vk::DeviceSize size = 0;
    vk::DeviceSize allocated = 0; // bytes of device memory, counted in deviceBytes()
    void* mapped = nullptr;       // persistently mapped when host visible (freeing unmaps)
    vk::UniqueDeviceMemory ownedMemory;
    vk::UniqueBuffer ownedBuffer;
    // The buffer seen as texels (RGBA32F, or the format asked for), where it was made with a
    // texel-buffer usage: how the passes bind the per-pixel records (interface.glsl.h).
    vk::BufferView texels;
    vk::UniqueBufferView ownedTexels;
};

struct Image {
    vk::Image image;
    vk::DeviceMemory memory;
    vk::ImageView view;
    vk::DeviceSize bytes = 0;
    vk::UniqueDeviceMemory ownedMemory;
    vk::UniqueImage ownedImage;
    vk::UniqueImageView ownedView;
};

// What a buffer of per-pixel records or of a world table is made for: bound as a storage buffer
// by some passes and as a uniform or storage texel buffer by others (interface.glsl.h).
inline constexpr vk::BufferUsageFlags kRecordBufferUsage =
    vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
    vk::BufferUsageFlagBits::eStorageTexelBuffer;

// Owns everything it creates (RAII) and counts device memory; its destructor waits for the
// device to be idle first, since nothing may still use what it frees.
class ResourceSet {
public:
    explicit ResourceSet(Context& context) : ctx_(context) {}
    ~ResourceSet();
    ResourceSet(const ResourceSet&) = delete;
    ResourceSet& operator=(const ResourceSet&) = delete;

    // A host-visible buffer, mapped; with a texel-buffer usage also its view as texels of
    // texelFormat (Buffer::texels), refused with an error naming the device's limit when it
    // holds more texels than the device's texel buffers allow.
    Buffer& hostBuffer(vk::DeviceSize size, vk::BufferUsageFlags usage,
                       vk::Format texelFormat = vk::Format::eR32G32B32A32Sfloat);
    // An RGBA8 image with the texture's whole mip chain, filled through a staging buffer on cmd
    // (which must be submitted before the image is sampled).
    Image& texture(const Texture3D& texture, vk::CommandBuffer cmd);
    Image& texture(const Texture2D& texture, vk::CommandBuffer cmd);
    // Frees the staging copies of the textures uploaded so far, for a set that outlives its
    // uploads; call only once those command buffers have completed.
    void releaseStaging();

    uint64_t deviceBytes() const { return deviceBytes_; }
    uint64_t textureBytes() const { return textureBytes_; }

private:
    // Whole texels of `format` in `bytes`, refused past the device's maxTexelBufferElements.
    vk::DeviceSize texelsIn(vk::DeviceSize bytes, vk::Format format) const;
    Image& uploadImage(vk::ImageType type, uint32_t width, uint32_t height, uint32_t depth,
                       const std::vector<std::vector<float>>& levels, vk::CommandBuffer cmd);
    vk::UniqueDeviceMemory allocate(vk::MemoryRequirements requirements,
                                    vk::MemoryPropertyFlags wanted,
                                    vk::MemoryPropertyFlags fallback);

    Context& ctx_;
    std::vector<std::unique_ptr<Buffer>> buffers_;
    std::vector<std::unique_ptr<Image>> images_;
    std::vector<const Buffer*> staging_;
    uint64_t deviceBytes_ = 0;
    uint64_t textureBytes_ = 0;
};

} // namespace cloudscape::vulkan
