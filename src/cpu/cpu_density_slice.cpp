#include "cpu/cpu_density_slice.h"

#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "model/debug_view.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace cloudscape::cpu {

DensitySliceFrame densitySliceFrame(const Scene& scene, int height) {
    const float top = 1.15f * std::max(scene.cloudTopM, scene.cameraPosition.y);
    return {top / static_cast<float>(std::max(height, 1)), top};
}

std::vector<glm::vec3> densitySlice(const Scene& scene, const SceneResources& resources, int width,
                                    int height) {
    const model::CloudParams P = makeCloudParams(scene, resources);
    const DensitySliceFrame frame = densitySliceFrame(scene, height);
    const glm::vec3 forward = directionFromAngles(scene.cameraHeadingDeg, 0.0f);
    const glm::vec2 heading(forward.x, forward.z);
    const glm::vec2 camera(scene.cameraPosition.x, scene.cameraPosition.z);
    TextureSet textures{&resources.noise.base, &resources.noise.detail, &resources.noise.curl,
                        &resources.weather};
    textures.terrain =
        resources.terrain.heights.empty() ? nullptr : resources.terrain.heights.data();
    std::vector<glm::vec3> out(static_cast<size_t>(width) * height);
    tbb::parallel_for(0, height, [&](int y) {
        ScopedTextureBinding bind(textures);
        const float altitude =
            frame.topAltitude - (static_cast<float>(y) + 0.5f) * frame.metresPerPixel;
        for (int x = 0; x < width; ++x) {
            const float along = (static_cast<float>(x) + 0.5f) * frame.metresPerPixel;
            const glm::vec3 p =
                model::densitySlicePoint(camera, heading, along, altitude, P.planetRadius);
            out[static_cast<size_t>(y) * width + x] = model::debugDensitySlice(p, P);
        }
    });
    return out;
}

} // namespace cloudscape::cpu
