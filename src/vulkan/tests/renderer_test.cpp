// GPU category: the persistent Renderer on the Vulkan backend keeps its device, textures and
// history, renders what the one-shot functions render, takes a coverage change as a uniform and
// a new weather map as one texture upload, and reads back only what is asked for.
#include <cloudscape/error.h>
#include <cloudscape/persistent_renderer.h>

#include <gtest/gtest.h>

#include <cmath>

#include "vulkan/tests/vulkan_test_support.h"

using cloudscape::Readback;
using cloudscape::Scene;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

namespace {

Scene smallScene() {
    Scene s;
    s.width = 64;
    s.height = 36;
    s.cameraPitchDeg = 20.0f;
    return s;
}

void expectNoValidationMessages(const cloudscape::RenderResult& r) {
    EXPECT_TRUE(r.stats.validationMessages.empty()) << r.stats.validationMessages.front();
}

} // namespace

TEST(VulkanRenderer, KeepsItsDeviceAndRendersWhatTheOneShotFunctionsRender) {
    const Scene s = smallScene();
    cloudscape::Renderer renderer(s, sharedResources(), vulkanWithValidation());
    EXPECT_NE(renderer.backendName().find("vulkan"), std::string::npos);
    const cloudscape::RenderResult once =
        cloudscape::renderVulkan(s, sharedResources(), vulkanWithValidation());
    for (int i = 0; i < 2; ++i) {
        const cloudscape::RenderResult r = renderer.render(s);
        expectNoValidationMessages(r);
        EXPECT_EQ(r.composite, once.composite) << "render " << i;
        EXPECT_EQ(r.cloud, once.cloud) << "render " << i;
        EXPECT_EQ(r.stats.densitySamples, once.stats.densitySamples);
    }
    const cloudscape::Renderer::DeviceImage image = renderer.deviceImage();
    EXPECT_NE(image.buffer, 0u);
    EXPECT_EQ(image.bytes, static_cast<uint64_t>(s.width) * s.height * 16);
    // Half-resolution clouds are upsampled on the device, as the one-shot render does.
    Scene half = s;
    half.cloudResolution = 0.5f;
    const cloudscape::RenderResult reduced = renderer.render(half);
    expectNoValidationMessages(reduced);
    EXPECT_EQ(reduced.composite,
              cloudscape::renderVulkan(half, sharedResources(), vulkanWithValidation()).composite);
    EXPECT_EQ(reduced.stats.rays, static_cast<uint64_t>(32 * 18));
}

TEST(VulkanRenderer, CoverageIsAUniformAndANewWeatherMapOneUpload) {
    const Scene s = smallScene();
    cloudscape::Renderer renderer(s, sharedResources(), vulkanWithValidation());
    const cloudscape::RenderResult before = renderer.render(s, {}, Readback::Display);

    Scene covered = s;
    covered.coverage = 0.75f;
    const cloudscape::UpdateReport uniform = renderer.update(covered);
    EXPECT_FALSE(uniform.noise || uniform.weather || uniform.depth);
    const cloudscape::RenderResult after = renderer.render(covered, {}, Readback::Display);
    expectNoValidationMessages(after);
    EXPECT_NE(after.composite, before.composite);
    // The same image a renderer opened for that coverage makes.
    cloudscape::Renderer fresh(covered, sharedResources(), vulkanWithValidation());
    EXPECT_EQ(after.composite, fresh.render(covered, {}, Readback::Display).composite);

    Scene retyped = covered;
    retyped.cloudType = 0.35f;
    EXPECT_TRUE(renderer.update(retyped).weather);
    const cloudscape::RenderResult uploaded = renderer.render(retyped, {}, Readback::Display);
    expectNoValidationMessages(uploaded);
    cloudscape::SceneResources regenerated = sharedResources();
    regenerated.weather = cloudscape::prepareWeather(retyped);
    regenerated.weatherCoverage = cloudscape::CoverageField(regenerated.weather);
    cloudscape::Renderer reference(retyped, regenerated, vulkanWithValidation());
    EXPECT_EQ(uploaded.composite, reference.render(retyped, {}, Readback::Display).composite);
}

