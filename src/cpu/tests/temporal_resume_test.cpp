// A temporal sequence continued from a saved state, through its checkpoint file, renders the
// same bits as the uninterrupted sequence: after a kill, `render --frames` resumes exactly.
#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/sequence_checkpoint.h>
#include <cloudscape/temporal.h>

#include "core/tests/storm_scene.h"
#include "model/sample_gather.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;
using namespace cloudscape;

namespace {

const SceneResources& smallResources() {
    static const SceneResources r = [] {
        SceneResources res;
        res.noise.base = generateBaseNoise(1, 32);
        res.noise.detail = generateDetailNoise(1, 16);
        res.noise.curl = generateCurlNoise(1, 32);
        Scene s;
        s.weatherResolution = 64;
        res.weather = prepareWeather(s);
        return res;
    }();
    return r;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

constexpr int kLastFrame = 22;

struct Case {
    const char* path;
    float cloudResolution;
    int gatherFrames; // render.moving_gather_frames (with the moving camera's 2x2 block)
};

} // namespace

TEST(TemporalResume, AContinuedSequenceEqualsTheUninterruptedOne) {
    const std::string file =
        (fs::temp_directory_path() / ("cloudscape_resume_" + std::to_string(::getpid()) + ".exr"))
            .string();
    // The fast pan gathers its last 16 frames' marches: the ring goes into the checkpoint too.
    for (const Case c :
         {Case{"slow-pan", 1.0f, 0}, Case{"fly-forward", 0.5f, 0}, Case{"fast-pan", 1.0f, 16}}) {
        Scene base;
        base.width = 48;
        base.height = 28;
        base.cameraPitchDeg = 25.0f;
        base.cloudResolution = c.cloudResolution; // then the history is at the pass size
        base.movingGatherFrames = c.gatherFrames;
        base.movingBlock2x2 = c.gatherFrames > 0;
        std::vector<RenderResult> expected;
        TemporalRenderer uninterrupted(smallResources());
        for (int f = 0; f <= kLastFrame; ++f)
            expected.push_back(uninterrupted.renderFrame(sceneOnPath(base, c.path, f, 24.0f), f));

        // Stopped before the first 16-frame cycle ends, right after it, and within the next.
        for (const int stop : {5, 15, 16, 19}) {
            TemporalRenderer killed(smallResources());
            for (int f = 0; f <= stop; ++f)
                killed.renderFrame(sceneOnPath(base, c.path, f, 24.0f), f);
            writeSequenceCheckpoint(file, {"test", killed.saveState()});

            TemporalRenderer rerun(smallResources());
            rerun.restoreState(readSequenceCheckpoint(file).state);
            for (int f = stop + 1; f <= kLastFrame; ++f) {
                const RenderResult r = rerun.renderFrame(sceneOnPath(base, c.path, f, 24.0f), f);
                const RenderResult& e = expected[static_cast<size_t>(f)];
                ASSERT_TRUE(sameBits(r.cloud, e.cloud) && sameBits(r.depth, e.depth) &&
                            sameBits(r.composite, e.composite))
                    << c.path << ": stopped after frame " << stop << ", frame " << f << " differs";
            }
        }
    }
    fs::remove(file);
}

TEST(TemporalResume, StatesAreSavedOnlyAfterAFrameAndCheckedOnRestore) {
    TemporalRenderer renderer(smallResources());
    EXPECT_TRUE(renderer.saveState().empty());
    Scene scene;
    scene.width = 32;
    scene.height = 18;
    renderer.renderFrame(scene, 3);
    TemporalState state = renderer.saveState();
    EXPECT_EQ(state.frameIndex, 3);
    EXPECT_EQ(state.width, 32);
    EXPECT_EQ(state.cloud.size(), 32u * 18u * 4u);
    EXPECT_EQ(renderer.backendName(), "cpu");

    TemporalRenderer other(smallResources());
    TemporalState shortHistory = state;
    shortHistory.depth.pop_back();
    EXPECT_THROW(other.restoreState(shortHistory), Error);
    TemporalState wrongParams = state;
    wrongParams.frameParams.resize(8);
    EXPECT_THROW(other.restoreState(wrongParams), Error);
    TemporalState wrongSize = state;
    wrongSize.width = 16;
    wrongSize.cloud.resize(16u * 18u * 4u);
    wrongSize.depth.resize(16u * 18u);
    wrongSize.weight.resize(16u * 18u);
    wrongSize.flash.resize(16u * 18u);
    EXPECT_THROW(other.restoreState(wrongSize), Error) << "frame parameters say 32 wide";
    EXPECT_THROW(other.restoreState(TemporalState{}), Error);
    TemporalState shortFlash = state;
    shortFlash.flash.resize(5);
    EXPECT_THROW(other.restoreState(shortFlash), Error);
    TemporalState ringless = state; // the frame parameters say no ring: none may come
    ringless.gatherFrames.resize(state.frameParams.size()); // one frame's
    ringless.gatherRing.resize(16u * 9u * 8u);
    EXPECT_THROW(other.restoreState(ringless), Error) << "a ring the parameters do not have";
    TemporalState noFlash = state; // a state from before the channel was kept
    noFlash.flash.clear();
    other.restoreState(noFlash);
    other.restoreState(state);
    EXPECT_EQ(other.saveState().frameIndex, 3);

    // With render.moving_gather_frames the ring is saved, whole, and checked on restore.
    TemporalRenderer gathering(smallResources());
    scene.movingGatherFrames = 4;
    gathering.renderFrame(scene, 3);
    const TemporalState ringed = gathering.saveState();
    EXPECT_EQ(ringed.gatherFrames.size(), 4u * state.frameParams.size());
    const size_t entering =
        cloudscape::model::ENTERING_FRAMES * cloudscape::model::ENTERING_MARCHES * 16u * 9u * 8u;
    EXPECT_EQ(ringed.gatherRing.size(), 4u * 16u * 9u * 8u + entering)
        << "4 frames of 16x9 blocks, then the entering ring";
    TemporalState shortRing = ringed;
    shortRing.gatherRing.pop_back();
    EXPECT_THROW(other.restoreState(shortRing), Error);
    TemporalState partFrame = ringed;
    partFrame.gatherFrames.pop_back();
    EXPECT_THROW(other.restoreState(partFrame), Error);
    other.restoreState(ringed);
    EXPECT_EQ(other.saveState().gatherRing, ringed.gatherRing);
}

// A storm's lightning flash lives in its own history channel (the flash mask): a sequence killed
// while a flash is being accumulated resumes to the same bits only if the channel is saved.
TEST(TemporalResume, AContinuedSequenceKeepsTheLightningFlash) {
    const std::string file = (fs::temp_directory_path() /
                              ("cloudscape_resume_flash_" + std::to_string(::getpid()) + ".exr"))
                                 .string();
    const Scene base = cloudscape::testing::underALightningStorm();
    const float flashStart = cloudscape::testing::firstFlashStart(base);
    ASSERT_GT(flashStart, 0.0f) << "no flash in two minutes";
    // 24 frames a second, the flash starting at frame 12; killed after frame 15, mid-flash.
    auto frame = [&](int f) {
        Scene s = base;
        s.timeS = flashStart + 0.003f + float(f - 12) / 24.0f;
        return s;
    };
    constexpr int kStop = 15, kLast = 24;
    TemporalRenderer uninterrupted(smallResources());
    TemporalRenderer killed(smallResources());
    std::vector<RenderResult> expected;
    for (int f = 0; f <= kLast; ++f) {
        expected.push_back(uninterrupted.renderFrame(frame(f), f));
        if (f <= kStop)
            killed.renderFrame(frame(f), f);
    }
    const TemporalState saved = killed.saveState();
    float flashInHistory = 0.0f;
    for (float v : saved.flash)
        flashInHistory = std::max(flashInHistory, v);
    ASSERT_GT(flashInHistory, 0.0f) << "the test must stop while the history holds a flash";
    writeSequenceCheckpoint(file, {"test", saved});
    TemporalRenderer rerun(smallResources());
    rerun.restoreState(readSequenceCheckpoint(file).state);
    fs::remove(file);
    for (int f = kStop + 1; f <= kLast; ++f) {
        const RenderResult r = rerun.renderFrame(frame(f), f);
        const RenderResult& e = expected[static_cast<size_t>(f)];
        ASSERT_TRUE(sameBits(r.cloud, e.cloud) && sameBits(r.composite, e.composite))
            << "frame " << f << " differs after the resume";
    }
}
