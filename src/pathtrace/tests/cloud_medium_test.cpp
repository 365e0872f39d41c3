// The clouds as a path-tracing medium: the majorant grid bounds the model's extinction, and the
// trackers over it agree with a fine deterministic integration of the same field.
#include <cloudscape/metrics.h>
#include <cloudscape/noise.h>
#include <cloudscape/pathtrace.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "pathtrace/cloud_medium.h"
#include "pathtrace/tracking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace pt = cloudscape::pathtrace;
namespace cm = cloudscape::model;

namespace {

struct CloudFixture {
    cloudscape::NoiseTextures noise;
    cloudscape::Texture2D weather;
    cloudscape::cpu::TextureSet set;
    cm::CloudParams params;
    glm::vec3 camera{0.0f, 500.0f, 0.0f};

    explicit CloudFixture(float coverage, int rainCells = 0, float stormBlend = 0.0f) {
        noise.base = cloudscape::generateBaseNoise(3, 32);
        noise.detail = cloudscape::generateDetailNoise(4, 16);
        noise.curl = cloudscape::generateCurlNoise(5, 32);
        cloudscape::Scene scene;
        scene.coverage = coverage;
        scene.rainCells = rainCells;
        scene.weatherResolution = 128;
        scene.weatherExtentM = 20000.0f;
        // A storm near the map's edge, so that its wrapped copy matters too.
        scene.stormBlend = stormBlend;
        scene.stormXM = 8500.0f;
        scene.stormZM = -3000.0f;
        scene.stormRadiusM = 6000.0f;
        weather = cloudscape::prepareWeather(scene);
        set.baseNoise = &noise.base;
        set.detailNoise = &noise.detail;
        set.curlNoise = &noise.curl;
        set.weatherMap = &weather;
        params = cloudscape::makeCloudParams(
            scene, cloudscape::CoverageField(weather).biasFor(scene.coverage));
    }
};

} // namespace

TEST(CloudMedium, MajorantGridBoundsTheExtinction) {
    for (int rain : {0, 3}) {
        CloudFixture f(0.6f, rain);
        cloudscape::cpu::ScopedTextureBinding binding(f.set);
        const pt::CloudMedium medium(f.params, f.camera, f.weather);
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        int nonZero = 0;
        for (int i = 0; i < 200000; ++i) {
            const glm::vec3 p(-30000.0f + 60000.0f * u(rng),
                              f.params.layerBottom +
                                  (f.params.layerTop - f.params.layerBottom) * u(rng),
                              -30000.0f + 60000.0f * u(rng));
            const float sigma = medium.sigmaT(p);
            const glm::ivec2 c = medium.cellIndexAt(p.x, p.z);
            const pt::CloudMedium::Cell& cell = medium.cell(c.x, c.y);
            ASSERT_LE(sigma, cell.sigmaMax) << "at " << p.x << ", " << p.y << ", " << p.z;
            if (sigma > 0.0f) {
                nonZero += 1;
                ASSERT_LE(cm::altitudeOf(p, f.params.planetRadius), cell.topAltitude);
            }
        }
        EXPECT_GT(nonZero, 1000) << "the test must see cloud to mean anything";
        // The bound is useful, not just safe: cells somewhere are empty or low-topped.
        int emptyOrLow = 0;
        for (int z = 0; z < 64; ++z)
            for (int x = 0; x < 64; ++x) {
                const auto& c = medium.cell(x, z);
                emptyOrLow += (c.sigmaMax == 0.0f || c.topAltitude < f.params.layerTop) ? 1 : 0;
            }
        EXPECT_GT(emptyOrLow, 0);
    }
}

