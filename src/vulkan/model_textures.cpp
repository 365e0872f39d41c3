#include "vulkan/model_textures.h"

#include <cloudscape/blue_noise.h>
#include <cloudscape/error.h>

#include "vulkan/submit.h"

#include <array>

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

ModelTextures::ModelTextures(Context& ctx, const SceneResources& resources)
    : set_(std::make_unique<ResourceSet>(ctx)) {
    checkImageLimit(ctx, resources.weather, "the weather map");
    // Wrap addressing and trilinear filtering: the same sampler the CPU backend emulates. Blue
    // noise is read with texelFetch, so this sampler never filters it.
    sampler_ = ctx.device.createSamplerUnique(vk::SamplerCreateInfo(
        {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eLinear,
        vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat,
        vk::SamplerAddressMode::eRepeat, 0.0f, VK_FALSE, 1.0f, VK_FALSE, vk::CompareOp::eNever,
        0.0f, VK_LOD_CLAMP_NONE));
    const bool timed = ctx.timestampValidBits > 0;
    const vk::UniqueQueryPool queries =
        ctx.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, 2});
    submitAndWait(ctx, [&](vk::CommandBuffer cmd) {
        cmd.resetQueryPool(*queries, 0, 2);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries, 0);
        base_ = &set_->texture(resources.noise.base, cmd);
        detail_ = &set_->texture(resources.noise.detail, cmd);
        curl_ = &set_->texture(resources.noise.curl, cmd);
        weather_ = &set_->texture(resources.weather, cmd);
        blue_ = &set_->texture(blueNoiseTexture(), cmd);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries, 1);
    });
    set_->releaseStaging(); // 10.7 MB that would otherwise live as long as the textures
    if (timed) {
        std::array<uint64_t, 2> ticks{};
        const vk::Result r = ctx.device.getQueryPoolResults(
            *queries, 0, 2, sizeof ticks, ticks.data(), sizeof(uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (r == vk::Result::eSuccess)
            uploadMs_ = static_cast<double>(ticks[1] - ticks[0]) *
                        ctx.properties.limits.timestampPeriod * 1e-6;
    }
}

} // namespace cloudscape::vulkan
