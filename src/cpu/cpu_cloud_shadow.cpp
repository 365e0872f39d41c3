#include "cpu/cpu_cloud_shadow.h"

#include "cpu/cpu_model.h"

#include <tbb/parallel_for.h>

namespace cloudscape::cpu {

std::vector<glm::vec4> computeCloudShadowMap(const model::CloudParams& cloud,
                                             const TextureSet& textures) {
    if (!model::cloudShadowMapUsable(cloud))
        return {};
    const int n = cloud.cloudShadow.resolution;
    std::vector<glm::vec4> map(static_cast<size_t>(n) * n);
    tbb::parallel_for(0, n, [&](int y) {
        ScopedTextureBinding bind(textures);
        for (int x = 0; x < n; ++x)
            map[model::cloudShadowStorageIndex({x, y}, cloud.cloudShadow)] =
                model::cloudShadowMapTexel({x, y}, cloud);
    });
    return map;
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
