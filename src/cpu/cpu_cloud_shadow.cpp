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
            map[static_cast<size_t>(y) * n + x] = model::cloudShadowMapTexel({x, y}, cloud);
    });
    return map;
}

} // namespace cloudscape::cpu
