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
                                              vk::BufferUsageFlagBits::eStorageBuffer);
    replaceAtmosphere(resources.atmosphere);
    replaceTerrain(resources.terrain.heights);
}

void ModelTextures::replaceTerrain(const std::vector<float>& heights) {
    ctx_.device.waitIdle(); // nothing may still read the buffer released below
    auto set = std::make_unique<ResourceSet>(ctx_);
    const size_t count = std::max<size_t>(heights.size(), 1);
    Buffer& buffer =
        set->hostBuffer(sizeof(float) * count, vk::BufferUsageFlagBits::eStorageBuffer);
    if (heights.empty())
        std::memset(buffer.mapped, 0, buffer.size);
    else
        std::memcpy(buffer.mapped, heights.data(), sizeof(float) * heights.size());
    terrain_ = &buffer;
    terrainSet_ = std::move(set);
    ++generation_;
}

void ModelTextures::replaceAtmosphere(const std::vector<glm::vec4>& tables) {
    ctx_.device.waitIdle(); // nothing may still read the tables overwritten below
    if (tables.size() == static_cast<size_t>(model::ATMOSPHERE_LUT_TEXELS))
        std::memcpy(atmosphere_->mapped, tables.data(), atmosphere_->size);
    else
        std::memset(atmosphere_->mapped, 0, atmosphere_->size);
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
    noise_ = std::move(set);
    ++generation_;
}

void ModelTextures::replaceWeather(const Texture2D& weather) {
    checkImageLimit(ctx_, weather, "the weather map");
    ctx_.device.waitIdle();
    auto set = std::make_unique<ResourceSet>(ctx_);
    upload(*set, [&](vk::CommandBuffer cmd) { weather_ = &set->texture(weather, cmd); });
    weatherSet_ = std::move(set);
    ++generation_;
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
           atmosphereSet_->deviceBytes() + terrainSet_->deviceBytes();
}

uint64_t ModelTextures::textureBytes() const {
    return noise_->textureBytes() + weatherSet_->textureBytes() + blueSet_->textureBytes();
}

} // namespace cloudscape::vulkan
