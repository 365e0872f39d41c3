// GPU category: the temporal reconstruction on the Vulkan backend (render_clouds.comp in block
// mode, then temporal_resolve.comp) against the CPU backend's, and against a full Vulkan render,
// under the validation layers.
#include <cloudscape/backend.h>
#include <cloudscape/camera_path.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>
#include <cloudscape/weather.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "vulkan/compute_pass.h"
#include "vulkan/tests/vulkan_test_support.h"

namespace {

using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

cloudscape::Scene smallScene() {
    cloudscape::Scene s;
    s.width = 96;
    s.height = 64;
    s.cameraPitchDeg = 20.0f;
    return s;
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        m = std::max(m, static_cast<double>(std::abs(a[i] - b[i])));
    return m;
}

// Runs `frames` frames of a camera path on both backends; returns the worst per-frame PSNR of
// the cloud radiance and of the transmittance.
void compareSequences(const std::string& path, int frames, double& worstRadiance,
                      double& worstTransmittance, const cloudscape::Scene& base = smallScene(),
                      const cloudscape::SceneResources& resources = sharedResources(),
                      double maxMeanError = 0.01) {
    cloudscape::TemporalRenderer cpu(resources);
    cloudscape::TemporalRenderer gpu(resources, vulkanWithValidation());
    worstRadiance = worstTransmittance = 1e9;
    for (int f = 0; f < frames; ++f) {
        const cloudscape::Scene scene = cloudscape::sceneOnPath(base, path, f, 24.0f);
        const cloudscape::RenderResult a = cpu.renderFrame(scene, f);
        const cloudscape::RenderResult b = gpu.renderFrame(scene, f);
        ASSERT_TRUE(b.stats.validationMessages.empty())
            << path << " frame " << f << ": " << b.stats.validationMessages.front();
        ASSERT_NE(b.stats.backend.find("vulkan"), std::string::npos);
        EXPECT_EQ(a.stats.rays, b.stats.rays) << "both march one pixel per block";
        const auto radiance =
            cloudscape::compareImages(channels(a.cloud, 0, 3), channels(b.cloud, 0, 3), 3);
        const auto transmittance =
            cloudscape::compareImages(channels(a.cloud, 3, 1), channels(b.cloud, 3, 1), 1, {}, 1.0);
        EXPECT_LT(radiance.meanError, maxMeanError) << path << " frame " << f;
        // CLOUDSCAPE_TEST_VERBOSE=1 prints every frame.
        if (std::getenv("CLOUDSCAPE_TEST_VERBOSE"))
            std::printf("  frame %d: %.1f %.1f dB max %.4f, %.4f\n", f, radiance.psnr,
                        transmittance.psnr, radiance.maxError, transmittance.maxError);
        worstRadiance = std::min(worstRadiance, radiance.psnr);
        worstTransmittance = std::min(worstTransmittance, transmittance.psnr);
        // Where each pixel came from must agree too (a few pixels may flip at the one-pixel
        // consistency threshold of the reprojection).
        EXPECT_NEAR(cpu.lastBreakdown().reprojected, gpu.lastBreakdown().reprojected, 0.02)
            << path << " frame " << f;
        EXPECT_NEAR(cpu.lastBreakdown().fallback, gpu.lastBreakdown().fallback, 0.02)
            << path << " frame " << f;
        if (f == frames - 1)
            std::printf("%-9s frame %2d: cloud radiance PSNR %5.1f dB (mean error %.5f), "
                        "transmittance PSNR %5.1f dB\n",
                        path.c_str(), f, radiance.psnr, radiance.meanError, transmittance.psnr);
    }
    std::printf("%-9s worst of %d frames: radiance %5.1f dB, transmittance %5.1f dB\n",
                path.c_str(), frames, worstRadiance, worstTransmittance);
}

} // namespace

