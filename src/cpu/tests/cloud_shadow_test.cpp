// The clouds' shadow map (src/model/cloud_shadow.glsl.h) and the light shafts
// (src/model/light_shafts.glsl.h) on the CPU backend: the map against a fine march of the same
// density, the terrain's direct sun under thick cloud and in gaps, the shadow's motion with the
// wind, shadowed air against lit air, the shafts' temporal stability, and the keys' refusals.
#include <cloudscape/backend.h>
#include <cloudscape/error.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/renderer.h>
#include <cloudscape/temporal.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "core/tests/kept_shadow_map_checks.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_model.h"

#include "small_resources.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using cloudscape::Scene;
namespace cm = cloudscape::model;
namespace cpu = cloudscape::cpu;

namespace {

using cloudscape::test::smallResources;

// A scene with the map on: broken cumulus, a sun 35 degrees up, the camera low.
Scene shadowScene() {
    Scene s;
    s.width = 48;
    s.height = 27;
    s.weatherResolution = 64;
    s.coverage = 0.5f;
    s.sunElevationDeg = 35.0f;
    s.sunHeadingDeg = 200.0f;
    s.cameraPosition = {0.0f, 300.0f, 0.0f};
    s.cloudShadowEnabled = true;
    s.cloudShadowResolution = 128;
    s.cloudShadowExtentM = 20000.0f;
    return s;
}

// The parameters, resources and map of a scene, bound to this thread.
struct BoundShadow {
    cloudscape::SceneResources resources;
    cm::CloudParams params;
    cpu::TextureSet set;
    std::vector<glm::vec4> map;
    explicit BoundShadow(const Scene& s)
        : resources(smallResources(s)),
          params(cloudscape::makeCloudParams(s, resources)), set{&resources.noise.base,
                                                                 &resources.noise.detail,
                                                                 &resources.noise.curl,
                                                                 &resources.weather} {
        set.atmosphere = resources.atmosphere.data();
        remake();
    }
    void remake() {
        map = cpu::computeCloudShadowMap(params, set);
        cpu::bindCloudShadowMap(set, map);
    }
};

// The clouds' transmittance toward the sun from p by a fine march of the full density at the mip
// the map reads (the light march's): what the map approximates.
float referenceTransmittance(glm::vec3 p, const cm::CloudParams& P) {
    const glm::vec3 sun = P.sky.sunDirection;
    const glm::vec4 spans = cm::shellIntervals(p, sun, P.planetRadius, P.layerBottom, P.layerTop);
    const float crossing = spans.y - spans.x;
    if (crossing <= 0.0f)
        return 1.0f;
    const int steps = 512;
    const float dt = crossing / steps;
    float depth = 0.0f;
    for (int i = 0; i < steps; ++i)
        depth += cm::extinctionOf(cm::cloudDensityAt(p + sun * (spans.x + (i + 0.5f) * dt),
                                                     float(P.lightMipBias), false, P),
                                  P) *
                 dt;
    return std::exp(-depth);
}

// The reference transmittance at p and at four points 1.5 map texels around it: all of them
// below `below` (deep under cloud) or all of them 1 (well inside a gap).
bool everywhereAround(glm::vec3 p, const cm::CloudParams& P, float texel, bool gap) {
    const glm::vec2 offsets[] = {{0, 0}, {1.5f, 0}, {-1.5f, 0}, {0, 1.5f}, {0, -1.5f}};
    for (glm::vec2 o : offsets) {
        const float t = referenceTransmittance(p + glm::vec3(o.x, 0.0f, o.y) * texel, P);
        if (gap ? t < 1.0f : t > 0.01f)
            return false;
    }
    return true;
}

} // namespace

