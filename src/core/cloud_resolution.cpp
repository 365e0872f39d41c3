#include "core/cloud_resolution.h"

#include <cloudscape/error.h>

#include "core/model_params.h"
#include "core/pixel_store.h"
#include "model/pixel.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cloudscape {

Scene cloudPassScene(const Scene& full) {
    Scene s = full;
    s.width = std::max(1, static_cast<int>(std::ceil(full.width * full.cloudResolution)));
    s.height = std::max(1, static_cast<int>(std::ceil(full.height * full.cloudResolution)));
    s.cloudResolution = 1.0f;
    return s;
}

std::vector<float> sceneDepthFor(const Scene& scene, const SceneResources& resources) {
    const DepthBuffer& d = resources.depth;
    if (d.empty())
        return {};
    if (d.width == scene.width && d.height == scene.height)
        return d.metres;
    if (d.width < scene.width || d.height < scene.height)
        throw Error("render.depth_file is " + std::to_string(d.width) + "x" +
                    std::to_string(d.height) + " but the render is " + std::to_string(scene.width) +
                    "x" + std::to_string(scene.height));
    std::vector<float> out(static_cast<size_t>(scene.width) * scene.height);
    for (int y = 0; y < scene.height; ++y) {
        const int y0 = y * d.height / scene.height;
        const int y1 = std::max(y0 + 1, (y + 1) * d.height / scene.height);
        for (int x = 0; x < scene.width; ++x) {
            const int x0 = x * d.width / scene.width;
            const int x1 = std::max(x0 + 1, (x + 1) * d.width / scene.width);
            float farthest = 0.0f;
            for (int yy = y0; yy < y1; ++yy)
                for (int xx = x0; xx < x1; ++xx)
                    farthest = std::max(farthest, d.metres[static_cast<size_t>(yy) * d.width + xx]);
            out[static_cast<size_t>(y) * scene.width + x] = farthest;
        }
    }
    return out;
}

RenderResult upsampleCloudPass(const RenderResult& pass, const Scene& full,
                               const SceneResources& resources) {
    const auto start = std::chrono::steady_clock::now();
    const model::CloudParams cloud = makeCloudParams(full, resources);
    const model::FrameParams frame = makeFrameParams(full);
    const std::vector<float> depth = sceneDepthFor(full, resources);
    RenderResult out;
    allocateResult(out, full.width, full.height);
    const float sx = static_cast<float>(pass.width) / static_cast<float>(full.width);
    const float sy = static_cast<float>(pass.height) / static_cast<float>(full.height);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    tbb::parallel_for(0, full.height, [&](int y) {
        for (int x = 0; x < full.width; ++x) {
            const size_t i = static_cast<size_t>(y) * full.width + x;
            const float geometry = depth.empty() ? kInf : depth[i];
            // Pixel centres: output (x + 0.5) lands at pass coordinate (x + 0.5) * s - 0.5.
            const float u = std::clamp((x + 0.5f) * sx - 0.5f, 0.0f, pass.width - 1.0f);
            const float v = std::clamp((y + 0.5f) * sy - 0.5f, 0.0f, pass.height - 1.0f);
            const int x0 = static_cast<int>(u), y0 = static_cast<int>(v);
            const int x1 = std::min(x0 + 1, pass.width - 1), y1 = std::min(y0 + 1, pass.height - 1);
            const float ax = u - x0, ay = v - y0;
            glm::vec4 sum(0.0f);
            auto tap = [&](int px, int py, float w) {
                const size_t j = static_cast<size_t>(py) * pass.width + px;
                const float tapDepth = std::isinf(pass.depth[j]) ? model::NO_HIT : pass.depth[j];
                if (model::cloudHiddenByGeometry(tapDepth, geometry)) {
                    sum += glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) * w;
                    return;
                }
                sum += glm::vec4(pass.cloud[j * 4], pass.cloud[j * 4 + 1], pass.cloud[j * 4 + 2],
                                 pass.cloud[j * 4 + 3]) *
                       w;
            };
            tap(x0, y0, (1 - ax) * (1 - ay));
            tap(x1, y0, ax * (1 - ay));
            tap(x0, y1, (1 - ax) * ay);
            tap(x1, y1, ax * ay);
            const int nx = ax < 0.5f ? x0 : x1, ny = ay < 0.5f ? y0 : y1;
            float cloudDepth = pass.depth[static_cast<size_t>(ny) * pass.width + nx];
            if (std::isinf(cloudDepth) || model::cloudHiddenByGeometry(cloudDepth, geometry))
                cloudDepth = kInf;
            const glm::vec3 dir =
                model::cameraRayDirection(frame, static_cast<float>(x), static_cast<float>(y));
            const glm::vec3 radiance(sum.x, sum.y, sum.z);
            const glm::vec3 colour = model::compositeOver(
                radiance, sum.w,
                model::backgroundRadiance(dir, std::min(geometry, cloud.maxDistance), cloud));
            storePixel(out, i, radiance, sum.w, colour,
                       std::isinf(cloudDepth) ? model::NO_HIT : cloudDepth);
        }
    });
    out.stats = pass.stats;
    out.stats.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

RenderResult renderAtCloudResolution(const Scene& full, const SceneResources& resources,
                                     const std::function<RenderResult(const Scene&)>& pass) {
    return upsampleCloudPass(pass(cloudPassScene(full)), full, resources);
}

} // namespace cloudscape
