// The default scene at 1280x720 on the CPU backend and on the Vulkan backend (lavapipe on a
// CPU-only machine), in one run so the ratio compares like with like.
#include <cloudscape/backend.h>
#include <cloudscape/scene.h>

#include <benchmark/benchmark.h>

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

} // namespace

BENCHMARK(BM_Default720_Cpu)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_Default720_Vulkan)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK_MAIN();