// A scene that turns march.noise_skipping on makes the clearance field (resources prepared for
// a scene without it have none) and the device takes it: the same image, fewer samples.
TEST(VulkanRenderer, TurningNoiseSkippingOnUploadsTheClearanceField) {
    const Scene s = smallScene();
    cloudscape::SceneResources resources = sharedResources();
    resources.noise.baseClearance.clear();
    cloudscape::Renderer renderer(s, resources, vulkanWithValidation());
    const cloudscape::RenderResult plain = renderer.render(s);
    Scene skipping = s;
    skipping.noiseSkipping = true;
    // An update that turns the key on and then fails (a weather image that is not there) must
    // not leave the field on the host only: the next update would find it made and not upload.
    Scene failing = skipping;
    failing.weatherImage = "/nonexistent/weather.png";
    EXPECT_THROW(renderer.update(failing), cloudscape::Error);
    const cloudscape::RenderResult skipped = renderer.render(skipping);
    expectNoValidationMessages(skipped);
    EXPECT_FALSE(renderer.resources().noise.baseClearance.empty());
    EXPECT_EQ(skipped.composite, plain.composite);
    EXPECT_LT(skipped.stats.densitySamples, plain.stats.densitySamples);
}

TEST(VulkanRenderer, TemporalFramesReadBackOnlyTheDisplayedImage) {
    Scene s = smallScene();
    s.cloudResolution = 0.5f; // the upsample on the device too
    cloudscape::Renderer all(s, sharedResources(), vulkanWithValidation());
    cloudscape::Renderer display(s, sharedResources(), vulkanWithValidation());
    for (int f = 0; f < 6; ++f) {
        Scene moved = s;
        moved.timeS = static_cast<float>(f) / 24.0f;
        const cloudscape::RenderResult a = all.renderFrame(moved, f, Readback::All);
        const cloudscape::RenderResult d = display.renderFrame(moved, f, Readback::Display);
        expectNoValidationMessages(d);
        ASSERT_EQ(a.composite, d.composite) << "frame " << f;
        EXPECT_EQ(a.cloud.size(), static_cast<size_t>(s.width) * s.height * 4);
        EXPECT_TRUE(d.cloud.empty() && d.depth.empty());
        EXPECT_EQ(a.stats.densitySamples, d.stats.densitySamples);
    }
    EXPECT_NE(display.deviceImage().buffer, 0u);
    EXPECT_EQ(display.renderFrame(s, 6, Readback::None).composite.size(), 0u);
}

// Two renderers on their own devices in one process, one under the validation layers and one
// not, used in turn (a library user's viewer beside a thumbnail renderer; the shadow-map test
// once had a second one by choosing Auto): each device's calls must go down its own chain. The
// dispatcher loaded with the second device's entry points sent the first's calls to lavapipe
// directly, which crashed.
TEST(VulkanRenderer, TwoRenderersOnTheirOwnDevicesWorkInTurn) {
    const Scene s = smallScene();
    cloudscape::Renderer checked(s, sharedResources(), vulkanWithValidation());
    cloudscape::BackendOptions plainOptions;
    plainOptions.choice = cloudscape::BackendChoice::Vulkan;
    cloudscape::Renderer plain(s, sharedResources(), plainOptions);
    const cloudscape::RenderResult a = checked.render(s);
    const cloudscape::RenderResult b = plain.render(s);
    const cloudscape::RenderResult c = checked.renderFrame(s, 0);
    const cloudscape::RenderResult d = plain.renderFrame(s, 0);
    expectNoValidationMessages(a);
    expectNoValidationMessages(c);
    EXPECT_EQ(a.composite, b.composite);
    EXPECT_EQ(c.composite, d.composite);
}

