#include "vulkan/model_textures.h"

#include <cloudscape/blue_noise.h>
#include <cloudscape/error.h>

#include "model/atmosphere.glsl.h"
#include "vulkan/submit.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace cloudscape::vulkan {
namespace {

void checkImageLimit(const Context& ctx, const Texture2D& t, const char* what) {
    const uint32_t limit = ctx.properties.limits.maxImageDimension2D;
    if (static_cast<uint32_t>(t.width) > limit || static_cast<uint32_t>(t.height) > limit)
        throw Error(std::string(what) + " is " + std::to_string(t.width) + "x" +
                    std::to_string(t.height) + ", beyond this device's 2D image limit of " +
                    std::to_string(limit));
}

} // namespace

ModelTextures::ModelTextures(Context& ctx, const SceneResources& resources) : ctx_(ctx) {
    // Wrap addressing and trilinear filtering: the same sampler the CPU backend emulates. Blue
    // noise is read with texelFetch, so this sampler never filters it.
    sampler_ = ctx.device.createSamplerUnique(vk::SamplerCreateInfo(
        {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eLinear,
        vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat,
        vk::SamplerAddressMode::eRepeat, 0.0f, VK_FALSE, 1.0f, VK_FALSE, vk::CompareOp::eNever,
        0.0f, VK_LOD_CLAMP_NONE));
    blueSet_ = std::make_unique<ResourceSet>(ctx_);
    upload(*blueSet_,
           [&](vk::CommandBuffer cmd) { blue_ = &blueSet_->texture(blueNoiseTexture(), cmd); });
    replaceNoise(resources.noise);
    const double noiseMs = uploadMs_;
    replaceWeather(resources.weather);
    if (noiseMs >= 0.0 && uploadMs_ >= 0.0)
        uploadMs_ += noiseMs;
    atmosphereSet_ = std::make_unique<ResourceSet>(ctx_);
    atmosphere_ = &atmosphereSet_->hostBuffer(sizeof(glm::vec4) * model::ATMOSPHERE_LUT_TEXELS,
                                              kRecordBufferUsage);
    replaceAtmosphere(resources.atmosphere);
    replaceTerrain(resources.terrain.heights);
}

void ModelTextures::replaceTerrain(const std::vector<float>& heights) {
    ctx_.device.waitIdle(); // nothing may still read the buffer released below
    auto set = std::make_unique<ResourceSet>(ctx_);
    const size_t count = std::max<size_t>(heights.size(), 1);
    Buffer& buffer =
        set->hostBuffer(sizeof(float) * count, kRecordBufferUsage, vk::Format::eR32Sfloat);
    if (heights.empty())
        std::memset(buffer.mapped, 0, buffer.size);
    else
        std::memcpy(buffer.mapped, heights.data(), sizeof(float) * heights.size());
    terrain_ = &buffer;
    terrainSet_ = std::move(set);
    ++generation_;
    ++contentVersion_;
    ++backgroundVersion_;
}

void ModelTextures::replaceAtmosphere(const std::vector<glm::vec4>& tables) {
    ctx_.device.waitIdle(); // nothing may still read the tables overwritten below
    if (tables.size() == static_cast<size_t>(model::ATMOSPHERE_LUT_TEXELS))
        std::memcpy(atmosphere_->mapped, tables.data(), atmosphere_->size);
    else
        std::memset(atmosphere_->mapped, 0, atmosphere_->size);
    ++contentVersion_;
    ++backgroundVersion_;
}

namespace {

// Bound where resources carry no high-altitude texture: the model then never reads it (its
// coverage is 0, makeCloudParams), but every pass's binding needs an image.
const Texture2D& emptyTexture2D() {
    static const Texture2D texture = [] {
        Texture2D t;
        t.width = t.height = 1;
        t.mips.assign(1, std::vector<float>(4, 0.0f));
        return t;
    }();
    return texture;
}

} // namespace

void ModelTextures::replaceNoise(const NoiseTextures& noise) {
    ctx_.device.waitIdle(); // nothing may still sample the images replaced below
    auto set = std::make_unique<ResourceSet>(ctx_);
    upload(*set, [&](vk::CommandBuffer cmd) {
        base_ = &set->texture(noise.base, cmd);
        detail_ = &set->texture(noise.detail, cmd);
        curl_ = &set->texture(noise.curl, cmd);
        highClouds_ =
            &set->texture(noise.highClouds.mips.empty() ? emptyTexture2D() : noise.highClouds, cmd);
    });
    // The clearance field, where the device's texel buffers can hold it (2^19 words; Vulkan
    // promises 2^16, desktop devices and lavapipe 2^27): elsewhere one zero word, and the march
    // is told not to use it (restrictToBound).
    const std::vector<uint32_t>& field = noise.baseClearance;
    clearanceBound_ =
        !field.empty() && field.size() <= ctx_.properties.limits.maxTexelBufferElements;
    const size_t words = clearanceBound_ ? field.size() : 1;
    Buffer& clearance =
        set->hostBuffer(sizeof(uint32_t) * words, kRecordBufferUsage, vk::Format::eR32Uint);
    if (clearanceBound_)
        std::memcpy(clearance.mapped, field.data(), sizeof(uint32_t) * words);
    else
        std::memset(clearance.mapped, 0, clearance.size);
    clearance_ = &clearance;
    noise_ = std::move(set);
    ++generation_;
    ++contentVersion_;
}

void ModelTextures::replaceWeather(const Texture2D& weather) {
    checkImageLimit(ctx_, weather, "the weather map");
    ctx_.device.waitIdle();
    auto set = std::make_unique<ResourceSet>(ctx_);
    upload(*set, [&](vk::CommandBuffer cmd) { weather_ = &set->texture(weather, cmd); });
    weatherSet_ = std::move(set);
    weatherWidth_ = static_cast<uint32_t>(weather.width);
    weatherHeight_ = static_cast<uint32_t>(weather.height);
    weatherLevels_ = static_cast<uint32_t>(weather.mips.size());
    ++generation_;
    ++contentVersion_;
}

namespace {

vk::ImageMemoryBarrier weatherBarrier(vk::Image image, uint32_t levels, vk::AccessFlags from,
                                      vk::AccessFlags to, vk::ImageLayout oldLayout,
                                      vk::ImageLayout newLayout) {
    return {from,
            to,
            oldLayout,
            newLayout,
            VK_QUEUE_FAMILY_IGNORED,
            VK_QUEUE_FAMILY_IGNORED,
            image,
            vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, levels, 0, 1)};
}

} // namespace

