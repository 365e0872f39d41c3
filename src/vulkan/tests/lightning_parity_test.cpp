// GPU category: lightning on the Vulkan backend against the CPU backend, the same model headers:
// a still at a ground discharge (the flash, the external flash and the bolt in the composite),
// and a temporal sequence through a flash, where the flash mask's channel lives in the device's
// history.
#include <cloudscape/backend.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include "core/lightning.h"
#include "core/tests/storm_scene.h"
#include "vulkan/tests/vulkan_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

// The shared storm (src/core/tests/storm_scene.h), seen lower.
cloudscape::Scene underTheStorm() {
    cloudscape::Scene s = cloudscape::testing::underALightningStorm();
    s.cameraPitchDeg = 10.0f;
    return s;
}

float flashStart(const cloudscape::Scene& s, bool ground) {
    for (float t = 0.0f; t < 120.0f; t += 0.005f) {
        const cloudscape::LightningState l = cloudscape::lightningStateAt(s, t);
        if (l.peak > 0.0f && l.startS > 1.0f && l.ground == ground)
            return l.startS;
    }
    ADD_FAILURE() << "no flash found";
    return 0.0f;
}

double luminanceSum(const std::vector<float>& rgba) {
    double sum = 0.0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4)
        sum += 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    return sum;
}

// A still of the scene on both backends: the composite's PSNR and mean error (printed under
// `label`) and its luminance ratio, Vulkan over CPU; the Vulkan render must be free of
// validation messages.
struct StillAgreement {
    double psnr;
    double luminanceRatio;
};

StillAgreement stillAgreement(const cloudscape::Scene& s, const char* label) {
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, sharedResources());
    const cloudscape::RenderResult gpu =
        cloudscape::renderVulkan(s, sharedResources(), vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    const auto d =
        cloudscape::compareImages(channels(cpu.composite, 0, 3), channels(gpu.composite, 0, 3), 3);
    std::printf("%s: composite PSNR %.1f dB (mean error %.5f)\n", label, d.psnr, d.meanError);
    return {d.psnr, luminanceSum(gpu.composite) / luminanceSum(cpu.composite)};
}

} // namespace

TEST(VulkanLightning, AGroundDischargeStillMatchesTheCpuBackend) {
    cloudscape::Scene s = underTheStorm();
    s.timeS = flashStart(s, true) + 0.003f;
    const StillAgreement a = stillAgreement(s, "ground discharge");
    EXPECT_GT(a.psnr, 34.0);
    EXPECT_NEAR(a.luminanceRatio, 1.0, 0.01);
}

TEST(VulkanLightning, TheFlashMaskThroughTheDeviceHistoryMatchesTheCpu) {
    cloudscape::Scene s = underTheStorm();
    s.cameraPitchDeg = 35.0f;
    const float start = flashStart(s, false);
    const float dt = 1.0f / 24.0f;
    const int before = 20, during = 6;
    cloudscape::TemporalRenderer cpu(sharedResources());
    cloudscape::TemporalRenderer gpu(sharedResources(), vulkanWithValidation());
    double cpuFlash = 0.0, gpuFlash = 0.0;
    for (int i = 0; i < before + during; ++i) {
        cloudscape::Scene f = s;
        f.timeS = start + 0.003f + float(i - before) * dt;
        const cloudscape::RenderResult a = cpu.renderFrame(f, i);
        const cloudscape::RenderResult b = gpu.renderFrame(f, i);
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        if (i >= before) {
            cpuFlash += luminanceSum(a.composite);
            gpuFlash += luminanceSum(b.composite);
            const auto d = cloudscape::compareImages(channels(a.composite, 0, 3),
                                                     channels(b.composite, 0, 3), 3);
            EXPECT_GT(d.psnr, 34.0) << "frame " << i;
        }
    }
    EXPECT_NEAR(gpuFlash / cpuFlash, 1.0, 0.01);
}

// The low tier's vortex picks one ring per sample in the overlaps from a hash of the sample's
// 25 cm cell: both backends pick alike (they disagree only within a thousandth of a cell's edge).
TEST(VulkanLightning, TheLowTiersRingPicksMatchTheCpuBackend) {
    cloudscape::Scene s = underTheStorm();
    s.stormLightning = false;
    s.cameraPitchDeg = 35.0f;
    s.stormRingJitter = true;
    const StillAgreement a = stillAgreement(s, "under the storm, ring jitter");
    EXPECT_GT(a.psnr, 40.0);
    EXPECT_NEAR(a.luminanceRatio, 1.0, 0.005);
}
