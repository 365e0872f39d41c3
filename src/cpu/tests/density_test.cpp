// The textured part of the model (density, march) through the CPU backend's samplers.
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"

#include <gtest/gtest.h>

#include <random>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

// Small noise textures keep the tests quick; the density code does not depend on their size.
const cloudscape::NoiseTextures& testNoise() {
    static const cloudscape::NoiseTextures noise = [] {
        cloudscape::NoiseTextures n;
        n.base = cloudscape::generateBaseNoise(3, 32);
        n.detail = cloudscape::generateDetailNoise(4, 16);
        n.curl = cloudscape::generateCurlNoise(5, 32);
        return n;
    }();
    return noise;
}

struct Fixture {
    cloudscape::Texture2D weather;
    cloudscape::cpu::TextureSet set;
    cm::CloudParams params;

    explicit Fixture(float coverage, const Scene& scene = Scene{}) {
        cloudscape::WeatherParams w;
        w.resolution = 64;
        weather = cloudscape::generateWeatherMap(w);
        set.baseNoise = &testNoise().base;
        set.detailNoise = &testNoise().detail;
        set.curlNoise = &testNoise().curl;
        set.weatherMap = &weather;
        params = cloudscape::makeCloudParams(scene,
                                             cloudscape::CoverageField(weather).biasFor(coverage));
    }
};

glm::vec3 pointInLayer(std::mt19937& rng, const cm::CloudParams& p, float extent) {
    std::uniform_real_distribution<float> xz(-extent, extent);
    std::uniform_real_distribution<float> alt(p.layerBottom, p.layerTop);
    return {xz(rng), alt(rng), xz(rng)};
}

} // namespace

TEST(CpuSampler, EightBitCopyReadsTheSameFloats) {
    // quantizeToUnorm8 keeps an 8-bit copy the sampler reads instead of the floats (a quarter of
    // the bytes); the results must be bit-identical, at every level and between levels.
    const cloudscape::Texture3D& eight = testNoise().base;
    ASSERT_EQ(eight.unorm8.size(), eight.mips.size());
    cloudscape::Texture3D floats = eight;
    floats.unorm8.clear();
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), lod(0.0f, 6.0f);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p(u(rng), u(rng), u(rng));
        const float l = i % 4 == 0 ? 0.0f : lod(rng);
        const glm::vec4 a = cloudscape::cpu::sampleTexture(eight, p, l);
        const glm::vec4 b = cloudscape::cpu::sampleTexture(floats, p, l);
        ASSERT_EQ(a, b) << i;
    }
    // A level written after quantising without clearing the copy would be read stale: the
    // copy must match the floats exactly.
    for (size_t l = 0; l < eight.mips.size(); ++l)
        for (size_t i = 0; i < eight.mips[l].size(); ++i)
            ASSERT_EQ(eight.mips[l][i], static_cast<float>(eight.unorm8[l][i]) / 255.0f);
}

TEST(CpuSampler, TexelCentresAndWrap) {
    cloudscape::Texture3D t;
    t.size = 4;
    t.mips.assign(1, std::vector<float>(4 * 4 * 4 * 4, 0.0f));
    t.texel(0, 1, 2, 3)[0] = 1.0f;
    cloudscape::buildMipChain(t);
    // At a texel centre trilinear filtering returns the texel.
    EXPECT_FLOAT_EQ(cloudscape::cpu::sampleTexture(t, {1.5f / 4, 2.5f / 4, 3.5f / 4}, 0).x, 1.0f);
    // Halfway between texel x = 3 and (wrapped) x = 0.
    t.mips[0].assign(t.mips[0].size(), 0.0f);
    t.texel(0, 0, 0, 0)[0] = 1.0f;
    EXPECT_NEAR(cloudscape::cpu::sampleTexture(t, {0.0f, 0.5f / 4, 0.5f / 4}, 0).x, 0.5f, 1e-6);
    EXPECT_NEAR(cloudscape::cpu::sampleTexture(t, {1.0f, 0.5f / 4, 0.5f / 4}, 0).x, 0.5f, 1e-6);
    // Whole-number shifts of the coordinate give the same value (wrap).
    EXPECT_NEAR(cloudscape::cpu::sampleTexture(t, {0.3f, 0.6f, 0.1f}, 0).x,
                cloudscape::cpu::sampleTexture(t, {2.3f, -1.4f, 5.1f}, 0).x, 1e-5);
}

