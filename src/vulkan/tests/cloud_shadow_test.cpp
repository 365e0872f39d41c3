// GPU category: the clouds' shadow map (cloud_shadow.comp, the model's cloudShadowMapTexel) and
// the light shafts on the Vulkan backend against the CPU backend (the same model headers), under
// the validation layers: stills, the temporal resolve and the upsample of a reduced pass.
#include <cloudscape/backend.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>
#include <cloudscape/terrain.h>

#include "core/resources.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "vulkan/tests/vulkan_test_support.h"

using cloudscape::testing::channels;
using cloudscape::testing::vulkanWithValidation;

namespace {

// The mountains preset (which turns the map and the shafts on), small, with small textures.
cloudscape::Scene mountains() {
    cloudscape::Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    s.width = 64;
    s.height = 36;
    s.weatherResolution = 64;
    s.terrainResolution = 128;
    s.cloudShadowResolution = 128;
    return s;
}

cloudscape::SceneResources resourcesFor(const cloudscape::Scene& s) {
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    r.weatherCoverage = cloudscape::CoverageField(r.weather);
    cloudscape::prepareAtmosphere(s, r);
    cloudscape::prepareTerrain(s, r);
    return r;
}

double psnr(const std::vector<float>& a, const std::vector<float>& b) {
    return cloudscape::compareImages(channels(a, 0, 3), channels(b, 0, 3), 3).psnr;
}

} // namespace

TEST(VulkanCloudShadow, StillsWithTheMapAndShaftsMatchTheCpuBackend) {
    cloudscape::Scene s = mountains();
    ASSERT_TRUE(s.cloudShadowEnabled && s.shaftsEnabled) << "the preset turns both on";
    const cloudscape::SceneResources r = resourcesFor(s);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    const cloudscape::RenderResult gpu = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    const double agree = psnr(cpu.composite, gpu.composite);
    // The map and shafts are used on the device: without them the image is another one.
    s.shaftsEnabled = false;
    s.cloudShadowEnabled = false;
    const cloudscape::RenderResult plain = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    const double changed = psnr(plain.composite, gpu.composite);
    std::printf("shadow map + shafts still: CPU vs Vulkan %.1f dB; Vulkan on vs off %.1f dB\n",
                agree, changed);
    EXPECT_GT(agree, 42.0);
    EXPECT_LT(changed, agree - 6.0) << "the backends agree far better than on differs from off";
}

TEST(VulkanCloudShadow, TemporalAndUpsampledFramesMatchTheCpuBackend) {
    cloudscape::Scene s = mountains();
    s.cloudResolution = 0.5f;
    const cloudscape::SceneResources r = resourcesFor(s);
    cloudscape::TemporalRenderer cpu(r);
    cloudscape::TemporalRenderer gpu(r, vulkanWithValidation());
    for (int f = 0; f < 3; ++f) {
        s.timeS = 20.0f * float(f); // the map is remade each frame as the clouds move
        const cloudscape::RenderResult a = cpu.renderFrame(s, f);
        const cloudscape::RenderResult b = gpu.renderFrame(s, f);
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        const double agree = psnr(a.composite, b.composite);
        std::printf("shadow map + shafts temporal frame %d: CPU vs Vulkan %.1f dB\n", f, agree);
        EXPECT_GT(agree, 42.0) << "frame " << f;
    }
}
