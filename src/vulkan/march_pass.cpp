#include "vulkan/march_pass.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace cloudscape::vulkan {
namespace {

const uint32_t kRenderCloudsSpirv[] = {
#include "shaders/render_clouds.spv.inc"
};

constexpr int kWorkgroup = model::PASS_WORKGROUP_SIDE; // local_size_x/y of every pass

} // namespace

MarchPass::MarchPass(const Context& ctx)
    : pass_(ctx, model::MARCH_PASS, kRenderCloudsSpirv, sizeof kRenderCloudsSpirv) {}

void MarchPass::bind(const Context& ctx, vk::DescriptorSet set, const ModelTextures& textures,
                     const Buffers& b) const {
    const vk::Sampler sampler = textures.sampler();
    DescriptorWriter(model::MARCH_PASS, set)
        .buffer(model::MARCH_CLOUD_PARAMS, *b.cloudParams)
        .buffer(model::MARCH_FRAME_PARAMS, *b.frameParams)
        .image(model::MARCH_BASE_NOISE, sampler, textures.baseNoise())
        .image(model::MARCH_DETAIL_NOISE, sampler, textures.detailNoise())
        .image(model::MARCH_CURL_NOISE, sampler, textures.curlNoise())
        .image(model::MARCH_WEATHER_MAP, sampler, textures.weatherMap())
        .image(model::MARCH_BLUE_NOISE, sampler, textures.blueNoise())
        .image(model::MARCH_HIGH_CLOUDS, sampler, textures.highClouds())
        .buffer(model::MARCH_SCENE_DEPTH, *b.sceneDepth)
        .buffer(model::MARCH_OUT_CLOUD, *b.outCloud)
        .buffer(model::MARCH_OUT_COMPOSITE, *b.outComposite)
        .buffer(model::MARCH_COUNTERS, *b.counters)
        .buffer(model::MARCH_ATMOSPHERE, textures.atmosphere())
        .buffer(model::MARCH_TERRAIN, textures.terrain())
        .buffer(model::MARCH_CLOUD_SHADOW, *b.cloudShadow)
        .buffer(model::MARCH_PREVIOUS_FRAME, *b.previousFrame)
        .buffer(model::MARCH_OUT_ENTERING, *b.outEntering)
        .buffer(model::MARCH_NOISE_CLEARANCE, textures.noiseClearance())
        .commit(ctx.device);
}

void MarchPass::recordTiles(vk::CommandBuffer cmd, vk::DescriptorSet set, int x1, int y0, int y1,
                            bool blockMode, int features) const {
    static_assert(kTile % kWorkgroup == 0, "a tile starts on a workgroup");
    // Callers start rows at whole tiles: the full-frame march finds a workgroup's place in its
    // tile from a base that is a multiple of kTile (dispatch_order.glsl).
    assert(y0 % kTile == 0);
    // Block mode writes no composite (the resolve makes it): its pipeline drops the code.
    pass_.bind(cmd, set, blockMode ? blockModeFeatures(features) : features);
    pass_.push(cmd, model::MarchPush{blockMode ? 1 : 0, 0, 0, 0});
    for (int ty = y0; ty < y1; ty += kTile)
        for (int tx = 0; tx < x1; tx += kTile) {
            // The tile's origin is its base workgroup, not a push constant: lavapipe would
            // compile and keep a variant of the march per origin.
            const int w = std::min(kTile, x1 - tx), h = std::min(kTile, y1 - ty);
            cmd.dispatchBase(static_cast<uint32_t>(tx / kWorkgroup),
                             static_cast<uint32_t>(ty / kWorkgroup), 0,
                             static_cast<uint32_t>((w + kWorkgroup - 1) / kWorkgroup),
                             static_cast<uint32_t>((h + kWorkgroup - 1) / kWorkgroup), 1);
        }
}

void MarchPass::recordRows(vk::CommandBuffer cmd, vk::DescriptorSet set, int width, int y0, int y1,
                           int features) const {
    recordTiles(cmd, set, width, y0, y1, false, features);
}

void MarchPass::recordBlocks(vk::CommandBuffer cmd, vk::DescriptorSet set, int blocksX, int blocksY,
                             int features) const {
    recordTiles(cmd, set, blocksX, 0, blocksY, true, features);
}

void dispatchImage(vk::CommandBuffer cmd, int width, int height) {
    cmd.dispatch(static_cast<uint32_t>((width + kWorkgroup - 1) / kWorkgroup),
                 static_cast<uint32_t>((height + kWorkgroup - 1) / kWorkgroup), 1);
}

void resetCounters(vk::CommandBuffer cmd, const Buffer& counters) {
    cmd.fillBuffer(counters.buffer, 0, VK_WHOLE_SIZE, 0u);
    const vk::MemoryBarrier filled(vk::AccessFlagBits::eTransferWrite,
                                   vk::AccessFlagBits::eShaderRead |
                                       vk::AccessFlagBits::eShaderWrite);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eComputeShader, {}, filled, {}, {});
}

model::FrameCounters readCounters(const Context& ctx, const Buffer& counters) {
    ctx.device.invalidateMappedMemoryRanges(
        vk::MappedMemoryRange(counters.memory, 0, VK_WHOLE_SIZE));
    model::FrameCounters c{};
    std::memcpy(&c, counters.mapped, sizeof c);
    return c;
}

namespace {
// A 64-bit sum kept in FrameCounters as (low, high) words.
uint64_t wide(uint32_t low, uint32_t high) {
    return (static_cast<uint64_t>(high) << 32) | low;
}
} // namespace

uint64_t densitySamples(const model::FrameCounters& c) {
    return wide(c.densitySamplesLow, c.densitySamplesHigh);
}

uint64_t lightSamples(const model::FrameCounters& c) {
    return wide(c.lightSamplesLow, c.lightSamplesHigh);
}

uint64_t cloudSamples(const model::FrameCounters& c) {
    return wide(c.cloudSamplesLow, c.cloudSamplesHigh);
}

uint64_t emptySkips(const model::FrameCounters& c) {
    return wide(c.emptySkipsLow, c.emptySkipsHigh);
}

} // namespace cloudscape::vulkan
