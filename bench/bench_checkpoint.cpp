// What a sequence checkpoint costs (`render --frames`, every --checkpoint-every frames): writing
// and reading the temporal state of the default scene after 17 frames of a slow pan, beside one
// CPU temporal frame and the frame's own PNG write at the same size, for scale. Counters: the
// file's size, in MB and in bytes per history pixel. Figures in docs/PERFORMANCE.md.
#include <cloudscape/camera_path.h>
#include <cloudscape/image_io.h>
#include <cloudscape/scene.h>
#include <cloudscape/sequence_checkpoint.h>
#include <cloudscape/temporal.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <utility>

namespace {

namespace fs = std::filesystem;

const cloudscape::SceneResources& resources() {
    static const cloudscape::SceneResources r = cloudscape::prepareResources(cloudscape::Scene{});
    return r;
}

cloudscape::Scene sceneOfSize(int width, int height) {
    cloudscape::Scene s;
    s.width = width;
    s.height = height;
    return s;
}

// A renderer 17 frames into a slow pan, per size (the history is established and accumulating).
cloudscape::TemporalRenderer& rendererAt(int width, int height) {
    static std::map<std::pair<int, int>, std::unique_ptr<cloudscape::TemporalRenderer>> cache;
    auto& slot = cache[{width, height}];
    if (!slot) {
        slot = std::make_unique<cloudscape::TemporalRenderer>(resources());
        for (int f = 0; f <= 16; ++f)
            slot->renderFrame(
                cloudscape::sceneOnPath(sceneOfSize(width, height), "slow-pan", f, 24.0f), f);
    }
    return *slot;
}

std::string checkpointPath() {
    return (fs::temp_directory_path() / "cloudscape_bench_checkpoint.exr").string();
}

void BM_TemporalFrame(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    cloudscape::TemporalRenderer& renderer = rendererAt(w, h);
    const cloudscape::TemporalState start = renderer.saveState();
    for (auto _ : state) {
        renderer.restoreState(start); // every iteration renders the same frame 17
        benchmark::DoNotOptimize(renderer.renderFrame(
            cloudscape::sceneOnPath(sceneOfSize(w, h), "slow-pan", 17, 24.0f), 17));
    }
    renderer.restoreState(start); // the other benchmarks checkpoint the state after frame 16
}

void BM_WriteFramePng(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    cloudscape::TemporalRenderer& renderer = rendererAt(w, h);
    const cloudscape::TemporalState start = renderer.saveState();
    const cloudscape::RenderResult frame =
        renderer.renderFrame(cloudscape::sceneOnPath(sceneOfSize(w, h), "slow-pan", 17, 24.0f), 17);
    renderer.restoreState(start);
    const std::string path = (fs::temp_directory_path() / "cloudscape_bench_frame.png").string();
    for (auto _ : state)
        cloudscape::writePng(path, w, h, cloudscape::toneMapToSrgb8(frame, 1.0f));
    state.counters["MB"] = static_cast<double>(fs::file_size(path)) / 1048576.0;
    fs::remove(path);
}

void BM_WriteCheckpoint(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    const cloudscape::SequenceCheckpoint checkpoint{"bench", rendererAt(w, h).saveState()};
    for (auto _ : state)
        cloudscape::writeSequenceCheckpoint(checkpointPath(), checkpoint);
    const double bytes = static_cast<double>(fs::file_size(checkpointPath()));
    state.counters["MB"] = bytes / 1048576.0;
    state.counters["bytes_per_px"] = bytes / (static_cast<double>(w) * h);
    fs::remove(checkpointPath());
}

void BM_ReadAndRestoreCheckpoint(benchmark::State& state) {
    const int w = static_cast<int>(state.range(0)), h = static_cast<int>(state.range(1));
    cloudscape::writeSequenceCheckpoint(checkpointPath(), {"bench", rendererAt(w, h).saveState()});
    cloudscape::TemporalRenderer fresh(resources());
    for (auto _ : state)
        fresh.restoreState(cloudscape::readSequenceCheckpoint(checkpointPath()).state);
    fs::remove(checkpointPath());
}

void sizes(benchmark::internal::Benchmark* b) {
    b->Args({640, 360})->Args({960, 540})->Args({1920, 1080});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

BENCHMARK(BM_TemporalFrame)->Apply(sizes);
BENCHMARK(BM_WriteFramePng)->Apply(sizes);
BENCHMARK(BM_WriteCheckpoint)->Apply(sizes);
BENCHMARK(BM_ReadAndRestoreCheckpoint)->Apply(sizes);

BENCHMARK_MAIN();