TEST(CloudShadow, TheTerrainGetsUnderTenPercentUnderThickCloudAndOverNinetyInAGap) {
    Scene s = shadowScene();
    BoundShadow b(s);
    cpu::ScopedTextureBinding bind(b.set);
    ASSERT_FALSE(b.map.empty());
    const float texel = s.cloudShadowExtentM / float(s.cloudShadowResolution);
    // Ground points on a grid well inside the map (which is centred near the camera).
    int thick = 0, gaps = 0;
    float worstThick = 0.0f, worstGap = 1.0f;
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    for (int z = -12; z <= 12; ++z)
        for (int x = -12; x <= 12; ++x) {
            const glm::vec3 p(x * 500.0f, 0.0f, z * 500.0f);
            bool inMap = false;
            cm::cloudShadowFromMap(p, b.params, inMap);
            ASSERT_TRUE(inMap) << "the grid lies inside the map";
            // The terrain's fraction of direct sun (its own shadow cannot apply: terrain off).
            const float direct =
                cm::terrainSunVisibility(p, up, 1.0f, cm::cloudShadowAt(p, b.params), b.params);
            if (everywhereAround(p, b.params, texel, false)) {
                ++thick;
                worstThick = std::max(worstThick, direct);
            } else if (everywhereAround(p, b.params, texel, true)) {
                ++gaps;
                worstGap = std::min(worstGap, direct);
            }
        }
    std::printf("direct sun: worst of %d points under thick cloud %.4f, of %d in gaps %.4f\n",
                thick, worstThick, gaps, worstGap);
    ASSERT_GE(thick, 10) << "the scene has thick cloud to test under";
    ASSERT_GE(gaps, 10) << "and gaps";
    EXPECT_LT(worstThick, 0.1f) << "of " << thick << " points under thick cloud";
    EXPECT_GT(worstGap, 0.9f) << "of " << gaps << " points in gaps";
}

TEST(CloudShadow, TheGroundReadsTheMapInsteadOfTwoSamples) {
    Scene s = shadowScene();
    BoundShadow b(s);
    cpu::ScopedTextureBinding bind(b.set);
    // Where the map and the two cheap samples disagree most, the ground's light follows the map.
    float largest = 0.0f;
    for (int x = -20; x <= 20; ++x) {
        const glm::vec3 p(x * 300.0f, 0.0f, 1000.0f);
        bool inMap = false;
        const float mapped = cm::cloudShadowFromMap(p, b.params, inMap);
        EXPECT_EQ(cm::cloudShadowAt(p, b.params), mapped);
        largest = std::max(largest, std::fabs(mapped - cm::groundCloudShadow(p, b.params)));
    }
    EXPECT_GT(largest, 0.05f) << "the map is not the two-sample shadow under another name";
    // Outside the map the two-sample shadow stands in.
    const glm::vec3 far(200000.0f, 0.0f, 0.0f);
    EXPECT_EQ(cm::cloudShadowAt(far, b.params), cm::groundCloudShadow(far, b.params));
}

