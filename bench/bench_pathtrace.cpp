// Speed of the path tracer: paths per second and scattering events per path on presets (CPU,
// all cores, 96x54, one sample per pixel per iteration). Reported as counters; the noise that a
// given time buys is in docs/QUALITY.md.
#include <cloudscape/pathtrace.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace {

cloudscape::Scene presetScene(const std::string& name) {
    cloudscape::Scene s = cloudscape::loadScene(cloudscape::resolveScenePath(name));
    s.width = 96;
    s.height = 54;
    s.phaseFunction = cloudscape::PhaseFunctionKind::HgDraine;
    return s;
}

const cloudscape::SceneResources& resourcesFor(const std::string& name) {
    static std::map<std::string, cloudscape::SceneResources> cache;
    auto it = cache.find(name);
    if (it == cache.end())
        it = cache.emplace(name, cloudscape::prepareResources(presetScene(name))).first;
    return it->second;
}

void pathTracePreset(benchmark::State& state, const std::string& name) {
    const cloudscape::Scene scene = presetScene(name);
    const cloudscape::SceneResources& resources = resourcesFor(name);
    uint64_t paths = 0;
    uint64_t collisions = 0;
    for (auto _ : state) {
        cloudscape::PathTraceImage image;
        const cloudscape::PathTraceStats s = cloudscape::pathTrace(scene, resources, image, 1);
        paths += s.paths;
        collisions += s.collisions;
    }
    state.counters["paths_per_s"] =
        benchmark::Counter(static_cast<double>(paths), benchmark::Counter::kIsRate);
    state.counters["events_per_path"] =
        paths ? static_cast<double>(collisions) / static_cast<double>(paths) : 0.0;
}

} // namespace

BENCHMARK_CAPTURE(pathTracePreset, fair_weather, std::string("fair-weather-cumulus"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(pathTracePreset, overcast, std::string("overcast-stratus"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(pathTracePreset, inside_cloud, std::string("inside-cloud"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
