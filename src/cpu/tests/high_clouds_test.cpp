// The high-altitude layer (src/model/high_clouds.glsl.h) and its texture
// (generateHighCloudTexture): what GPU Pro 7 4.5.4 and the issue ask of it, written out here.
#include <cloudscape/error.h>
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using cloudscape::Scene;
namespace cm = cloudscape::model;

namespace {

const cloudscape::Texture2D& highTexture() {
    // The shipped size: smaller textures alias the cirrus fibres' finest octaves.
    static const cloudscape::Texture2D t = cloudscape::generateHighCloudTexture(7, 512);
    return t;
}

float channel(const cloudscape::Texture2D& t, int x, int y, int c) {
    return t.texel(0, (x + t.width) % t.width, (y + t.height) % t.height)[c];
}

// Mean absolute difference of a channel between texels (dx, dy) apart, over the texture.
double meanStep(const cloudscape::Texture2D& t, int c, int dx, int dy) {
    double sum = 0.0;
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x)
            sum += std::abs(channel(t, x + dx, y + dy, c) - channel(t, x, y, c));
    return sum / (t.width * t.height);
}

// The scene's high layer with its texture bound to this thread (no volumetric cloud is read).
struct BoundLayer {
    cm::CloudParams params;
    cloudscape::cpu::TextureSet set;
    cloudscape::cpu::ScopedTextureBinding binding;

    explicit BoundLayer(const Scene& scene)
        : params(makeParams(scene)), set(textures()), binding(set) {}
    static cm::CloudParams makeParams(const Scene& scene) {
        cm::CloudParams p = cloudscape::makeCloudParams(scene, 0.0f);
        p.highClouds.coverage = scene.highCloudCoverage; // the texture is bound below
        return p;
    }
    static cloudscape::cpu::TextureSet textures() {
        cloudscape::cpu::TextureSet t;
        t.highClouds = &highTexture();
        return t;
    }
};

Scene cirrusScene() {
    Scene s;
    s.skyModel = cloudscape::SkyModel::Gradient; // no tables needed
    s.highCloudCoverage = 0.6f;
    s.highCloudPeriodM = 20000.0f;
    return s;
}

} // namespace

TEST(HighCloudTexture, TilesIsDeterministicAndFillsItsRange) {
    const cloudscape::Texture2D& t = highTexture();
    const cloudscape::Texture2D again =
        cloudscape::generateHighCloudTexture(7, 512); // the shipped size
    EXPECT_EQ(t.mips[0], again.mips[0]);
    EXPECT_NE(t.mips[0], cloudscape::generateHighCloudTexture(8, 512).mips[0]);
    for (int c = 0; c < 3; ++c) {
        float lo = 1.0f, hi = 0.0f;
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x < t.width; ++x) {
                lo = std::min(lo, channel(t, x, y, c));
                hi = std::max(hi, channel(t, x, y, c));
            }
        EXPECT_EQ(lo, 0.0f) << "channel " << c;
        EXPECT_EQ(hi, 1.0f) << "channel " << c;
        // Across the seam (last column to first, last row to first) the texture changes no more
        // than between interior neighbours: it wraps.
        double seamX = 0.0, seamY = 0.0;
        for (int i = 0; i < t.width; ++i) {
            seamX += std::abs(channel(t, 0, i, c) - channel(t, t.width - 1, i, c));
            seamY += std::abs(channel(t, i, 0, c) - channel(t, i, t.height - 1, c));
        }
        EXPECT_LT(seamX / t.width, 3.0 * meanStep(t, c, 1, 0)) << "channel " << c;
        EXPECT_LT(seamY / t.height, 3.0 * meanStep(t, c, 0, 1)) << "channel " << c;
    }
}

TEST(HighCloudTexture, CirrusFibresRunAlongZ) {
    // Cirrus (G) changes several times faster across its fibres (x) than along them (z = v).
    const cloudscape::Texture2D& t = highTexture();
    std::printf("cirrus steps x %.4f z %.4f; puffs x %.4f z %.4f\n", meanStep(t, 1, 1, 0),
                meanStep(t, 1, 0, 1), meanStep(t, 2, 1, 0), meanStep(t, 2, 0, 1));
    EXPECT_GT(meanStep(t, 1, 1, 0), 2.5 * meanStep(t, 1, 0, 1));
    // The veil (R) and the puffs (B) are not stretched that way.
    EXPECT_LT(meanStep(t, 2, 1, 0), 1.5 * meanStep(t, 2, 0, 1));
}