TEST(CloudShadow, TheCloudsPassDiffuseLightIntoTheirShadow) {
    // In the open nothing is added; under cloud the light below is more than the beam (the
    // cloud's forward-scattered light), never more than the open sky's, and falls as the cloud
    // thickens; under a thick cumulus it is the third of the two-stream slab's transmission that
    // leaves through the base (tau 30: 1/3 x 1 / (1 + 0.75 x 0.14 x 30) = 0.0803).
    EXPECT_EQ(cm::cloudDiffuseShare(1.0f), 0.0f);
    EXPECT_EQ(cm::lightBelowClouds(1.0f), 1.0f);
    float previous = 1.0f;
    for (float tau = 0.25f; tau <= 100.0f; tau *= 1.5f) {
        const float direct = std::exp(-tau);
        const float below = cm::lightBelowClouds(direct);
        EXPECT_GT(below, direct) << "tau " << tau;
        EXPECT_LT(below, previous) << "tau " << tau;
        previous = below;
    }
    EXPECT_NEAR(cm::lightBelowClouds(std::exp(-30.0f)), 0.0803f, 0.001f);
    // The ground in a thick shadow gets it: the ground's radiance there, less what the sky
    // alone gives it, is that share of the open ground's sunlight.
    Scene s = shadowScene();
    BoundShadow b(s);
    cpu::ScopedTextureBinding bind(b.set);
    int shadowed = 0;
    for (int x = -20; x <= 20; ++x) {
        const glm::vec3 p(x * 300.0f, 0.0f, 1000.0f);
        const float clouds = cm::cloudShadowAt(p, b.params);
        if (clouds > 0.01f) {
            continue;
        }
        ++shadowed;
        const glm::vec3 albedo = b.params.sky.atmosphere.groundAlbedo;
        const glm::vec3 sky = albedo * cm::skyMeanRadianceAt(p, b.params);
        const glm::vec2 rMuS =
            cm::atmospherePositionToward(p, cm::cloudLightDirection(b.params.sky), b.params.sky);
        const glm::vec3 open =
            albedo * cm::cloudLightIrradianceAt(p, b.params.sky) * (rMuS.y / cm::PI);
        const glm::vec3 sun = cm::groundRadiance(p, b.params) - sky;
        EXPECT_NEAR(sun.y / open.y, cm::lightBelowClouds(clouds), 1e-4f) << "at x " << p.x;
        EXPECT_GT(sun.y / open.y, 0.05f) << "a thick shadow still gets the clouds' glow";
    }
    EXPECT_GE(shadowed, 3) << "the line crosses thick shadows";
}

TEST(CloudShadow, TheShadowMovesWithTheWind) {
    // The whole field drifts with the wind: the weather map too (weather.drift_ratio 1) and the
    // detail noise at the base noise's speed, without updraft.
    Scene s = shadowScene();
    s.windSpeedMps = 20.0f;
    s.updraft = 0.0f;
    s.weatherDriftRatio = 1.0f;
    s.detailSpeedRatio = 1.0f;
    BoundShadow b(s);
    cpu::ScopedTextureBinding bind(b.set);
    // Transmittance along a line downwind (the map's own resolution), now and 60 s later.
    const glm::vec3 wind = b.params.windDirection;
    auto line = [&](float offset) {
        std::vector<float> t;
        for (int i = -60; i <= 60; ++i) {
            const glm::vec3 p = wind * (i * 100.0f + offset);
            bool inMap = false;
            t.push_back(cm::cloudShadowFromMap(p, b.params, inMap));
        }
        return t;
    };
    const std::vector<float> before = line(0.0f);
    const std::vector<float> beforeUpwind = line(-1200.0f); // where the clouds come from
    s.timeS = 60.0f;                                        // 1200 m of wind
    b.params = cloudscape::makeCloudParams(s, b.resources);
    b.remake();
    const std::vector<float> after = line(0.0f);
    double moved = 0.0, still = 0.0, change = 0.0;
    for (size_t i = 0; i < after.size(); ++i) {
        moved += std::fabs(after[i] - beforeUpwind[i]);
        still += std::fabs(after[i] - before[i]);
    }
    change = still / after.size();
    std::printf("shadow after 60 s: mean change %.3f in place, %.3f against 1200 m upwind\n",
                still / after.size(), moved / after.size());
    EXPECT_GT(change, 0.02) << "the shadow changes over time_s";
    EXPECT_LT(moved, 0.5 * still) << "and the change is the clouds' drift downwind";
}

TEST(CloudShadow, TheMapIsMadeOnlyWhenAskedForAndTheSunIsUp) {
    Scene s = shadowScene();
    s.cloudShadowEnabled = false;
    BoundShadow off(s);
    EXPECT_TRUE(off.map.empty());
    s.cloudShadowEnabled = true;
    s.sunElevationDeg = 0.5f;
    BoundShadow low(s);
    EXPECT_TRUE(low.map.empty()) << "a sun at the horizon gets no map";
    cpu::ScopedTextureBinding bind(low.set);
    const glm::vec3 p(0.0f, 0.0f, 0.0f);
    EXPECT_EQ(cm::cloudShadowAt(p, low.params), cm::groundCloudShadow(p, low.params));
}

