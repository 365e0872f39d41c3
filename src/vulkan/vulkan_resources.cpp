#include "vulkan/vulkan_resources.h"

#include <cloudscape/error.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cloudscape::vulkan {

namespace {

vk::DeviceSize texelBytes(vk::Format format) {
    if (format == vk::Format::eR32Sfloat || format == vk::Format::eR32Uint)
        return 4;
    if (format != vk::Format::eR32G32B32A32Sfloat)
        throw Error("texel buffers are R32F, R32UI or RGBA32F, not " + vk::to_string(format));
    return 16;
}

} // namespace

ResourceSet::~ResourceSet() {
    waitIdleBeforeFreeing(ctx_.device); // nothing may still be using what the members free
}

vk::UniqueDeviceMemory ResourceSet::allocate(vk::MemoryRequirements requirements,
                                             vk::MemoryPropertyFlags wanted,
                                             vk::MemoryPropertyFlags fallback) {
    const uint32_t type = ctx_.memoryTypeFor(requirements.memoryTypeBits, wanted, fallback);
    vk::UniqueDeviceMemory memory =
        ctx_.device.allocateMemoryUnique(vk::MemoryAllocateInfo(requirements.size, type));
    deviceBytes_ += requirements.size;
    return memory;
}

Buffer& ResourceSet::hostBuffer(vk::DeviceSize size, vk::BufferUsageFlags usage,
                                vk::Format texelFormat) {
    const bool texelBuffer =
        static_cast<bool>(usage & (vk::BufferUsageFlagBits::eUniformTexelBuffer |
                                   vk::BufferUsageFlagBits::eStorageTexelBuffer));
    // Checked before anything is made: a refused buffer leaves nothing behind.
    const vk::DeviceSize texels = texelBuffer ? texelsIn(size, texelFormat) : 0;
    auto b = std::make_unique<Buffer>();
    b->size = size;
    b->ownedBuffer = ctx_.device.createBufferUnique(vk::BufferCreateInfo({}, size, usage));
    b->buffer = *b->ownedBuffer;
    // Cached host memory reads back fast; coherent is the fallback every device has.
    const vk::MemoryRequirements requirements = ctx_.device.getBufferMemoryRequirements(b->buffer);
    b->allocated = requirements.size;
    b->ownedMemory = allocate(
        requirements,
        vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent |
            vk::MemoryPropertyFlagBits::eHostCached,
        vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent);
    b->memory = *b->ownedMemory;
    ctx_.device.bindBufferMemory(b->buffer, b->memory, 0);
    b->mapped = ctx_.device.mapMemory(b->memory, 0, size);
    if (texels > 0) { // a placeholder smaller than a texel is never bound as one
        b->ownedTexels = ctx_.device.createBufferViewUnique(vk::BufferViewCreateInfo(
            {}, b->buffer, texelFormat, 0, texels * texelBytes(texelFormat)));
        b->texels = *b->ownedTexels;
    }
    buffers_.push_back(std::move(b));
    return *buffers_.back();
}

vk::DeviceSize ResourceSet::texelsIn(vk::DeviceSize bytes, vk::Format format) const {
    const vk::DeviceSize texels = bytes / texelBytes(format);
    const uint32_t limit = ctx_.properties.limits.maxTexelBufferElements;
    if (texels > limit)
        throw Error("this Vulkan device's texel buffers hold at most " + std::to_string(limit) +
                    " texels; a buffer of " + std::to_string(texels) +
                    " is needed (choose a smaller image)");
    return texels;
}

void ResourceSet::releaseStaging() {
    for (const Buffer* staging : staging_) {
        const auto it = std::find_if(buffers_.begin(), buffers_.end(),
                                     [&](const auto& b) { return b.get() == staging; });
        deviceBytes_ -= (*it)->allocated; // the erase frees buffer and memory
        buffers_.erase(it);
    }
    staging_.clear();
}

