#include "vulkan/cloud_shadow_map.h"

#include "core/cloud_shadow_update.h"
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

bool CloudShadowMap::record(vk::CommandBuffer cmd, const model::CloudParams& cloud, int features,
                            uint64_t texturesVersion) {
    texelsMade_ = 0;
    if (resolution_ <= 0)
        return false;
    // CloudParams is plain data written whole by makeCloudParams: equal bytes, equal records.
    auto now = std::make_unique<Inputs>();
    std::memset(now.get(), 0, sizeof *now);
    std::memcpy(&now->cloud, &cloud, sizeof cloud);
    clearCloudShadowPlacement(now->cloud);
    now->features = features;
    now->texturesVersion = texturesVersion;
    const bool sameRecords = !holds_.changed(*now);
    const CloudShadowRegions regions = cloudShadowRegionsToMake(
        sameRecords, cloud.cloudShadow.firstTexel - held_.firstTexel, resolution_);
    held_ = cloud.cloudShadow;
    if (regions.count == 0)
        return false;
    pass_.bind(cmd, set_, features);
    for (int i = 0; i < regions.count; ++i)
        recordRegion(cmd, regions.parts[i].begin, regions.parts[i].end);
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
