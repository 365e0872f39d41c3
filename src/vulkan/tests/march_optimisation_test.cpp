// GPU category: issue 4's march optimisations on the Vulkan backend (blue-noise offsets, the
// step optimisation, the scene depth buffer, half-resolution clouds) against the CPU backend,
// under the validation layers.
#include <cloudscape/backend.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "vulkan/tests/vulkan_test_support.h"

namespace {

using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

} // namespace

TEST(VulkanMarchOptimisation, MatchesTheCpuBackendWithEveryOptimisationOn) {
    cloudscape::Scene scene;
    scene.width = 96;
    scene.height = 54;
    scene.blueNoise = true;
    scene.stepOptimisation = 1.0f;
    // Geometry: a near wall over the left third, a far ridge inside the cloud layer below the
    // middle, sky elsewhere.
    cloudscape::SceneResources resources = sharedResources();
    resources.depth.width = scene.width;
    resources.depth.height = scene.height;
    resources.depth.metres.assign(static_cast<size_t>(scene.width) * scene.height,
                                  std::numeric_limits<float>::infinity());
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            float& m = resources.depth.metres[static_cast<size_t>(y) * scene.width + x];
            if (x < scene.width / 3)
                m = 30.0f;
            else if (y > scene.height / 2)
                m = 9000.0f;
        }
    for (float resolution : {1.0f, 0.5f}) {
        scene.cloudResolution = resolution;
        const cloudscape::RenderResult cpu = cloudscape::renderCpu(scene, resources);
        const cloudscape::RenderResult gpu =
            cloudscape::renderVulkan(scene, resources, vulkanWithValidation());
        ASSERT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
        ASSERT_EQ(gpu.width, scene.width);
        const auto d = cloudscape::compareImages(cpu.cloud, gpu.cloud, 4, {3});
        const auto t = cloudscape::compareImages(cpu.cloud, gpu.cloud, 4, {0, 1, 2}, 1.0);
        std::printf("resolution %.1f: radiance PSNR %.1f dB, transmittance PSNR %.1f dB\n",
                    resolution, d.psnr, t.psnr);
        EXPECT_GT(d.psnr, 34.0);
        EXPECT_GT(t.psnr, 34.0);
        // Behind the wall: no cloud on either backend.
        for (int y = 0; y < scene.height; ++y)
            for (int x = 0; x < scene.width / 3 - 1; ++x) {
                const size_t i = static_cast<size_t>(y) * scene.width + x;
                ASSERT_EQ(gpu.cloud[i * 4 + 3], 1.0f) << x << "," << y;
                ASSERT_EQ(gpu.cloud[i * 4], 0.0f) << x << "," << y;
            }
        // The sample counts agree to within the isolated pixels where float evaluation differs.
        EXPECT_NEAR(static_cast<double>(gpu.stats.densitySamples),
                    static_cast<double>(cpu.stats.densitySamples),
                    0.02 * static_cast<double>(cpu.stats.densitySamples));
    }
}

TEST(VulkanMarchOptimisation, NoiseSkippingIsExact) {
    // march.noise_skipping (noise_clearance.glsl.h) on the device: the same image bit for bit,
    // with fewer density samples, in a full frame (the temporal block march runs the same
    // shader code; its exactness is checked by hand in docs/PERFORMANCE.md).
    cloudscape::Scene scene;
    scene.width = 96;
    scene.height = 54;
    const cloudscape::SceneResources& resources = sharedResources();
    ASSERT_FALSE(resources.noise.baseClearance.empty());
    scene.noiseSkipping = false;
    const cloudscape::RenderResult plain =
        cloudscape::renderVulkan(scene, resources, vulkanWithValidation());
    scene.noiseSkipping = true;
    const cloudscape::RenderResult skipped =
        cloudscape::renderVulkan(scene, resources, vulkanWithValidation());
    ASSERT_TRUE(skipped.stats.validationMessages.empty())
        << skipped.stats.validationMessages.front();
    EXPECT_EQ(plain.cloud, skipped.cloud);
    EXPECT_EQ(plain.composite, skipped.composite);
    std::printf("full frame: density samples %llu -> %llu\n",
                static_cast<unsigned long long>(plain.stats.densitySamples),
                static_cast<unsigned long long>(skipped.stats.densitySamples));
    EXPECT_LT(skipped.stats.densitySamples, plain.stats.densitySamples);
}
