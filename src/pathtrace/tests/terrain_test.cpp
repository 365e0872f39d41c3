// The terrain in the path tracer (integrator.h's Ground with a terrain): an opaque Lambertian
// surface at the model's albedos, lit by the sun through the clouds' traced transmittance and its
// own shadow, and by whatever the paths that leave it find. Checked against closed forms: flat
// ground under a uniform sky, exact zeros in the terrain's own shadow, the direct light on lit
// slopes, and (almost) nothing under a thick deck.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_textures.h"
#include "pathtrace/air_integrator.h"
#include "pathtrace/cloud_medium.h"
#include "pathtrace/integrator.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace {

using cloudscape::pathtrace::Ground;
using cloudscape::pathtrace::kInfinity;
using cloudscape::pathtrace::NoClouds;
using cloudscape::pathtrace::PathCounters;
using cloudscape::pathtrace::PathLimits;
using cloudscape::pathtrace::Random;
using cloudscape::pathtrace::SunLight;

constexpr float kPi = glm::pi<float>();

// A generated terrain under a gradient sky (no atmosphere: the sun's light is sun.irradiance).
cloudscape::Scene terrainScene(float offsetXM) {
    cloudscape::Scene s;
    s.skyModel = cloudscape::SkyModel::Gradient;
    s.terrainEnabled = true;
    s.terrainResolution = 128;
    s.terrainExtentM = 20000.0f;
    s.terrainHeightM = 1500.0f;
    s.terrainFeatureSizeM = 6000.0f;
    s.terrainOffsetXM = offsetXM;
    s.cameraPosition = {0.0f, 2200.0f, 0.0f};
    s.coverage = 0.0f;
    s.weatherResolution = 64;
    return s;
}

struct World {
    cloudscape::SceneResources resources;
    cloudscape::model::CloudParams params;
    cloudscape::cpu::TextureSet textures;
};

void prepare(const cloudscape::Scene& s, World& w) {
    w.resources.noise.base = cloudscape::generateBaseNoise(1, 32);
    w.resources.noise.detail = cloudscape::generateDetailNoise(1, 16);
    w.resources.noise.curl = cloudscape::generateCurlNoise(1, 32);
    w.resources.weather = cloudscape::prepareWeather(s);
    cloudscape::prepareTerrain(s, w.resources);
    w.params = cloudscape::makeCloudParams(s, w.resources);
    w.textures.baseNoise = &w.resources.noise.base;
    w.textures.detailNoise = &w.resources.noise.detail;
    w.textures.curlNoise = &w.resources.noise.curl;
    w.textures.weatherMap = &w.resources.weather;
    w.textures.terrain = w.resources.terrain.heights.data();
}

Ground terrainGround(const World& w) {
    Ground g;
    g.enabled = true;
    g.radius = w.params.planetRadius;
    g.terrain = &w.params;
    return g;
}

glm::vec3 directionFromAngles(float elevationDeg, float headingDeg) {
    const float e = glm::radians(elevationDeg);
    const float h = glm::radians(headingDeg);
    return {std::cos(e) * std::sin(h), std::sin(e), std::cos(e) * std::cos(h)};
}

} // namespace

