// The persistent Renderer on the CPU backend: the same images as the one-shot functions, only the
// resources a scene change touches are regenerated, and readback modes drop what is not asked for.
#include "core/atmosphere_luts.h"

#include <cloudscape/error.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/temporal.h>

#include "core/resources.h"

#include <gtest/gtest.h>

using cloudscape::Readback;
using cloudscape::Scene;

namespace {

cloudscape::SceneResources smallResources(const Scene& s) {
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    r.weatherCoverage = cloudscape::CoverageField(r.weather);
    cloudscape::prepareAtmosphere(s, r);
    return r;
}

Scene smallScene() {
    Scene s;
    s.width = 40;
    s.height = 24;
    s.weatherResolution = 64;
    s.cameraPitchDeg = 20.0f;
    return s;
}

cloudscape::BackendOptions cpu() {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Cpu;
    return o;
}

} // namespace

TEST(Renderer, MatchesTheOneShotFunctionsBitForBit) {
    const Scene s = smallScene();
    const cloudscape::SceneResources resources = smallResources(s);
    cloudscape::Renderer renderer(s, resources, cpu());
    EXPECT_EQ(renderer.backendName(), "cpu");
    const cloudscape::RenderResult still = cloudscape::renderCpu(s, resources);
    EXPECT_EQ(renderer.render(s).composite, still.composite);
    EXPECT_EQ(renderer.render(s).cloud, still.cloud); // and again, from the kept state
    cloudscape::TemporalRenderer temporal(resources);
    for (int f = 0; f < 5; ++f) {
        Scene moved = s;
        moved.cameraHeadingDeg += 0.5f * static_cast<float>(f);
        moved.timeS = static_cast<float>(f) / 24.0f;
        const cloudscape::RenderResult a = temporal.renderFrame(moved, f);
        const cloudscape::RenderResult b = renderer.renderFrame(moved, f);
        ASSERT_EQ(a.cloud, b.cloud) << "frame " << f;
        ASSERT_EQ(a.composite, b.composite) << "frame " << f;
    }
    // The camera-and-clock form continues the sequence at the next frame (5).
    const cloudscape::Camera camera = cloudscape::cameraOf(renderer.scene());
    const cloudscape::RenderResult next = renderer.renderFrame(camera, 5.0f / 24.0f);
    const cloudscape::RenderResult expected =
        temporal.renderFrame(cloudscape::withCamera(renderer.scene(), camera, 5.0f / 24.0f), 5);
    EXPECT_EQ(next.composite, expected.composite);
    EXPECT_GT(renderer.lastBreakdown().reprojected, 0.0) << "the history was used";
    EXPECT_TRUE(next.cloud.empty()) << "Display readback by default";
}

TEST(Renderer, ReadbackModesKeepOnlyWhatIsAskedFor) {
    const Scene s = smallScene();
    cloudscape::Renderer renderer(s, smallResources(s), cpu());
    const cloudscape::RenderResult all = renderer.render(s);
    const cloudscape::RenderResult display = renderer.render(s, {}, Readback::Display);
    const cloudscape::RenderResult none = renderer.render(s, {}, Readback::None);
    EXPECT_EQ(display.composite, all.composite);
    EXPECT_TRUE(display.cloud.empty() && display.depth.empty());
    EXPECT_TRUE(none.composite.empty() && none.cloud.empty());
    EXPECT_EQ(none.width, s.width);
    EXPECT_EQ(none.stats.densitySamples, all.stats.densitySamples);
}

