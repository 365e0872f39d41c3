// The atmosphere's tables (docs/PERFORMANCE.md): the host's fill (computeAtmosphereLuts, TBB over
// texels) against the Vulkan device's (atmosphere_tables.comp, lavapipe on a CPU-only machine),
// interleaved in one loop so a shared machine's load falls on both alike, at the default scene,
// the sun alternating between two elevations as a time-of-day slider would move it.
#include <cloudscape/backend.h>
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "vulkan/vulkan_device.h"

#include <benchmark/benchmark.h>

#include <chrono>

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const cloudscape::SceneResources& resources() {
    static const cloudscape::SceneResources r = [] {
        cloudscape::SceneResources res;
        res.noise = cloudscape::generateNoiseTextures(1);
        res.weather = cloudscape::prepareWeather(cloudscape::Scene{});
        return res;
    }();
    return r;
}

cloudscape::vulkan::VulkanDevice openDevice() {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Vulkan;
    return {o, resources()};
}

cloudscape::model::SkyParams sky(int i) {
    cloudscape::Scene s;
    s.sunElevationDeg = i % 2 == 0 ? 35.0f : 4.0f;
    return cloudscape::makeSkyParams(s);
}

// Per iteration: a host fill, then a device fill of the same sky and its read-back, on one
// device kept open (a live Renderer's remake).
void BM_HostThenDevice(benchmark::State& state) {
    cloudscape::vulkan::VulkanDevice device(openDevice());
    cloudscape::vulkan::AtmosphereTables& tables = device.atmosphereTables();
    tables.fill(sky(1)); // the pipeline's first use (lavapipe compiles variants then)
    double host = 0.0, wall = 0.0, gpu = 0.0, readback = 0.0;
    int n = 0;
    for (auto _ : state) {
        const cloudscape::model::SkyParams s = sky(n);
        Clock::time_point start = Clock::now();
        benchmark::DoNotOptimize(cloudscape::computeAtmosphereLuts(s).data());
        host += msSince(start);
        start = Clock::now();
        tables.fill(s);
        const double filled = msSince(start);
        benchmark::DoNotOptimize(tables.texels().data());
        wall += msSince(start);
        readback += msSince(start) - filled;
        gpu += tables.gpuMs();
        ++n;
    }
    state.counters["host_ms"] = host / n;
    state.counters["device_wall_ms"] = wall / n;
    state.counters["device_gpu_ms"] = gpu / n;
    state.counters["readback_ms"] = readback / n;
    for (int t = 0; t < cloudscape::model::ATMOSPHERE_TABLE_COUNT; ++t)
        state.counters["gpu_table" + std::to_string(t) + "_ms"] = tables.tableMs()[t];
}

// A device's first fill: the pipeline's creation and first dispatches (a Renderer's start-up),
// against a host fill just before it.
void BM_FirstDeviceFill(benchmark::State& state) {
    double host = 0.0, first = 0.0, gpu = 0.0;
    int n = 0;
    for (auto _ : state) {
        state.PauseTiming();
        cloudscape::vulkan::VulkanDevice device(openDevice());
        state.ResumeTiming();
        Clock::time_point start = Clock::now();
        benchmark::DoNotOptimize(cloudscape::computeAtmosphereLuts(sky(0)).data());
        host += msSince(start);
        start = Clock::now();
        device.atmosphereTables().fill(sky(0));
        benchmark::DoNotOptimize(device.atmosphereTables().texels().data());
        first += msSince(start);
        gpu += device.atmosphereTables().gpuMs();
        ++n;
    }
    state.counters["host_ms"] = host / n;
    state.counters["first_device_wall_ms"] = first / n;
    state.counters["first_device_gpu_ms"] = gpu / n;
}

} // namespace

BENCHMARK(BM_HostThenDevice)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();
BENCHMARK(BM_FirstDeviceFill)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK_MAIN();
