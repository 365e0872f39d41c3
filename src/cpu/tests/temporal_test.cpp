// Temporal reconstruction: convergence, reprojection accuracy and history rejection.
#include <cloudscape/metrics.h>
#include <cloudscape/temporal.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "model/temporal.glsl.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

const cloudscape::SceneResources& smallResources() {
    static const cloudscape::SceneResources r = [] {
        cloudscape::SceneResources res;
        res.noise.base = cloudscape::generateBaseNoise(1, 32);
        res.noise.detail = cloudscape::generateDetailNoise(1, 16);
        res.noise.curl = cloudscape::generateCurlNoise(1, 32);
        Scene s;
        s.weatherResolution = 64;
        res.weather = cloudscape::prepareWeather(s);
        return res;
    }();
    return r;
}

Scene smallScene() {
    Scene s;
    s.width = 48;
    s.height = 28;
    s.cameraPitchDeg = 25.0f;
    return s;
}

// A low view over generated hills (64x36): the terrain and the horizon fill most of the frame.
Scene lowViewOverHills(cloudscape::SceneResources& resources) {
    Scene scene = smallScene();
    scene.width = 64;
    scene.height = 36;
    scene.cameraPitchDeg = -4.0f;
    scene.cameraPosition.y = 600.0f;
    scene.terrainEnabled = true;
    scene.terrainExtentM = 20000.0f;
    scene.terrainHeightM = 300.0f;
    scene.terrainResolution = 128;
    resources = smallResources();
    cloudscape::prepareTerrain(scene, resources);
    return scene;
}

// The mean error of a frame's cloud layer against a full render of `scene` at `samples` samples
// a pixel.
double cloudErrorToFullRender(const cloudscape::RenderResult& frame, Scene scene, int samples) {
    scene.samplesPerPixel = samples;
    const cloudscape::RenderResult full = cloudscape::renderCpu(scene, smallResources());
    return cloudscape::compareImages(full.cloud, frame.cloud, 4).meanError;
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        m = std::max(m, static_cast<double>(std::abs(a[i] - b[i])));
    return m;
}

} // namespace

TEST(Temporal, BlockOrderVisitsEveryPixelOnceIn16Frames) {
    std::set<std::pair<int, int>> seen;
    for (int f = 0; f < 16; ++f) {
        const glm::ivec2 o = cm::blockOffsetForFrame(f, cm::TEMPORAL_BLOCK);
        EXPECT_TRUE(seen.insert({o.x, o.y}).second) << "frame " << f;
    }
    EXPECT_EQ(seen.size(), 16u);
    EXPECT_EQ(cm::blockOffsetForFrame(16, 4), cm::blockOffsetForFrame(0, 4));
}

// A translating camera's 2x2 blocks: every pixel of a block in any 4 consecutive frames, whatever
// frame the flight starts at.
TEST(Temporal, MovingBlockOrderVisitsEveryPixelInAny4Frames) {
    for (int start = 0; start < 16; ++start) {
        std::set<std::pair<int, int>> seen;
        for (int f = start; f < start + 4; ++f) {
            const glm::ivec2 o = cm::blockOffsetForFrame(f, cm::TEMPORAL_SMALL_BLOCK);
            EXPECT_TRUE(seen.insert({o.x, o.y}).second) << "frame " << f;
        }
        EXPECT_EQ(seen.size(), 4u) << "from frame " << start;
    }
}

TEST(Temporal, StillCameraConvergesToTheFullImageIn16Frames) {
    const Scene scene = smallScene();
    const cloudscape::RenderResult full = cloudscape::renderCpu(scene, smallResources());
    cloudscape::TemporalRenderer temporal(smallResources());
    cloudscape::RenderResult r;
    for (int f = 0; f < 16; ++f) {
        r = temporal.renderFrame(scene, f);
        if (f == 7) {
            EXPECT_GT(maxDifference(r.cloud, full.cloud), 0.05) << "half way it must differ";
        }
        // Every frame marches 1/16 of the pixels.
        EXPECT_EQ(r.stats.rays, static_cast<uint64_t>(12 * 7));
    }
    // Bound: each pixel was marched once, with the jitter the full-resolution render uses, and
    // a still camera reprojects every pixel onto itself up to the float round trip through
    // ray and projection (~1e-4 px of bilinear blur), so the images agree to 1e-3.
    EXPECT_LT(maxDifference(r.cloud, full.cloud), 1e-3);
    EXPECT_LT(maxDifference(r.composite, full.composite), 1e-3);
    const auto b = temporal.lastBreakdown();
    EXPECT_NEAR(b.marched, 1.0 / 16.0, 0.01);
    EXPECT_NEAR(b.reprojected, 15.0 / 16.0, 0.01);
}

