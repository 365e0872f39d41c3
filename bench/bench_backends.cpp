// The default scene at 1280x720 on the CPU backend and on the Vulkan backend (lavapipe on a
// CPU-only machine), in one run so the ratio compares like with like; and at 640x360 the Vulkan
// temporal renderer against a Vulkan full-frame render (and the CPU temporal renderer).
#include <cloudscape/backend.h>
#include <cloudscape/camera_path.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <utility>

namespace {

const cloudscape::SceneResources& resources() {
    static const cloudscape::SceneResources r = cloudscape::prepareResources(cloudscape::Scene{});
    return r;
}

cloudscape::Scene scene720() {
    cloudscape::Scene s;
    s.width = 1280;
    s.height = 720;
    return s;
}

void BM_Default720_Cpu(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::renderCpu(scene720(), resources()));
}

void BM_Default720_Vulkan(benchmark::State& state) {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Vulkan;
    for (auto _ : state) {
        const cloudscape::RenderResult r = cloudscape::renderVulkan(scene720(), resources(), o);
        // The GPU's own timestamp of the march pass, beside the wall time (which also counts
        // device setup, pipeline creation, texture upload and readback).
        state.counters["gpu_march_ms"] = r.stats.gpuMarchMs;
        state.counters["gpu_upload_ms"] = r.stats.gpuUploadMs;
        state.counters["gpu_MB"] = static_cast<double>(r.stats.gpuMemoryBytes) / 1048576.0;
    }
}

cloudscape::Scene scene360() {
    cloudscape::Scene s;
    s.width = 640;
    s.height = 360;
    return s;
}

void BM_Default360_VulkanFullFrame(benchmark::State& state) {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Vulkan;
    for (auto _ : state) {
        const cloudscape::RenderResult r = cloudscape::renderVulkan(scene360(), resources(), o);
        // Wall time also counts device and pipeline set-up and the texture upload, which this
        // path repeats every call; the timestamp is the march alone.
        state.counters["gpu_ms"] = r.stats.gpuMarchMs;
        state.counters["samples_per_ray"] =
            static_cast<double>(r.stats.densitySamples + r.stats.lightSamples) / r.stats.rays;
    }
}

// Frames of a camera path through one temporal renderer (device, pipelines, textures and history
// kept), after 16 warm-up frames so the history is established; every layer read back (All) or
// only the displayed image (Display, what a PNG sequence or a preview needs).
void temporal360(benchmark::State& state, cloudscape::BackendChoice choice, const char* path,
                 cloudscape::Readback readback = cloudscape::Readback::All) {
    cloudscape::BackendOptions o;
    o.choice = choice;
    resources(); // generated before the clock starts
    const auto start = std::chrono::steady_clock::now();
    cloudscape::TemporalRenderer temporal(resources(), o);
    const cloudscape::Scene base = scene360();
    int frame = 0;
    temporal.renderFrame(cloudscape::sceneOnPath(base, path, frame, 24.0f), frame);
    // Once per renderer: device, pipelines, texture upload, buffers, and the first frame.
    state.counters["setup_ms"] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (++frame; frame < 16; ++frame)
        temporal.renderFrame(cloudscape::sceneOnPath(base, path, frame, 24.0f), frame);
    double marchMs = 0.0, resolveMs = 0.0, samples = 0.0, rays = 0.0;
    for (auto _ : state) {
        const cloudscape::Scene scene = cloudscape::sceneOnPath(base, path, frame, 24.0f);
        const cloudscape::RenderResult r = temporal.renderFrame(scene, frame++, readback);
        marchMs += r.stats.marchSeconds * 1000.0;
        resolveMs += r.stats.resolveSeconds * 1000.0;
        samples += static_cast<double>(r.stats.densitySamples + r.stats.lightSamples);
        rays += static_cast<double>(r.stats.rays);
    }
    state.counters["samples_per_ray"] = samples / rays;
    // Vulkan: GPU timestamps of the block march and of the resolve; CPU: their wall times.
    const auto n = static_cast<double>(state.iterations());
    state.counters["gpu_ms"] = (marchMs + resolveMs) / n;
    state.counters["march_ms"] = marchMs / n;
    state.counters["resolve_ms"] = resolveMs / n;
}