// Each marched pixel differs between the two compilations of the model by float evaluation
// alone, and the resolve only moves and blends marched values, so a sequence must stay as close
// as one frame: the bounds are VulkanParity's (as shipped). Measured worst frames of 20 while
// the model was being tuned: still 46-50 dB radiance / 40 dB transmittance, slow pan 37-43 /
// 40 dB (the worst when one sunlit edge pixel, HDR radiance ~5, differs and is kept by the
// history); the per-frame mean-error bound catches any systematic drift.
constexpr double kMinRadiancePsnr = 34.0;
constexpr double kMinTransmittancePsnr = 34.0;

namespace {

// compareSequences held to those bounds.
void expectSequencesMatch(const std::string& path, int frames,
                          const cloudscape::Scene& base = smallScene()) {
    double radiance = 0.0, transmittance = 0.0;
    compareSequences(path, frames, radiance, transmittance, base);
    EXPECT_GT(radiance, kMinRadiancePsnr) << path;
    EXPECT_GT(transmittance, kMinTransmittancePsnr) << path;
}

// A translating camera gathering earlier marches places each by its first cloud's distance: a
// march that meets a wisp on one backend and none on the other (a density at the threshold,
// float evaluation alone) lands pixels apart, and a pixel with few marches near it follows it.
// Measured (96x64, 18 frames): worst radiance 47.9 dB, transmittance 34.4 dB, per-frame mean
// error up to 0.0104, against 0.007 and 38 dB for the same flight resampled; a systematic
// drift would pass these bounds by far (the resume test's wrongly restored history: 0.1).
constexpr double kMinGatheredFlightTransmittancePsnr = 32.0;
constexpr double kMaxGatheredFlightMeanError = 0.015;

} // namespace

TEST(VulkanTemporal, StillCameraMatchesTheCpuTemporalRenderer) {
    expectSequencesMatch("still", 20);
}

TEST(VulkanTemporal, SlowPanMatchesTheCpuTemporalRenderer) {
    expectSequencesMatch("slow-pan", 20);
}

// Flying: translation, the history clamp and the moving camera's 2x2 blocks
// (render.moving_block_2x2) on both backends.
TEST(VulkanTemporal, FlyForwardMatchesTheCpuTemporalRenderer) {
    cloudscape::Scene base = smallScene();
    base.movingBlock2x2 = true;
    expectSequencesMatch("fly-forward", 12, base);
}

// A still camera marching 2x2 blocks (render.still_block_2x2), each march with a new jitter
// (marchCycleFor), on both backends.
TEST(VulkanTemporal, StillCameraIn2x2BlocksMatchesTheCpuTemporalRenderer) {
    cloudscape::Scene base = smallScene();
    base.stillBlock2x2 = true;
    expectSequencesMatch("still", 12, base);
}

// A turning camera in 2x2 blocks averages two marches a pixel (marchCountFor) on both backends.
TEST(VulkanTemporal, TurningIn2x2BlocksMatchesTheCpuTemporalRenderer) {
    cloudscape::Scene base = smallScene();
    base.movingBlock2x2 = true;
    expectSequencesMatch("fast-pan", 12, base);
}

// A moving camera gathering its last frames' marches (render.moving_gather_frames), turning and
// flying, on both backends: 18 frames, so the 16-frame ring wraps around.
TEST(VulkanTemporal, GatheringMatchesTheCpuTemporalRenderer) {
    cloudscape::Scene base = smallScene();
    base.movingBlock2x2 = true;
    base.movingGatherFrames = 16;
    expectSequencesMatch("fast-pan", 18, base);
    double radiance = 0.0, transmittance = 0.0;
    compareSequences("fly-forward", 18, radiance, transmittance, base, sharedResources(),
                     kMaxGatheredFlightMeanError);
    EXPECT_GT(radiance, kMinRadiancePsnr);
    EXPECT_GT(transmittance, kMinGatheredFlightTransmittancePsnr);
}

