// GPU category: the terrain on the Vulkan backend against the CPU backend (the same model
// headers), under the validation layers: stills, the temporal resolve and the upsample of a
// reduced-resolution pass, and the cloud march ending at the terrain.
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

// The mountains preset, small, with small textures.
cloudscape::Scene mountains() {
    cloudscape::Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    s.width = 64;
    s.height = 36;
    s.weatherResolution = 64;
    s.terrainResolution = 128;
    // The terrain as these tests measured it (lit through the two-sample cloud shadow): the
    // shadow map and shafts the preset turns on have their own parity tests
    // (cloud_shadow_test.cpp).
    s.cloudShadowEnabled = false;
    s.shaftsEnabled = false;
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

// Composite PSNR (peak: the CPU image's largest value) and the fraction of pixels whose
// luminance differs by more than 2 %.
struct Agreement {
    double psnr;
    double differing;
};
Agreement agreement(const std::vector<float>& cpu, const std::vector<float>& gpu) {
    const auto d = cloudscape::compareImages(channels(cpu, 0, 3), channels(gpu, 0, 3), 3);
    size_t off = 0;
    for (size_t i = 0; i < cpu.size(); i += 4) {
        const double a = 0.2126 * cpu[i] + 0.7152 * cpu[i + 1] + 0.0722 * cpu[i + 2];
        const double b = 0.2126 * gpu[i] + 0.7152 * gpu[i + 1] + 0.0722 * gpu[i + 2];
        off += std::fabs(a - b) > 0.02 * std::max(a, 1e-3) ? 1 : 0;
    }
    return {d.psnr, double(off) / double(cpu.size() / 4)};
}

} // namespace

TEST(VulkanTerrain, StillMatchesTheCpuBackend) {
    const cloudscape::Scene s = mountains();
    const cloudscape::SceneResources r = resourcesFor(s);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    const cloudscape::RenderResult gpu = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    const Agreement a = agreement(cpu.composite, gpu.composite);
    std::printf("terrain still: composite PSNR %.1f dB, %.2f %% of pixels differ by > 2 %%\n",
                a.psnr, 100.0 * a.differing);
    // Where the two differ is a silhouette pixel whose terrain march ends one side of a ridge on
    // one backend and the other side on the other (a last-bit float difference), or the
    // march's hit tolerance shifting a shadow edge: a few pixels, not a drift.
    // Measured on lavapipe: 48.0 dB, 0.52 % (12 pixels of 2304, on ridges and shadow edges).
    EXPECT_GT(a.psnr, 42.0);
    EXPECT_LT(a.differing, 0.02);
}

TEST(VulkanTerrain, TheDefaultLandscapesFieldsMatchTheCpuBackend) {
    // The default preset's gentle hills with their fields (terrain.field_variation), fields made
    // large so that a 64x36 image resolves them; the shadow map has its own parity tests.
    cloudscape::Scene s =
        cloudscape::loadScene(cloudscape::resolveScenePath("fair-weather-cumulus"));
    ASSERT_TRUE(s.terrainEnabled);
    ASSERT_GT(s.terrainFieldVariation, 0.0f);
    s.width = 64;
    s.height = 36;
    s.weatherResolution = 64;
    s.terrainResolution = 128;
    s.terrainFieldSizeM = 2000.0f;
    s.cloudShadowEnabled = false;
    const cloudscape::SceneResources r = resourcesFor(s);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    const cloudscape::RenderResult gpu = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    const Agreement a = agreement(cpu.composite, gpu.composite);
    cloudscape::Scene plain = s;
    plain.terrainFieldVariation = 0.0f;
    const cloudscape::RenderResult cpuPlain = cloudscape::renderCpu(plain, r);
    const Agreement fields = agreement(cpu.composite, cpuPlain.composite);
    const Agreement plainAgreement = agreement(
        cpuPlain.composite, cloudscape::renderVulkan(plain, r, vulkanWithValidation()).composite);
    std::printf("default landscape: composite PSNR %.1f dB, %.2f %% of pixels differ by > 2 %% "
                "(without fields %.1f dB, %.2f %%); %.1f %% of pixels changed by the fields\n",
                a.psnr, 100.0 * a.differing, plainAgreement.psnr, 100.0 * plainAgreement.differing,
                100.0 * fields.differing);
    EXPECT_GT(fields.differing, 0.05) << "the fields must show for this test to mean anything";
    // Measured on lavapipe: 48.8 dB, 2.65 % of pixels (61 of 2304) differing by > 2 %, the same
    // with the fields and without: those pixels are the landscape's own, not the fields' (not
    // located further; a last-bit float difference moving a sample across an edge, as in the
    // other parity tests, is the likely cause). The fields must add no disagreement: a field
    // that differed as a whole (say a hash that read a negative cell index differently) would add
    // the pixels of that field.
    EXPECT_GT(a.psnr, 42.0);
    EXPECT_LT(a.differing, 0.04);
    EXPECT_LE(a.differing, plainAgreement.differing + 0.005);
    EXPECT_GT(a.psnr, plainAgreement.psnr - 1.0);
}

