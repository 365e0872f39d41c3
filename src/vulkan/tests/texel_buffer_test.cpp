// GPU category: the per-pixel records' buffers as texel buffers (interface.glsl.h). A buffer made
// with a texel-buffer usage carries its view, whole texels of the format asked for; a placeholder
// smaller than one texel has none; and a buffer larger than the device's texel buffers allow is
// refused with a message that names the limit, before any of it is made.
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_device.h"
#include "vulkan/vulkan_resources.h"

#include <cloudscape/backend.h>
#include <cloudscape/error.h>

#include <gtest/gtest.h>

#include <initializer_list>

#include <string>

using cloudscape::vulkan::Buffer;
using cloudscape::vulkan::Context;
using cloudscape::vulkan::kRecordBufferUsage;
using cloudscape::vulkan::ResourceSet;

TEST(VulkanTexelBuffers, ARecordBufferCarriesItsViewAndAPlaceholderNone) {
    Context context(-1, true);
    {
        ResourceSet set(context);
        const Buffer& records = set.hostBuffer(64 * 32, kRecordBufferUsage);
        EXPECT_TRUE(records.texels);
        const Buffer& heights = set.hostBuffer(17 * 4, kRecordBufferUsage, vk::Format::eR32Sfloat);
        EXPECT_TRUE(heights.texels);
        const Buffer& placeholder = set.hostBuffer(4, kRecordBufferUsage);
        EXPECT_FALSE(placeholder.texels);
        const Buffer& plain = set.hostBuffer(64, vk::BufferUsageFlagBits::eStorageBuffer);
        EXPECT_FALSE(plain.texels);
    }
    EXPECT_TRUE(context.takeValidationMessages().empty());
}

TEST(VulkanTexelBuffers, ABufferBeyondTheDevicesLimitIsRefusedByName) {
    Context context(-1, true);
    context.properties.limits.maxTexelBufferElements = 64; // as a small device would have
    {
        ResourceSet set(context);
        EXPECT_NO_THROW(set.hostBuffer(64 * 16, kRecordBufferUsage));
        const uint64_t before = set.deviceBytes();
        try {
            set.hostBuffer(65 * 16, kRecordBufferUsage);
            FAIL() << "a buffer of 65 texels was accepted";
        } catch (const cloudscape::Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("at most 64 texels"), std::string::npos) << message;
            EXPECT_NE(message.find("65"), std::string::npos) << message;
        }
        EXPECT_EQ(set.deviceBytes(), before) << "the refused buffer left memory behind";
    }
    EXPECT_TRUE(context.takeValidationMessages().empty());
}

namespace {

// checkImageSize refuses width x height with a message holding each of `expected`.
void expectImageRefused(const Context& context, int width, int height,
                        std::initializer_list<const char*> expected) {
    try {
        cloudscape::vulkan::checkImageSize(context, width, height);
        FAIL() << "a " << width << "x" << height << " image was accepted";
    } catch (const cloudscape::Error& e) {
        const std::string message = e.what();
        for (const char* part : expected)
            EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

} // namespace

// The image-size check every renderer makes before any device work (checkImageSize) knows the
// largest record read as texels, the kept background's light, three texels a pixel.
TEST(VulkanTexelBuffers, AnImageBeyondTheTexelLimitIsRefusedUpFront) {
    Context context(-1, true);
    context.properties.limits.maxTexelBufferElements = 1000;
    EXPECT_NO_THROW(cloudscape::vulkan::checkImageSize(context, 16, 16)); // 768 texels
    expectImageRefused(context, 64, 64, {"64x64", "12288 texels", "limit of 1000"});
    EXPECT_TRUE(context.takeValidationMessages().empty());
}

// What a storage-buffer binding still spans per pixel is one vec4 (the composite the viewer
// presents); the records are texel buffers. So a 3840x2160 frame fits the storage range every
// Vulkan device has (2^27 bytes, the spec's minimum, and lavapipe's), and a smaller range refuses
// with the bytes it would need.
TEST(VulkanTexelBuffers, FourKFitsTheSpecsMinimumStorageRange) {
    Context context(-1, true);
    context.properties.limits.maxStorageBufferRange = 1u << 27;
    context.properties.limits.maxTexelBufferElements = 1u << 27;
    EXPECT_NO_THROW(cloudscape::vulkan::checkImageSize(context, 3840, 2160));
    context.properties.limits.maxStorageBufferRange = 16 * 1000;
    EXPECT_NO_THROW(cloudscape::vulkan::checkImageSize(context, 25, 40));
    expectImageRefused(context, 64, 64, {"64x64", "65536-byte", "limit of 16000"});
    EXPECT_TRUE(context.takeValidationMessages().empty());
}
