// GPU category: `cloudscape view --script` in a real window under Xvfb (xvfb-run) on the Vulkan
// device (lavapipe in CI) with the validation layers on. A converged screenshot matches
// `cloudscape render` of the same scene and camera, a scripted key change changes it, and the
// saved scene renders the same image again.
#include "cli_test_support.h"

#include <cloudscape/camera_path.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>

#include "model/debug_view.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

using namespace cloudscape::clitest;

namespace {

const std::string kXvfb = "xvfb-run -a -s '-screen 0 640x480x24'";
const std::string kScene = "--width 64 --height 36 --set camera.pitch_deg=20 "
                           "--set wind.speed_mps=0 --set atmosphere.aerial_perspective=false ";
// The view's converged temporal path reproduces the one-sample march; a still's default is 4
// samples (issue 15), so the stills compared with it name one.
const std::string kOneSample = "--set render.samples_per_pixel=1 ";

std::vector<float> compositeRgb(const Layers& l) {
    std::vector<float> v;
    for (size_t i = 0; i < l.size(); ++i)
        v.insert(v.end(), {l.r[i], l.g[i], l.b[i]});
    return v;
}

double psnr(const Layers& a, const Layers& b) {
    return cloudscape::compareImages(compositeRgb(a), compositeRgb(b), 3, {}).psnr;
}

} // namespace

