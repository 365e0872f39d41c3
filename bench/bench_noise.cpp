// Time to generate each texture at its default size, on all cores.
#include <cloudscape/noise.h>
#include <cloudscape/weather.h>

#include <benchmark/benchmark.h>

namespace {

void BM_BaseNoise128(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::generateBaseNoise(1, 128));
}

void BM_DetailNoise32(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::generateDetailNoise(1, 32));
}

void BM_CurlNoise128(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::generateCurlNoise(1, 128));
}

void BM_WeatherMap512(benchmark::State& state) {
    cloudscape::WeatherParams p;
    p.rainCells = 4;
    for (auto _ : state)
        benchmark::DoNotOptimize(cloudscape::generateWeatherMap(p));
}

} // namespace

BENCHMARK(BM_BaseNoise128)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_DetailNoise32)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();
BENCHMARK(BM_CurlNoise128)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();
BENCHMARK(BM_WeatherMap512)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();
BENCHMARK_MAIN();