TEST(CloudMedium, FadesDistantCloudAsTheRealTimeMarchDoes) {
    // The defaults: march.max_distance_m 60 km, march.horizon_fade 0.55. Cloud at distance d from
    // the camera keeps 1 - smoothstep(33 km, 60 km, d) of its extinction, written out here.
    CloudFixture f(0.6f);
    cloudscape::cpu::ScopedTextureBinding binding(f.set);
    const pt::CloudMedium medium(f.params, f.camera, f.weather);
    const auto fade = [](float d) {
        const float x = std::clamp((d - 33000.0f) / 27000.0f, 0.0f, 1.0f);
        return 1.0f - x * x * (3.0f - 2.0f * x);
    };
    int halfFaded = 0;
    for (int i = 0; i < 40000; ++i) {
        const float d = 20000.0f + 50.0f * static_cast<float>(i % 900); // 20-65 km
        const float a = 0.37f * static_cast<float>(i);
        const glm::vec3 p = f.camera + glm::vec3(d * std::sin(a), 0.0f, d * std::cos(a));
        const float h = 0.1f + 0.8f * std::fmod(0.618034f * static_cast<float>(i), 1.0f);
        const glm::vec3 q(p.x, glm::mix(f.params.layerBottom, f.params.layerTop, h), p.z);
        const float distance = glm::length(q - f.camera);
        const float unfaded =
            cm::extinctionOf(cm::cloudDensityAt(q, 0.0f, false, f.params), f.params);
        const float expected = unfaded * fade(distance);
        ASSERT_NEAR(medium.sigmaT(q), expected, 1e-6f + 1e-5f * unfaded) << "at " << distance;
        if (unfaded > 0.0f && fade(distance) > 0.1f && fade(distance) < 0.9f)
            ++halfFaded;
    }
    EXPECT_GT(halfFaded, 100) << "the test must see cloud inside the fade";
}

TEST(CloudMedium, MajorantGridBoundsAStormsCoverageTypeAndAnvil) {
    // A storm raises coverage and type toward its centre and puts the anvil at the layer's top:
    // the cells must bound that too, or the path tracer is biased.
    CloudFixture f(0.35f, 0, 1.0f);
    cloudscape::cpu::ScopedTextureBinding binding(f.set);
    const pt::CloudMedium medium(f.params, f.camera, f.weather);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int inStorm = 0, high = 0;
    for (int i = 0; i < 200000; ++i) {
        // Half the points in the storm's column (either wrapped copy), half anywhere.
        glm::vec3 p(-30000.0f + 60000.0f * u(rng), 0.0f, -30000.0f + 60000.0f * u(rng));
        if (i % 2 == 0) {
            const float r = 6000.0f * std::sqrt(u(rng)), a = 6.2831853f * u(rng);
            p.x = 8500.0f + r * std::cos(a) - (i % 4 == 0 ? 20000.0f : 0.0f);
            p.z = -3000.0f + r * std::sin(a);
        }
        p.y = f.params.layerBottom + (f.params.layerTop - f.params.layerBottom) * u(rng);
        const float sigma = medium.sigmaT(p);
        const glm::ivec2 c = medium.cellIndexAt(p.x, p.z);
        const pt::CloudMedium::Cell& cell = medium.cell(c.x, c.y);
        ASSERT_LE(sigma, cell.sigmaMax) << "at " << p.x << ", " << p.y << ", " << p.z;
        if (sigma > 0.0f) {
            ASSERT_LE(cm::altitudeOf(p, f.params.planetRadius), cell.topAltitude);
            inStorm += glm::length(cm::stormOffset({p.x, p.z}, f.params)) < 6000.0f;
            high += cm::altitudeOf(p, f.params.planetRadius) > 7000.0f;
        }
    }
    EXPECT_GT(inStorm, 10000) << "the test must see the storm's cloud";
    EXPECT_GT(high, 1000) << "and its tall foot and anvil";
}