void ModelTextures::updateWeather(const Texture2D& weather, const std::vector<TexelRect>& rects) {
    if (static_cast<uint32_t>(weather.width) != weatherWidth_ ||
        static_cast<uint32_t>(weather.height) != weatherHeight_ ||
        weather.mips.size() != weatherLevels_) {
        replaceWeather(weather); // another map: nothing to update in place
        return;
    }
    std::vector<vk::BufferImageCopy> copies;
    size_t bytes = 0;
    for (uint32_t l = 0; l < weatherLevels_; ++l)
        for (const TexelRect& r : weatherFootprint(rects, weather, static_cast<int>(l))) {
            copies.emplace_back(
                bytes, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, l, 0, 1),
                vk::Offset3D(r.x, r.y, 0),
                vk::Extent3D(static_cast<uint32_t>(r.width), static_cast<uint32_t>(r.height), 1));
            bytes += static_cast<size_t>(r.width) * r.height * 4;
        }
    if (copies.empty())
        return;
    if (!editStaging_ || editStaging_->size < bytes) {
        ctx_.device.waitIdle(); // the old staging buffer may still be the source of a copy
        editSet_ = std::make_unique<ResourceSet>(ctx_);
        editStaging_ = &editSet_->hostBuffer(std::max<size_t>(bytes, 64 * 1024),
                                             vk::BufferUsageFlagBits::eTransferSrc |
                                                 vk::BufferUsageFlagBits::eTransferDst);
    }
    // The quantised texels become the RGBA8 bytes they were rounded to, as in a whole upload.
    auto* out = static_cast<uint8_t*>(editStaging_->mapped);
    for (const vk::BufferImageCopy& c : copies) {
        const int level = static_cast<int>(c.imageSubresource.mipLevel);
        for (uint32_t j = 0; j < c.imageExtent.height; ++j) {
            const float* row = weather.texel(level, c.imageOffset.x, c.imageOffset.y + int(j));
            for (uint32_t i = 0; i < c.imageExtent.width * 4; ++i)
                *out++ = static_cast<uint8_t>(std::lround(std::clamp(row[i], 0.0f, 1.0f) * 255.0f));
        }
    }
    // The renders' reads of the image are done (they wait for their work before returning); the
    // barriers keep the copy after them and the next render's reads after the copy.
    const vk::Image image = weather_->image;
    ++contentVersion_;
    submitAndWait(ctx_, [&](vk::CommandBuffer cmd) {
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                            vk::PipelineStageFlagBits::eTransfer, {}, {}, {},
                            weatherBarrier(image, weatherLevels_, vk::AccessFlagBits::eShaderRead,
                                           vk::AccessFlagBits::eTransferWrite,
                                           vk::ImageLayout::eShaderReadOnlyOptimal,
                                           vk::ImageLayout::eTransferDstOptimal));
        cmd.copyBufferToImage(editStaging_->buffer, image, vk::ImageLayout::eTransferDstOptimal,
                              copies);
        cmd.pipelineBarrier(
            vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eComputeShader, {}, {},
            {},
            weatherBarrier(image, weatherLevels_, vk::AccessFlagBits::eTransferWrite,
                           vk::AccessFlagBits::eShaderRead, vk::ImageLayout::eTransferDstOptimal,
                           vk::ImageLayout::eShaderReadOnlyOptimal));
    });
}

