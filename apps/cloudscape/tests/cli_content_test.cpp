// What the tool writes, read back and checked, on the CPU backend: the EXR cloud layers obey
// their own definitions, a still sequence converges to the full-resolution render, and
// sequences and stills are the same bytes whatever the number of threads.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace cloudscape::clitest;

namespace {

// The layers' additive definition (composite = cloud + T * sky) holds without the air between
// the camera and the clouds, which dims the cloud's light and adds its own.
const std::string kNoAir = "--set atmosphere.aerial_perspective=false ";

// Small, still (no wind, so the clouds do not move between frames) and quick.
// One sample per pixel, named: a still's default is 4 (issue 15), and a temporal sequence's
// first cycle reproduces the one-sample march.
const std::string kStill = "--backend cpu --width 48 --height 28 --set camera.pitch_deg=20 "
                           "--set wind.speed_mps=0 --set render.samples_per_pixel=1 " +
                           kNoAir;

} // namespace

TEST(CliContent, ExrLayersObeyTheirDefinitions) {
    TempDir dir;
    // The camera above the layer (the other stills here look up from below it).
    for (const char* scene : {"above-the-deck"}) {
        const std::string out = dir.file(std::string(scene) + ".exr");
        const RunResult r = run(std::string("render ") + scene +
                                " --backend cpu --width 64 --height 36 " + kNoAir + "-o " + out);
        ASSERT_EQ(r.status, 0) << r.err;
        expectConsistentLayers(readLayers(out), scene);
    }
}

TEST(CliContent, AStillSequenceConvergesToTheFullRender) {
    // 1/16 of the pixels are marched a frame, with the full render's jitter in the first 16-frame
    // cycle: frame 15 must equal the still render (to the float round trip of reprojection), and
    // frame 7 must not yet.
    TempDir dir;
    ASSERT_EQ(run("render " + kStill + "-o " + dir.file("full.exr")).status, 0);
    const RunResult seq = run("render " + kStill + "--frames 0:15 -o " + dir.file("f%02d.exr"));
    ASSERT_EQ(seq.status, 0) << seq.err;
    const Layers full = readLayers(dir.file("full.exr"));
    expectConsistentLayers(full, "full");
    for (int f : {0, 7, 15}) {
        char name[16];
        std::snprintf(name, sizeof name, "f%02d.exr", f);
        const Layers frame = readLayers(dir.file(name));
        expectConsistentLayers(frame, name, false);
        const double d = maxCloudDifference(full, frame);
        if (f == 15) {
            EXPECT_LT(d, 1e-3) << "converged";
        } else {
            EXPECT_GT(d, 0.05) << name << " is still being filled in";
        }
    }
}

TEST(CliContent, SequencesAreTheSameBytesOnOneThreadOrAll) {
    // The CPU backend schedules tiles on every core TBB is allowed; `taskset -c 0` allows one.
    // A moving sequence (wind on, a camera path) must not depend on that. (Stills and the
    // library's renderers are checked across thread counts in src/cpu/tests.)
    TempDir dir;
    const std::string moving = "--backend cpu --width 48 --height 28 --camera-path slow-pan "
                               "--frames 0:5 --fps 4 ";
    ASSERT_EQ(run("render " + moving + "-o " + dir.file("a%d.exr")).status, 0);
    const RunResult one = run("render " + moving + "-o " + dir.file("c%d.exr"), "taskset -c 0");
    ASSERT_EQ(one.status, 0) << one.err;
    for (int f = 0; f <= 5; ++f) {
        const std::string a = readBytes(dir.file(std::string("a") + std::to_string(f) + ".exr"));
        ASSERT_FALSE(a.empty()) << f;
        EXPECT_EQ(a, readBytes(dir.file(std::string("c") + std::to_string(f) + ".exr")))
            << "frame " << f << " on one thread";
    }
    EXPECT_NE(readBytes(dir.file("a0.exr")), readBytes(dir.file("a5.exr"))) << "the view moves";
}
