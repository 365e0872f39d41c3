// Density samples per second, cheap (base only) and full, through the CPU backend's samplers,
// on the default-size textures; and a whole small render.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"

#include <benchmark/benchmark.h>

#include <random>

namespace cm = cloudscape::model;

namespace {

struct World {
    cloudscape::NoiseTextures noise = cloudscape::generateNoiseTextures(1);
    cloudscape::Texture2D weather = cloudscape::generateWeatherMap({});
    cloudscape::cpu::TextureSet set{&noise.base, &noise.detail, &noise.curl, &weather};
    cm::CloudParams params = cloudscape::makeCloudParams(
        cloudscape::Scene{},
        cloudscape::CoverageField(weather).biasFor(cloudscape::Scene{}.coverage));
    std::vector<glm::vec3> points;
    World() {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f);
        std::uniform_real_distribution<float> alt(1500.0f, 4500.0f);
        // Points inside clouds (non-zero base shape), where the full sample does its erosion
        // work; empty-sky points would make both variants return early.
        cloudscape::cpu::ScopedTextureBinding bind(set);
        while (points.size() < 4096) {
            // Braces: drawn left to right (a call's arguments have no order).
            const glm::vec3 p{xz(rng), alt(rng), xz(rng)};
            if (cm::cloudDensityAt(p, 0.0f, true, params) > 0.0f)
                points.push_back(p);
        }
    }
};

World& world() {
    static World w;
    return w;
}

void densitySamples(benchmark::State& state, bool cheap) {
    World& w = world();
    cloudscape::cpu::ScopedTextureBinding bind(w.set);
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(cm::cloudDensityAt(w.points[i++ & 4095], 0.0f, cheap, w.params));
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}

void BM_DensityCheap(benchmark::State& state) {
    densitySamples(state, true);
}
void BM_DensityFull(benchmark::State& state) {
    densitySamples(state, false);
}

void BM_RenderDefault320x180(benchmark::State& state) {
    cloudscape::Scene scene;
    scene.width = 320;
    scene.height = 180;
    World& w = world();
    cloudscape::SceneResources resources;
    resources.noise = w.noise;
    resources.weather = w.weather;
    for (auto _ : state) {
        const cloudscape::RenderResult r = cloudscape::renderCpu(scene, resources);
        state.counters["density_samples_per_px"] =
            static_cast<double>(r.stats.densitySamples) / r.stats.rays;
        state.counters["light_samples_per_px"] =
            static_cast<double>(r.stats.lightSamples) / r.stats.rays;
    }
}

} // namespace

BENCHMARK(BM_DensityCheap);
BENCHMARK(BM_DensityFull);
BENCHMARK(BM_RenderDefault320x180)->Unit(benchmark::kMillisecond)->Iterations(2)->UseRealTime();
BENCHMARK_MAIN();