void BM_Default360_VulkanTemporal(benchmark::State& state) {
    temporal360(state, cloudscape::BackendChoice::Vulkan, "still");
}

void BM_Default360_VulkanTemporalSlowPan(benchmark::State& state) {
    temporal360(state, cloudscape::BackendChoice::Vulkan, "slow-pan");
}

void BM_Default360_CpuTemporal(benchmark::State& state) {
    temporal360(state, cloudscape::BackendChoice::Cpu, "still");
}

void BM_Default360_VulkanTemporalDisplayOnly(benchmark::State& state) {
    temporal360(state, cloudscape::BackendChoice::Vulkan, "still", cloudscape::Readback::Display);
}

void BM_Default360_VulkanTemporalNoReadback(benchmark::State& state) {
    temporal360(state, cloudscape::BackendChoice::Vulkan, "still", cloudscape::Readback::None);
}

// Where the default preset's temporal frame goes on the device: the shipped
// fair-weather-cumulus preset (terrain, cloud shadow map, atmosphere, high layer) at 640x360,
// still camera, with one feature switched off per variant (or another tier). GPU timestamps of
// the march and the resolve (and the shadow map). Run with --benchmark_repetitions=N
// --benchmark_enable_random_interleaving=true so the variants interleave on a shared machine.
void presetAblation(benchmark::State& state, const char* assignments) {
    cloudscape::Scene base =
        cloudscape::loadScene(cloudscape::resolveScenePath("fair-weather-cumulus"));
    base.width = 640;
    base.height = 360;
    std::string rest = assignments;
    while (!rest.empty()) {
        const size_t end = rest.find(' ');
        const std::string token = rest.substr(0, end);
        if (token.rfind("tier=", 0) == 0)
            cloudscape::applyTier(base, token.substr(5));
        else
            cloudscape::applyOverride(base, token);
        rest = end == std::string::npos ? "" : rest.substr(end + 1);
    }
    const cloudscape::SceneResources res = cloudscape::prepareResources(base);
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Vulkan;
    cloudscape::TemporalRenderer temporal(res, o);
    int frame = 0;
    for (; frame < 16; ++frame)
        temporal.renderFrame(cloudscape::sceneOnPath(base, "still", frame, 24.0f), frame,
                             cloudscape::Readback::None);
    double marchMs = 0.0, resolveMs = 0.0, shadowMs = 0.0, samples = 0.0, rays = 0.0;
    for (auto _ : state) {
        const cloudscape::RenderResult r =
            temporal.renderFrame(cloudscape::sceneOnPath(base, "still", frame, 24.0f), frame,
                                 cloudscape::Readback::None);
        ++frame;
        marchMs += r.stats.marchSeconds * 1000.0;
        resolveMs += r.stats.resolveSeconds * 1000.0;
        shadowMs += std::max(r.stats.gpuShadowMs, 0.0);
        samples += static_cast<double>(r.stats.densitySamples + r.stats.lightSamples);
        rays += static_cast<double>(r.stats.rays);
    }
    const auto n = static_cast<double>(state.iterations());
    state.counters["march_ms"] = marchMs / n;
    state.counters["resolve_ms"] = resolveMs / n;
    state.counters["shadow_ms"] = shadowMs / n;
    state.counters["samples_per_ray"] = samples / std::max(rays, 1.0);
}

// The persistent Renderer's full-frame render: after the first, no device set-up, pipeline
// creation or texture upload (against BM_Default360_VulkanFullFrame, which pays them per call).
void BM_Default360_VulkanPersistentStill(benchmark::State& state) {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Vulkan;
    cloudscape::Renderer renderer(scene360(), resources(), o);
    renderer.render(scene360());
    for (auto _ : state) {
        const cloudscape::RenderResult r = renderer.render(scene360());
        state.counters["gpu_ms"] = r.stats.gpuMarchMs;
    }
}

