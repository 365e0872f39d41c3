// GPU category: a Vulkan temporal sequence continued from a saved state (through the checkpoint
// file) matches the uninterrupted Vulkan sequence, to the backends' parity tolerance or better.
#include <cloudscape/camera_path.h>
#include <cloudscape/metrics.h>
#include <cloudscape/sequence_checkpoint.h>
#include <cloudscape/temporal.h>

#include "core/tests/storm_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "vulkan/tests/vulkan_test_support.h"

namespace fs = std::filesystem;
using namespace cloudscape;
using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

namespace {

// Renders `path` to frame 20, and again stopped after frame 16 and continued from the checkpoint
// file; expects the continued frames to match.
void expectResumeMatches(const char* path, int gatherFrames) {
    Scene base;
    base.width = 64;
    base.height = 40;
    base.cameraPitchDeg = 20.0f;
    base.movingGatherFrames = gatherFrames; // the ring of marches goes into the state too
    base.movingBlock2x2 = gatherFrames > 0;
    constexpr int kStop = 16, kLast = 20; // stopped after frame 16, as after a kill
    const std::string file = (fs::temp_directory_path() /
                              ("cloudscape_vk_resume_" + std::to_string(::getpid()) + ".exr"))
                                 .string();
    TemporalRenderer uninterrupted(sharedResources(), vulkanWithValidation());
    TemporalRenderer killed(sharedResources(), vulkanWithValidation());
    std::vector<RenderResult> expected;
    for (int f = 0; f <= kLast; ++f) {
        const Scene scene = sceneOnPath(base, path, f, 24.0f);
        expected.push_back(uninterrupted.renderFrame(scene, f));
        if (f <= kStop)
            killed.renderFrame(scene, f);
    }
    writeSequenceCheckpoint(file, {"test", killed.saveState()});
    TemporalRenderer rerun(sharedResources(), vulkanWithValidation());
    rerun.restoreState(readSequenceCheckpoint(file).state);
    fs::remove(file);
    double worstPsnr = INFINITY, worstMeanError = 0.0, largest = 0.0;
    for (int f = kStop + 1; f <= kLast; ++f) {
        const RenderResult r = rerun.renderFrame(sceneOnPath(base, path, f, 24.0f), f);
        ASSERT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
        const RenderResult& e = expected[static_cast<size_t>(f)];
        const auto radiance = compareImages(channels(r.cloud, 0, 3), channels(e.cloud, 0, 3), 3);
        worstPsnr = std::min(worstPsnr, radiance.psnr);
        worstMeanError = std::max(worstMeanError, radiance.meanError);
        for (size_t i = 0; i < r.cloud.size(); ++i)
            largest = std::max(largest, static_cast<double>(std::abs(r.cloud[i] - e.cloud[i])));
    }
    std::printf("%s, gathering %d frames, resumed after frame %d: worst radiance PSNR %.1f dB, "
                "mean error %g, largest difference %g\n",
                path, gatherFrames, kStop, worstPsnr, worstMeanError, largest);
    // The promise is the two backends' parity bound (temporal_test.cpp). One device against
    // itself, with the same bits restored, should be far closer (lavapipe: identical); a history
    // restored wrongly (its accumulation counts lost) is off by about 0.1.
    EXPECT_GT(worstPsnr, 34.0) << path;
    EXPECT_LT(worstMeanError, 1e-4) << path;
}

} // namespace

TEST(VulkanTemporalResume, AContinuedSequenceMatchesTheUninterruptedOne) {
    expectResumeMatches("slow-pan", 0);
    // A ring restored wrongly (or not at all) restarts the gather: the pan's frames lose most
    // of their marches.
    expectResumeMatches("fast-pan", 16);
}

// The lightning flash's own history channel (the flash mask) goes into the saved state and back
// onto the device: a sequence killed mid-flash resumes to the uninterrupted composite (lavapipe:
// identical bits), where a history restored without the channel loses the flash's brightness.
TEST(VulkanTemporalResume, AContinuedSequenceKeepsTheLightningFlash) {
    const Scene base = cloudscape::testing::underALightningStorm();
    const float flashStart = cloudscape::testing::firstFlashStart(base);
    ASSERT_GT(flashStart, 0.0f) << "no flash in two minutes";
    auto frame = [&](int f) { // 24 frames a second, the flash starting at frame 12
        Scene s = base;
        s.timeS = flashStart + 0.003f + float(f - 12) / 24.0f;
        return s;
    };
    constexpr int kStop = 15, kLast = 18;
    TemporalRenderer uninterrupted(sharedResources(), vulkanWithValidation());
    TemporalRenderer killed(sharedResources(), vulkanWithValidation());
    std::vector<RenderResult> expected;
    for (int f = 0; f <= kLast; ++f) {
        expected.push_back(uninterrupted.renderFrame(frame(f), f));
        if (f <= kStop)
            killed.renderFrame(frame(f), f);
    }
    TemporalState saved = killed.saveState();
    ASSERT_EQ(saved.flash.size(), saved.weight.size());
    ASSERT_GT(*std::max_element(saved.flash.begin(), saved.flash.end()), 0.0f)
        << "the history holds a flash when the sequence stops";
    auto worstAfterResume = [&](const TemporalState& state) {
        TemporalRenderer rerun(sharedResources(), vulkanWithValidation());
        rerun.restoreState(state);
        double worst = 0.0;
        for (int f = kStop + 1; f <= kLast; ++f) {
            const RenderResult r = rerun.renderFrame(frame(f), f);
            EXPECT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
            const RenderResult& e = expected[static_cast<size_t>(f)];
            for (size_t i = 0; i < r.composite.size(); ++i)
                worst = std::max(worst, double(std::fabs(r.composite[i] - e.composite[i]) /
                                               std::max(e.composite[i], 1e-3f)));
        }
        return worst;
    };
    const double kept = worstAfterResume(saved);
    saved.flash.clear();
    const double dropped = worstAfterResume(saved);
    std::printf("resumed mid-flash: worst relative composite difference %.2g with the flash "
                "channel, %.2g without it\n",
                kept, dropped);
    EXPECT_LT(kept, 1e-4);
    EXPECT_GT(dropped, 100.0 * std::max(kept, 1e-5));
}