TEST(HighClouds, AnUpwardRayIsDimmedAndLitWhereTheLayerIs) {
    BoundLayer layer(cirrusScene());
    const glm::vec3 camera(0.0f, 100.0f, 0.0f);
    int dimmed = 0, rays = 0;
    for (int i = 0; i < 64; ++i) {
        const float a = 0.1f * static_cast<float>(i);
        const glm::vec3 dir =
            glm::normalize(glm::vec3(std::cos(a) * 0.3f, 1.0f, std::sin(a) * 0.3f));
        const cm::HighCloudLayer l = cm::highCloudLayerAlong(camera, dir, layer.params);
        ++rays;
        if (l.distance == cm::NO_HIT)
            continue;
        // The layer at its altitude: 10 km up, a little further along a slanted ray.
        EXPECT_GT(l.distance, 9900.0f);
        EXPECT_LT(l.distance, 10600.0f);
        EXPECT_LT(l.transmittance, 1.0f);
        EXPECT_GT(l.radiance.x + l.radiance.y + l.radiance.z, 0.0f);
        ++dimmed;
    }
    // Coverage 0.6 of the cirrus formation: some rays meet cloud, some do not.
    EXPECT_GT(dimmed, 4);
    EXPECT_LT(dimmed, rays);
}

TEST(HighClouds, SunlightReachesTheLayersMiddleThroughHalfOfIt) {
    // Sun only (no ambient): a ray meeting the layer where its density is d gets
    //   E * HG(cos, g) * exp(-tau / 2 / max(mu_sun, 0.35)) * (1 - exp(-tau / max(mu_view, 0.05)))
    // with tau = optical_depth * d: the sun crosses half the layer to its middle. Written out
    // here from the layer's own density and the sun's irradiance at the point.
    Scene s = cirrusScene();
    s.highCloudOpticalDepth = 2.0f; // deep enough that half and all of it differ clearly
    s.sunElevationDeg = 30.0f;
    BoundLayer layer(s);
    layer.params.sky.ambientStrength = 0.0f;
    const cm::CloudParams& P = layer.params;
    const glm::vec3 camera(0.0f, 100.0f, 0.0f);
    const glm::vec3 light = cm::cloudLightDirection(P.sky);
    int telling = 0;
    for (int i = 0; i < 256; ++i) {
        const float a = 0.1f * static_cast<float>(i);
        const glm::vec3 dir =
            glm::normalize(glm::vec3(std::cos(a) * 0.5f, 1.0f, std::sin(a) * 0.5f));
        const cm::HighCloudLayer l = cm::highCloudLayerAlong(camera, dir, P);
        if (l.distance == cm::NO_HIT)
            continue;
        const glm::vec3 p = camera + dir * l.distance;
        const glm::vec3 up = glm::normalize(p - cm::planetCentre(P.planetRadius));
        const float tau = s.highCloudOpticalDepth * cm::highCloudDensity(glm::vec2(p.x, p.z), P);
        const float muSun = std::max(glm::dot(light, up), 0.35f);
        const float muView = std::max(glm::dot(dir, up), 0.05f);
        const glm::vec3 sun = cm::cloudLightIrradianceAt(p, P.sky) *
                              cm::henyeyGreenstein(glm::dot(dir, light), s.highCloudPhaseG);
        const float opacity = 1.0f - std::exp(-tau / muView);
        const glm::vec3 expected = sun * (std::exp(-0.5f * tau / muSun) * opacity);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(l.radiance[c], expected[c], 1e-4f * expected[c] + 1e-9f) << "ray " << i;
        // Would the whole layer's depth be told apart from half of it here (by > 5 %)?
        telling += std::exp(-0.5f * tau / muSun) > 1.05f * std::exp(-tau / muSun) ? 1 : 0;
    }
    EXPECT_GT(telling, 10) << "the test must meet enough cloud to mean anything";
}

