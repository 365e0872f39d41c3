// GPU category: a Vulkan temporal sequence continued from a saved state (through the checkpoint
// file) matches the uninterrupted Vulkan sequence, to the backends' parity tolerance or better.
#include <cloudscape/camera_path.h>
#include <cloudscape/metrics.h>
#include <cloudscape/sequence_checkpoint.h>
#include <cloudscape/temporal.h>

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

TEST(VulkanTemporalResume, AContinuedSequenceMatchesTheUninterruptedOne) {
    Scene base;
    base.width = 64;
    base.height = 40;
    base.cameraPitchDeg = 20.0f;
    constexpr int kStop = 16, kLast = 20; // stopped after frame 16, as after a kill
    const std::string file =
        (fs::temp_directory_path() / ("cloudscape_vk_resume_" + std::to_string(::getpid()) +
                                      ".exr"))
            .string();
    TemporalRenderer uninterrupted(sharedResources(), vulkanWithValidation());
    TemporalRenderer killed(sharedResources(), vulkanWithValidation());
    std::vector<RenderResult> expected;
    for (int f = 0; f <= kLast; ++f) {
        const Scene scene = sceneOnPath(base, "slow-pan", f, 24.0f);
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
        const RenderResult r = rerun.renderFrame(sceneOnPath(base, "slow-pan", f, 24.0f), f);
        ASSERT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
        const RenderResult& e = expected[static_cast<size_t>(f)];
        const auto radiance =
            compareImages(channels(r.cloud, 0, 3), channels(e.cloud, 0, 3), 3);
        worstPsnr = std::min(worstPsnr, radiance.psnr);
        worstMeanError = std::max(worstMeanError, radiance.meanError);
        for (size_t i = 0; i < r.cloud.size(); ++i)
            largest = std::max(largest, static_cast<double>(std::abs(r.cloud[i] - e.cloud[i])));
    }
    std::printf("resumed after frame %d: worst radiance PSNR %.1f dB, mean error %g, largest "
                "difference %g\n",
                kStop, worstPsnr, worstMeanError, largest);
    // The promise is the two backends' parity bound (temporal_test.cpp). One device against
    // itself, with the same bits restored, should be far closer (lavapipe: identical); a history
    // restored wrongly (its accumulation counts lost) is off by about 0.1.
    EXPECT_GT(worstPsnr, 34.0);
    EXPECT_LT(worstMeanError, 1e-4);
}