TEST(Temporal, ReprojectionOfAStaticCloudLandsWithinAPixel) {
    Scene a = smallScene();
    a.width = 640;
    a.height = 360;
    Scene b = a;
    b.cameraPosition = a.cameraPosition + glm::vec3(120.0f, 15.0f, -60.0f);
    b.cameraHeadingDeg = a.cameraHeadingDeg + 3.0f;
    b.cameraPitchDeg = a.cameraPitchDeg - 1.5f;
    a.windSpeedMps = 0.0f;
    const cm::FrameParams previous = cloudscape::makeFrameParams(a);
    const cm::FrameParams current = cloudscape::makeFrameParams(b);
    const cm::CloudParams cloud = cloudscape::makeCloudParams(a, 0.0f); // no weather read
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.1f, 0.9f);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        // A cloud point seen by the current camera at 2-20 km.
        const float px = u(rng) * 640.0f, py = u(rng) * 360.0f;
        const glm::vec3 dir = cm::cameraRayDirection(current, px, py);
        const float depth = 2000.0f + 18000.0f * u(rng);
        const glm::vec3 world = b.cameraPosition + dir * depth;
        bool visible = false;
        const glm::vec2 expected = cm::projectToPixel(previous, world, visible);
        if (!visible)
            continue;
        bool visible2 = false;
        const glm::vec2 got =
            cm::reprojectPixel(current, previous, cloud, px, py, depth, 0.0f, visible2);
        EXPECT_TRUE(visible2);
        EXPECT_LT(glm::length(got - expected), 0.05f) << i;
        // Round trip: the current camera sees the point where the ray came from.
        const glm::vec2 back = cm::projectToPixel(current, world, visible);
        EXPECT_LT(glm::length(back - glm::vec2(px, py)), 0.05f);
        ++checked;
    }
    EXPECT_GT(checked, 150);
}

TEST(Temporal, WindMotionIsFollowed) {
    Scene s = smallScene();
    s.width = 640;
    s.height = 360;
    const cm::FrameParams f = cloudscape::makeFrameParams(s);
    const cm::CloudParams cloud = cloudscape::makeCloudParams(s, 0.0f); // 10 m/s toward east
    const glm::vec3 dir = cm::cameraRayDirection(f, 320.0f, 100.0f);
    const glm::vec3 world = s.cameraPosition + dir * 5000.0f;
    bool visible = false;
    // One second ago the cloud now at `world` was 10 m further west.
    const glm::vec2 expected = cm::projectToPixel(f, world - cm::cloudMotion(cloud, 1.0f), visible);
    const glm::vec2 got = cm::reprojectPixel(f, f, cloud, 320.0f, 100.0f, 5000.0f, 1.0f, visible);
    EXPECT_LT(glm::length(got - expected), 0.01f);
    EXPECT_GT(glm::length(got - glm::vec2(320.0f, 100.0f)), 0.5f) << "the motion must show";
}