// The record of what made each pixel (the viewer's temporal-source and samples views), read back
// from the device's history: its sources agree with the frame's breakdown (the device's own
// counters), its sample counts add up to the frame's density samples, and it matches the CPU
// backend's record.
TEST(VulkanRenderer, TheTemporalRecordAgreesWithTheFramesCountersAndTheCpu) {
    Scene s = smallScene();
    s.movingBlock2x2 = true; // the pan marches a quarter of the pixels
    cloudscape::Renderer gpu(s, sharedResources(), vulkanWithValidation());
    cloudscape::BackendOptions onCpu;
    onCpu.choice = cloudscape::BackendChoice::Cpu;
    cloudscape::Renderer cpu(s, sharedResources(), onCpu);
    size_t sourcesDiffering = 0, pixels = 0;
    uint64_t gpuInCloud = 0, cpuInCloud = 0, gpuSkips = 0, cpuSkips = 0;
    for (int f = 0; f < 18; ++f) {
        s.cameraHeadingDeg = f < 12 ? 0.0f : 0.5f * float(f - 11); // still, then a slow pan
        const cloudscape::RenderResult r = gpu.renderFrame(s, f);
        expectNoValidationMessages(r);
        const cloudscape::RenderResult onCpu = cpu.renderFrame(s, f);
        gpuInCloud += r.stats.cloudSamples;
        cpuInCloud += onCpu.stats.cloudSamples;
        gpuSkips += r.stats.emptySkips;
        cpuSkips += onCpu.stats.emptySkips;
        const cloudscape::TemporalDebugImage image = gpu.temporalDebug();
        const cloudscape::TemporalDebugImage reference = cpu.temporalDebug();
        ASSERT_EQ(image.source.size(), size_t(s.width) * s.height);
        ASSERT_EQ(reference.source.size(), image.source.size());
        size_t counts[3] = {0, 0, 0};
        double total = 0.0;
        for (size_t i = 0; i < image.source.size(); ++i) {
            ++counts[static_cast<int>(image.source[i])];
            total += image.samples[i];
            sourcesDiffering += image.source[i] != reference.source[i];
        }
        pixels += image.source.size();
        const double n = double(image.source.size());
        const cloudscape::TemporalRenderer::Breakdown b = gpu.lastBreakdown();
        EXPECT_NEAR(counts[1] / n, b.reprojected, 1e-9) << "frame " << f;
        EXPECT_NEAR(counts[2] / n, b.fallback, 1e-9) << "frame " << f;
        // A block's worth of copies of each march: 4x4 blocks still, 2x2 while panning.
        const double blockPixels = f < 12 ? 16.0 : 4.0;
        EXPECT_EQ(total, blockPixels * double(r.stats.densitySamples)) << "frame " << f;
    }
    std::printf("temporal record: %zu of %zu pixel sources differ from the CPU's\n",
                sourcesDiffering, pixels);
    EXPECT_LT(double(sourcesDiffering), 0.01 * double(pixels));
    // The marches' samples in cloud and skips, counted on the device as on the CPU.
    EXPECT_GT(cpuInCloud, 0u);
    EXPECT_NEAR(double(gpuInCloud), double(cpuInCloud), 0.02 * double(cpuInCloud));
    EXPECT_GT(cpuSkips, 0u);
    EXPECT_NEAR(double(gpuSkips), double(cpuSkips), 0.02 * double(cpuSkips));
    gpu.render(s);
    EXPECT_TRUE(gpu.temporalDebug().empty());
}

// An edit of the weather map in place (the viewer's brush) reaches the device as a copy of its
// footprint at every level: the device's map reads back as the host's, and the edited renderer
// renders exactly what a renderer given the edited map whole renders (the same texels sampled,
// the same coverage distribution and empty-space cells). A rectangle outside the map is refused.
TEST(VulkanRenderer, AWeatherEditReachesTheDeviceAsTheWholeEditedMapWould) {
    const Scene s = smallScene();
    cloudscape::Renderer edited(s, sharedResources(), vulkanWithValidation());
    expectNoValidationMessages(edited.render(s, {}, Readback::Display));
    const uint64_t version = edited.weatherMapVersion();
    const std::vector<cloudscape::TexelRect> rects = {{200, 230, 60, 50}, {0, 0, 7, 3}};
    edited.editWeatherMap(rects, [&](cloudscape::Texture2D& map) {
        for (int l = 0; l < map.levelCount(); ++l)
            for (const cloudscape::TexelRect& r : cloudscape::weatherFootprint(rects, map, l))
                for (int j = r.y; j < r.y + r.height; ++j)
                    for (int i = r.x; i < r.x + r.width; ++i) {
                        float* t = map.texel(l, i, j);
                        t[0] = t[3] = 1.0f; // the whole coverage field
                        t[1] = 0.0f;
                    }
    });
    EXPECT_EQ(edited.weatherMapVersion(), version) << "an edit, not a new map";
    const cloudscape::Texture2D& map = edited.resources().weather;
    const std::vector<uint8_t> device = edited.deviceWeatherMap();
    size_t k = 0, mismatches = 0;
    for (const std::vector<float>& level : map.mips)
        for (float v : level)
            mismatches += k < device.size() && device[k++] != std::lround(v * 255.0f);
    EXPECT_EQ(k, device.size());
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(device[0], 255) << "the corner rectangle reached the device";

    cloudscape::SceneResources whole = sharedResources();
    whole.weather = map;
    whole.weatherCoverage = {};
    cloudscape::Renderer uploaded(s, std::move(whole), vulkanWithValidation());
    const cloudscape::RenderResult a = edited.render(s, {}, Readback::Display);
    const cloudscape::RenderResult b = uploaded.render(s, {}, Readback::Display);
    expectNoValidationMessages(a);
    EXPECT_EQ(a.composite, b.composite);

    try {
        edited.editWeatherMap({{500, 10, 20, 20}}, [](cloudscape::Texture2D&) {});
        ADD_FAILURE() << "a rectangle past the map's edge was taken";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("outside the 512x512 map"), std::string::npos)
            << e.what();
    }
}