// Level ground (the flat planet around a terrain far away) under a uniform sky L and a sun of
// irradiance E at zenith angle theta reflects albedo (E cos(theta) / pi + L): the sky is the
// whole upper hemisphere, and nothing else is in view.
TEST(PathTraceTerrain, LevelGroundUnderAUniformSkyIsLambertian) {
    const cloudscape::Scene scene = terrainScene(2.0e6f); // the field 2000 km east
    World w;
    prepare(scene, w);
    const cloudscape::cpu::ScopedTextureBinding bind(w.textures);
    const Ground ground = terrainGround(w);
    const glm::vec3 sunDirection = directionFromAngles(40.0f, 30.0f);
    const glm::vec3 irradiance(6.0f, 5.0f, 4.0f);
    const SunLight sun = cloudscape::pathtrace::makeSunLight(sunDirection, 0.0046f, irradiance);
    const glm::vec3 sky(0.3f, 0.5f, 0.9f);
    auto environment = [&](glm::vec3, bool) { return sky; };
    const glm::vec3 camera = scene.cameraPosition;
    const glm::vec3 view = directionFromAngles(-50.0f, 250.0f); // down, away from the field
    ASSERT_LT(ground.intersect(camera, view), kInfinity);

    PathLimits limits;
    PathCounters counters;
    constexpr int kPaths = 40000;
    glm::dvec3 sum(0.0);
    glm::dvec3 squares(0.0);
    for (int i = 0; i < kPaths; ++i) {
        Random random(0x7e77a1 + i, 17);
        const glm::vec3 x = cloudscape::pathtrace::traceRadiance(
            NoClouds{}, sun, ground, environment, camera, view, random, limits, counters);
        sum += glm::dvec3(x);
        squares += glm::dvec3(x) * glm::dvec3(x);
    }
    const glm::dvec3 mean = sum / double(kPaths);
    const glm::dvec3 standardError =
        glm::sqrt(glm::max(squares / double(kPaths) - mean * mean, 0.0) / double(kPaths));
    const glm::vec3 albedo = scene.terrainAlbedo; // level, below the snow line: the plain albedo
    const glm::vec3 expected = albedo * (irradiance * sunDirection.y / kPi + sky);
    std::printf("level ground: traced %.5f %.5f %.5f, Lambertian %.5f %.5f %.5f\n", mean.x, mean.y,
                mean.z, expected.x, expected.y, expected.z);
    for (int c = 0; c < 3; ++c) {
        // The planet's curvature hides a sliver of the sky (the horizon dips 1 mrad at the lift
        // of a metre or two): 0.1 % on top of the noise.
        EXPECT_NEAR(mean[c], expected[c], 4.0 * standardError[c] + 1e-3 * expected[c])
            << "channel " << c;
        EXPECT_LT(standardError[c], 0.01 * expected[c]);
    }
    EXPECT_EQ(counters.truncated, 0u);
}