TEST(Temporal, InvalidHistoryIsDetected) {
    Scene scene = smallScene();
    cloudscape::TemporalRenderer temporal(smallResources());
    for (int f = 0; f < 16; ++f)
        temporal.renderFrame(scene, f);
    // Turning around: nothing of the previous view is on screen, so nothing is reprojected.
    scene.cameraHeadingDeg += 180.0f;
    temporal.renderFrame(scene, 16);
    EXPECT_NEAR(temporal.lastBreakdown().fallback, 15.0 / 16.0, 0.01);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9);
    // Pixels filled by the fallback are not history: until each is marched they fall back
    // again. After a full cycle a small pan keeps most of the history.
    temporal.renderFrame(scene, 17);
    EXPECT_GT(temporal.lastBreakdown().fallback, 0.8);
    for (int f = 18; f < 34; ++f)
        temporal.renderFrame(scene, f);
    scene.cameraHeadingDeg += 2.0f;
    temporal.renderFrame(scene, 34);
    EXPECT_GT(temporal.lastBreakdown().reprojected, 0.8);
    // A skipped frame index breaks the sequence: no history is used.
    temporal.renderFrame(scene, 40);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9);
}

// With render.moving_block_2x2 a moving camera marches a quarter of the pixels: turning around
// falls back everywhere else, the next still frame marches 1/16 again and keeps as history only
// what was marched (a fallback-filled pixel is not history), and a skipped frame index is still a
// broken sequence.
TEST(Temporal, AMovingCameraMarchesAQuarterOfThePixels) {
    Scene scene = smallScene();
    EXPECT_FALSE(scene.movingBlock2x2) << "off by default";
    scene.movingBlock2x2 = true;
    cloudscape::TemporalRenderer temporal(smallResources());
    for (int f = 0; f < 16; ++f)
        temporal.renderFrame(scene, f);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 1.0 / 16.0, 0.01) << "a still camera";
    scene.cameraHeadingDeg += 180.0f;
    temporal.renderFrame(scene, 16);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 0.25, 0.01);
    EXPECT_NEAR(temporal.lastBreakdown().fallback, 0.75, 0.01);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9);
    temporal.renderFrame(scene, 17);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 1.0 / 16.0, 0.01);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.25 - 1.0 / 16.0, 0.01)
        << "frame 17's 4x4 pixel lies in frame 16's 2x2 quadrant";
    scene.cameraPosition.x += 50.0f; // flying
    temporal.renderFrame(scene, 18);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 0.25, 0.01);
    scene.cameraPosition.x += 50.0f;
    temporal.renderFrame(scene, 20);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9) << "a broken sequence";
    EXPECT_NEAR(temporal.lastBreakdown().marched, 1.0 / 16.0, 0.01) << "no history to move";
}

TEST(Temporal, APanKeepsItsHistory) {
    // Panning by fractions of a pixel a frame: the history moves by fractions of a pixel while the
    // accumulated-march count is read from the nearest pixel, a whole pixel at a time. Pixels
    // that were filled by the fallback must still be usable history for moving content, or
    // columns of fallback drift across the image and are never replaced (a quarter of the
    // pixels on the slow pan before issue 4's fix). Only the strip the pan reveals falls back.
    Scene scene = smallScene();
    cloudscape::TemporalRenderer temporal(smallResources());
    double fallback = 0.0;
    for (int f = 0; f < 32; ++f) {
        scene.cameraHeadingDeg += 1.0f;
        temporal.renderFrame(scene, f);
        if (f >= 16)
            fallback += temporal.lastBreakdown().fallback / 16.0;
    }
    EXPECT_LT(fallback, 0.08);
    EXPECT_GT(fallback, 0.0) << "the revealed strip has no history";
}

TEST(Temporal, AccumulationAveragesStepNoiseAway) {
    // A still camera: after 16 frames the image is one march per pixel; later cycles use new
    // jitter and are averaged in, so the image moves toward the many-sample reference.
    Scene scene = smallScene();
    Scene reference = scene;
    reference.samplesPerPixel = 16;
    const cloudscape::RenderResult ref = cloudscape::renderCpu(reference, smallResources());
    cloudscape::TemporalRenderer temporal(smallResources());
    auto error = [&](const cloudscape::RenderResult& r) {
        return cloudscape::compareImages(ref.cloud, r.cloud, 4).meanError;
    };
    double after16 = 0.0, after128 = 0.0;
    for (int f = 0; f < 128; ++f) {
        const cloudscape::RenderResult r = temporal.renderFrame(scene, f);
        if (f == 15)
            after16 = error(r);
        if (f == 127)
            after128 = error(r);
    }
    EXPECT_LT(after128, 0.7 * after16);
    // With accumulation 1 (replacement) there is no such gain.
    scene.temporalAccumulation = 1;
    cloudscape::TemporalRenderer replace(smallResources());
    cloudscape::RenderResult last;
    for (int f = 0; f < 128; ++f)
        last = replace.renderFrame(scene, f);
    EXPECT_GT(error(last), 0.8 * after16);
}

