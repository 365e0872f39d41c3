// The record of what made each pixel of a temporal frame (Renderer::temporalDebug, the viewer's
// temporal-source and samples views): its sources agree with the frame's own breakdown, its
// sample counts add up to the frame's density samples, the code packing is exact, and a still
// has none.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/temporal.h>

#include "model/interface.glsl.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

using namespace cloudscape;

namespace {

SceneResources smallResources(const Scene& s) {
    SceneResources r;
    r.noise.base = generateBaseNoise(1, 32);
    r.noise.detail = generateDetailNoise(1, 16);
    r.noise.curl = generateCurlNoise(1, 32);
    r.weather = prepareWeather(s);
    return r;
}

BackendOptions onCpu() {
    BackendOptions o;
    o.choice = BackendChoice::Cpu;
    return o;
}

} // namespace

TEST(TemporalDebug, TheCodeHoldsASourceAndASampleCountExactly) {
    for (int source : {0, 1, 2, 3})
        for (float samples : {0.0f, 1.0f, 31.0f, 4097.0f, 1048575.0f}) {
            const float code = model::texelDebugCode(source, samples);
            EXPECT_EQ(model::texelDebugSource(code), source) << samples;
            EXPECT_EQ(model::texelDebugSamples(code), samples) << source;
        }
}

TEST(TemporalDebug, SourcesAndSamplesAgreeWithTheFramesOwnFigures) {
    Scene s;
    s.width = 48; // 12 x 7 whole 4x4 blocks
    s.height = 28;
    s.cameraPitchDeg = 20.0f;
    s.weatherResolution = 64;
    s.movingBlock2x2 = true; // the pan marches a quarter of the pixels
    Renderer renderer(s, smallResources(s), onCpu());
    for (int f = 0; f < 20; ++f) {
        Scene frame = s;
        frame.cameraHeadingDeg = f < 12 ? 0.0f : 0.5f * float(f - 11); // still, then a slow pan
        const RenderResult r = renderer.renderFrame(frame, f);
        const TemporalDebugImage image = renderer.temporalDebug();
        ASSERT_EQ(image.width, s.width);
        ASSERT_EQ(image.height, s.height);
        ASSERT_EQ(image.source.size(), size_t(s.width) * s.height);
        size_t counts[3] = {0, 0, 0};
        for (TemporalSource source : image.source)
            ++counts[static_cast<int>(source)];
        const double pixels = double(image.source.size());
        const TemporalRenderer::Breakdown b = renderer.lastBreakdown();
        EXPECT_DOUBLE_EQ(counts[0] / pixels, b.marched) << "frame " << f;
        EXPECT_DOUBLE_EQ(counts[1] / pixels, b.reprojected) << "frame " << f;
        EXPECT_DOUBLE_EQ(counts[2] / pixels, b.fallback) << "frame " << f;
        // Still frames march one pixel of each 4x4 block, the pan's one of each 2x2
        // (render.moving_block_2x2); every pixel carries its block's march, so the record holds
        // a block's worth of copies of each march's count.
        const double blockPixels = f < 12 ? 16.0 : 4.0;
        EXPECT_EQ(counts[0], pixels / blockPixels) << "one pixel a block marched, frame " << f;
        const double total = std::accumulate(image.samples.begin(), image.samples.end(), 0.0);
        EXPECT_EQ(total, blockPixels * double(r.stats.densitySamples)) << "frame " << f;
        if (f == 0) {
            EXPECT_EQ(counts[2], pixels - pixels / 16) << "no history yet: all fallback";
        }
        if (f == 15) {
            EXPECT_EQ(counts[1], pixels - pixels / blockPixels) << "a slow pan after a still view";
        }
    }
    renderer.render(s);
    EXPECT_TRUE(renderer.temporalDebug().empty()) << "a still has no temporal record";
}