namespace {

// Pipelines built by the frames of a camera that starts to turn after two still frames, on a
// renderer that is interactive (the viewer's) or not.
uint64_t pipelinesBuiltWhenTurning(const cloudscape::Scene& base, bool interactive) {
    cloudscape::BackendOptions options = vulkanWithValidation();
    options.interactive = interactive;
    cloudscape::TemporalRenderer gpu(sharedResources(), options);
    for (int f = 0; f < 2; ++f)
        gpu.renderFrame(cloudscape::sceneOnPath(base, "still", f, 24.0f), f);
    const uint64_t before = cloudscape::vulkan::ComputePass::pipelinesBuilt();
    for (int f = 2; f < 5; ++f) {
        const cloudscape::RenderResult r =
            gpu.renderFrame(cloudscape::sceneOnPath(base, "fast-pan", f, 24.0f), f);
        EXPECT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
    }
    return cloudscape::vulkan::ComputePass::pipelinesBuilt() - before;
}

} // namespace

// An interactive renderer builds the pipelines of a moving camera's frames with its still
// frames, so the first frame that moves compiles nothing (on lavapipe a quarter to half a second
// each: a hitch in the viewer the moment a person starts to turn): the high tier's gathering
// frames, and the low tier's, whose background comes from the reduced pass.
TEST(VulkanTemporal, TheFirstMovingFrameOfAnInteractiveRendererBuildsNoPipeline) {
    cloudscape::Scene gathering = smallScene();
    gathering.movingBlock2x2 = true;
    gathering.movingGatherFrames = 16;
    cloudscape::Scene reduced = smallScene();
    reduced.cloudResolution = 0.5f;
    reduced.movingBackgroundReduced = true;
    reduced.cloudShadowEnabled = true; // the ground fallback's list and its dispatch too
    for (const cloudscape::Scene& scene : {gathering, reduced}) {
        EXPECT_EQ(pipelinesBuiltWhenTurning(scene, true), 0u);
        // A batch render builds them when a frame first needs them (so the test sees the
        // moving frames' pipelines at all).
        EXPECT_GE(pipelinesBuiltWhenTurning(scene, false), 2u);
    }
}

// A ridge of scene geometry 3 km away across the lower part of a low view: marches stop at it and
// the resolve must not paint reprojected cloud over it.
cloudscape::SceneResources withRidge(const cloudscape::Scene& scene) {
    cloudscape::SceneResources resources = sharedResources();
    resources.depth.width = scene.width;
    resources.depth.height = scene.height;
    resources.depth.metres.assign(static_cast<size_t>(scene.width) * scene.height,
                                  std::numeric_limits<float>::infinity());
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x)
            if (y > 34 + static_cast<int>(6.0f * std::sin(0.15f * static_cast<float>(x))))
                resources.depth.metres[static_cast<size_t>(y) * scene.width + x] = 3000.0f;
    return resources;
}

TEST(VulkanTemporal, SceneDepthBufferMatchesTheCpu) {
    cloudscape::Scene scene = smallScene();
    scene.cameraPitchDeg = 8.0f;
    double radiance = 0.0, transmittance = 0.0;
    compareSequences("slow-pan", 20, radiance, transmittance, scene, withRidge(scene));
    // Measured 43.7 / 37.5 dB.
    EXPECT_GT(radiance, kMinRadiancePsnr);
    EXPECT_GT(transmittance, kMinTransmittancePsnr);
}

TEST(VulkanTemporal, ReducedCloudResolutionMatchesTheCpu) {
    // The low tier's half-resolution clouds: the reconstruction runs at 48x32 and is upsampled.
    cloudscape::Scene scene = smallScene();
    scene.cameraPitchDeg = 8.0f;
    scene.cloudResolution = 0.5f;
    double radiance = 0.0, transmittance = 0.0;
    compareSequences("slow-pan", 20, radiance, transmittance, scene, withRidge(scene));
    // Measured worst frames 33-34 / 30 dB (typical frames 40-47 dB). A single-frame render at
    // 48x32 already differs by up to 0.3 at some 10 cloud-edge values a frame (a coarse sample
    // flips between zero and non-zero, as in VulkanParity); here one such pass pixel marched
    // with and without a cloud hit is then kept by the history for the rest of the cycle and
    // spread over 2x2 output pixels by the upsample. The per-frame mean-error bound in
    // compareSequences is what catches a systematic difference.
    EXPECT_GT(radiance, 30.0);
    EXPECT_GT(transmittance, 27.0);
}

