// The light's horizon over the terrain (appendLightHorizon, terrainLightHorizonAt): the altitude a
// point must reach to see the sun past the field, made once per light direction, standing in for
// the terrain's shadow rays in the real-time shading (terrainSunVisibility).
#include <cloudscape/renderer.h>
#include <cloudscape/terrain.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "model/ground.glsl.h"
#include "model/terrain.glsl.h"

#include "small_resources.h"
#include "terrain_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using cloudscape::HeightField;
using cloudscape::Scene;
namespace cm = cloudscape::model;

using cloudscape::test::BoundTerrain;
using cloudscape::test::fieldOf;

TEST(TerrainLight, TheHorizonBehindARidgeFallsAtTheSunsElevation) {
    // A ridge along x at z = 0 (slopes of 1:2, steeper than the sun), 128 texels over 8 km, the
    // sun in the north (+z) at 20 degrees: behind the ridge a point must be as high as the line
    // from the ridge's top texel down at the sun's elevation; in front of it, on the ground.
    const int n = 128;
    const float extent = 8000.0f, texel = extent / n;
    HeightField f = fieldOf(
        n, extent, [](float, float z) { return std::max(0.0f, 1000.0f - 0.5f * std::fabs(z)); });
    const size_t fieldTexels = f.heights.size();
    const float tanSun = std::tan(glm::radians(20.0f));
    const glm::vec3 sun(0.0f, std::sin(glm::radians(20.0f)), std::cos(glm::radians(20.0f)));
    cloudscape::appendLightHorizon(f, sun, texel, texel);
    ASSERT_EQ(f.lightHorizonOffset, fieldTexels);
    ASSERT_EQ(f.heights.size(), fieldTexels + size_t(n) * n);
    const float top = f.heights[size_t(n / 2) * n]; // the ridge's top texels: z = +-31.25 m
    for (int z = 0; z < n; ++z) {
        const float zm = (z + 0.5f) * texel - 0.5f * extent;
        const float ground = f.heights[size_t(z) * n + 7];
        const float horizon = f.heights[f.lightHorizonOffset + size_t(z) * n + 7];
        const float expected =
            zm < 0.0f ? std::max(ground, top - tanSun * (-0.5f * texel - zm)) : ground;
        EXPECT_NEAR(horizon, expected, 0.01f) << "z = " << zm;
    }
    // Made again for another light, it replaces the first.
    cloudscape::appendLightHorizon(f, glm::vec3(0.0f, 1.0f, 0.0f), texel, texel);
    EXPECT_EQ(f.heights.size(), fieldTexels + size_t(n) * n);
    EXPECT_EQ(f.heights[f.lightHorizonOffset + size_t(10) * n], f.heights[size_t(10) * n])
        << "a sun overhead: nothing stands higher than the ground";
}

TEST(TerrainLight, TheHorizonAgreesWithTheShadowRaysOverTheMountains) {
    // Points on the mountains preset's terrain over its whole field (its own low sun, from the
    // side: the sweep reads between two texels), lit or not by the horizon and by the march's
    // shadow ray. They may disagree only on the shadows' edges, within a texel.
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    s.skyModel = cloudscape::SkyModel::Gradient;
    cloudscape::SceneResources r;
    cloudscape::prepareTerrain(s, r);
    ASSERT_TRUE(cloudscape::prepareTerrainLight(s, r));
    EXPECT_FALSE(cloudscape::prepareTerrainLight(s, r)) << "made once for a light";
    BoundTerrain b(s, r.terrain);
    cm::CloudParams marched = b.params;
    cm::CloudParams horizon = b.params;
    horizon.terrain.lightHorizon = static_cast<int>(r.terrain.lightHorizonOffset);
    long points = 0, lit = 0, disagree = 0;
    const int grid = 150;
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            const glm::vec2 xz =
                b.params.terrain.origin +
                (glm::vec2(i + 0.5f, j + 0.5f) / float(grid) - 0.5f) * b.params.terrain.extent;
            const float h = cm::terrainHeightAt(xz, b.params.terrain);
            const glm::vec3 p(xz.x, h, xz.y);
            const glm::vec3 up = glm::normalize(p - cm::planetCentre(b.params.planetRadius));
            const float lift = cm::terrainLeaveLift(1000.0f);
            const float a = cm::terrainSunVisibility(p, up, lift, 1.0f, marched);
            const float c = cm::terrainSunVisibility(p, up, lift, 1.0f, horizon);
            ++points;
            lit += a > 0.5f ? 1 : 0;
            disagree += (a > 0.5f) != (c > 0.5f) ? 1 : 0;
        }
    std::printf("mountains: %ld points, %ld lit by the shadow rays, %ld disagree with the "
                "horizon (%.2f %%)\n",
                points, lit, disagree, 100.0 * double(disagree) / double(points));
    EXPECT_GT(lit, points / 5);
    EXPECT_LT(lit, points * 95 / 100) << "the low sun leaves some of the field in shadow";
    EXPECT_LT(disagree, points / 50);
}

TEST(TerrainLight, TheHorizonIsUsedOnlyForTheLightItWasMadeFor) {
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    s.terrainResolution = 128;
    s.weatherResolution = 64;
    cloudscape::SceneResources r = cloudscape::test::smallResources(s);
    cloudscape::prepareTerrain(s, r);
    EXPECT_EQ(cloudscape::makeCloudParams(s, r).terrain.lightHorizon, 0) << "none made yet";
    ASSERT_TRUE(cloudscape::prepareTerrainLight(s, r));
    EXPECT_EQ(cloudscape::makeCloudParams(s, r).terrain.lightHorizon,
              static_cast<int>(r.terrain.lightHorizonOffset));
    Scene later = s;
    later.sunElevationDeg += 5.0f;
    EXPECT_EQ(cloudscape::makeCloudParams(later, r).terrain.lightHorizon, 0)
        << "a stale horizon is not read: the shadow rays are marched";
    EXPECT_TRUE(cloudscape::prepareTerrainLight(later, r));
    EXPECT_GT(cloudscape::makeCloudParams(later, r).terrain.lightHorizon, 0);
}