// The map follows the camera on one world grid: moved by whole texels it holds, for every world
// texel both places cover, the same record at the same place in its toroidal buffer (what lets
// the Vulkan renderer make only the texels a move brings in), and a point's shadow read from
// either map is the same.
TEST(CloudShadow, AMovedMapKeepsEveryTexelItStillCoversWhereItWas) {
    Scene s = shadowScene();
    BoundShadow here(s);
    const cm::CloudShadowParams& a = here.params.cloudShadow;
    const int n = a.resolution;
    const float texel = cm::cloudShadowTexelSize(a);
    Scene moved = s;
    moved.cameraPosition += glm::vec3(5.0f * texel, 0.0f, -3.0f * texel);
    cm::CloudParams movedParams = cloudscape::makeCloudParams(moved, here.resources);
    const cm::CloudShadowParams& b = movedParams.cloudShadow;
    ASSERT_EQ(b.firstTexel - a.firstTexel, glm::ivec2(5, -3)) << "whole texels move it so";
    const std::vector<glm::vec4> there = cpu::computeCloudShadowMap(movedParams, here.set);
    ASSERT_EQ(there.size(), here.map.size());
    size_t shared = 0, same = 0, cloudy = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::ivec2 inA = glm::ivec2(i, j) + b.firstTexel - a.firstTexel;
            if (inA.x < 0 || inA.y < 0 || inA.x >= n || inA.y >= n)
                continue;
            const int storedA = cm::cloudShadowStorageIndex(inA, a);
            const int storedB = cm::cloudShadowStorageIndex({i, j}, b);
            ++shared;
            same += storedA == storedB && here.map[storedA] == there[storedB] ? 1 : 0;
            cloudy += there[storedB].z > 0.0f ? 1 : 0;
        }
    EXPECT_EQ(shared, size_t(n - 5) * size_t(n - 3));
    EXPECT_EQ(same, shared);
    EXPECT_GT(cloudy, shared / 10) << "the map holds cloud";
    // Every texel is stored once.
    std::vector<int> stores(size_t(n) * n, 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            ++stores[cm::cloudShadowStorageIndex({i, j}, b)];
    EXPECT_EQ(std::count(stores.begin(), stores.end(), 1), n * n);
    // A point's shadow, read from either map.
    double worst = 0.0;
    for (int k = 0; k < 64; ++k) {
        const glm::vec3 p((k % 8 - 3.5f) * 700.0f, 0.0f, (k / 8 - 3.5f) * 700.0f);
        float fromHere, fromThere;
        {
            cpu::ScopedTextureBinding bind(here.set);
            fromHere = cm::cloudShadowAt(p, here.params);
        }
        cpu::TextureSet set = here.set;
        cpu::bindCloudShadowMap(set, there);
        cpu::ScopedTextureBinding bind(set);
        fromThere = cm::cloudShadowAt(p, movedParams);
        worst = std::max(worst, double(std::fabs(fromHere - fromThere)));
    }
    EXPECT_LT(worst, 1e-4);
}

cloudscape::BackendOptions cpuBackend() {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Cpu;
    return o;
}

// The CPU temporal renderer keeps its map while its inputs stay, as the Vulkan renderers do
// (src/core/tests/kept_shadow_map_checks.h).
TEST(CloudShadow, ASequenceKeepsItsMapWhileItsInputsStay) {
    const Scene s = shadowScene();
    cloudscape::Renderer cpu(s, smallResources(s), cpuBackend());
    cloudscape::testing::expectTheMapMadeAgainOnlyWhenItsInputsChange(cpu, s);
}

