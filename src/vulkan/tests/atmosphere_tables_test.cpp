// GPU category: the atmosphere's tables made on the device (atmosphere_tables.comp through
// vulkan::AtmosphereTables) against the host's computeAtmosphereLuts: every texel of the buffer
// the renders read, for a day and for a moonlit night, and after a live change of the sun through
// the persistent Renderer.
#include <cloudscape/metrics.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "model/atmosphere.glsl.h"
#include "vulkan/tests/vulkan_test_support.h"
#include "vulkan/vulkan_device.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace cm = cloudscape::model;
using cloudscape::Scene;
using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

namespace {

const char* const kTableNames[cm::ATMOSPHERE_TABLE_COUNT] = {"transmittance",
                                                             "multiple scattering",
                                                             "sky view",
                                                             "ambient above",
                                                             "ambient below",
                                                             "moon's sky view",
                                                             "aerial-perspective light",
                                                             "aerial-perspective transmittance",
                                                             "moon's aerial-perspective light"};

// The texels of every table outside the kernel test's tolerance (atmosphere_kernels_test.cpp):
// 0.2 % of the host's value or 1e-6 absolute, per RGB channel (float sums in another order and
// the device's exp/sqrt). One line per table that has any, with its worst texel; empty if none.
std::string tableDifferences(const std::vector<glm::vec4>& device,
                             const std::vector<glm::vec4>& host) {
    std::ostringstream out;
    if (device.size() != host.size())
        return "sizes differ: " + std::to_string(device.size()) + " against " +
               std::to_string(host.size()) + "\n";
    for (int table = 0; table < cm::ATMOSPHERE_TABLE_COUNT; ++table) {
        const glm::ivec3 layout = cm::atmosphereTableLayout(table);
        int bad = 0;
        double worst = 0.0;
        int worstTexel = -1;
        for (int i = layout.x; i < layout.x + layout.y * layout.z; ++i)
            for (int c = 0; c < 3; ++c) {
                const double expected = host[static_cast<size_t>(i)][c];
                const double error = std::abs(device[static_cast<size_t>(i)][c] - expected);
                const double excess = error / (2e-3 * std::abs(expected) + 1e-6);
                if (excess > 1.0 && c == 0)
                    ++bad;
                if (excess > worst) {
                    worst = excess;
                    worstTexel = i - layout.x;
                }
            }
        if (worst > 1.0)
            out << kTableNames[table] << ": " << bad << " texels outside; the worst, ("
                << worstTexel % layout.y << ", " << worstTexel / layout.y << "), at " << worst
                << " x the tolerance\n";
    }
    return out.str();
}

bool allZero(const std::vector<glm::vec4>& texels, int table) {
    const glm::ivec3 layout = cm::atmosphereTableLayout(table);
    for (int i = layout.x; i < layout.x + layout.y * layout.z; ++i)
        if (texels[static_cast<size_t>(i)] != glm::vec4(0.0f))
            return false;
    return true;
}

Scene nightScene() {
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("night"));
    s.width = 64;
    s.height = 36;
    return s;
}

Scene dayScene() {
    Scene s;
    s.width = 64;
    s.height = 36;
    s.cameraPitchDeg = 8.0f; // some sky and its horizon above the clouds
    return s;
}

// The shared textures without the atmosphere's tables, as a Renderer prepares them: a device
// opened over them starts with zeros in the tables' buffer, not the host's tables.
cloudscape::SceneResources resourcesWithoutTables() {
    cloudscape::SceneResources resources = sharedResources();
    resources.atmosphere.clear();
    resources.atmosphereInputs.clear();
    return resources;
}

} // namespace

TEST(VulkanAtmosphere, TheDeviceFillsEveryTableAsTheHostDoes) {
    cloudscape::vulkan::VulkanDevice device(vulkanWithValidation(), resourcesWithoutTables());
    cloudscape::vulkan::AtmosphereTables& tables = device.atmosphereTables();
    // The night first: the day that follows must leave no moon in the buffer it rewrites.
    for (const Scene& scene : {nightScene(), dayScene()}) {
        const cm::SkyParams sky = cloudscape::makeSkyParams(scene);
        const bool night = sky.moonEnabled != 0;
        const std::vector<glm::vec4> host = cloudscape::computeAtmosphereLuts(sky);
        tables.fill(sky);
        const std::vector<glm::vec4> got = tables.texels();
        EXPECT_EQ(tableDifferences(got, host), "") << (night ? "night" : "day");
        EXPECT_EQ(allZero(got, cm::ATMOSPHERE_TABLE_MOON_SKYVIEW), !night);
        EXPECT_EQ(allZero(got, cm::ATMOSPHERE_TABLE_MOON_AERIAL_SCATTER), !night);
        std::printf("%s: tables on the device in %.1f ms of GPU time\n", night ? "night" : "day",
                    tables.gpuMs());
    }
    EXPECT_EQ(cloudscape::makeSkyParams(nightScene()).moonEnabled, 1) << "the night has a moon";
    const std::vector<std::string> messages = device.context().takeValidationMessages();
    EXPECT_TRUE(messages.empty()) << messages.front();
}

TEST(VulkanAtmosphere, ALiveSunChangeRemakesTheTablesOnTheDevice) {
    // The device makes the tables the resources lack at start-up.
    const Scene day = dayScene();
    cloudscape::Renderer renderer(day, resourcesWithoutTables(), vulkanWithValidation());
    ASSERT_TRUE(renderer.resources().atmosphereOnDevice);
    EXPECT_EQ(tableDifferences(renderer.resources().atmosphere,
                               cloudscape::computeAtmosphereLuts(cloudscape::makeSkyParams(day))),
              "");
    const cloudscape::RenderResult before = renderer.render(day);

    Scene low = day;
    low.sunElevationDeg = 4.0f;
    const cloudscape::UpdateReport report = renderer.update(low);
    EXPECT_TRUE(report.atmosphere);
    ASSERT_TRUE(renderer.resources().atmosphereOnDevice);
    // The copy read back from the buffer the renders bind: the low sun's tables.
    EXPECT_EQ(tableDifferences(renderer.resources().atmosphere,
                               cloudscape::computeAtmosphereLuts(cloudscape::makeSkyParams(low))),
              "");
    const cloudscape::RenderResult after = renderer.render(low);
    EXPECT_TRUE(after.stats.validationMessages.empty()) << after.stats.validationMessages.front();

    // The render is the low sun's: as a one-shot render over the host's tables for it, and far
    // from the high sun's image.
    cloudscape::SceneResources hostLow = sharedResources();
    cloudscape::prepareAtmosphere(low, hostLow);
    const cloudscape::RenderResult expected =
        cloudscape::renderVulkan(low, hostLow, vulkanWithValidation());
    const auto same = cloudscape::compareImages(channels(after.composite, 0, 3),
                                                channels(expected.composite, 0, 3), 3);
    const auto moved = cloudscape::compareImages(channels(after.composite, 0, 3),
                                                 channels(before.composite, 0, 3), 3);
    std::printf("live sun change: device tables against host tables PSNR %.1f dB (mean error "
                "%.3g); the sun's change moves the image by a mean %.3g\n",
                same.psnr, same.meanError, moved.meanError);
    EXPECT_GT(same.psnr, 50.0);
    EXPECT_GT(moved.meanError, 50.0 * same.meanError);
}
