// Runs killed (SIGKILL, injected at exact points with CLOUDSCAPE_TEST_FAULT) and rerun end with
// exactly the bytes an uninterrupted run writes: frame sequences through their temporal
// checkpoint, path traces through their float running mean. Multi-file exports land whole or not
// at all. Each run generates the noise textures (~2 s of CPU), so each test chains its kills in
// one directory rather than starting over for each.
#include "cli_support.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace cloudscape::testing;

namespace {

// Names of the files that differ between two snapshots (or exist in only one).
std::string differences(const std::map<std::string, std::string>& got,
                        const std::map<std::string, std::string>& expected) {
    std::string out;
    for (const auto& [name, bytes] : got)
        if (!expected.count(name) || expected.at(name) != bytes)
            out += " " + name + (expected.count(name) ? " (differs)" : " (unexpected)");
    for (const auto& [name, bytes] : expected)
        if (!got.count(name))
            out += " " + name + " (missing)";
    return out;
}

// Without the temporaries (dot files).
std::map<std::string, std::string> outputs(std::map<std::string, std::string> files) {
    std::erase_if(files, [](const auto& f) { return f.first[0] == '.'; });
    return files;
}

bool hasTemporary(const std::map<std::string, std::string>& files, const std::string& output) {
    return std::any_of(files.begin(), files.end(), [&](const auto& f) {
        return f.first.rfind("." + output + ".tmp-", 0) == 0;
    });
}

std::string fault(const std::string& spec) {
    return "CLOUDSCAPE_TEST_FAULT='" + spec + "'";
}

const std::string kSequence = "render --backend cpu --frames 0:24 --fps 12 --camera-path slow-pan "
                              "--width 48 --height 28 --checkpoint-every 8 -o ";
const std::string kCheckpoint = "%04d.png.checkpoint.exr";

} // namespace

// Checkpoints after frames 7, 15, 23 and 24. The 16-frame cycle of the reconstruction means a
// kill after frame 16 is the case a warm-up could not rebuild.
TEST(Resume, AKilledSequenceRerunsToTheBytesOfAnUninterruptedOne) {
    ScratchDir reference("sequence_reference");
    ToolRun run = runToolWith("", kSequence + reference.file("%04d.png"));
    ASSERT_EQ(run.status, 0) << run.stderrText;
    const auto expected = snapshot(reference.path());
    ASSERT_EQ(expected.size(), 26u) << "25 frames and the checkpoint";

    ScratchDir dir("sequence_killed");
    const std::string args = kSequence + dir.file("%04d.png");
    struct Kill {
        const char* fault;
        const char* halfWritten; // the output whose temporary the kill leaves, if any
    };
    const Kill kills[] = {
        {"kill-after-commit:0005.png", nullptr},     // before the first checkpoint
        {"kill-after-commit:0016.png", nullptr},     // after frame 16; checkpoint at 15
        {"kill-before-commit:0020.png", "0020.png"}, // during frame 20's write
        {"kill-before-commit:%04d.png.checkpoint.exr", "%04d.png.checkpoint.exr"}, // frame 23's
    };
    for (const Kill& k : kills) {
        run = runToolWith(fault(k.fault), args);
        ASSERT_TRUE(run.killed) << k.fault << ": " << run.stderrText;
        const auto files = snapshot(dir.path());
        if (k.halfWritten) {
            EXPECT_TRUE(hasTemporary(files, k.halfWritten)) << k.fault;
        }
        for (const auto& [name, bytes] : outputs(files)) {
            if (name != kCheckpoint) { // an earlier frame's checkpoint
                EXPECT_TRUE(expected.count(name) && expected.at(name) == bytes)
                    << k.fault << ": " << name << " is not what the uninterrupted run wrote";
            }
        }
    }
    // A changed scene refuses the checkpoint (one line, no output written; the stale
    // temporaries may go).
    const auto before = outputs(snapshot(dir.path()));
    run = runToolWith("", args + " --set weather.coverage=0.3");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.stderrText.find(kCheckpoint), std::string::npos) << run.stderrText;
    EXPECT_NE(run.stderrText.find("--force"), std::string::npos) << run.stderrText;
    EXPECT_EQ(std::count(run.stderrText.begin(), run.stderrText.end(), '\n'), 1) << run.stderrText;
    EXPECT_EQ(differences(outputs(snapshot(dir.path())), before), "");

    run = runToolWith("", args);
    ASSERT_EQ(run.status, 0) << run.stderrText;
    EXPECT_EQ(differences(snapshot(dir.path()), expected), "")
        << "the stale temporaries are gone and every frame is the uninterrupted run's";
}