// The parameter block does not see every change of the textures (the noise of another seed
// under a painted weather map leaves it as it was): the renderer counts their versions, and a
// kept map is made again, with the new textures, for a new version alone.
TEST(CloudShadow, AKeptMapIsMadeAgainForNewTexturesUnderTheSameParameters) {
    const Scene s = shadowScene();
    BoundShadow first(s);
    Scene reseeded = s;
    reseeded.seed = s.seed + 1;
    BoundShadow second(reseeded);
    second.params = first.params; // the same bytes, read through other noise
    second.remake();
    cpu::KeptCloudShadowMap kept;
    const int64_t n2 = int64_t(s.cloudShadowResolution) * s.cloudShadowResolution;
    kept.update(first.params, first.set, 0);
    EXPECT_EQ(kept.texelsMade(), n2);
    kept.update(first.params, second.set, 0);
    EXPECT_EQ(kept.texelsMade(), 0) << "the same version: the map is kept";
    const std::vector<glm::vec4>& map = kept.update(first.params, second.set, 1);
    EXPECT_EQ(kept.texelsMade(), n2) << "a new version: made again";
    ASSERT_EQ(map.size(), second.map.size());
    EXPECT_EQ(std::memcmp(map.data(), second.map.data(), map.size() * sizeof map[0]), 0);
    EXPECT_NE(std::memcmp(map.data(), first.map.data(), map.size() * sizeof map[0]), 0)
        << "the other noise makes another map";
}

// A camera flying over the map with the wind's time held: the CPU temporal renderer makes only
// the rows and columns each move brings in, bit for bit the whole map computeCloudShadowMap
// makes for that camera.
TEST(CloudShadow, AFlyingSequenceMakesOnlyTheTexelsItsMoveBringsIn) {
    Scene s = shadowScene();
    s.cloudShadowResolution = 64;
    BoundShadow whole(s);
    cloudscape::Renderer flying(s, whole.resources, cpuBackend());
    cloudscape::testing::expectAFlyingCameraMakesOnlyTheTexelsItsMoveBringsIn(
        flying, s, [&](const Scene& at) {
            whole.params = cloudscape::makeCloudParams(at, whole.resources);
            whole.remake();
            return cpu::cloudShadowMapInRows(whole.map, whole.params.cloudShadow);
        });
}

// The clouds' own light beyond the cone (cloud_shadow.on_clouds): the map's optical depth from the
// cone's end replaces the long sample, and brings the light march's optical depth nearer a fine
// march of the whole way to the sun, most where the far path is long (below and inside cloud).
TEST(CloudShadow, TheCloudsLightReadsTheMapBeyondItsConeAndGetsNearerTheWholePath) {
    Scene s = shadowScene();
    s.coverage = 0.7f; // thick, towering cloud: long far paths
    s.sunElevationDeg = 20.0f;
    s.cloudShadowExtentM = 30000.0f; // the cloud's sun rays meet the ground 6 km sunward
    BoundShadow b(s);
    cpu::ScopedTextureBinding bind(b.set);
    ASSERT_EQ(b.params.cloudShadow.lightsClouds, 1) << "on by default";
    cm::CloudParams longSample = b.params;
    longSample.cloudShadow.lightsClouds = 0;
    const float lod = float(b.params.lightMipBias);
    const float cap = 12.0f; // optical depths beyond it all mean black to the octaves
    double errorMap = 0.0, errorLong = 0.0;
    int n = 0, mapped = 0;
    for (int z = -16; z <= 16; ++z)
        for (int x = -16; x <= 16; ++x) {
            const glm::vec3 p(x * 300.0f, 2200.0f, z * 300.0f);
            if (cm::cloudDensityAt(p, lod, false, b.params) <= 0.0f)
                continue;
            bool inMap = false;
            const float tail = cm::cloudShadowOpticalDepth(
                p + b.params.sky.sunDirection * b.params.coneLength, b.params, inMap);
            ASSERT_TRUE(inMap);
            const float withMap = cm::sunOpticalDepth(p, 0.0f, lod, false, b.params).opticalDepth;
            const float withLong =
                cm::sunOpticalDepth(p, 0.0f, lod, false, longSample).opticalDepth;
            // Without the long sample's term, the two share the cone: the map's term is the tail.
            cm::CloudParams coneOnly = longSample;
            coneOnly.longSample = 0;
            const float cone = cm::sunOpticalDepth(p, 0.0f, lod, false, coneOnly).opticalDepth;
            EXPECT_NEAR(withMap, cone + tail, 1e-3f * (1.0f + withMap));
            mapped += tail > 0.0f;
            const float truth = -std::log(std::max(referenceTransmittance(p, b.params), 1e-30f));
            errorMap += std::abs(std::min(withMap, cap) - std::min(truth, cap));
            errorLong += std::abs(std::min(withLong, cap) - std::min(truth, cap));
            ++n;
        }
    ASSERT_GT(n, 40) << "enough samples in cloud";
    EXPECT_GT(mapped, n / 4) << "the map shades a good share of them";
    std::printf("cloud samples %d (map tail > 0 at %d): mean |tau - fine march tau| (capped at %g) "
                "long sample %.3f, map %.3f\n",
                n, mapped, cap, errorLong / n, errorMap / n);
    EXPECT_LT(errorMap, 0.8 * errorLong);
}

