// The CPU backend's results do not depend on how many threads TBB runs them on: stills, temporal
// sequences and the path tracer, each on one thread and on three (more than this machine's two
// cores, so tiles are interleaved differently), must be the same bits.
#include <cloudscape/noise.h>
#include <cloudscape/pathtrace.h>
#include <cloudscape/renderer.h>
#include <cloudscape/temporal.h>

#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

namespace {

const cloudscape::SceneResources& resources() {
    static const cloudscape::SceneResources r = [] {
        cloudscape::SceneResources res;
        res.noise.base = cloudscape::generateBaseNoise(1, 32);
        res.noise.detail = cloudscape::generateDetailNoise(1, 16);
        res.noise.curl = cloudscape::generateCurlNoise(1, 32);
        cloudscape::Scene s;
        s.weatherResolution = 64;
        res.weather = cloudscape::prepareWeather(s);
        return res;
    }();
    return r;
}

cloudscape::Scene smallScene() {
    cloudscape::Scene s;
    s.width = 56;
    s.height = 32;
    s.cameraPitchDeg = 20.0f;
    s.samplesPerPixel = 2;
    return s;
}

template <class F> auto onThreads(int threads, F f) {
    tbb::task_arena arena(threads);
    return arena.execute(f);
}

// Everything a frame holds, as one vector to compare.
std::vector<float> contents(const cloudscape::RenderResult& r) {
    std::vector<float> v = r.cloud;
    v.insert(v.end(), r.depth.begin(), r.depth.end());
    v.insert(v.end(), r.composite.begin(), r.composite.end());
    v.push_back(static_cast<float>(r.stats.densitySamples));
    v.push_back(static_cast<float>(r.stats.lightSamples));
    return v;
}

} // namespace

TEST(Determinism, SameBitsOnOneThreadAndOnThree) {
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 3);
    const cloudscape::Scene scene = smallScene();
    EXPECT_EQ(onThreads(1, [&] { return contents(cloudscape::renderCpu(scene, resources())); }),
              onThreads(3, [&] { return contents(cloudscape::renderCpu(scene, resources())); }));

    // A moving sequence: the camera turns and the wind blows.
    auto sequence = [&] {
        cloudscape::TemporalRenderer temporal(resources());
        std::vector<float> all;
        for (int f = 0; f < 20; ++f) {
            cloudscape::Scene s = scene;
            s.cameraHeadingDeg += 0.5f * f;
            s.timeS = f * 0.5f;
            const std::vector<float> c = contents(temporal.renderFrame(s, f));
            all.insert(all.end(), c.begin(), c.end());
        }
        return all;
    };
    EXPECT_EQ(onThreads(1, sequence), onThreads(3, sequence));

    auto traced = [&] {
        cloudscape::Scene s = scene;
        s.width = 24;
        s.height = 16;
        cloudscape::PathTraceImage image;
        cloudscape::pathTrace(s, resources(), image, 2);
        return image.mean;
    };
    EXPECT_EQ(onThreads(1, traced), onThreads(3, traced));
}