TEST(HighClouds, CoverageZeroIsTheLayerAbsent) {
    Scene s = cirrusScene();
    s.highCloudCoverage = 0.0f;
    BoundLayer layer(s);
    const glm::vec3 camera(0.0f, 100.0f, 0.0f);
    const glm::vec3 sky(0.3f, 0.5f, 0.9f);
    for (int i = 0; i < 32; ++i) {
        const glm::vec3 dir = glm::normalize(glm::vec3(0.05f * i, 1.0f, 0.02f * i));
        const glm::vec3 seen = cm::highCloudsOver(sky, cm::NO_HIT, camera, dir, layer.params);
        EXPECT_EQ(seen, sky);
    }
}

TEST(HighClouds, FromAboveTheLayerLiesBelowTheCameraAndNotOverhead) {
    // An airliner's view: the camera at 12 km, the layer at 10 km. Rays down meet it 2 km below
    // (a little further on a slant); rays up never do.
    BoundLayer layer(cirrusScene());
    const glm::vec3 camera(0.0f, 12000.0f, 0.0f);
    int dimmed = 0;
    for (int i = 0; i < 64; ++i) {
        const float a = 0.1f * static_cast<float>(i);
        const glm::vec3 down =
            glm::normalize(glm::vec3(std::cos(a) * 0.3f, -1.0f, std::sin(a) * 0.3f));
        const cm::HighCloudLayer l = cm::highCloudLayerAlong(camera, down, layer.params);
        EXPECT_EQ(cm::highCloudLayerAlong(camera, -down, layer.params).distance, cm::NO_HIT);
        if (l.distance == cm::NO_HIT)
            continue;
        EXPECT_GT(l.distance, 1990.0f);
        EXPECT_LT(l.distance, 2120.0f);
        EXPECT_LT(l.transmittance, 1.0f);
        EXPECT_GT(l.radiance.x + l.radiance.y + l.radiance.z, 0.0f);
        ++dimmed;
    }
    EXPECT_GT(dimmed, 4);
    EXPECT_LT(dimmed, 64);
}

TEST(HighClouds, FromAboveTheLayerVeilsTheCloudsAndGroundBelow) {
    // Looking down through a thick layer, what lies below (a bright cloud, a dark one, the
    // ground) fades toward the same layer radiance; from below the same cloud is not veiled.
    Scene s = cirrusScene();
    s.highCloudOpticalDepth = 30.0f;
    s.highCloudCoverage = 1.0f;
    s.highCloudType = 0.0f; // the veil: cloud nearly everywhere
    BoundLayer layer(s);
    cm::FrameParams above{};
    above.cameraPosition = glm::vec3(0.0f, 12000.0f, 0.0f);
    // A ray down through a thick part of the layer.
    glm::vec3 down(0.0f, -1.0f, 0.0f);
    cm::HighCloudLayer l{};
    for (int i = 0; i < 256; ++i) {
        const float a = 0.1f * static_cast<float>(i);
        down = glm::normalize(glm::vec3(std::cos(a) * 0.3f, -1.0f, std::sin(a) * 0.3f));
        l = cm::highCloudLayerAlong(above.cameraPosition, down, layer.params);
        if (l.distance != cm::NO_HIT && l.transmittance < 1e-4f)
            break;
    }
    ASSERT_LT(l.transmittance, 1e-4f);
    const float cloudDepth = 9000.0f; // a cloud top 3 km below the layer
    const float noGeometry = 1e30f;
    const glm::vec3 bright = cm::compositeCloud(glm::vec3(1.0f), 0.0f, cloudDepth, down, noGeometry,
                                                above, layer.params);
    const glm::vec3 dark = cm::compositeCloud(glm::vec3(0.01f), 0.0f, cloudDepth, down, noGeometry,
                                              above, layer.params);
    EXPECT_NEAR(bright.x, dark.x, 0.01f * (bright.x + 1e-6f));
    EXPECT_NEAR(bright.x, l.radiance.x, 0.01f * l.radiance.x); // gradient sky: no air
    const glm::vec3 ground =
        cm::backgroundRadiance(above.cameraPosition, down, noGeometry, layer.params);
    EXPECT_NEAR(ground.x, l.radiance.x, 0.01f * l.radiance.x);
    // From below, a cloud between the camera and the layer is seen as it is.
    cm::FrameParams below{};
    below.cameraPosition = glm::vec3(0.0f, 100.0f, 0.0f);
    const glm::vec3 up = -down;
    const glm::vec3 seen =
        cm::compositeCloud(glm::vec3(5.0f), 0.0f, 3000.0f, up, noGeometry, below, layer.params);
    EXPECT_FLOAT_EQ(seen.x, 5.0f);
}

