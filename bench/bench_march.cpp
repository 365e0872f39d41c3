// Cost and quality of each march optimisation, one at a time and together, on the default scene
// (CPU backend, 320x180). Quality is against a brute-force reference: 4x the seeds' step counts,
// no coarse/fine, full light samples at mip 0, 4 samples per pixel. Counters: density and light
// samples per pixel, SSIM and MS-SSIM of the display luminance, relative HDR error.
#include <cloudscape/metrics.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <benchmark/benchmark.h>

namespace {

cloudscape::Scene base() {
    cloudscape::Scene s;
    s.width = 320;
    s.height = 180;
    s.coarseStepFactor = 1;
    s.cheapLightAlpha = 1.0f;
    s.lightMipBias = 0;
    return s;
}

const cloudscape::SceneResources& resources() {
    static const cloudscape::SceneResources r = cloudscape::prepareResources(base());
    return r;
}

const std::vector<float>& reference() {
    static const std::vector<float> ref = [] {
        cloudscape::Scene s = base();
        s.zenithSteps = 256;
        s.horizonSteps = 512;
        s.samplesPerPixel = 4;
        return cloudscape::compositeRgb(cloudscape::renderCpu(s, resources()));
    }();
    return ref;
}

void run(benchmark::State& state, const cloudscape::Scene& scene) {
    reference(); // not timed
    cloudscape::RenderResult r;
    for (auto _ : state)
        r = cloudscape::renderCpu(scene, resources());
    const std::vector<float> img = cloudscape::compositeRgb(r);
    const auto la = cloudscape::displayLuminance(reference(), 3, 1.0f);
    const auto lb = cloudscape::displayLuminance(img, 3, 1.0f);
    state.counters["density_per_px"] = static_cast<double>(r.stats.densitySamples) / r.stats.rays;
    state.counters["light_per_px"] = static_cast<double>(r.stats.lightSamples) / r.stats.rays;
    state.counters["ssim"] = cloudscape::ssim(la, lb, scene.width, scene.height);
    state.counters["ms_ssim"] = cloudscape::msSsim(la, lb, scene.width, scene.height);
    state.counters["rel_err"] = cloudscape::relativeError(reference(), img);
}

void BM_SeedsPlainMarch(benchmark::State& state) {
    run(state, base());
}
void BM_CoarseFine2(benchmark::State& state) {
    cloudscape::Scene s = base();
    s.coarseStepFactor = 2;
    run(state, s);
}
void BM_CoarseFine4(benchmark::State& state) {
    cloudscape::Scene s = base();
    s.coarseStepFactor = 4;
    run(state, s);
}
void BM_CheapLightAfterAlpha03(benchmark::State& state) {
    cloudscape::Scene s = base();
    s.cheapLightAlpha = 0.3f;
    run(state, s);
}
void BM_LightMipPlusOne(benchmark::State& state) {
    cloudscape::Scene s = base();
    s.lightMipBias = 1;
    run(state, s);
}
void BM_AllTogether(benchmark::State& state) {
    cloudscape::Scene s = base();
    s.coarseStepFactor = 2;
    s.cheapLightAlpha = 0.3f;
    s.lightMipBias = 1;
    run(state, s);
}
void BM_ShippedDefaults(benchmark::State& state) {
    cloudscape::Scene s;
    s.width = 320;
    s.height = 180;
    run(state, s);
}

} // namespace

#define MARCH_BENCH(name)                                                                          \
    BENCHMARK(name)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime()
MARCH_BENCH(BM_SeedsPlainMarch);
MARCH_BENCH(BM_CoarseFine2);
MARCH_BENCH(BM_CoarseFine4);
MARCH_BENCH(BM_CheapLightAfterAlpha03);
MARCH_BENCH(BM_LightMipPlusOne);
MARCH_BENCH(BM_AllTogether);
MARCH_BENCH(BM_ShippedDefaults);
BENCHMARK_MAIN();
