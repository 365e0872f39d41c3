#include "vulkan/cloud_shadow_map.h"

#include "model/cloud_shadow.glsl.h"
#include "model/interface.glsl.h"
#include "vulkan/march_pass.h"
#include "vulkan/submit.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace cloudscape::vulkan {

CloudShadowMap::CloudShadowMap(Context& ctx, const ComputePass& pass) : ctx_(ctx), pass_(pass) {
    set_ = pass_.allocateSet();
    resize(0);
}

int CloudShadowMap::resolutionFor(const model::CloudParams& cloud) {
    return model::cloudShadowMapUsable(cloud) ? cloud.cloudShadow.resolution : 0;
}

bool CloudShadowMap::resize(int resolution) {
    if (resolution == resolution_)
        return false;
    const size_t texels = resolution > 0 ? static_cast<size_t>(resolution) * resolution : 1;
    auto resources = std::make_unique<ResourceSet>(ctx_);
    buffer_ = &resources->hostBuffer(texels * sizeof(float) * 4, kRecordBufferUsage);
    resources_ = std::move(resources); // the old buffer is freed once the device is idle
    resolution_ = resolution;
    holds_.invalidate();
    return true;
}

std::vector<glm::vec4> CloudShadowMap::texels() const {
    if (resolution_ <= 0)
        return {};
    const auto* stored = static_cast<const glm::vec4*>(buffer_->mapped);
    std::vector<glm::vec4> out(static_cast<size_t>(resolution_) * resolution_);
    for (int y = 0; y < resolution_; ++y)
        for (int x = 0; x < resolution_; ++x)
            out[static_cast<size_t>(y) * resolution_ + x] =
                stored[model::cloudShadowStorageIndex({x, y}, held_)];
    return out;
}

void CloudShadowMap::bind(const Buffer& cloudParams, const ModelTextures& textures) {
    const vk::Sampler sampler = textures.sampler();
    DescriptorWriter(model::SHADOW_PASS, set_)
        .buffer(model::SHADOW_CLOUD_PARAMS, cloudParams)
        .image(model::SHADOW_BASE_NOISE, sampler, textures.baseNoise())
        .image(model::SHADOW_DETAIL_NOISE, sampler, textures.detailNoise())
        .image(model::SHADOW_CURL_NOISE, sampler, textures.curlNoise())
        .image(model::SHADOW_WEATHER_MAP, sampler, textures.weatherMap())
        .buffer(model::SHADOW_OUT_MAP, *buffer_)
        .commit(ctx_.device);
}

namespace {

// Leaves in `p` the parameters a texel's record depends on: all but where the map lies (its
// first texel and storage shift) and the sky-view table's radius (the camera's altitude, which
// the map never reads), so a camera flying over the map keeps every texel it still covers.
void clearPlacement(model::CloudParams& p) {
    p.cloudShadow.firstTexel = glm::ivec2(0);
    p.cloudShadow.storageShiftX = 0;
    p.cloudShadow.storageShiftZ = 0;
    p.sky.atmosphere.skyViewRadius = 0.0f;
}

} // namespace

bool CloudShadowMap::record(vk::CommandBuffer cmd, const model::CloudParams& cloud, int features,
                            uint64_t texturesVersion) {
    texelsMade_ = 0;
    if (resolution_ <= 0)
        return false;
    // CloudParams is plain data written whole by makeCloudParams: equal bytes, equal records.
    auto now = std::make_unique<Inputs>();
    std::memset(now.get(), 0, sizeof *now);
    std::memcpy(&now->cloud, &cloud, sizeof cloud);
    clearPlacement(now->cloud);
    now->features = features;
    now->texturesVersion = texturesVersion;
    const bool sameRecords = !holds_.changed(*now);
    const glm::ivec2 move = cloud.cloudShadow.firstTexel - held_.firstTexel;
    const int n = resolution_;
    held_ = cloud.cloudShadow;
    if (sameRecords && move == glm::ivec2(0))
        return false;
    pass_.bind(cmd, set_, features);
    if (!sameRecords || std::abs(move.x) >= n || std::abs(move.y) >= n) {
        recordRegion(cmd, {0, 0}, {n, n});
    } else {
        // The columns the move brings in (over all rows), then the rows (over the other columns).
        const int x0 = move.x > 0 ? n - move.x : 0;
        const int x1 = move.x > 0 ? n : -move.x;
        const int keptX0 = move.x > 0 ? 0 : x1;
        const int keptX1 = move.x > 0 ? x0 : n;
        recordRegion(cmd, {x0, 0}, {x1, n});
        const int y0 = move.y > 0 ? n - move.y : 0;
        const int y1 = move.y > 0 ? n : -move.y;
        recordRegion(cmd, {keptX0, y0}, {keptX1, y1});
    }
    shaderWritesToShader(cmd);
    return true;
}

void CloudShadowMap::recordRegion(vk::CommandBuffer cmd, glm::ivec2 begin, glm::ivec2 end) {
    if (end.x <= begin.x || end.y <= begin.y)
        return;
    texelsMade_ += static_cast<int64_t>(end.x - begin.x) * (end.y - begin.y);
    // In tiles, as the march is: no single dispatch of a large map runs long.
    const int tile = MarchPass::kTile;
    for (int y = begin.y; y < end.y; y += tile)
        for (int x = begin.x; x < end.x; x += tile) {
            pass_.push(cmd, model::ShadowPush{x, y, end.x, end.y});
            dispatchImage(cmd, std::min(tile, end.x - x), std::min(tile, end.y - y));
        }
}

} // namespace cloudscape::vulkan