TEST(HighClouds, TheLayerDriftsWithItsOwnWind) {
    // Heading 90 (toward east, +x) at 20 m/s: after 50 s the pattern sits 1000 m further east,
    // whatever the volumetric wind does.
    Scene s = cirrusScene();
    s.highCloudWindHeadingDeg = 90.0f;
    s.highCloudWindSpeedMps = 20.0f;
    s.windHeadingDeg = 0.0f;
    s.windSpeedMps = 50.0f;
    BoundLayer before(s);
    s.timeS = 50.0f;
    const cm::CloudParams after = BoundLayer::makeParams(s);
    int moved = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::vec2 xz(137.0f * i, 91.0f * i - 5000.0f);
        const float then = cm::highCloudDensity(xz, before.params);
        EXPECT_NEAR(cm::highCloudDensity(xz + glm::vec2(1000.0f, 0.0f), after), then, 1e-4f);
        moved += std::abs(cm::highCloudDensity(xz, after) - then) > 1e-3f;
    }
    EXPECT_GT(moved, 50); // and the same place did change
}

TEST(HighClouds, RenderWithCoverageZeroIsByteIdentical) {
    Scene s;
    s.width = 48;
    s.height = 27;
    s.cameraPitchDeg = 30.0f;
    s.weatherResolution = 64;
    const cloudscape::SceneResources res = cloudscape::prepareResources(s);
    Scene changed = s;
    changed.highCloudType = 2.0f;
    changed.highCloudOpticalDepth = 3.0f;
    changed.highCloudAltitudeM = 12000.0f;
    const cloudscape::RenderResult a = cloudscape::renderCpu(s, res);
    const cloudscape::RenderResult b = cloudscape::renderCpu(changed, res);
    EXPECT_EQ(a.composite, b.composite);
    cloudscape::SceneResources without = res;
    without.noise.highClouds = {};
    EXPECT_EQ(cloudscape::renderCpu(s, without).composite, a.composite);
    // With coverage the sky changes, the clouds' own layer does not.
    changed.highCloudCoverage = 0.5f;
    const cloudscape::RenderResult c = cloudscape::renderCpu(changed, res);
    EXPECT_NE(c.composite, a.composite);
    EXPECT_EQ(c.cloud, a.cloud);
}

TEST(HighClouds, MustLieAboveTheVolumetricLayer) {
    Scene s;
    s.highCloudAltitudeM = 7000.0f;                              // below clouds.top_m 8000
    EXPECT_NO_THROW(cloudscape::validateScene(s, "scene.json")); // no layer: nothing to check
    s.highCloudCoverage = 0.2f;
    try {
        cloudscape::validateScene(s, "scene.json");
        FAIL() << "accepted a high layer inside the volumetric one";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("high_clouds.altitude_m"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos);
    }
}

// ---- The storm's cirrus (issue 14: "a cirrus formation above the storm, offset downwind").