TEST(Renderer, UpdatesRegenerateOnlyWhatAChangeTouches) {
    const Scene s = smallScene();
    cloudscape::Renderer renderer(s, smallResources(s), cpu());
    const cloudscape::RenderResult before = renderer.render(s);

    Scene covered = s;
    covered.coverage = 0.8f; // a uniform
    covered.sunElevationDeg = 20.0f;
    const cloudscape::UpdateReport uniform = renderer.update(covered);
    EXPECT_FALSE(uniform.noise || uniform.weather || uniform.depth);
    EXPECT_NE(renderer.render(covered).composite, before.composite);

    Scene retyped = covered;
    retyped.cloudType = 0.3f; // the procedural map's input
    const cloudscape::UpdateReport weather = renderer.update(retyped);
    EXPECT_TRUE(weather.weather);
    EXPECT_FALSE(weather.noise);
    // The regenerated map is the one a fresh preparation makes.
    EXPECT_EQ(renderer.resources().weather.mips, cloudscape::prepareWeather(retyped).mips);

    // The rules themselves (a seed change would regenerate the full-size noise here).
    Scene reseeded = s;
    reseeded.seed = 7;
    const cloudscape::ResourceChanges seed = cloudscape::resourceChanges(s, reseeded);
    EXPECT_TRUE(seed.noise && seed.weather); // the procedural map follows the seed
    Scene painted = s;
    painted.weatherImage = "storm.png";
    Scene paintedReseeded = painted;
    paintedReseeded.seed = 7;
    EXPECT_FALSE(cloudscape::resourceChanges(painted, paintedReseeded).weather);
    Scene resized = s;
    resized.width = 80;
    EXPECT_FALSE(cloudscape::resourceChanges(s, resized).depth) << "no depth file";
    resized.depthFile = "depth.exr";
    Scene resizedAgain = resized;
    resizedAgain.width = 40;
    EXPECT_TRUE(cloudscape::resourceChanges(resized, resizedAgain).depth);
}

// The base noise's clearance field is made only for a scene whose march reads it
// (march.noise_skipping): a renderer whose scene turns it on makes it then, and the march uses
// it (fewer samples, the same image: the skips are exact).
TEST(Renderer, TurningNoiseSkippingOnMakesTheClearanceField) {
    const Scene s = smallScene();
    cloudscape::SceneResources resources = smallResources(s);
    cloudscape::prepareNoise(s, resources); // the full-size noise, where the field skips
    EXPECT_TRUE(resources.noise.baseClearance.empty()) << "not made for a scene without it";
    Scene skipping = s;
    skipping.noiseSkipping = true;
    EXPECT_TRUE(cloudscape::wantsNoiseClearance(skipping));
    skipping.emptySpaceSkipping = false;
    EXPECT_FALSE(cloudscape::wantsNoiseClearance(skipping)) << "it skips only with the grid";
    skipping.emptySpaceSkipping = true;

    cloudscape::Renderer renderer(s, resources, cpu());
    const cloudscape::RenderResult plain = renderer.render(s);
    const cloudscape::UpdateReport report = renderer.update(skipping);
    EXPECT_FALSE(report.noise) << "the noise itself is kept";
    const cloudscape::SceneResources& r = renderer.resources();
    EXPECT_EQ(r.noise.baseClearance, cloudscape::generateNoiseClearance(r.noise.base));
    const cloudscape::RenderResult skipped = renderer.render(skipping);
    EXPECT_EQ(skipped.composite, plain.composite);
    EXPECT_LT(skipped.stats.densitySamples, plain.stats.densitySamples);
}

// An update refused half-way (the camera under a terrain made higher) must leave nothing made
// for the refused scene behind: going back to the scene before remakes what the refused update
// had already remade, instead of keeping the refused scene's terrain under the old scene.
TEST(Renderer, ARefusedUpdateLeavesNothingOfTheRefusedScene) {
    Scene s = smallScene();
    s.terrainEnabled = true;
    s.terrainResolution = 64;
    s.cameraPosition.y = 3000.0f;
    cloudscape::SceneResources r = smallResources(s);
    cloudscape::prepareTerrain(s, r);
    cloudscape::Renderer renderer(s, std::move(r), cpu());
    const std::vector<float> heights = renderer.resources().terrain.heights;
    Scene high = s;
    high.terrainHeightM = 20000.0f;
    EXPECT_THROW(renderer.update(high), cloudscape::Error);
    cloudscape::UpdateReport back;
    ASSERT_NO_THROW(back = renderer.update(s));
    EXPECT_TRUE(back.terrain) << "the refused update's terrain is made again for the scene";
    EXPECT_EQ(renderer.resources().terrain.heights, heights);
    EXPECT_FALSE(renderer.update(s).terrain) << "and only once";
}