// What a change of one key costs a live renderer (Renderer::update, then the render that uses
// it is not counted): weather.coverage is a uniform; weather.type regenerates and uploads the
// weather map; seed regenerates and uploads every noise texture.
void updateCost(benchmark::State& state, cloudscape::BackendChoice choice, const char* key,
                const char* a, const char* b) {
    cloudscape::BackendOptions o;
    o.choice = choice;
    cloudscape::Scene first = scene360(), second = scene360();
    cloudscape::applyOverride(first, std::string(key) + "=" + a);
    cloudscape::applyOverride(second, std::string(key) + "=" + b);
    cloudscape::Renderer renderer(first, resources(), o);
    bool flip = false;
    double regenerated = 0.0;
    for (auto _ : state) {
        const cloudscape::UpdateReport r = renderer.update((flip = !flip) ? second : first);
        regenerated += (r.noise || r.weather) ? 1.0 : 0.0;
    }
    state.counters["textures_rebuilt"] = regenerated / static_cast<double>(state.iterations());
}

// The host half of a coverage change that the render after it pays: the bias search over the
// weather map's coverage-field distribution (the upload is the 336-byte CloudParams).
void BM_CoverageBias(benchmark::State& state) {
    const cloudscape::CoverageField field(resources().weather);
    float coverage = 0.1f;
    for (auto _ : state) {
        benchmark::DoNotOptimize(field.biasFor(coverage));
        coverage = coverage > 0.85f ? 0.1f : coverage + 0.07f;
    }
}

void BM_Update_Coverage_Vulkan(benchmark::State& state) {
    updateCost(state, cloudscape::BackendChoice::Vulkan, "weather.coverage", "0.3", "0.6");
}
void BM_Update_WeatherType_Vulkan(benchmark::State& state) {
    updateCost(state, cloudscape::BackendChoice::Vulkan, "weather.type", "0.5", "0.6");
}
void BM_Update_Coverage_Cpu(benchmark::State& state) {
    updateCost(state, cloudscape::BackendChoice::Cpu, "weather.coverage", "0.3", "0.6");
}
void BM_Update_WeatherType_Cpu(benchmark::State& state) {
    updateCost(state, cloudscape::BackendChoice::Cpu, "weather.type", "0.5", "0.6");
}

} // namespace

BENCHMARK(BM_Default720_Cpu)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_Default720_Vulkan)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_Default360_VulkanFullFrame)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();
BENCHMARK(BM_Default360_VulkanTemporal)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(32)
    ->UseRealTime();
BENCHMARK(BM_Default360_VulkanTemporalSlowPan)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(32)
    ->UseRealTime();
BENCHMARK(BM_Default360_CpuTemporal)->Unit(benchmark::kMillisecond)->Iterations(32)->UseRealTime();
BENCHMARK(BM_Default360_VulkanTemporalDisplayOnly)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(32)
    ->UseRealTime();
BENCHMARK(BM_Default360_VulkanTemporalNoReadback)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(32)
    ->UseRealTime();
BENCHMARK(BM_Default360_VulkanPersistentStill)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();
BENCHMARK(BM_CoverageBias)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Update_Coverage_Vulkan)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_Update_WeatherType_Vulkan)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(6)
    ->UseRealTime();
BENCHMARK(BM_Update_Coverage_Cpu)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_Update_WeatherType_Cpu)->Unit(benchmark::kMillisecond)->Iterations(6)->UseRealTime();
// presetAblation's variants: a name and the assignments it applies to the shipped preset.
const bool kPresetAblationsRegistered = [] {
    const std::pair<const char*, const char*> variants[] = {
        {"shipped", ""},
        {"no_terrain", "terrain.enabled=false"},
        {"no_cloud_shadow", "cloud_shadow.enabled=false"},
        {"no_map_on_clouds", "cloud_shadow.on_clouds=false"},
        // The data field switched on at almost no effect (tops lowered by at most 1 % of the
        // layer): the same clouds, with the field's reads in every density evaluation.
        {"data_field", "weather.top_variation=0.01"},
        {"no_aerial_perspective", "atmosphere.aerial_perspective=false"},
        {"gradient_sky", "sky.model=gradient"},
        {"no_high_clouds", "high_clouds.coverage=0"},
        {"low_tier", "tier=low"},
        {"bare", "terrain.enabled=false cloud_shadow.enabled=false sky.model=gradient "
                 "high_clouds.coverage=0"},
    };
    for (const auto& [name, assignments] : variants)
        benchmark::RegisterBenchmark((std::string("presetAblation/") + name).c_str(),
                                     presetAblation, assignments)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(6)
            ->UseRealTime();
    return true;
}();
BENCHMARK_MAIN();