namespace {

// A storm at the origin, radius 10 km, the wind blowing toward heading `windHeading`; the layer's
// own coverage as given (0: the storm's cirrus alone).
Scene stormCirrusScene(float windHeading, float layerCoverage, float blend) {
    Scene s = cirrusScene();
    s.highCloudCoverage = layerCoverage;
    s.weatherExtentM = 100000.0f;
    s.stormBlend = blend;
    s.stormRadiusM = 10000.0f;
    s.windHeadingDeg = windHeading;
    return s;
}

// The storm's cirrus on: the texture is bound (BoundLayer), so as makeCloudParams does with one.
cm::CloudParams withStormCirrus(cm::CloudParams p, const Scene& s) {
    p.highClouds.stormCirrus = p.stormBlend > 0.0f ? s.stormCirrus : 0.0f;
    return p;
}

struct SideDepths {
    double downwind = 0.0; // mean optical depth over the samples
    double upwind = 0.0;
    int downwindCloudy = 0; // samples with any cloud
    int upwindCloudy = 0;
};

// The layer's vertical optical depth on a grid downwind (0.3 .. 1.7 R along the wind) and the
// mirror grid upwind, each 1.2 R across.
SideDepths depthsBySide(const cm::CloudParams& P, float windHeading, float radius) {
    const float h = glm::radians(windHeading);
    const glm::vec2 along(std::sin(h), std::cos(h)); // x east, z north; heading from north
    const glm::vec2 across(along.y, -along.x);
    SideDepths d;
    int n = 0;
    for (int i = 0; i < 29; ++i)
        for (int j = -6; j <= 6; ++j) {
            const float u = (0.3f + 0.05f * static_cast<float>(i)) * radius;
            const float v = 0.1f * static_cast<float>(j) * radius;
            const float down = cm::highCloudOpticalDepthAt(along * u + across * v, P);
            const float up = cm::highCloudOpticalDepthAt(-along * u + across * v, P);
            d.downwind += down;
            d.upwind += up;
            d.downwindCloudy += down > 0.0f;
            d.upwindCloudy += up > 0.0f;
            ++n;
        }
    d.downwind /= n;
    d.upwind /= n;
    return d;
}

} // namespace

TEST(StormCirrus, TheLayerThickensDownwindOfAStormAndNotUpwind) {
    for (float heading : {90.0f, 215.0f}) { // the scene's wind decides the side
        const Scene s = stormCirrusScene(heading, 0.0f, 1.0f);
        BoundLayer layer(s);
        const cm::CloudParams P = withStormCirrus(layer.params, s);
        const SideDepths d = depthsBySide(P, heading, s.stormRadiusM);
        std::printf("heading %.0f: mean optical depth downwind %.3f (%d of 377 cloudy), upwind "
                    "%.3f (%d)\n",
                    heading, d.downwind, d.downwindCloudy, d.upwind, d.upwindCloudy);
        // Anvil cirrus: of order 1 where it is, over a good part of the patch.
        EXPECT_GT(d.downwind, 0.2) << "heading " << heading;
        EXPECT_GT(d.downwindCloudy, 100) << "heading " << heading;
        EXPECT_EQ(d.upwindCloudy, 0) << "heading " << heading;
        // The layer is drawn there: rays from below meet it downwind.
        const glm::vec3 camera(0.0f, 100.0f, 0.0f);
        const float h = glm::radians(heading);
        const glm::vec3 towardDownwind =
            glm::normalize(glm::vec3(std::sin(h), 1.0f, std::cos(h))); // meets it ~10 km along
        EXPECT_NE(cm::highCloudDistance(camera, towardDownwind, P), cm::NO_HIT);
    }
}