std::vector<uint8_t> ModelTextures::readWeather() const {
    std::vector<vk::BufferImageCopy> copies;
    size_t bytes = 0;
    for (uint32_t l = 0; l < weatherLevels_; ++l) {
        const vk::Extent3D extent(std::max(weatherWidth_ >> l, 1u),
                                  std::max(weatherHeight_ >> l, 1u), 1);
        copies.emplace_back(bytes, 0, 0,
                            vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, l, 0, 1),
                            vk::Offset3D(0, 0, 0), extent);
        bytes += static_cast<size_t>(extent.width) * extent.height * 4;
    }
    ResourceSet set(ctx_);
    Buffer& buffer = set.hostBuffer(bytes, vk::BufferUsageFlagBits::eTransferDst);
    const vk::Image image = weather_->image;
    submitAndWait(ctx_, [&](vk::CommandBuffer cmd) {
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                            vk::PipelineStageFlagBits::eTransfer, {}, {}, {},
                            weatherBarrier(image, weatherLevels_, vk::AccessFlagBits::eShaderRead,
                                           vk::AccessFlagBits::eTransferRead,
                                           vk::ImageLayout::eShaderReadOnlyOptimal,
                                           vk::ImageLayout::eTransferSrcOptimal));
        cmd.copyImageToBuffer(image, vk::ImageLayout::eTransferSrcOptimal, buffer.buffer, copies);
        cmd.pipelineBarrier(
            vk::PipelineStageFlagBits::eTransfer,
            vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eHost, {}, {},
            {},
            weatherBarrier(image, weatherLevels_, {}, vk::AccessFlagBits::eShaderRead,
                           vk::ImageLayout::eTransferSrcOptimal,
                           vk::ImageLayout::eShaderReadOnlyOptimal));
        const vk::BufferMemoryBarrier toHost(
            vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead,
            VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, buffer.buffer, 0, VK_WHOLE_SIZE);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost,
                            {}, {}, toHost, {});
    });
    const auto* in = static_cast<const uint8_t*>(buffer.mapped);
    return std::vector<uint8_t>(in, in + bytes);
}

void ModelTextures::upload(ResourceSet& set, const std::function<void(vk::CommandBuffer)>& record) {
    const bool timed = ctx_.timestampValidBits > 0;
    const vk::UniqueQueryPool queries =
        ctx_.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, 2});
    submitAndWait(ctx_, [&](vk::CommandBuffer cmd) {
        cmd.resetQueryPool(*queries, 0, 2);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries, 0);
        record(cmd);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries, 1);
    });
    set.releaseStaging(); // as large as the textures; not needed once they are on the device
    uploadMs_ = -1.0;
    if (timed) {
        std::array<uint64_t, 2> ticks{};
        const vk::Result r = ctx_.device.getQueryPoolResults(
            *queries, 0, 2, sizeof ticks, ticks.data(), sizeof(uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (r == vk::Result::eSuccess)
            uploadMs_ = static_cast<double>(ticks[1] - ticks[0]) *
                        ctx_.properties.limits.timestampPeriod * 1e-6;
    }
}

uint64_t ModelTextures::deviceBytes() const {
    return noise_->deviceBytes() + weatherSet_->deviceBytes() + blueSet_->deviceBytes() +
           atmosphereSet_->deviceBytes() + terrainSet_->deviceBytes() +
           (editSet_ ? editSet_->deviceBytes() : 0);
}

uint64_t ModelTextures::textureBytes() const {
    return noise_->textureBytes() + weatherSet_->textureBytes() + blueSet_->textureBytes();
}

} // namespace cloudscape::vulkan