// render.moving_background_reduced: with reduced-resolution clouds, a moving camera's background
// (here terrain and sky) is the pass's brought up to the output; the first frame, a still
// camera's frames (the first after a move included) and full-resolution clouds keep the output's
// own background, bit for bit; the clouds themselves never change with it.
TEST(Temporal, AMovingCamerasBackgroundComesFromTheReducedPass) {
    cloudscape::SceneResources resources;
    Scene scene = lowViewOverHills(resources);
    for (float resolution : {0.5f, 1.0f}) {
        scene.cloudResolution = resolution;
        Scene off = scene;
        Scene on = scene;
        on.movingBackgroundReduced = true;
        cloudscape::TemporalRenderer a(resources), b(resources);
        auto frame = [&](int f, bool moving) {
            const cloudscape::RenderResult x = a.renderFrame(off, f);
            const cloudscape::RenderResult y = b.renderFrame(on, f);
            EXPECT_EQ(x.cloud, y.cloud) << "frame " << f << ": the clouds are the same";
            if (!moving || resolution == 1.0f) {
                EXPECT_EQ(x.composite, y.composite) << "frame " << f << " at " << resolution;
                return;
            }
            const double psnr = cloudscape::compareImages(x.composite, y.composite, 4).psnr;
            std::printf("moving frame %d: %.1f dB against the full-size background\n", f, psnr);
            EXPECT_LT(psnr, 60.0) << "frame " << f << ": the background came from the pass";
            EXPECT_GT(psnr, 25.0) << "frame " << f << ": as an upsampled image differs";
        };
        frame(0, false);
        for (Scene* s : {&off, &on})
            s->cameraHeadingDeg += 3.0f;
        frame(1, true);
        for (Scene* s : {&off, &on})
            s->cameraPosition.z += 80.0f;
        frame(2, true);
        frame(3, false);
    }
}

// render.background_samples: the temporal frame's background (made apart from the clouds'
// marches) averages that many rays through each pixel, so the hills' edges and the horizon come
// out anti-aliased as a still's samples make them, instead of as seen through pixel centres.
TEST(Temporal, BackgroundSamplesAntiAliasTheTerrain) {
    cloudscape::SceneResources resources;
    Scene scene = lowViewOverHills(resources);
    scene.coverage = 0.0f; // no cumulus: what the frame shows is the background
    EXPECT_EQ(scene.backgroundSamples, 1) << "one ray a pixel by default";
    Scene reference = scene;
    reference.samplesPerPixel = 16;
    const cloudscape::RenderResult ref = cloudscape::renderCpu(reference, resources);
    auto errorWith = [&](int samples) {
        Scene s = scene;
        s.backgroundSamples = samples;
        cloudscape::TemporalRenderer temporal(resources);
        const cloudscape::RenderResult r = temporal.renderFrame(s, 0);
        return cloudscape::compareImages(ref.composite, r.composite, 4).meanError;
    };
    const double one = errorWith(1), four = errorWith(4);
    std::printf("background against 16 samples a pixel: mean error %.5f with one ray, %.5f with "
                "four\n",
                one, four);
    EXPECT_LT(four, 0.7 * one);
}