TEST(StormCirrus, NoStormOrBlendZeroLeavesTheLayerAsItWas) {
    for (float coverage : {0.0f, 0.5f}) {
        const Scene none = stormCirrusScene(90.0f, coverage, 0.0f);
        BoundLayer noStorm(none);
        const cm::CloudParams P0 = withStormCirrus(noStorm.params, none);
        // Blend 0 with the storm's cirrus key on is no storm at all.
        Scene zero = none;
        zero.stormCirrus = 1.0f;
        const cm::CloudParams Pz = withStormCirrus(BoundLayer::makeParams(zero), zero);
        // And the full storm, for the other side of the comparison.
        const Scene full = stormCirrusScene(90.0f, coverage, 1.0f);
        const cm::CloudParams P1 = withStormCirrus(BoundLayer::makeParams(full), full);
        const glm::vec3 camera(0.0f, 100.0f, 0.0f);
        int changed = 0;
        for (int i = 0; i < 400; ++i) {
            const float a = 0.05f * static_cast<float>(i);
            const float r = 0.5f + 0.004f * static_cast<float>(i);
            const glm::vec3 dir = glm::normalize(glm::vec3(std::cos(a) * r, 1.0f, std::sin(a) * r));
            const cm::HighCloudLayer a0 = cm::highCloudLayerAlong(camera, dir, P0);
            const cm::HighCloudLayer az = cm::highCloudLayerAlong(camera, dir, Pz);
            EXPECT_EQ(a0.distance, az.distance);
            EXPECT_EQ(a0.transmittance, az.transmittance);
            EXPECT_EQ(a0.radiance, az.radiance);
            if (coverage == 0.0f) {
                EXPECT_EQ(cm::highCloudDistance(camera, dir, P0), cm::NO_HIT);
            }
            const cm::HighCloudLayer a1 = cm::highCloudLayerAlong(camera, dir, P1);
            // Where the storm sheds cirrus the layer only thickens.
            EXPECT_LE(a1.transmittance, a0.transmittance);
            changed += a1.transmittance < a0.transmittance;
        }
        EXPECT_GT(changed, 20) << "coverage " << coverage << ": the rays must meet the plume";
    }
}

TEST(StormCirrus, FadesWithTheStormsBlend) {
    double previous = -1.0;
    for (float blend : {0.0f, 0.25f, 0.5f, 1.0f}) {
        const Scene s = stormCirrusScene(90.0f, 0.0f, blend);
        BoundLayer layer(s);
        const cm::CloudParams P = withStormCirrus(layer.params, s);
        const double depth = depthsBySide(P, 90.0f, s.stormRadiusM).downwind;
        std::printf("blend %.2f: mean optical depth downwind %.4f\n", blend, depth);
        if (blend == 0.0f) {
            EXPECT_EQ(depth, 0.0);
        } else {
            EXPECT_GT(depth, previous) << "blend " << blend;
        }
        previous = depth;
    }
}

TEST(StormCirrus, RenderedBehindTheCloudsAndOnlyWithAStorm) {
    // The host's wiring: makeCloudParams turns the plume on where the texture exists and the
    // storm blends in. The storm 6 km south, the wind toward north, the camera looking up: the
    // plume lies overhead, behind (not in) the volumetric layer.
    Scene s;
    s.width = 48;
    s.height = 27;
    s.cameraPitchDeg = 75.0f;
    s.weatherResolution = 64;
    s.weatherExtentM = 100000.0f;
    s.windHeadingDeg = 0.0f;
    s.stormBlend = 1.0f;
    s.stormZM = -6000.0f;
    s.stormRadiusM = 8000.0f;
    const cloudscape::SceneResources res = cloudscape::prepareResources(s);
    Scene off = s;
    off.stormCirrus = 0.0f;
    const cloudscape::RenderResult with = cloudscape::renderCpu(s, res);
    const cloudscape::RenderResult without = cloudscape::renderCpu(off, res);
    EXPECT_NE(with.composite, without.composite);
    EXPECT_EQ(with.cloud, without.cloud);
    // No texture, no plume (and no crash).
    cloudscape::SceneResources bare = res;
    bare.noise.highClouds = {};
    EXPECT_EQ(cloudscape::renderCpu(s, bare).composite, without.composite);
}

TEST(StormCirrus, NeedsTheHighLayerAboveTheClouds) {
    Scene s;
    s.stormBlend = 1.0f;
    s.cloudTopM = 12000.0f; // above the high layer's default 10 km
    try {
        cloudscape::validateScene(s, "storm.json");
        FAIL() << "accepted the storm's cirrus inside the volumetric layer";
    } catch (const cloudscape::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("high_clouds.altitude_m"), std::string::npos) << what;
        EXPECT_NE(what.find("storm.cirrus"), std::string::npos) << what;
        EXPECT_NE(what.find("storm.json"), std::string::npos) << what;
    }
    s.stormCirrus = 0.0f;
    EXPECT_NO_THROW(cloudscape::validateScene(s, "storm.json"));
    s.stormCirrus = 0.8f;
    s.highCloudAltitudeM = 13000.0f;
    EXPECT_NO_THROW(cloudscape::validateScene(s, "storm.json"));
}
