// The clouds' shadow map and the light shafts on the CPU backend (docs/PERFORMANCE.md): one map
// per frame at the mountains preset's settings and two resolutions, on all cores, and the shafts'
// cost per pixel, with the default-size textures.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_model.h"

#include <benchmark/benchmark.h>

#include <random>

namespace cm = cloudscape::model;

namespace {

struct World {
    cloudscape::Scene scene = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    cloudscape::SceneResources resources;
    cm::CloudParams params;
    cloudscape::cpu::TextureSet set;
    std::vector<glm::vec4> map;
    World() {
        resources.noise = cloudscape::generateNoiseTextures(1);
        resources.weather = cloudscape::prepareWeather(scene);
        resources.weatherCoverage = cloudscape::CoverageField(resources.weather);
        cloudscape::prepareAtmosphere(scene, resources);
        params = cloudscape::makeCloudParams(scene, resources);
        set = {&resources.noise.base, &resources.noise.detail, &resources.noise.curl,
               &resources.weather};
        set.atmosphere = resources.atmosphere.data();
        map = cloudscape::cpu::computeCloudShadowMap(params, set);
        cloudscape::cpu::bindCloudShadowMap(set, map);
    }
};

World& world() {
    static World w;
    return w;
}

void BM_CloudShadowMap(benchmark::State& state) {
    World& w = world();
    cm::CloudParams p = w.params;
    p.cloudShadow.resolution = static_cast<int>(state.range(0));
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::cpu::computeCloudShadowMap(p, w.set).data());
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * state.range(0) *
                            state.range(0));
}

// One pixel's shafts (32 steps, the preset's) along view rays spread over the preset's view.
void BM_LightShaftsPerPixel(benchmark::State& state) {
    World& w = world();
    cloudscape::cpu::ScopedTextureBinding bind(w.set);
    const cm::FrameParams f = cloudscape::makeFrameParams(w.scene);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> dirs;
    for (int i = 0; i < 1024; ++i)
        dirs.push_back(cm::cameraRayDirection(f, u(rng) * f.width, u(rng) * f.height));
    size_t i = 0;
    for (auto _ : state) {
        const glm::vec3 d = dirs[i++ & 1023];
        benchmark::DoNotOptimize(cm::lightShaftsDelta(f.cameraPosition, d, cm::NO_HIT, 1.0f,
                                                      w.params.maxDistance, 0.5f, w.params));
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

} // namespace

BENCHMARK(BM_CloudShadowMap)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LightShaftsPerPixel);
BENCHMARK_MAIN();