Image& ResourceSet::texture(const Texture3D& t, vk::CommandBuffer cmd) {
    const auto n = static_cast<uint32_t>(t.size);
    return uploadImage(vk::ImageType::e3D, n, n, n, t.mips, cmd);
}

Image& ResourceSet::texture(const Texture2D& t, vk::CommandBuffer cmd) {
    return uploadImage(vk::ImageType::e2D, static_cast<uint32_t>(t.width),
                       static_cast<uint32_t>(t.height), 1, t.mips, cmd);
}

Image& ResourceSet::uploadImage(vk::ImageType type, uint32_t width, uint32_t height, uint32_t depth,
                                const std::vector<std::vector<float>>& levels,
                                vk::CommandBuffer cmd) {
    const auto levelCount = static_cast<uint32_t>(levels.size());
    // Staging: the quantised texel values become exactly the RGBA8 bytes they were rounded to.
    size_t totalBytes = 0;
    for (const auto& level : levels)
        totalBytes += level.size();
    Buffer& staging = hostBuffer(totalBytes, vk::BufferUsageFlagBits::eTransferSrc);
    staging_.push_back(&staging);
    auto* bytes = static_cast<uint8_t*>(staging.mapped);
    std::vector<vk::BufferImageCopy> copies;
    size_t offset = 0;
    for (uint32_t l = 0; l < levelCount; ++l) {
        for (size_t i = 0; i < levels[l].size(); ++i)
            bytes[offset + i] =
                static_cast<uint8_t>(std::lround(std::clamp(levels[l][i], 0.0f, 1.0f) * 255.0f));
        const vk::Extent3D extent(std::max(width >> l, 1u), std::max(height >> l, 1u),
                                  std::max(depth >> l, 1u));
        copies.emplace_back(offset, 0, 0,
                            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, l, 0, 1),
                            vk::Offset3D(0, 0, 0), extent);
        offset += levels[l].size();
    }

    auto img = std::make_unique<Image>();
    img->ownedImage = ctx_.device.createImageUnique(vk::ImageCreateInfo(
        {}, type, vk::Format::eR8G8B8A8Unorm, vk::Extent3D(width, height, depth), levelCount, 1,
        vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal,
        // Transfer source too: the weather map is read back to check its edits (readWeather).
        vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eTransferSrc |
            vk::ImageUsageFlagBits::eSampled));
    img->image = *img->ownedImage;
    const vk::MemoryRequirements req = ctx_.device.getImageMemoryRequirements(img->image);
    img->bytes = req.size;
    textureBytes_ += req.size;
    img->ownedMemory = allocate(req, vk::MemoryPropertyFlagBits::eDeviceLocal, {});
    img->memory = *img->ownedMemory;
    ctx_.device.bindImageMemory(img->image, img->memory, 0);
    const vk::ImageSubresourceRange all(vk::ImageAspectFlagBits::eColor, 0, levelCount, 0, 1);
    img->ownedView = ctx_.device.createImageViewUnique(vk::ImageViewCreateInfo(
        {}, img->image,
        type == vk::ImageType::e3D ? vk::ImageViewType::e3D : vk::ImageViewType::e2D,
        vk::Format::eR8G8B8A8Unorm, {}, all));
    img->view = *img->ownedView;

    vk::ImageMemoryBarrier toTransfer({}, vk::AccessFlagBits::eTransferWrite,
                                      vk::ImageLayout::eUndefined,
                                      vk::ImageLayout::eTransferDstOptimal, VK_QUEUE_FAMILY_IGNORED,
                                      VK_QUEUE_FAMILY_IGNORED, img->image, all);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTopOfPipe, vk::PipelineStageFlagBits::eTransfer,
                        {}, {}, {}, toTransfer);
    cmd.copyBufferToImage(staging.buffer, img->image, vk::ImageLayout::eTransferDstOptimal, copies);
    vk::ImageMemoryBarrier toShader(
        vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eShaderRead,
        vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
        VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, img->image, all);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eComputeShader, {}, {}, {}, toShader);
    images_.push_back(std::move(img));
    return *images_.back();
}

} // namespace cloudscape::vulkan