TEST(VulkanTemporal, StillCameraConvergesToTheFullVulkanRenderIn16Frames) {
    const cloudscape::Scene scene = smallScene();
    const cloudscape::RenderResult full =
        cloudscape::renderVulkan(scene, sharedResources(), vulkanWithValidation());
    cloudscape::TemporalRenderer temporal(sharedResources(), vulkanWithValidation());
    cloudscape::RenderResult r;
    for (int f = 0; f < 16; ++f) {
        r = temporal.renderFrame(scene, f);
        ASSERT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
        EXPECT_EQ(r.stats.rays, static_cast<uint64_t>(24 * 16)) << "1/16 of the pixels";
        if (f == 7) {
            EXPECT_GT(maxDifference(r.cloud, full.cloud), 0.05) << "half way it must differ";
        }
    }
    // Bound: after 16 frames every pixel was marched once by the same shader code with the same
    // jitter as the full render, and a still camera reprojects each pixel onto itself up to the
    // float round trip through ray and projection (~1e-4 px), so the history is read that far
    // off the pixel centre: the error is ~1e-4 of the steepest step between neighbouring pixels
    // (HDR radiance: 18 at a sunlit edge here). 2e-4 of that step (at least 1e-3) allows twice
    // that offset; measured 9.1e-4 (1.5e-4 before the sunlit edges of the current model).
    double step = 5.0;
    for (int y = 0; y + 1 < scene.height; ++y)
        for (int x = 0; x + 1 < scene.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const size_t i = (static_cast<size_t>(y) * scene.width + x) * 4 + c;
                step = std::max(
                    {step, static_cast<double>(std::abs(full.cloud[i + 4] - full.cloud[i])),
                     static_cast<double>(std::abs(
                         full.cloud[i + static_cast<size_t>(scene.width) * 4] - full.cloud[i]))});
            }
    const double cloudError = maxDifference(r.cloud, full.cloud);
    const double compositeError = maxDifference(r.composite, full.composite);
    std::printf("after 16 frames: max difference cloud %.2e, composite %.2e (steepest step %.2f)\n",
                cloudError, compositeError, step);
    EXPECT_LT(cloudError, 2e-4 * step);
    EXPECT_LT(compositeError, 2e-4 * step);
    EXPECT_NEAR(temporal.lastBreakdown().marched, 1.0 / 16.0, 0.01);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 15.0 / 16.0, 0.01);
    EXPECT_GT(r.stats.gpuMemoryBytes, r.stats.gpuTextureBytes);
}

TEST(VulkanTemporal, HistoryResetsOnASkippedFrameOrANewSizeAndAutoPicksVulkan) {
    cloudscape::Scene scene = smallScene();
    std::string notice;
    cloudscape::BackendOptions automatic;
    automatic.validation = true;
    cloudscape::TemporalRenderer temporal(sharedResources(), automatic, &notice);
    EXPECT_TRUE(notice.empty()) << notice;
    for (int f = 0; f < 16; ++f)
        EXPECT_NE(temporal.renderFrame(scene, f).stats.backend.find("vulkan"), std::string::npos);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 15.0 / 16.0, 0.01);
    temporal.renderFrame(scene, 20); // a gap: no history
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9);
    // Fallback pixels are not history: only frame 20's marches are reprojected into frame 21.
    temporal.renderFrame(scene, 21);
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 1.0 / 16.0, 0.01);
    scene.width = 50; // partial edge blocks; new buffers, no history
    scene.height = 30;
    const cloudscape::RenderResult r = temporal.renderFrame(scene, 22);
    EXPECT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
    EXPECT_EQ(r.width, 50);
    EXPECT_EQ(r.stats.rays, static_cast<uint64_t>(13 * 8));
    EXPECT_NEAR(temporal.lastBreakdown().reprojected, 0.0, 1e-9);
}