TEST(ViewVulkan, ScriptedScreenshotsMatchRenderAndFollowKeys) {
    TempDir dir;
    std::ofstream(dir.file("s.txt")) << "# converge, shoot, save, change the coverage, shoot\n"
                                     << "wait 20\n"
                                     << "screenshot " << dir.file("view.exr") << "\n"
                                     << "screenshot " << dir.file("view.png") << "\n"
                                     << "capture " << dir.file("window.png") << "\n"
                                     << "save " << dir.file("saved.json") << "\n"
                                     << "set weather.coverage 0.8\n"
                                     << "wait 20\n"
                                     << "screenshot " << dir.file("covered.exr") << "\n"
                                     << "quit\n";
    const RunResult view =
        run("view --vulkan-validation --stats " + kScene + "--script " + dir.file("s.txt"), kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;
    EXPECT_NE(view.out.find("frames at 64x36"), std::string::npos) << view.out;
    // Both rates: with the first frame's set-up, and after it (40-odd frames presented).
    const size_t rates = view.out.find("fps in the window (");
    ASSERT_NE(rates, std::string::npos) << view.out;
    double all = 0.0, afterFirst = 0.0;
    ASSERT_EQ(std::sscanf(view.out.c_str() + rates, "fps in the window (%lf after the first frame",
                          &afterFirst),
              1)
        << view.out;
    const size_t allRate = view.out.rfind(", ", rates);
    ASSERT_NE(allRate, std::string::npos) << view.out;
    ASSERT_EQ(std::sscanf(view.out.c_str() + allRate, ", %lf fps in the window", &all), 1)
        << view.out;
    EXPECT_GT(all, 0.0);
    EXPECT_GT(afterFirst, 0.0);
    std::printf("%s", view.out.c_str());

    const RunResult still = run("render --backend vulkan --device 0 " + kScene + kOneSample +
                                "-o " + dir.file("still.exr"));
    ASSERT_EQ(still.status, 0) << still.err;
    const Layers rendered = readLayers(dir.file("still.exr"));
    const Layers shot = readLayers(dir.file("view.exr"));
    ASSERT_EQ(shot.width, 64);
    ASSERT_EQ(shot.height, 36);
    expectConsistentLayers(shot, "view screenshot", false);
    const double converged = psnr(rendered, shot);
    std::printf("converged view screenshot vs render: %.1f dB\n", converged);
    EXPECT_GT(converged, 35.0);
    // What the window shows of that frame (drawn on the device from the renderer's buffer,
    // through the same tone curve compiled as GLSL) is its PNG screenshot (tone-mapped on the
    // host), to a step of rounding: the window is the image's size, a window pixel an image one.
    int width = 0, height = 0, channels = 0;
    const auto png = cloudscape::readPng(dir.file("view.png"), width, height, channels);
    EXPECT_EQ(width, 64);
    int cw = 0, ch = 0, cc = 0;
    const auto window = cloudscape::readPng(dir.file("window.png"), cw, ch, cc);
    ASSERT_EQ(cw, width);
    ASSERT_EQ(ch, height);
    ASSERT_EQ(cc, channels);
    int worst = 0;
    for (size_t i = 0; i < png.size(); ++i)
        worst = std::max(worst, std::abs(int(png[i]) - int(window[i])));
    EXPECT_LE(worst, 2) << "the window's pixels against the screenshot";

    const Layers covered = readLayers(dir.file("covered.exr"));
    const double changed = psnr(shot, covered);
    std::printf("after set weather.coverage 0.8: %.1f dB from before\n", changed);
    EXPECT_LT(changed, 25.0) << "more coverage, other clouds";
    const RunResult renderedCovered =
        run("render --backend vulkan --device 0 " + kScene + kOneSample +
            "--set weather.coverage=0.8 -o " + dir.file("still_covered.exr"));
    ASSERT_EQ(renderedCovered.status, 0) << renderedCovered.err;
    EXPECT_GT(psnr(readLayers(dir.file("still_covered.exr")), covered), 35.0);

    // The saved scene (the keys that differ from the defaults) renders the same image.
    const RunResult reloaded = run("render --backend vulkan --device 0 " + dir.file("saved.json") +
                                   " " + kOneSample + "-o " + dir.file("reloaded.exr"));
    ASSERT_EQ(reloaded.status, 0) << reloaded.err;
    EXPECT_EQ(readBytes(dir.file("reloaded.exr")), readBytes(dir.file("still.exr")));
}

TEST(ViewVulkan, WindowEndsWithTheScriptAndAMovedCameraRenders) {
    TempDir dir;
    std::ofstream(dir.file("s.txt"))
        << "wait 3\nmove 0 50 100\nturn 20 5\nwait 3\n"
        << "camera 0 10 0 45 15\nscreenshot " << dir.file("moved.exr") << "\n"
        << "save " << dir.file("moved.json") << "\n";
    const RunResult view =
        run("view --vulkan-validation " + kScene + "--script " + dir.file("s.txt"), kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;
    expectConsistentLayers(readLayers(dir.file("moved.exr")), "moved camera", false);
    // 10 m up is inside the default landscape's hills: the viewer keeps the camera over them
    // (where `render` refuses it), at the same x and z, and saves a scene `render` accepts.
    const cloudscape::Scene moved = cloudscape::loadScene(dir.file("moved.json"));
    EXPECT_GT(moved.cameraPosition.y, 10.0f);
    EXPECT_NEAR(moved.cameraPosition.x, 0.0f, 0.01f);
    EXPECT_NEAR(moved.cameraPosition.z, 0.0f, 0.01f);
    const RunResult rendered = run("render --backend cpu --width 16 --height 16 " +
                                   dir.file("moved.json") + " -o " + dir.file("moved.png"));
    EXPECT_EQ(rendered.status, 0) << rendered.err;
}

// One session for the camera tools and hot reload (a window's start-up is the costly part):
// orbit, a recording played back and saved as keyframes, a `render --camera-path` path, and the
// scene file rewritten on disk while the window runs (by a shell loop that waits for the
// viewer's first screenshot), which the window picks up and renders as `render` does.
TEST(ViewVulkan, CameraToolsAndHotReload) {
    TempDir dir;
    const std::string sceneFile = dir.file("scene.json");
    std::ofstream(sceneFile) << R"({"weather": {"coverage": 0.35}})";
    std::ofstream(dir.file("changed.json"))
        << R"({"weather": {"coverage": 0.8, "type": 0.6}, "sun": {"elevation_deg": 25}})";
    std::ofstream(dir.file("s.txt"))
        << "wait 1\norbit 1000 180 0\nsave " << dir.file("orbited.json") << "\n"
        << "record on\nwait 1\nmove 0 0 100\nwait 1\nturn 10 0\nwait 1\nrecord off\n"
        << "save " << dir.file("recorded.json") << "\n"
        << "camera 0 10 0 45 15\nplay\nsave " << dir.file("played.json") << "\n"
        << "save-path " << dir.file("camera.json") << "\n"
        << "path fly-forward 3\nsave " << dir.file("path.json") << "\n"
        << "save " << sceneFile << "\n" // the viewer's own save is no reload
        << "screenshot " << dir.file("before.png") << "\n"
        << "await-reload 120\nwait 20\nscreenshot " << dir.file("reloaded.exr") << "\n";
    // Once before.png exists, the scene file is replaced (a new size and time: a change).
    const std::string rewrite = "(for i in $(seq 1200); do [ -f " + dir.file("before.png") +
                                " ] && break; sleep 0.1; done; sleep 0.2; cp " +
                                dir.file("changed.json") + " " + sceneFile + ") & ";
    const RunResult view = run("view --vulkan-validation " + sceneFile + " " + kScene +
                                   "--script " + dir.file("s.txt"),
                               rewrite + kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;

    // Orbiting 180 deg around the point 1000 m ahead (pitch 20 deg) puts the camera 2 x 1000 x
    // cos(20 deg) further north, at the same height, looking back south.
    const cloudscape::Scene orbited = cloudscape::loadScene(dir.file("orbited.json"));
    EXPECT_NEAR(orbited.cameraPosition.x, 0.0f, 0.05f);
    EXPECT_NEAR(orbited.cameraPosition.y, 2.0f, 0.05f);
    EXPECT_NEAR(orbited.cameraPosition.z, 2000.0f * std::cos(20.0f * 3.14159265f / 180.0f), 0.05f);
    EXPECT_NEAR(orbited.cameraHeadingDeg, 180.0f, 1e-3f);

    // The recording played back ends where it ended; its keyframes follow each recorded frame.
    const cloudscape::Scene recorded = cloudscape::loadScene(dir.file("recorded.json"));
    const cloudscape::Scene played = cloudscape::loadScene(dir.file("played.json"));
    EXPECT_EQ(played.cameraPosition, recorded.cameraPosition);
    EXPECT_EQ(played.cameraHeadingDeg, recorded.cameraHeadingDeg);
    const cloudscape::Keyframes keys = cloudscape::loadKeyframes(dir.file("camera.json"), played);
    const cloudscape::Scene first = keys.sceneAt(played, 0.0);
    const cloudscape::Scene last = keys.sceneAt(played, 2.0 / 24.0);
    EXPECT_NEAR(first.cameraPosition.z, orbited.cameraPosition.z, 0.05f); // before the move
    EXPECT_NEAR(first.cameraHeadingDeg, 180.0f, 1e-3f);
    EXPECT_NEAR(last.cameraPosition.z, recorded.cameraPosition.z, 0.05f);
    EXPECT_NEAR(last.cameraHeadingDeg, recorded.cameraHeadingDeg, 1e-3f);

    // fly-forward: 40 m a frame along the level view direction.
    const cloudscape::Scene flown = cloudscape::loadScene(dir.file("path.json"));
    const cloudscape::Scene expected = cloudscape::sceneOnPath(played, "fly-forward", 3, 24.0f);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(flown.cameraPosition[i], expected.cameraPosition[i], 0.05f);

    // The reloaded scene is the changed file with the command line's --set on top: as render.
    const RunResult still = run("render --backend vulkan --device 0 " + dir.file("changed.json") +
                                " " + kScene + kOneSample + "-o " + dir.file("still.exr"));
    ASSERT_EQ(still.status, 0) << still.err;
    const double reloaded =
        psnr(readLayers(dir.file("still.exr")), readLayers(dir.file("reloaded.exr")));
    std::printf("hot-reloaded view vs render of the changed file: %.1f dB\n", reloaded);
    EXPECT_GT(reloaded, 35.0);
}

// A brush stroke on the weather map: the map changes inside the brush's circle only (the saved
// maps compared texel by texel), the window's clouds change, undo puts the map back exactly, and
// the painted map saved as a PNG, read through weather.image with the scene saved beside it,
// renders what the window showed.
TEST(ViewVulkan, PaintedStrokeChangesTheMapInsideTheBrushOnly) {
    TempDir dir;
    const float cx = 0.0f, cz = 6000.0f, radius = 3000.0f;
    std::ofstream(dir.file("s.txt"))
        << "wait 20\nsave-weather " << dir.file("w0.png") << "\nscreenshot " << dir.file("p0.exr")
        << "\n"
        << "paint coverage " << cx << " " << cz << " " << radius << " 1\n"
        << "save-weather " << dir.file("w1.png") << "\nsave " << dir.file("painted.json")
        << "\nwait 20\nscreenshot " << dir.file("p1.exr") << "\n"
        << "undo\nsave-weather " << dir.file("w2.png") << "\n"
        << "view transmittance\nscreenshot " << dir.file("t.exr") << "\ncapture "
        << dir.file("t.png") << "\nview depth\nscreenshot " << dir.file("d.exr") << "\ncapture "
        << dir.file("d.png") << "\nview weather\ncapture " << dir.file("m.png")
        << "\nview shadow-map\ncapture " << dir.file("sm.png") << "\nview density-slice\ncapture "
        << dir.file("ds.png") << "\nview temporal-source\ncapture " << dir.file("ts.png")
        << "\nview samples\ncapture " << dir.file("hm.png") << "\npaint anvil " << cx << " " << cz
        << " " << radius << " 1\nview data-field\ncapture " << dir.file("df.png") << "\n";
    const RunResult view =
        run("view --vulkan-validation " + kScene + "--script " + dir.file("s.txt"), kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;

    int w = 0, h = 0, c = 0;
    const auto before = cloudscape::readPng(dir.file("w0.png"), w, h, c);
    int w1 = 0, h1 = 0, c1 = 0;
    const auto after = cloudscape::readPng(dir.file("w1.png"), w1, h1, c1);
    ASSERT_EQ(c, 3);
    ASSERT_EQ(w1, w);
    ASSERT_EQ(h1, h);
    const float extent = 60000.0f; // weather.extent_m's default, centred on the origin
    int inside = 0, changedInside = 0, changedOutside = 0, otherChannels = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float x = ((i + 0.5f) / w - 0.5f) * extent;
            const float z = ((j + 0.5f) / h - 0.5f) * extent;
            const bool in = std::hypot(x - cx, z - cz) < radius;
            const size_t k = (static_cast<size_t>(j) * w + i) * 3;
            const bool changed = before[k] != after[k];
            inside += in;
            changedInside += in && changed;
            changedOutside += !in && changed;
            otherChannels += before[k + 1] != after[k + 1] || before[k + 2] != after[k + 2];
            if (in && changed) {
                EXPECT_GT(after[k], before[k]) << "coverage painted up at " << i << ", " << j;
            }
        }
    std::printf("brush: %d texels inside, %d changed; %d changed outside\n", inside, changedInside,
                changedOutside);
    EXPECT_GT(changedInside, inside / 2);
    EXPECT_EQ(changedOutside, 0);
    EXPECT_EQ(otherChannels, 0) << "a coverage stroke leaves precipitation and type alone";
    int w2 = 0, h2 = 0, c2 = 0;
    EXPECT_EQ(cloudscape::readPng(dir.file("w2.png"), w2, h2, c2), before) << "undo";

    const Layers p0 = readLayers(dir.file("p0.exr"));
    const Layers p1 = readLayers(dir.file("p1.exr"));
    const double stroke = psnr(p0, p1);
    std::printf("window after the stroke: %.1f dB from before\n", stroke);
    EXPECT_LT(stroke, 30.0) << "the stroke reached the renderer on the device";

    const RunResult still =
        run("render --backend vulkan --device 0 " + dir.file("painted.json") +
            " --set weather.image=" + dir.file("w1.png") + " -o " + dir.file("still.exr"));
    ASSERT_EQ(still.status, 0) << still.err;
    const double saved = psnr(readLayers(dir.file("still.exr")), p1);
    std::printf("render of the saved map and scene vs the painted window: %.1f dB\n", saved);
    EXPECT_GT(saved, 30.0);

    // The debug views show the model's rule of each pixel (debug_view.glsl.h), from the frame's
    // own layers (the screenshot of the same frame) or the map: the window's bytes, to rounding.
    auto windowPixels = [](const std::string& path) {
        int cw = 0, ch = 0, cc = 0;
        auto rgba = cloudscape::readPng(path, cw, ch, cc);
        EXPECT_EQ(cw, 64);
        EXPECT_EQ(ch, 36);
        EXPECT_EQ(cc, 4);
        return rgba;
    };
    auto byteOf = [](float v) {
        return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const Layers t = readLayers(dir.file("t.exr"));
    const auto tWindow = windowPixels(dir.file("t.png"));
    const Layers d = readLayers(dir.file("d.exr"));
    const auto dWindow = windowPixels(dir.file("d.png"));
    const auto mWindow = windowPixels(dir.file("m.png"));
    int worstT = 0, worstD = 0, worstM = 0;
    for (size_t p = 0; p < t.size() && p * 4 < tWindow.size(); ++p) {
        const glm::vec3 tv = cloudscape::model::debugTransmittance(t.ct[p]);
        worstT = std::max(worstT, std::abs(byteOf(tv.x) - tWindow[p * 4]));
        const glm::vec3 dv = cloudscape::model::debugDepth(d.cz[p], 60000.0f);
        for (int k = 0; k < 3; ++k)
            worstD = std::max(worstD, std::abs(byteOf(dv[k]) - dWindow[p * 4 + k]));
        // The map view: precipitation and cloud type (the coverage depends on the bias).
        const int x = static_cast<int>(p % 64), y = static_cast<int>(p / 64);
        const size_t k = (static_cast<size_t>(y * h / 36) * w + x * w / 64) * 3;
        const glm::vec4 texel(before[k] / 255.0f, before[k + 1] / 255.0f, before[k + 2] / 255.0f,
                              before[k] / 255.0f);
        const glm::vec3 mv = cloudscape::model::debugWeather(texel, 0.0f);
        worstM = std::max({worstM, std::abs(byteOf(mv.y) - mWindow[p * 4 + 1]),
                           std::abs(byteOf(mv.z) - mWindow[p * 4 + 2])});
    }
    EXPECT_LE(worstT, 2) << "transmittance view";
    EXPECT_LE(worstD, 2) << "depth view";
    EXPECT_LE(worstM, 2) << "weather map view";

    // The shadow map (the default landscape turns it on) holds sunlit ground and shadow; the
    // density slice has the air over the layer in its top rows, ground at the camera's foot
    // and cloud in the layer (its rules are checked on the CPU: DensitySlice.*).
    const auto smWindow = windowPixels(dir.file("sm.png"));
    int lit = 0, shadowed = 0;
    for (size_t p = 0; p < smWindow.size(); p += 4) {
        lit += smWindow[p] > 240 ? 1 : 0;
        shadowed += smWindow[p] < 60 ? 1 : 0;
    }
    std::printf("shadow-map view: %d lit and %d shadowed pixels of %zu\n", lit, shadowed,
                smWindow.size() / 4);
    EXPECT_GT(lit, 64);
    EXPECT_GT(shadowed, 16);
    const auto dsWindow = windowPixels(dir.file("ds.png"));
    const glm::vec3 above(0.05f, 0.08f, 0.16f), ground(0.32f, 0.24f, 0.15f);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(dsWindow[k], byteOf(above[k]), 1) << "top-left pixel: air over the layer";
        EXPECT_NEAR(dsWindow[(35 * 64) * 4 + k], byteOf(ground[k]), 1) << "bottom-left: ground";
    }
    int cloud = 0;
    for (size_t p = 0; p < dsWindow.size(); p += 4)
        cloud += dsWindow[p] > 128 && dsWindow[p + 2] > 128 ? 1 : 0;
    EXPECT_GT(cloud, 4) << "cloud in the slice";

    // The data field's view after an anvil stroke: its regions stretched over the image as the
    // weather view draws the map; green (anvil coverage) inside the brush only, and elsewhere the
    // neutral field: bottom type 0, the whole layer (blue 1).
    const auto dfWindow = windowPixels(dir.file("df.png"));
    int anvil = 0, anvilOutside = 0, strongest = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            const size_t p = (static_cast<size_t>(y) * 64 + x) * 4;
            const float rx = ((x * 64 / 64) + 0.5f) / 64.0f, rz = ((y * 64 / 36) + 0.5f) / 64.0f;
            const bool in =
                std::hypot((rx - 0.5f) * extent - cx, (rz - 0.5f) * extent - cz) < radius - 1000.0f;
            const bool out =
                std::hypot((rx - 0.5f) * extent - cx, (rz - 0.5f) * extent - cz) > radius + 1000.0f;
            anvil += in && dfWindow[p + 1] > 0 ? 1 : 0;
            strongest = std::max(strongest, in ? int(dfWindow[p + 1]) : 0);
            anvilOutside += out && dfWindow[p + 1] != 0 ? 1 : 0;
            if (out) {
                EXPECT_EQ(dfWindow[p], 0) << x << ", " << y << ": bottom type";
                EXPECT_EQ(dfWindow[p + 2], 255) << x << ", " << y << ": height range";
            }
        }
    std::printf("data-field view: %d pixels of anvil inside the brush (the most %d), %d outside\n",
                anvil, strongest, anvilOutside);
    EXPECT_GE(anvil, 6);
    EXPECT_GT(strongest, 128);
    EXPECT_EQ(anvilOutside, 0);

    // Where each pixel came from: one pixel in each 4x4 block marched (green), the others
    // reprojected (grey) or fallen back (red); the heat map has marches of many samples.
    const auto tsWindow = windowPixels(dir.file("ts.png"));
    int marched = 0, other = 0;
    for (size_t p = 0; p < tsWindow.size(); p += 4) {
        const glm::vec3 c(tsWindow[p], tsWindow[p + 1], tsWindow[p + 2]);
        auto is = [&](glm::vec3 v) {
            return std::abs(c.x - byteOf(v.x)) <= 1 && std::abs(c.y - byteOf(v.y)) <= 1 &&
                   std::abs(c.z - byteOf(v.z)) <= 1;
        };
        if (is(cloudscape::model::debugTemporalSource(cloudscape::model::TEMPORAL_SOURCE_MARCHED)))
            ++marched;
        else if (is(cloudscape::model::debugTemporalSource(
                     cloudscape::model::TEMPORAL_SOURCE_REPROJECTED)) ||
                 is(cloudscape::model::debugTemporalSource(
                     cloudscape::model::TEMPORAL_SOURCE_FALLBACK)))
            ++other;
    }
    EXPECT_EQ(marched, 64 * 36 / 16) << "temporal-source view";
    EXPECT_EQ(marched + other, 64 * 36) << "every pixel one of the three sources";
    const auto hmWindow = windowPixels(dir.file("hm.png"));
    int busy = 0;
    for (size_t p = 0; p < hmWindow.size(); p += 4)
        busy += hmWindow[p + 1] > 100 ? 1 : 0; // green or beyond: 48 samples or more
    EXPECT_GT(busy, 16) << "samples view";
}

// The brush paints on the device by copying only the texels it touched (every mip level's
// footprint) into the image the passes sample: check-weather reads that image back and fails at
// the first texel that differs from the host's map (what the CPU backend and save-weather read).
// Strokes across the map's wrapped corner, on each channel, one covering the whole map, and
// undos back to the start; the map saved at the end is the one the session opened with.
TEST(ViewVulkan, DeviceWeatherMapIsTheHostsAfterStrokesAndUndo) {
    TempDir dir;
    std::ofstream(dir.file("s.txt"))
        << "wait 1\nsave-weather " << dir.file("w0.png") << "\ncheck-weather\n"
        << "paint coverage 29900 -29900 2500 1\nwait 1\n"      // across both wrapped edges
        << "paint precipitation -5000 3000 4000 0.8\nwait 1\n" // rain: type follows
        << "paint type 20000 20000 6000 -1\n"
        << "check-weather\n"
        << "paint coverage 0 0 60000 -0.3\nwait 1\ncheck-weather\n" // the whole map
        << "undo\nundo\ncheck-weather\nundo\nundo\nwait 1\ncheck-weather\n"
        << "save-weather " << dir.file("w1.png") << "\n";
    const RunResult view = run("view --vulkan-validation --stats --width 32 --height 18 "
                               "--set weather.resolution=256 --script " +
                                   dir.file("s.txt"),
                               kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;
    size_t checks = 0;
    const std::string checked = "device's weather map is the host's (87381 texels";
    for (size_t at = view.out.find(checked); at != std::string::npos;
         at = view.out.find(checked, at + 1))
        ++checks;
    EXPECT_EQ(checks, 5u) << view.out; // 256^2 texels and their mips: 87381
    EXPECT_NE(view.out.find("8 brush edits"), std::string::npos) << view.out;
    std::printf("%s", view.out.c_str());
    int w = 0, h = 0, c = 0, w1 = 0, h1 = 0, c1 = 0;
    const auto before = cloudscape::readPng(dir.file("w0.png"), w, h, c);
    EXPECT_EQ(w, 256);
    EXPECT_EQ(cloudscape::readPng(dir.file("w1.png"), w1, h1, c1), before) << "undone";
}

// `view --backend cpu`: the CPU backend renders, each frame's composite is copied into a
// host-visible buffer of a Vulkan device opened only to present (lavapipe here), and the same
// pass tone-maps it into the window. Its converged screenshot matches `render --backend cpu`,
// and the window shows that screenshot's pixels.
TEST(ViewVulkan, CpuBackendRendersIntoTheWindow) {
    TempDir dir;
    std::ofstream(dir.file("s.txt"))
        << "wait 20\nscreenshot " << dir.file("view.exr") << "\nscreenshot " << dir.file("view.png")
        << "\ncapture " << dir.file("window.png") << "\n";
    const RunResult view = run("view --backend cpu --vulkan-validation --stats " + kScene +
                                   "--script " + dir.file("s.txt"),
                               kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;
    EXPECT_NE(view.out.find("frames at 64x36"), std::string::npos) << view.out;
    EXPECT_NE(view.out.find(", cpu;"), std::string::npos) << "rendered on the CPU: " << view.out;
    const RunResult still =
        run("render --backend cpu " + kScene + kOneSample + "-o " + dir.file("still.exr"));
    ASSERT_EQ(still.status, 0) << still.err;
    const double converged =
        psnr(readLayers(dir.file("still.exr")), readLayers(dir.file("view.exr")));
    std::printf("view --backend cpu, converged, vs render --backend cpu: %.1f dB\n", converged);
    EXPECT_GT(converged, 35.0);
    int w = 0, h = 0, c = 0, cw = 0, ch = 0, cc = 0;
    const auto png = cloudscape::readPng(dir.file("view.png"), w, h, c);
    const auto window = cloudscape::readPng(dir.file("window.png"), cw, ch, cc);
    ASSERT_EQ(cw, w);
    ASSERT_EQ(ch, h);
    ASSERT_EQ(cc, c);
    int worst = 0;
    for (size_t i = 0; i < png.size(); ++i)
        worst = std::max(worst, std::abs(int(png[i]) - int(window[i])));
    EXPECT_LE(worst, 2) << "the window's pixels against the screenshot";
}
