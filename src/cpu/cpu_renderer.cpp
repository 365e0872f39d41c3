// The CPU backend: runs the model's per-pixel march over 16x16 tiles on all cores (TBB). Only
// plumbing lives here; the physics is in src/model.
#include <cloudscape/error.h>
#include <cloudscape/renderer.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/resources.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_model.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>

namespace cloudscape {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

namespace {

// renderCpu at the scene's own size; hands out the clouds' shadow map it made when asked.
RenderResult renderCpuPass(const Scene& scene, const SceneResources& resources,
                           const ProgressCallback& progress, std::vector<glm::vec4>* shadowMapOut);

} // namespace

RenderResult renderCpu(const Scene& scene, const SceneResources& resources,
                       const ProgressCallback& progress) {
    checkCameraAboveTerrain(scene, resources);
    if (scene.cloudResolution < 1.0f)
        return renderAtCloudResolution(
            scene, resources, [&](const Scene& pass, PassProducts& products) {
                return renderCpuPass(pass, resources, progress, &products.shadowMap);
            });
    return renderCpuPass(scene, resources, progress, nullptr);
}

namespace {

RenderResult renderCpuPass(const Scene& scene, const SceneResources& resources,
                           const ProgressCallback& progress, std::vector<glm::vec4>* shadowMapOut) {
    const auto start = std::chrono::steady_clock::now();
    const model::CloudParams cloud = makeCloudParams(scene, resources);
    model::FrameParams frame = makeFrameParams(scene);
    const std::vector<float> depth = sceneDepthFor(scene, resources);
    frame.hasSceneDepth = depth.empty() ? 0 : 1;
    const int width = scene.width;
    const int height = scene.height;

    RenderResult out;
    allocateResult(out, width, height);
    const size_t pixels = static_cast<size_t>(width) * height;

    cpu::TextureSet textures;
    textures.baseNoise = &resources.noise.base;
    textures.detailNoise = &resources.noise.detail;
    textures.curlNoise = &resources.noise.curl;
    textures.weatherMap = &resources.weather;
    textures.sceneDepth = depth.empty() ? nullptr : depth.data();
    textures.sceneDepthWidth = width;
    textures.noiseClearance =
        resources.noise.baseClearance.empty() ? nullptr : resources.noise.baseClearance.data();
    textures.atmosphere = resources.atmosphere.empty() ? nullptr : resources.atmosphere.data();
    textures.highClouds =
        resources.noise.highClouds.mips.empty() ? nullptr : &resources.noise.highClouds;
    textures.terrain =
        resources.terrain.heights.empty() ? nullptr : resources.terrain.heights.data();
    std::vector<glm::vec4> shadowMap = cpu::computeCloudShadowMap(cloud, textures);
    cpu::bindCloudShadowMap(textures, shadowMap);

    struct Counters {
        uint64_t densitySamples = 0;
        uint64_t cloudSamples = 0;
        uint64_t emptySkips = 0;
        uint64_t lightSamples = 0;
    };
    tbb::enumerable_thread_specific<Counters> counters;
    constexpr int kTile = 16;
    const int tilesX = (width + kTile - 1) / kTile;
    const int tilesY = (height + kTile - 1) / kTile;
    const size_t tileCount = static_cast<size_t>(tilesX) * tilesY;
    std::atomic<size_t> tilesDone{0};
    std::mutex progressMutex;

    // The per-pixel work is the model's renderPixel; this loop is only scheduling and storage.
    auto renderPixel = [&](int x, int y, size_t i, Counters& local) {
        const model::PixelResult p =
            model::renderPixel(static_cast<uint32_t>(x), static_cast<uint32_t>(y), frame, cloud);
        local.densitySamples += static_cast<uint64_t>(p.densitySamples);
        local.cloudSamples += static_cast<uint64_t>(p.cloudSamples);
        local.emptySkips += static_cast<uint64_t>(p.emptySkips);
        local.lightSamples += static_cast<uint64_t>(p.lightSamples);
        storePixel(out, i, p.cloudRadiance, p.transmittance, p.composite, p.depth);
    };

    tbb::parallel_for(tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1),
                      [&](const tbb::blocked_range2d<int>& range) {
                          cpu::ScopedTextureBinding binding(textures);
                          Counters& local = counters.local();
                          for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty) {
                              for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
                                  const int y1 = std::min(height, (ty + 1) * kTile);
                                  const int x1 = std::min(width, (tx + 1) * kTile);
                                  for (int y = ty * kTile; y < y1; ++y) {
                                      for (int x = tx * kTile; x < x1; ++x) {
                                          const size_t i = static_cast<size_t>(y) * width + x;
                                          renderPixel(x, y, i, local);
                                      }
                                  }
                                  const size_t done = ++tilesDone;
                                  if (progress) {
                                      std::lock_guard<std::mutex> lock(progressMutex);
                                      progress(static_cast<double>(done) /
                                               static_cast<double>(tileCount));
                                  }
                              }
                          }
                      });

    for (const Counters& c : counters) {
        out.stats.densitySamples += c.densitySamples;
        out.stats.cloudSamples += c.cloudSamples;
        out.stats.emptySkips += c.emptySkips;
        out.stats.lightSamples += c.lightSamples;
    }
    out.stats.shadowMapMade = !shadowMap.empty();
    out.stats.shadowMapTexelsMade = static_cast<int64_t>(shadowMap.size());
    out.stats.rays = pixels * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.seconds = secondsSince(start);
    if (shadowMapOut)
        *shadowMapOut = std::move(shadowMap);
    return out;
}

} // namespace

} // namespace cloudscape