// The estimate is written after every sample (--checkpoint 0); resuming continues the float
// running mean exactly.
TEST(Resume, AKilledPathTraceResumesToTheBytesOfAOneGoRender) {
    const std::string small =
        "pathtrace --width 24 --height 16 --set camera.pitch_deg=20 --checkpoint 0 --spp 5 ";
    ScratchDir dir("pathtrace_resume");
    ToolRun run = runToolWith("", small + "-o " + dir.file("one-go.exr"));
    ASSERT_EQ(run.status, 0) << run.stderrText;
    const std::string out = dir.file("p.exr");

    run = runToolWith(fault("kill-after-commit:p.exr#2"), small + "-o " + out);
    ASSERT_TRUE(run.killed) << run.stderrText; // 2 samples on disk
    // Resumed, then killed while writing its second estimate (4 samples): 3 stay on disk.
    run = runToolWith(fault("kill-before-commit:p.exr#2"), small + "--resume -o " + out);
    ASSERT_TRUE(run.killed) << run.stderrText;
    EXPECT_TRUE(hasTemporary(snapshot(dir.path()), "p.exr"));

    run = runToolWith("", small + "--resume -o " + out);
    ASSERT_EQ(run.status, 0) << run.stderrText;
    EXPECT_TRUE(readBytes(out) == readBytes(dir.file("one-go.exr")))
        << "resumed twice after kills, the image differs from the one-go render";
    EXPECT_FALSE(hasTemporary(snapshot(dir.path()), "p.exr"));
}

// `noise -o DIR` writes sixteen files; a full disk at one of the last leaves the directory as it
// was, and so does a kill during any write, apart from temporaries a later run removes.
TEST(Resume, NoiseExportsLandWholeOrNotAtAll) {
    ScratchDir dir("noise_set");
    // An earlier export (stand-ins: each noise run costs seconds) and a file of the user's.
    for (const char* texture : {"base_noise", "detail_noise", "curl_noise", "high_clouds"})
        for (const char* extension : {".png", ".raw", ".exr", ".json"})
            std::ofstream(dir.file(std::string(texture) + extension)) << "earlier " << texture;
    std::ofstream(dir.file("notes.txt")) << "the user's";
    const auto before = snapshot(dir.path());

    ToolRun run = runToolWith(fault("fail:curl_noise.json"), "noise --seed 3 -o " + dir.path());
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.stderrText.find(dir.file("curl_noise.json") + ": No space left on device"),
              std::string::npos)
        << run.stderrText;
    EXPECT_EQ(std::count(run.stderrText.begin(), run.stderrText.end(), '\n'), 1) << run.stderrText;
    EXPECT_EQ(differences(snapshot(dir.path()), before), "") << "a full disk changed nothing";

    run = runToolWith(fault("kill-before-commit:detail_noise.raw"),
                      "noise --seed 3 -o " + dir.path());
    ASSERT_TRUE(run.killed) << run.stderrText;
    const auto files = snapshot(dir.path());
    EXPECT_TRUE(hasTemporary(files, "base_noise.png")) << "staged, never committed";
    EXPECT_EQ(differences(outputs(files), before), "")
        << "a kill before the commit changed no output";
}