TEST(VulkanTerrain, TemporalAndUpsampledFramesMatchTheCpuBackend) {
    cloudscape::Scene s = mountains();
    s.cloudResolution = 0.5f;
    const cloudscape::SceneResources r = resourcesFor(s);
    cloudscape::TemporalRenderer cpu(r);
    cloudscape::TemporalRenderer gpu(r, vulkanWithValidation());
    for (int f = 0; f < 3; ++f) {
        s.timeS = 0.5f * float(f);
        const cloudscape::RenderResult a = cpu.renderFrame(s, f);
        const cloudscape::RenderResult b = gpu.renderFrame(s, f);
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        const Agreement g = agreement(a.composite, b.composite);
        std::printf("terrain temporal frame %d: composite PSNR %.1f dB, %.2f %% differ\n", f,
                    g.psnr, 100.0 * g.differing);
        EXPECT_GT(g.psnr, 42.0) << "frame " << f; // measured 48.2-48.5 dB, 0.09 %
        EXPECT_LT(g.differing, 0.01) << "frame " << f;
    }
}

TEST(VulkanTerrain, TheCloudMarchEndsAtTheTerrain) {
    // As the CPU test: a camera in a pit whose walls rise above the cloud layer takes no density
    // samples; without the walls it does.
    cloudscape::Scene s;
    s.width = 32;
    s.height = 20;
    s.weatherResolution = 64;
    s.coverage = 0.8f;
    s.cameraPosition = {0.0f, 100.0f, 0.0f};
    s.cameraPitchDeg = 0.0f;
    s.terrainEnabled = true;
    s.terrainExtentM = 20000.0f;
    s.terrainMaxSteps = 4096; // cliffs: short sphere-tracing steps (as the CPU test)
    cloudscape::SceneResources r = resourcesFor(s);
    r.terrain = cloudscape::HeightField{};
    const cloudscape::RenderResult open = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_GT(open.stats.densitySamples, 0u);
    cloudscape::HeightField& f = r.terrain;
    f.width = f.height = 64;
    f.heights.resize(64 * 64);
    for (int z = 0; z < 64; ++z)
        for (int x = 0; x < 64; ++x) {
            const float wx = (x + 0.5f) / 64.0f * 20000.0f - 10000.0f;
            const float wz = (z + 0.5f) / 64.0f * 20000.0f - 10000.0f;
            f.heights[size_t(z) * 64 + x] = std::hypot(wx, wz) < 2000.0f ? 0.0f : 9000.0f;
        }
    cloudscape::measureHeightField(f, 20000.0f / 64.0f, 20000.0f / 64.0f);
    const cloudscape::RenderResult walled = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(walled.stats.validationMessages.empty());
    EXPECT_EQ(walled.stats.densitySamples, 0u);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    EXPECT_GT(agreement(cpu.composite, walled.composite).psnr, 42.0);
}