TEST(Density, CoverageZeroGivesNoCloudAnywhere) {
    Fixture f(0.0f);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(1);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p = pointInLayer(rng, f.params, 40000.0f);
        ASSERT_EQ(cm::cloudDensityAt(p, 0.0f, false, f.params), 0.0f);
        ASSERT_EQ(cm::cloudDensityAt(p, 0.0f, true, f.params), 0.0f);
    }
}

TEST(Density, CoverageOneGivesCloudOverTheWholeMap) {
    Fixture f(1.0f);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    const float extent = f.params.weatherExtent;
    // Every column on a grid over the map has cloud at some height.
    for (int iz = 0; iz < 24; ++iz) {
        for (int ix = 0; ix < 24; ++ix) {
            const float x = (ix / 24.0f - 0.5f) * extent;
            const float z = (iz / 24.0f - 0.5f) * extent;
            float best = 0.0f;
            for (float alt = f.params.layerBottom; alt < f.params.layerTop; alt += 50.0f)
                best = std::max(best, cm::cloudDensityAt({x, alt, z}, 0.0f, false, f.params));
            EXPECT_GT(best, 0.0f) << "no cloud above (" << x << ", " << z << ")";
        }
    }
}

TEST(Density, StaysInUnitRangeAndIsZeroOutsideTheLayer) {
    Fixture f(0.6f);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(2);
    int nonZero = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p = pointInLayer(rng, f.params, 30000.0f);
        const float full = cm::cloudDensityAt(p, 0.0f, false, f.params);
        const float cheap = cm::cloudDensityAt(p, 0.0f, true, f.params);
        ASSERT_GE(full, 0.0f);
        ASSERT_LE(full, 1.0f);
        // Erosion only removes: the full sample never exceeds the cheap one.
        ASSERT_LE(full, cheap + 1e-6f);
        nonZero += full > 0.0f;
    }
    EXPECT_GT(nonZero, 500);
    EXPECT_EQ(cm::cloudDensityAt({0, 1000, 0}, 0, false, f.params), 0.0f);
    EXPECT_EQ(cm::cloudDensityAt({0, 9000, 0}, 0, false, f.params), 0.0f);
}

TEST(Density, WindMovesTheCloudsOverTime) {
    Scene later;
    later.timeS = 600.0f;
    Fixture a(0.6f);
    Fixture b(0.6f, later);
    cloudscape::cpu::ScopedTextureBinding bind(a.set);
    // Ten minutes at 10 m/s toward +x: the field at t is the field at 0 shifted 6 km downwind
    // (up to the slight updraft and the detail noise's own speed, so compare base shapes
    // at a height where shear is the same).
    std::mt19937 rng(3);
    int compared = 0;
    double err = 0.0;
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 p = pointInLayer(rng, a.params, 20000.0f);
        const cm::DensityContext c0 = cm::densityContextAt(p, a.params);
        glm::vec3 moved = p + glm::vec3(6000.0f, 0.0f, 0.0f);
        cm::DensityContext c1 = cm::densityContextAt(moved, b.params);
        c1.weather = c0.weather; // the weather map does not move with the noise
        const float before = cm::baseCloudDensity(c0, 0.0f, a.params);
        // The updraft lifts the field by 0.1 * 6 km too: follow it up.
        c1.position.y += 600.0f;
        c1.heightFraction = c0.heightFraction;
        const float after = cm::baseCloudDensity(c1, 0.0f, b.params);
        err += std::abs(before - after);
        ++compared;
    }
    EXPECT_LT(err / compared, 1e-3);
}

