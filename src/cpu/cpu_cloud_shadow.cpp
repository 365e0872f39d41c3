#include "cpu/cpu_cloud_shadow.h"

#include "core/cloud_shadow_update.h"
#include "cpu/cpu_model.h"

#include <cstring>

#include <tbb/parallel_for.h>

namespace cloudscape::cpu {

namespace {

// Makes the texels of `region` of `cloud`'s map into `map`, on all cores.
void makeRegion(std::vector<glm::vec4>& map, const CloudShadowRegion& region,
                const model::CloudParams& cloud, const TextureSet& textures) {
    tbb::parallel_for(region.begin.y, region.end.y, [&](int y) {
        ScopedTextureBinding bind(textures);
        for (int x = region.begin.x; x < region.end.x; ++x)
            map[model::cloudShadowStorageIndex({x, y}, cloud.cloudShadow)] =
                model::cloudShadowMapTexel({x, y}, cloud);
    });
}

} // namespace

std::vector<glm::vec4> computeCloudShadowMap(const model::CloudParams& cloud,
                                             const TextureSet& textures) {
    if (!model::cloudShadowMapUsable(cloud))
        return {};
    const int n = cloud.cloudShadow.resolution;
    std::vector<glm::vec4> map(static_cast<size_t>(n) * n);
    makeRegion(map, {{0, 0}, {n, n}}, cloud, textures);
    return map;
}

const std::vector<glm::vec4>& KeptCloudShadowMap::update(const model::CloudParams& cloud,
                                                         const TextureSet& textures,
                                                         uint64_t texturesVersion) {
    texelsMade_ = 0;
    if (!model::cloudShadowMapUsable(cloud)) {
        map_.clear();
        holds_.invalidate();
        return map_;
    }
    const int n = cloud.cloudShadow.resolution;
    if (map_.size() != static_cast<size_t>(n) * n) {
        map_.assign(static_cast<size_t>(n) * n, glm::vec4(0.0f));
        holds_.invalidate();
    }
    Inputs now;
    std::memset(&now, 0, sizeof now);
    std::memcpy(&now.cloud, &cloud, sizeof cloud);
    clearCloudShadowPlacement(now.cloud);
    now.texturesVersion = texturesVersion;
    const bool sameRecords = !holds_.changed(now);
    const CloudShadowRegions regions =
        cloudShadowRegionsToMake(sameRecords, cloud.cloudShadow.firstTexel - held_.firstTexel, n);
    held_ = cloud.cloudShadow;
    for (int i = 0; i < regions.count; ++i) {
        makeRegion(map_, regions.parts[i], cloud, textures);
        texelsMade_ += regions.parts[i].texels();
    }
    return map_;
}

std::vector<glm::vec4> cloudShadowMapInRows(const std::vector<glm::vec4>& stored,
                                            const model::CloudShadowParams& params) {
    const int n = params.resolution;
    if (stored.empty() || n <= 0)
        return {};
    std::vector<glm::vec4> rows(stored.size());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            rows[static_cast<size_t>(y) * n + x] =
                stored[model::cloudShadowStorageIndex({x, y}, params)];
    return rows;
}

} // namespace cloudscape::cpu
