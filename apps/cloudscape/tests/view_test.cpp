// CPU category: `cloudscape view`'s refusals, which need neither a display nor Vulkan: a script
// is read and checked before any window opens, and a machine with no display gets one line.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

using namespace cloudscape::clitest;

namespace {

int lines(const std::string& text) {
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// Runs `view` over a script of `text` with no display reachable.
RunResult viewWithScript(const TempDir& dir, const std::string& text) {
    std::ofstream(dir.file("s.txt")) << text;
    return run("view --width 32 --height 18 --script " + dir.file("s.txt"),
               "DISPLAY= WAYLAND_DISPLAY=");
}

} // namespace

TEST(View, ScriptErrorsNameTheLine) {
    TempDir dir;
    struct Case {
        std::string script;
        std::string expected;
    };
    const Case cases[] = {
        {"wait 2\n\n# a comment\nfly 3\n", "s.txt:4: unknown action 'fly'"},
        {"wait two\n", "s.txt:1: 'two' is not a number"},
        {"wait -1\n", "s.txt:1: wait '-1'"},
        {"camera 0 100 0 0\n", "s.txt:1: camera takes 5 arguments, got 4"},
        {"set weather.coverage 7\n", "weather.coverage = 7 is out of range"},
        {"set no.such_key 1\n", "unknown key 'no.such_key'"},
        {"move 0 -5000 0\n", "must be above the ground"},
        {"tier ultra\n", "s.txt:1"},
        {"screenshot " + dir.file("x.jpg") + "\n", "expected a .png or .exr file"},
        {"save " + dir.file("nodir/s.json") + "\n", "nodir"},
        {"quit now\n", "quit takes 0 arguments, got 1"},
        {"path spiral 3\n", "s.txt:1: --camera-path 'spiral': unknown path"},
        {"path fly-forward -2\n", "s.txt:1: path '-2': expected a whole number"},
        {"record maybe\n", "s.txt:1: record 'maybe': expected on or off"},
        {"wait 1\nplay\n", "s.txt:2: play before any 'record on'"},
        {"save-path " + dir.file("c.txt") + "\n", "expected a .json file"},
        {"await-reload 0\n", "s.txt:1: await-reload '0': expected seconds"},
        {"orbit 100000 0 60\n", "must be above the ground"},
        {"paint coverage 40000 0 1000 1\n", "s.txt:1: the brush at x 40000 m, z 0 m is outside "
                                            "the weather map (x in [-30000, 30000]"},
        {"paint cover 0 0 1000 1\n", "s.txt:1: brush channel 'cover'"},
        {"paint type 0 0 0 1\n", "s.txt:1: brush radius 0 m"},
        {"paint type 0 0 100 2\n", "s.txt:1: brush strength 2"},
        {"save-weather " + dir.file("w.jpg") + "\n", "expected a .png file"},
        {"view heat\n", "s.txt:1: view 'heat': expected picture, transmittance, depth, weather, "
                        "data-field, shadow-map, density-slice, temporal-source or samples"},
    };
    for (const Case& c : cases) {
        const RunResult r = viewWithScript(dir, c.script);
        EXPECT_NE(r.status, 0) << c.script;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.script << " -> " << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_EQ(r.err.find("display"), std::string::npos) << "checked before the window";
    }
    EXPECT_FALSE(fs::exists(dir.file("x.jpg")));
    // A backend the viewer does not have: one line, before any window.
    std::ofstream(dir.file("ok.txt")) << "wait 1\n";
    const RunResult backend =
        run("view --backend metal --script " + dir.file("ok.txt"), "DISPLAY= WAYLAND_DISPLAY=");
    EXPECT_NE(backend.status, 0);
    EXPECT_NE(backend.err.find("--backend"), std::string::npos) << backend.err;
    EXPECT_NE(backend.err.find("metal"), std::string::npos) << backend.err;
    EXPECT_EQ(lines(backend.err), 1) << backend.err;
}

TEST(View, NoDisplayIsOneLine) {
    TempDir dir;
    const RunResult r = viewWithScript(dir, "wait 1\nscreenshot " + dir.file("a.png") + "\n");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("a.png")));
    // A bad scene is refused first, by the scene loader.
    const RunResult bad = run("view " + dir.file("missing.json"), "DISPLAY=");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.err.find("missing.json"), std::string::npos) << bad.err;
    EXPECT_EQ(lines(bad.err), 1) << bad.err;
}