TEST(CloudMedium, TrackersAgreeWithFineQuadrature) {
    CloudFixture f(0.5f);
    // Thin clouds, so that rays through them keep a transmittance worth comparing.
    f.params.extinction = 0.0004f;
    cloudscape::cpu::ScopedTextureBinding binding(f.set);
    const pt::CloudMedium medium(f.params, f.camera, f.weather);
    int tested = 0;
    for (int k = 0; k < 40 && tested < 4; ++k) {
        const float azimuth = 0.7f * float(k);
        const float elevation = 0.15f + 0.03f * float(k);
        const glm::vec3 dir(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                            std::cos(elevation) * std::cos(azimuth));
        // Optical depth by a 1 m midpoint rule along the ray's shell intervals.
        const glm::vec4 spans = cm::shellIntervals(f.camera, dir, f.params.planetRadius,
                                                   f.params.layerBottom, f.params.layerTop);
        double depth = 0.0;
        for (int s = 0; s < 2; ++s) {
            const float a = s == 0 ? spans.x : spans.z;
            const float b = s == 0 ? spans.y : spans.w;
            for (float t = a + 0.5f; t < b; t += 1.0f)
                depth += medium.sigmaT(f.camera + dir * t);
        }
        const double expected = std::exp(-depth);
        if (expected < 0.05 || expected > 0.95)
            continue; // nothing to compare against usefully
        tested += 1;
        pt::Random random(99, 1);
        const int n = 4000;
        double sumRatio = 0.0;
        double sumSqRatio = 0.0;
        int crossed = 0;
        for (int i = 0; i < n; ++i) {
            const double tr =
                pt::estimateTransmittance(medium, f.camera, dir, pt::kInfinity, random, 0.0f);
            sumRatio += tr;
            sumSqRatio += tr * tr;
            crossed +=
                pt::sampleCollision(medium, f.camera, dir, pt::kInfinity, random) == pt::kInfinity;
        }
        const double mean = sumRatio / n;
        const double se = std::sqrt(std::max(sumSqRatio / n - mean * mean, 0.0) / n);
        EXPECT_NEAR(mean, expected, 4.0 * se + 2e-3) << "ratio tracking, optical depth " << depth;
        const double fraction = static_cast<double>(crossed) / n;
        EXPECT_NEAR(fraction, expected, 4.0 * std::sqrt(expected * (1 - expected) / n) + 2e-3)
            << "delta tracking, optical depth " << depth;
    }
    EXPECT_GT(tested, 0);
    EXPECT_EQ(pt::majorantViolations().load(), 0u);
}

// Where single scattering dominates (thin clouds, no sky light), the real-time march with one
// octave and no powder is the same physics as the path tracer, so the two must agree: this ties
// the two renderers' units, camera, sun and phase function together. The march lacks only the
// few per cent of multiply scattered light, so its image is a little darker, never brighter.
TEST(CloudMedium, RealTimeMatchesThePathTracerInThinClouds) {
    cloudscape::Scene scene;
    scene.width = 48;
    scene.height = 27;
    for (const char* o :
         {"clouds.extinction_per_m=0.0003", "lighting.powder=0", "lighting.scattering_octaves=1",
          "lighting.ambient_strength=0", "sky.zenith=[0,0,0]", "sky.horizon=[0,0,0]",
          "sky.ground=[0,0,0]", "lighting.phase=hg-draine", "lighting.rain_absorption=0",
          "camera.heading_deg=180", "march.distance_lod=false"})
        cloudscape::applyOverride(scene, o);
    cloudscape::applyTier(scene, "reference");
    cloudscape::validateScene(scene, "test");
    const cloudscape::SceneResources resources = cloudscape::prepareResources(scene);
    const cloudscape::RenderResult marched = cloudscape::renderCpu(scene, resources);
    cloudscape::PathTraceImage traced;
    const cloudscape::PathTraceStats stats = cloudscape::pathTrace(scene, resources, traced, 24);
    EXPECT_EQ(stats.majorantViolations, 0u);
    EXPECT_EQ(stats.truncated, 0u);
    const std::vector<float> reference = traced.mean;
    const std::vector<float> test = cloudscape::compositeRgb(marched);
    double sumReference = 0.0;
    double sumTest = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
        sumReference += reference[i];
        sumTest += test[i];
    }
    ASSERT_GT(sumReference, 0.0);
    const double ratio = sumTest / sumReference;
    std::printf("  marched / path-traced mean radiance: %.4f\n", ratio);
    EXPECT_GT(ratio, 0.9);
    EXPECT_LT(ratio, 1.02);
    EXPECT_LT(cloudscape::relativeError(reference, test), 0.35);
}