// ---- Light shafts.

TEST(LightShafts, ShadowedAirAddsLessLightThanLitAir) {
    Scene s = shadowScene();
    s.shaftsEnabled = true;
    BoundShadow b(s);
    // A hand-made map: thick cloud (optical depth 50 from the ground to 3 km along each ray) over
    // the half x < 0 of the plane, none over x > 0.
    const int n = b.params.cloudShadow.resolution;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            b.map[cm::cloudShadowStorageIndex({x, y}, b.params.cloudShadow)] =
                x < n / 2 ? glm::vec4(0.0f, 3000.0f, 50.0f, 0.0f) : glm::vec4(0.0f);
    cpu::bindCloudShadowMap(b.set, b.map);
    cpu::ScopedTextureBinding bind(b.set);
    ASSERT_TRUE(cm::lightShaftsActive(b.params));
    // Two horizontal 4 km rays at 200 m, one in each half, both well inside the map, each with
    // the projection of its points onto the plane on its own side.
    const glm::vec3 sun = b.params.sky.sunDirection;
    const glm::vec3 shift = -sun * (200.0f / sun.y);
    const glm::vec3 dir(0.0f, 0.0f, 1.0f);
    const glm::vec3 shadedStart = glm::vec3(-5000.0f, 200.0f, -2000.0f) - glm::vec3(shift.x, 0, 0);
    const glm::vec3 litStart = glm::vec3(5000.0f, 200.0f, -2000.0f) - glm::vec3(shift.x, 0, 0);
    const float length = 4000.0f;
    auto inScattered = [&](glm::vec3 o) {
        const cm::AirLight air = cm::aerialPerspective(o, dir, length, b.params.sky);
        return air.inScattered +
               cm::lightShaftsDelta(o, dir, cm::NO_HIT, 1.0f, length, 0.5f, b.params);
    };
    const glm::vec3 shaded = inScattered(shadedStart);
    const glm::vec3 lit = inScattered(litStart);
    const glm::vec3 litAir = cm::aerialPerspective(litStart, dir, length, b.params.sky).inScattered;
    EXPECT_EQ(lit, litAir) << "lit air keeps all of its in-scattering";
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(shaded[c], 0.8f * lit[c]) << "channel " << c;
        EXPECT_GE(shaded[c], 0.0f) << "shadow takes away light the air had, no more";
    }
}