// render.still_block_2x2: a still camera marches a quarter of the pixels a frame, each march of a
// pixel through a new point of it with a new start offset (marchCycleFor: the jitter's index
// moves on every 4 frames), so after 16 frames most pixels average the marches of the jitter
// indices 0-3, which a full render with 4 samples a pixel averages too (the rest 1-3, having
// missed index 0 in frame 0's 4x4 block); with the jitter left per 16-frame cycle they would
// be index 0's march 4 times, the 1-sample render.
TEST(Temporal, AStillCamerasSmallBlockAveragesFourMarchesIn16Frames) {
    EXPECT_EQ(cm::marchCycleFor(27, cm::TEMPORAL_SMALL_BLOCK, false), 6);
    EXPECT_EQ(cm::marchCycleFor(27, cm::TEMPORAL_SMALL_BLOCK, true), 1) << "moving: per cycle";
    EXPECT_EQ(cm::marchCycleFor(27, cm::TEMPORAL_BLOCK, false), 1);
    Scene scene = smallScene();
    EXPECT_FALSE(scene.stillBlock2x2) << "off by default";
    scene.stillBlock2x2 = true;
    cloudscape::TemporalRenderer temporal(smallResources());
    cloudscape::RenderResult r;
    for (int f = 0; f < 16; ++f) {
        r = temporal.renderFrame(scene, f);
        if (f > 0) {
            EXPECT_NEAR(temporal.lastBreakdown().marched, 0.25, 0.01) << "frame " << f;
        }
    }
    const double toOne = cloudErrorToFullRender(r, scene, 1);
    const double toFour = cloudErrorToFullRender(r, scene, 4);
    std::printf("after 16 still frames in 2x2 blocks, mean error to a full render of 1 sample a "
                "pixel %.5f, of 4 %.5f\n",
                toOne, toFour);
    EXPECT_LT(toFour, 0.5 * toOne);
    // Only a still camera: a turning one keeps the 4x4 block unless moving_block_2x2 asks.
    scene.cameraHeadingDeg += 2.0f;
    temporal.renderFrame(scene, 16);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 1.0 / 16.0, 0.01);
}

// A camera that turns without translating while it marches the small block
// (render.moving_block_2x2) averages two marches a pixel (marchCountFor): its reprojection is
// exact and its history at most 4 frames old. Against the same pan with
// render.temporal_accumulation 1 (every march replaces its history, what a moving pixel always did)
// the pan's last frame is nearer a 16-sample render of its camera; a translating camera still
// replaces.
TEST(Temporal, ATurningCameraAveragesTwoMarches) {
    EXPECT_EQ(cm::TURNING_ACCUMULATION, 2);
    Scene scene = smallScene();
    scene.movingBlock2x2 = true;
    auto panError = [&](int accumulation) {
        Scene s = scene;
        s.temporalAccumulation = accumulation;
        cloudscape::TemporalRenderer temporal(smallResources());
        for (int f = 0; f < 24; ++f) {
            s.cameraHeadingDeg += 0.7f;
            temporal.renderFrame(s, f);
        }
        s.cameraHeadingDeg += 0.7f;
        return cloudErrorToFullRender(temporal.renderFrame(s, 24), s, 16);
    };
    const double replaced = panError(1), averaged = panError(8);
    std::printf("a pan's frame against 16 samples a pixel: marches replaced %.5f, two averaged "
                "%.5f\n",
                replaced, averaged);
    EXPECT_LT(averaged, 0.9 * replaced);
    // The rule itself: only a turn (or zoom) in small blocks, never a translation.
    cm::FrameParams previous = cloudscape::makeFrameParams(scene);
    cm::FrameParams turned = previous;
    turned.cameraForward = glm::normalize(turned.cameraForward + glm::vec3(0.01f, 0.0f, 0.0f));
    cm::FrameParams flown = previous;
    flown.cameraPosition.x += 10.0f;
    const int small = cm::TEMPORAL_SMALL_BLOCK, large = cm::TEMPORAL_BLOCK;
    EXPECT_EQ(cm::marchCountFor(true, false, 5.0f, small, turned, previous), 2.0f);
    EXPECT_EQ(cm::marchCountFor(true, false, 5.0f, large, turned, previous), 1.0f);
    EXPECT_EQ(cm::marchCountFor(true, false, 5.0f, small, flown, previous), 1.0f);
    EXPECT_EQ(cm::marchCountFor(false, false, 5.0f, small, turned, previous), 1.0f);
    EXPECT_EQ(cm::marchCountFor(true, true, 5.0f, small, previous, previous), 6.0f);
}