TEST(March, EmptySkyIsTransparentAndCoarseStepsCrossItFaster) {
    Scene plain;
    plain.coarseStepFactor = 1;
    Fixture f(0.0f, plain);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    const glm::vec3 dir = glm::normalize(glm::vec3(0.2f, 1, 0.1f));
    const cm::MarchResult m = cm::marchClouds({0, 2, 0}, dir, 0.5f, 0.0f, f.params);
    EXPECT_EQ(m.transmittance, 1.0f);
    EXPECT_EQ(m.radiance, glm::vec3(0));
    EXPECT_EQ(m.depth, cm::NO_HIT);
    EXPECT_GE(m.densitySamples, 64);
    EXPECT_EQ(m.lightSamples, 0);
    for (int factor : {2, 3, 4}) {
        f.params.coarseStepFactor = factor;
        const cm::MarchResult coarse = cm::marchClouds({0, 2, 0}, dir, 0.5f, 0.0f, f.params);
        EXPECT_EQ(coarse.transmittance, 1.0f);
        EXPECT_NEAR(coarse.densitySamples, m.densitySamples / factor, 1) << factor;
    }
}

TEST(March, CoarseFineKeepsTheCloudsAndSavesSamples) {
    Scene plain;
    plain.coarseStepFactor = 1;
    Fixture f(0.5f, plain);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    double samplesPlain = 0, samplesCoarse = 0, errorT = 0;
    const int rays = 400;
    for (int r = 0; r < rays; ++r) {
        // Braces: drawn left to right (a call's arguments have no order).
        const glm::vec3 dir =
            glm::normalize(glm::vec3{u(rng), 0.4f + 0.6f * std::abs(u(rng)), u(rng)});
        f.params.coarseStepFactor = 1;
        const cm::MarchResult a = cm::marchClouds({0, 2, 0}, dir, 0.37f, 0.0f, f.params);
        f.params.coarseStepFactor = 2;
        const cm::MarchResult b = cm::marchClouds({0, 2, 0}, dir, 0.37f, 0.0f, f.params);
        samplesPlain += a.densitySamples;
        samplesCoarse += b.densitySamples;
        errorT += std::abs(a.transmittance - b.transmittance);
    }
    EXPECT_LT(samplesCoarse, 0.8 * samplesPlain); // cost falls
    EXPECT_LT(errorT / rays, 0.02);               // the clouds stay (mean |dT| over rays)
}

TEST(March, OvercastIsOpaqueFromBelowAndStepsGrowTowardTheHorizon) {
    Fixture f(1.0f);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    const cm::MarchResult up = cm::marchClouds({0, 2, 0}, {0, 1, 0}, 0.5f, 0.0f, f.params);
    EXPECT_LT(up.transmittance, 0.2f);
    EXPECT_GT(up.depth, 1400.0f);
    EXPECT_GT(up.lightSamples, 0);
    EXPECT_EQ(cm::viewStepCount({0, 2, 0}, {0, 1, 0}, f.params), 64);
    EXPECT_EQ(cm::viewStepCount({0, 2, 0}, {1, 0, 0}, f.params), 128);
}

TEST(Camera, EastIsOnTheRightWhenFacingNorth) {
    Scene s;
    s.cameraHeadingDeg = 0.0f;
    s.cameraPitchDeg = 0.0f;
    s.width = 100;
    s.height = 50;
    const cm::FrameParams f = cloudscape::makeFrameParams(s);
    const glm::vec3 rightEdge = cm::cameraRayDirection(f, 99.0f, 25.0f);
    const glm::vec3 topEdge = cm::cameraRayDirection(f, 50.0f, 0.0f);
    EXPECT_GT(rightEdge.x, 0.3f); // east
    EXPECT_GT(topEdge.y, 0.3f);   // up
    // A sun at heading 90 (east) lies on the right of a north-facing view.
    EXPECT_GT(cloudscape::directionFromAngles(90.0f, 0.0f).x, 0.99f);
}