// In the terrain's own shadow a point gets no direct sun at all, on lit slopes exactly
// albedo E cos / pi (no clouds, a black sky, one event: the light of the first bounce alone).
TEST(PathTraceTerrain, ShadowedSlopesGetNoSunAndLitSlopesTheDirectLight) {
    cloudscape::Scene scene = terrainScene(0.0f);
    World w;
    prepare(scene, w);
    const cloudscape::cpu::ScopedTextureBinding bind(w.textures);
    const Ground ground = terrainGround(w);
    const float sunRadius = 0.0046f;
    const glm::vec3 sunDirection = directionFromAngles(6.0f, 100.0f); // low: long shadows
    const glm::vec3 irradiance(5.0f);
    const SunLight sun = cloudscape::pathtrace::makeSunLight(sunDirection, sunRadius, irradiance);
    auto black = [](glm::vec3, bool) { return glm::vec3(0.0f); };
    PathLimits limits;
    limits.maxBounces = 1; // the hit's own light; the next event is cut
    PathCounters counters;
    const glm::vec3 camera = scene.cameraPosition;
    // Whether the terrain hides the sun's whole disc (centre and rim) from p, or none of it.
    auto sunBlocked = [&](glm::vec3 lifted, int& blocked) {
        blocked = 0;
        const glm::vec3 axisA = glm::normalize(glm::cross(sunDirection, glm::vec3(0, 1, 0)));
        const glm::vec3 axisB = glm::cross(axisA, sunDirection);
        for (int k = 0; k <= 8; ++k) {
            glm::vec3 d = sunDirection;
            if (k > 0) {
                const float a = 2.0f * kPi * float(k) / 8.0f;
                d = glm::normalize(sunDirection +
                                   1.05f * sunRadius * (std::cos(a) * axisA + std::sin(a) * axisB));
            }
            blocked += ground.intersect(lifted, d) < kInfinity ? 1 : 0;
        }
    };
    int shadowed = 0;
    int lit = 0;
    for (int j = 0; j < 24; ++j) {
        for (int i = 0; i < 48; ++i) {
            const glm::vec3 view = directionFromAngles(-4.0f - 1.5f * float(j), 7.5f * float(i));
            const float t = ground.intersect(camera, view);
            if (t == kInfinity)
                continue;
            const Ground::TerrainHit hit = ground.terrainAt(camera + view * t, t);
            int blocked = 0;
            sunBlocked(hit.leave, blocked);
            const float cosine = glm::dot(hit.normal, sunDirection);
            if (blocked != 0 && blocked != 9)
                continue; // the shadow's edge: partly lit
            glm::vec3 sum(0.0f);
            constexpr int kPaths = 16;
            for (int k = 0; k < kPaths; ++k) {
                Random random(0x5ad0 + 1000 * j + i, k);
                sum += cloudscape::pathtrace::traceRadiance(NoClouds{}, sun, ground, black, camera,
                                                            view, random, limits, counters);
            }
            const glm::vec3 mean = sum / float(kPaths);
            if (blocked == 9) {
                if (cosine > 0.1f)
                    ++shadowed; // facing the sun, behind a ridge
                EXPECT_EQ(mean, glm::vec3(0.0f)) << "shadowed view " << i << "," << j;
            } else if (cosine > 0.2f) {
                ++lit;
                // The disc's directions spread cos by at most sin(r) / cos = 2.3 %.
                const glm::vec3 expected = hit.albedo * irradiance * (cosine / kPi);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(mean[c], expected[c], 0.025f * expected[c])
                        << "lit view " << i << "," << j << " channel " << c;
            }
        }
    }
    std::printf("%d points in the terrain's shadow facing the sun, %d lit\n", shadowed, lit);
    // The scene must hold both kinds of point, or the test says nothing.
    EXPECT_GT(shadowed, 20);
    EXPECT_GT(lit, 100);
}

// Under a thick, full deck the ground's direct sun is the clouds' transmittance, traced: nothing
// to speak of; in the open it is the sun's full light. The shadow is the clouds' own, not a map's.
TEST(PathTraceTerrain, AThickDeckTakesTheDirectSunOffTheGround) {
    auto directLight = [](float coverage) {
        cloudscape::Scene scene = terrainScene(2.0e6f);
        scene.coverage = coverage;
        scene.extinctionPerM = 0.08f;
        scene.cameraPosition = {0.0f, 800.0f, 0.0f}; // under the layer
        World w;
        prepare(scene, w);
        const cloudscape::cpu::ScopedTextureBinding bind(w.textures);
        const Ground ground = terrainGround(w);
        const cloudscape::pathtrace::CloudMedium medium(w.params, scene.cameraPosition,
                                                        w.resources.weather);
        const SunLight sun = cloudscape::pathtrace::makeSunLight(directionFromAngles(60.0f, 0.0f),
                                                                 0.0046f, glm::vec3(5.0f));
        auto black = [](glm::vec3, bool) { return glm::vec3(0.0f); };
        PathLimits limits;
        limits.maxBounces = 1;
        PathCounters counters;
        double sum = 0.0;
        for (int i = 0; i < 400; ++i) {
            Random random(0xdec4 + i, 3);
            const glm::vec3 view = directionFromAngles(-30.0f - 0.1f * float(i % 100), 200.0f);
            sum += cloudscape::pathtrace::traceRadiance(medium, sun, ground, black,
                                                        scene.cameraPosition, view, random, limits,
                                                        counters)
                       .y;
        }
        return sum / 400.0;
    };
    const double open = directLight(0.0f);
    const double overcast = directLight(1.0f);
    std::printf("direct sun on the ground: %.5f open, %.6f under the deck\n", open, overcast);
    EXPECT_GT(open, 0.1);
    EXPECT_LT(overcast, 0.01 * open);
}
