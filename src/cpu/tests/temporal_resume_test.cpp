// A temporal sequence continued from a saved state, through its checkpoint file, renders the
// same bits as the uninterrupted sequence: after a kill, `render --frames` resumes exactly.
#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/sequence_checkpoint.h>
#include <cloudscape/temporal.h>

#include <gtest/gtest.h>

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
};

} // namespace

TEST(TemporalResume, AContinuedSequenceEqualsTheUninterruptedOne) {
    const std::string file =
        (fs::temp_directory_path() / ("cloudscape_resume_" + std::to_string(::getpid()) + ".exr"))
            .string();
    for (const Case c : {Case{"slow-pan", 1.0f}, Case{"fly-forward", 0.5f}}) {
        Scene base;
        base.width = 48;
        base.height = 28;
        base.cameraPitchDeg = 25.0f;
        base.cloudResolution = c.cloudResolution; // then the history is at the pass size
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
    EXPECT_THROW(other.restoreState(wrongSize), Error) << "frame parameters say 32 wide";
    EXPECT_THROW(other.restoreState(TemporalState{}), Error);
    other.restoreState(state);
    EXPECT_EQ(other.saveState().frameIndex, 3);
}