TEST(LightShafts, OffChangesNothingAndOnChangesTheImage) {
    Scene s = shadowScene();
    s.sunElevationDeg = 12.0f;
    s.cameraPitchDeg = 10.0f;
    s.sunHeadingDeg = 20.0f; // in front of the camera (heading 0)
    const cloudscape::SceneResources r = smallResources(s);
    const cloudscape::RenderResult mapOnly = cloudscape::renderCpu(s, r);
    s.shaftsEnabled = true;
    const cloudscape::RenderResult shafts = cloudscape::renderCpu(s, r);
    s.shaftsEnabled = false;
    EXPECT_EQ(cloudscape::renderCpu(s, r).composite, mapOnly.composite);
    EXPECT_EQ(shafts.cloud, mapOnly.cloud) << "the shafts are the air's, not the clouds'";
    double darker = 0.0;
    int brighter = 0;
    for (size_t i = 0; i < shafts.composite.size(); i += 4) {
        darker += mapOnly.composite[i + 1] - shafts.composite[i + 1];
        brighter += shafts.composite[i + 1] > mapOnly.composite[i + 1] ? 1 : 0;
    }
    EXPECT_GT(darker, 0.0) << "the shadowed air removes light";
    EXPECT_EQ(brighter, 0) << "and never adds any";
}

TEST(LightShafts, AStillSequenceDoesNotFlicker) {
    // 48 frames of the temporal renderer with a still camera and clock: the shafts' offsets are
    // fixed per pixel (or per cell of their grid), so they add no frame-to-frame change to what the
    // clouds' reconstruction already has (measured as the mean absolute change of the composite
    // between frames).
    Scene s = shadowScene();
    s.width = 64;
    s.height = 36;
    s.sunElevationDeg = 12.0f;
    s.sunHeadingDeg = 20.0f;
    s.cameraPitchDeg = 10.0f;
    s.temporal = true;
    const cloudscape::SceneResources r = smallResources(s);
    auto flicker = [&](bool shafts, int gridFactor) {
        s.shaftsEnabled = shafts;
        s.shaftsGridFactor = gridFactor;
        cloudscape::TemporalRenderer renderer(r);
        std::vector<float> previous;
        double change = 0.0;
        for (int f = 0; f < 48; ++f) {
            const cloudscape::RenderResult frame = renderer.renderFrame(s, f);
            if (f >= 16)
                for (size_t i = 0; i < frame.composite.size(); ++i)
                    change += std::fabs(frame.composite[i] - previous[i]);
            previous = frame.composite;
        }
        return change / (32.0 * previous.size());
    };
    const double without = flicker(false, 1);
    const double with = flicker(true, 1);
    // The temporal resolve's shafts from a 4x4 grid (shaft_grid.glsl.h): the cells' offsets are
    // fixed too.
    const double grid = flicker(true, 4);
    std::printf("48-frame flicker (mean |frame change| over frames 16-47): %.3g without shafts, "
                "%.3g with, %.3g with the 4x4 grid\n",
                without, with, grid);
    RecordProperty("flicker_without_shafts", std::to_string(without));
    RecordProperty("flicker_with_shafts", std::to_string(with));
    RecordProperty("flicker_with_shaft_grid", std::to_string(grid));
    EXPECT_LE(with, without * 1.05 + 1e-6) << "without " << without << ", with " << with;
    EXPECT_LE(grid, without * 1.05 + 1e-6) << "without " << without << ", grid " << grid;
}

TEST(LightShafts, KeysAreCheckedAndShaftsNeedTheMap) {
    Scene s;
    auto errorOf = [&](const std::string& assignment) {
        try {
            Scene copy = s;
            cloudscape::applyOverride(copy, assignment);
            cloudscape::validateScene(copy, "test");
        } catch (const cloudscape::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(errorOf("cloud_shadow.resolution=8"), "");
    EXPECT_NE(errorOf("cloud_shadow.resolution=100000"), "");
    EXPECT_NE(errorOf("cloud_shadow.extent_m=-5"), "");
    EXPECT_NE(errorOf("cloud_shadow.steps=0"), "");
    EXPECT_NE(errorOf("shafts.steps=0"), "");
    EXPECT_NE(errorOf("shafts.max_distance_m=nan"), "");
    const std::string needsMap = errorOf("shafts.enabled=true");
    EXPECT_NE(needsMap.find("cloud_shadow.enabled"), std::string::npos) << needsMap;
    s.cloudShadowEnabled = true;
    EXPECT_EQ(errorOf("shafts.enabled=true"), "");
}
