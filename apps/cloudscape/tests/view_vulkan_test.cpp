// GPU category: `cloudscape view --script` in a real window under Xvfb (xvfb-run) on the Vulkan
// device (lavapipe in CI) with the validation layers on. A converged screenshot matches
// `cloudscape render` of the same scene and camera, a scripted key change changes it, and the
// saved scene renders the same image again.
#include "cli_test_support.h"

#include <cloudscape/metrics.h>

#include <gtest/gtest.h>

#include <algorithm>
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
        << "camera 0 10 0 45 15\nscreenshot " << dir.file("moved.exr") << "\n";
    const RunResult view =
        run("view --vulkan-validation " + kScene + "--script " + dir.file("s.txt"), kXvfb);
    ASSERT_EQ(view.status, 0) << view.err;
    EXPECT_EQ(view.err.find("vulkan validation"), std::string::npos) << view.err;
    expectConsistentLayers(readLayers(dir.file("moved.exr")), "moved camera", false);
}
