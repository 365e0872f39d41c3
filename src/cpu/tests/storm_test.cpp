// Superstorms (storm.glsl.h, the Forbidden West talk): the stencil raises coverage and type to
// their maxima at the centre and the clouds there reach above 7 km; outside the radius and at
// blend 0 the density is bit-identical to no storm; the anvil spreads the top downwind; the
// vortex rings turn the detail noise at speeds that fall outward; the motion vectors follow the
// talk's listing; the light fields (density scale, ambient, glow) are the talk's formulas.
#include <cloudscape/error.h>
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "io/tests/refused_override.h"
#include "model/temporal.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

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

Scene stormScene(float blend = 1.0f) {
    Scene s;
    s.stormBlend = blend;
    s.stormXM = 3000.0f;
    s.stormZM = -2000.0f;
    s.stormRadiusM = 12000.0f;
    s.timeS = 100.0f;
    return s;
}

struct Fixture {
    cloudscape::Texture2D weather;
    cloudscape::cpu::TextureSet set;
    cm::CloudParams plain;
    cm::CloudParams storm;

    explicit Fixture(const Scene& withStorm) {
        cloudscape::WeatherParams w;
        w.resolution = 64;
        weather = cloudscape::generateWeatherMap(w);
        set.baseNoise = &testNoise().base;
        set.detailNoise = &testNoise().detail;
        set.curlNoise = &testNoise().curl;
        set.weatherMap = &weather;
        const float bias = cloudscape::CoverageField(weather).biasFor(withStorm.coverage);
        Scene without = withStorm;
        without.stormBlend = 0.0f;
        plain = cloudscape::makeCloudParams(without, bias);
        storm = cloudscape::makeCloudParams(withStorm, bias);
    }
};

float stormDistance(glm::vec3 p, const cm::CloudParams& P) {
    return glm::length(cm::stormOffset({p.x, p.z}, P));
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST(Storm, CentreHasFullCoverageTheTallestTypeAndCloudAbove7Km) {
    Fixture f(stormScene());
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    const glm::vec3 centre(3000.0f, 4000.0f, -2000.0f);
    const cm::DensityContext ctx = cm::densityContextAt(centre, f.storm);
    EXPECT_EQ(ctx.weather.x, 1.0f);
    EXPECT_EQ(ctx.weather.z, cm::TYPE_CUMULONIMBUS);
    // Above 7 km over the foot (within a tenth of the radius) most points are cloud; without the
    // storm (fair-weather cumulus, tops near 4.6 km) none are.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int high = 0, highPlain = 0, n = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 p(centre.x + 1200.0f * u(rng), 7000.0f + 400.0f * (u(rng) + 1.0f),
                          centre.z + 1200.0f * u(rng));
        n += 1;
        high += cm::cloudDensityAt(p, 0.0f, false, f.storm) > 0.0f;
        highPlain += cm::cloudDensityAt(p, 0.0f, false, f.plain) > 0.0f;
    }
    EXPECT_GT(high, n / 2);
    EXPECT_EQ(highPlain, 0);
}

TEST(Storm, OutsideTheRadiusAndAtBlendZeroTheDensityIsBitIdentical) {
    Fixture f(stormScene());
    Fixture off(stormScene(0.0f));
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    // Blend 0 is no storm at all: the very same parameter block.
    EXPECT_EQ(std::memcmp(&off.storm, &off.plain, sizeof off.plain), 0);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> xz(-30000.0f, 30000.0f);
    std::uniform_real_distribution<float> alt(1500.0f, 8000.0f);
    int outside = 0, inside = 0, insideGained = 0, cloudy = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p(xz(rng), alt(rng), xz(rng));
        const float full = cm::cloudDensityAt(p, 0.0f, false, f.storm);
        const float cheap = cm::cloudDensityAt(p, 0.0f, true, f.storm);
        const float plainFull = cm::cloudDensityAt(p, 0.0f, false, f.plain);
        if (stormDistance(p, f.storm) >= f.storm.stormRadius) {
            outside += 1;
            cloudy += plainFull > 0.0f;
            ASSERT_TRUE(sameBits(full, plainFull)) << p.x << ", " << p.y << ", " << p.z;
            ASSERT_TRUE(sameBits(cheap, cm::cloudDensityAt(p, 0.0f, true, f.plain)));
        } else {
            inside += 1;
            insideGained += full > 0.0f && plainFull == 0.0f;
        }
        ASSERT_TRUE(sameBits(cm::cloudDensityAt(p, 0.0f, false, off.storm), plainFull));
    }
    EXPECT_GT(outside, 1000) << "the bit-for-bit comparison must see points outside the storm";
    EXPECT_GT(cloudy, 300) << "the comparison must see clouds";
    EXPECT_GT(inside, 1000);
    EXPECT_GT(insideGained, inside / 10) << "inside the radius the storm must add cloud";
}

TEST(Storm, TheAnvilSpreadsTheTopDownwind) {
    Scene s = stormScene();
    s.windHeadingDeg = 90.0f; // toward +x
    Fixture f(s);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    // Top of the layer (87-97 %), between the foot and the radius, downwind and upwind.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int downwind = 0, upwind = 0, plainTop = 0;
    for (int i = 0; i < 3000; ++i) {
        const float r = 12000.0f * (0.5f + 0.2f * u(rng));
        const float a = (u(rng) - 0.5f) * 1.2f; // within about 35 degrees of the wind axis
        const float alt = 1500.0f + 6500.0f * (0.87f + 0.1f * u(rng));
        const glm::vec3 down(3000.0f + r * std::cos(a), alt, -2000.0f + r * std::sin(a));
        const glm::vec3 up(3000.0f - r * std::cos(a), alt, -2000.0f + r * std::sin(a));
        downwind += cm::cloudDensityAt(down, 0.0f, false, f.storm) > 0.0f;
        upwind += cm::cloudDensityAt(up, 0.0f, false, f.storm) > 0.0f;
        plainTop += cm::cloudDensityAt(down, 0.0f, false, f.plain) > 0.0f;
    }
    EXPECT_GT(downwind, 800) << "the anvil spreads at the top";
    EXPECT_GT(downwind, 2 * upwind + 100) << "and leans downwind";
    EXPECT_EQ(plainTop, 0);
}

// The anvil's detail noise is stretched along the wind (4x) more than across it (2x): its
// features change more slowly downwind; the foot below the anvil keeps the vortex's noise.
TEST(Storm, TheAnvilsDetailNoiseIsStretchedAlongTheWind) {
    Scene s = stormScene();
    s.windHeadingDeg = 90.0f; // toward +x
    Fixture f(s);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float step = 100.0f;
    double alongChange = 0.0, acrossChange = 0.0;
    for (int i = 0; i < 2000; ++i) {
        // Within half the anvil's radius of its centre, a quarter radius downwind.
        const float r = 4500.0f * u(rng);
        const float a = 6.2831853f * u(rng);
        const float alt = 1500.0f + 6500.0f * (0.9f + 0.08f * u(rng)); // in the anvil
        const glm::vec3 p(6000.0f + r * std::cos(a), alt, -2000.0f + r * std::sin(a));
        const cm::DensityContext here = cm::densityContextAt(p, f.storm);
        ASSERT_EQ(here.storm.anvil, 1.0f);
        const float fbm = cm::stormDetailFbm(here, 0.0f, f.storm);
        const glm::vec3 along = p + glm::vec3(step, 0.0f, 0.0f);
        const glm::vec3 across = p + glm::vec3(0.0f, 0.0f, step);
        alongChange +=
            std::abs(fbm - cm::stormDetailFbm(cm::densityContextAt(along, f.storm), 0.0f, f.storm));
        acrossChange += std::abs(
            fbm - cm::stormDetailFbm(cm::densityContextAt(across, f.storm), 0.0f, f.storm));
        // Well below the anvil the storm reads the vortex's noise alone.
        const glm::vec3 foot(p.x, 1500.0f + 6500.0f * 0.5f, p.z);
        const cm::DensityContext low = cm::densityContextAt(foot, f.storm);
        EXPECT_TRUE(sameBits(cm::stormDetailFbm(low, 0.0f, f.storm),
                             cm::vortexDetailFbm(low, 0.0f, f.storm)));
    }
    std::printf("anvil detail noise, mean change over %g m: along the wind %.4f, across %.4f\n",
                step, alongChange / 2000, acrossChange / 2000);
    EXPECT_LT(alongChange, 0.75 * acrossChange);
}

// The talk's varying heights: over the foot's core the underside is raised by a lumpy noise and
// a radial gradient (lowest at the centre, the wall cloud), with no cloud below the raised base;
// beyond the core the base is the layer's.
TEST(Storm, TheFootsUndersideIsRaisedLumpilyAndLowestAtTheCentre) {
    Scene s = stormScene();
    Fixture f(s);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    const cm::CloudParams& P = f.storm;
    const float depth = P.layerTop - P.layerBottom;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double centreSum = 0.0, ringSum = 0.0, ringSquares = 0.0;
    int centre = 0, ring = 0, underneath = 0;
    for (int i = 0; i < 3000; ++i) {
        const float a = 6.2831853f * u(rng);
        const float r = 12000.0f * 0.6f * u(rng);
        const glm::vec3 at(3000.0f + r * std::cos(a), P.layerBottom, -2000.0f + r * std::sin(a));
        const float rise = cm::densityContextAt(at, P).storm.baseRise;
        ASSERT_GE(rise, 0.0f);
        ASSERT_LE(rise, cm::STORM_BASE_RISE);
        if (r > 0.43f * 12000.0f) {
            EXPECT_EQ(rise, 0.0f) << "beyond the core (the foot's distorted 0.3 R)";
            continue;
        }
        // No cloud below the raised base (the rise read where the point is: the foot's outline,
        // and with it the core, wanders with height).
        const glm::vec3 below = at + glm::vec3(0.0f, 0.5f * rise * depth, 0.0f);
        if (cm::heightFractionAt(below, P) < cm::densityContextAt(below, P).storm.baseRise) {
            EXPECT_EQ(cm::cloudDensityAt(below, 0.0f, false, P), 0.0f);
            EXPECT_EQ(cm::cloudDensityAt(below, 0.0f, true, P), 0.0f);
            ++underneath;
        }
        if (r < 0.02f * 12000.0f) {
            centreSum += rise;
            ++centre;
        } else if (r > 0.15f * 12000.0f && r < 0.2f * 12000.0f) {
            ringSum += rise;
            ringSquares += double(rise) * rise;
            ++ring;
        }
    }
    ASSERT_GT(centre, 3);
    ASSERT_GT(ring, 50);
    EXPECT_GT(underneath, 500) << "points under the raised base were checked";
    const double ringMean = ringSum / ring;
    const double ringSpread = std::sqrt(std::max(ringSquares / ring - ringMean * ringMean, 0.0));
    std::printf("base rise (fraction of the layer): centre %.4f, at 0.15-0.2 R %.4f +- %.4f\n",
                centreSum / centre, ringMean, ringSpread);
    EXPECT_LT(centreSum / centre, ringMean) << "the wall cloud hangs lowest";
    EXPECT_GT(ringSpread, 0.005) << "lumpy, not a flat shelf";
}

// The low tier's vortex (PS4): in a ring overlap one ring's noise is read, the outer one with
// the overlap's blend as its chance; the other tiers read both and blend.
TEST(Storm, TheLowTierReadsOneRingInAnOverlapWithTheBlendAsItsChance) {
    Scene s = stormScene();
    Scene tiered = s;
    cloudscape::applyTier(tiered, "low");
    EXPECT_TRUE(tiered.stormRingJitter);
    cloudscape::applyTier(tiered, "high");
    EXPECT_FALSE(tiered.stormRingJitter);
    s.stormRingJitter = true;
    Fixture f(s);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    cm::CloudParams blended = f.storm;
    blended.stormRingJitter = 0;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int n = 0, outerPicks = 0;
    double chance = 0.0, jitteredSum = 0.0, blendedSum = 0.0;
    for (int i = 0; i < 4000; ++i) {
        const float a = 6.2831853f * u(rng);
        const float r = 12000.0f * u(rng);
        const glm::vec3 p(3000.0f + r * std::cos(a), 2500.0f, -2000.0f + r * std::sin(a));
        const cm::DensityContext ctx = cm::densityContextAt(p, f.storm);
        const glm::vec2 ring = cm::stormRing(ctx.storm.r);
        const float jittered = cm::vortexDetailFbm(ctx, 0.0f, f.storm);
        if (ring.y <= 0.0f) {
            EXPECT_TRUE(sameBits(jittered, cm::vortexDetailFbm(ctx, 0.0f, blended)));
            continue;
        }
        const int k = int(ring.x);
        const auto ringNoise = [&](int ringIndex) {
            const float angle = cm::stormRingAngle(ringIndex, ctx.storm.r, f.storm);
            return cm::detailFbmAt(cm::rotateAboutStorm(p, -angle, f.storm), ctx.heightFraction,
                                   0.0f, f.storm);
        };
        const bool outer = sameBits(jittered, ringNoise(k + 1));
        ASSERT_TRUE(outer || sameBits(jittered, ringNoise(k))) << "one ring's noise, unblended";
        outerPicks += outer;
        chance += ring.y;
        jitteredSum += jittered;
        blendedSum += cm::vortexDetailFbm(ctx, 0.0f, blended);
        ++n;
    }
    ASSERT_GT(n, 500) << "enough samples in overlaps";
    std::printf("%d samples in ring overlaps: outer ring picked %.3f of them, mean blend %.3f; "
                "mean noise %.4f picked, %.4f blended\n",
                n, double(outerPicks) / n, chance / n, jitteredSum / n, blendedSum / n);
    EXPECT_NEAR(double(outerPicks) / n, chance / n, 0.04);
    EXPECT_NEAR(jitteredSum / n, blendedSum / n, 0.01);
}

TEST(Storm, RingSpeedsFallOutwardAndTheNoiseTurnsAtTheRingsSpeed) {
    Scene s = stormScene();
    s.windSpeedMps = 0.0f; // only the vortex moves the detail noise
    Fixture f(s);
    // omega(r): non-increasing, strictly lower from ring to ring, zero at and beyond the radius.
    float previous = cm::stormAngularSpeed(0.0f, f.storm);
    EXPECT_FLOAT_EQ(previous, glm::radians(s.stormRotationDegPerS));
    for (int i = 1; i <= 120; ++i) {
        const float r = i / 120.0f;
        const float w = cm::stormAngularSpeed(r, f.storm);
        EXPECT_LE(w, previous) << "at r = " << r;
        previous = w;
    }
    for (int ring = 0; ring + 1 < cm::STORM_RINGS; ++ring)
        EXPECT_GT(cm::stormAngularSpeed((ring + 0.3f) / 6.0f, f.storm),
                  cm::stormAngularSpeed((ring + 1.3f) / 6.0f, f.storm));
    EXPECT_EQ(cm::stormAngularSpeed(1.0f, f.storm), 0.0f);

    // The detail noise at p a time dt later is the noise at p turned back by omega(r) dt now.
    Scene later = s;
    later.timeS += 20.0f;
    Fixture g(later);
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double matched = 0.0, wrongSpeed = 0.0;
    int n = 0;
    for (int i = 0; i < 600; ++i) {
        const int ring = i % 6;
        const float r = (ring + 0.1f + 0.5f * u(rng)) / 6.0f; // away from the overlaps
        const float a = 6.2831853f * u(rng);
        const glm::vec3 p(3000.0f + 12000.0f * r * std::cos(a), 3000.0f + 3000.0f * u(rng),
                          -2000.0f + 12000.0f * r * std::sin(a));
        const float omega = cm::stormAngularSpeed(r, f.storm);
        const glm::vec3 back = cm::rotateAboutStorm(p, -omega * 20.0f, f.storm);
        const glm::vec3 wrong = cm::rotateAboutStorm(p, -2.0f * omega * 20.0f, f.storm);
        const cm::DensityContext here = cm::densityContextAt(p, g.storm);
        // The planet's curvature changes the height fraction a little between p and the turned
        // points; compare the noise at the same one.
        cm::DensityContext before = cm::densityContextAt(back, f.storm);
        cm::DensityContext other = cm::densityContextAt(wrong, f.storm);
        before.heightFraction = other.heightFraction = here.heightFraction;
        const float now = cm::vortexDetailFbm(here, 0.0f, g.storm);
        matched += std::abs(now - cm::vortexDetailFbm(before, 0.0f, f.storm));
        wrongSpeed += std::abs(now - cm::vortexDetailFbm(other, 0.0f, f.storm));
        n += 1;
    }
    EXPECT_LT(matched / n, 2e-3);
    EXPECT_GT(wrongSpeed / n, 20.0 * matched / n + 1e-2);
}

TEST(Storm, MotionVectorsBlendScrollAndRotationAsTheTalksListing) {
    Scene s = stormScene(0.7f);
    Fixture f(s);
    const cm::CloudParams& P = f.storm;
    const float dt = 0.5f;
    for (float r : {0.05f, 0.3f, 0.62f, 0.97f, 1.0f, 1.4f}) {
        const glm::vec3 p(3000.0f + 12000.0f * r * 0.6f, 4000.0f, -2000.0f + 12000.0f * r * 0.8f);
        const glm::vec3 got = cm::previousCloudPosition(p, dt, P);
        // Written out: scroll = p - drift; rotated = p turned by -omega(r) * blend * dt about the
        // centre; mask = pow(saturate(1 - d / R), 0.1); lerp(scroll, rotated, mask).
        const glm::dvec3 scroll = glm::dvec3(p) - glm::dvec3(cm::cloudMotion(P, dt));
        const double d = 12000.0 * r;
        const double angle = -double(cm::stormAngularSpeed(r, P)) * 0.7 * dt;
        const double ox = p.x - 3000.0, oz = p.z + 2000.0;
        const glm::dvec3 rotated(3000.0 + std::cos(angle) * ox - std::sin(angle) * oz, p.y,
                                 -2000.0 + std::sin(angle) * ox + std::cos(angle) * oz);
        const double mask = std::pow(std::clamp(1.0 - d / 12000.0, 0.0, 1.0), 0.1);
        const glm::dvec3 expected = scroll + (rotated - scroll) * mask;
        EXPECT_NEAR(got.x, expected.x, 0.02) << "r " << r;
        EXPECT_NEAR(got.y, expected.y, 0.02) << "r " << r;
        EXPECT_NEAR(got.z, expected.z, 0.02) << "r " << r;
    }
    // With the storm's vectors off (storm.motion_vectors=false), the wind scroll everywhere.
    Scene scrollOnly = s;
    scrollOnly.stormMotionVectors = false;
    const cm::CloudParams Q = cloudscape::makeCloudParams(scrollOnly, 0.0f);
    const glm::vec3 inside(3000.0f + 2000.0f, 4000.0f, -2000.0f);
    EXPECT_EQ(cm::previousCloudPosition(inside, dt, Q), inside - cm::cloudMotion(Q, dt));
    EXPECT_NE(cm::previousCloudPosition(inside, dt, P), inside - cm::cloudMotion(P, dt));
    // Outside the radius, exactly the wind scroll.
    const glm::vec3 far(30000.0f, 4000.0f, 0.0f);
    const glm::vec3 scroll = far - cm::cloudMotion(P, dt);
    const glm::vec3 got = cm::previousCloudPosition(far, dt, P);
    EXPECT_TRUE(sameBits(got.x, scroll.x) && sameBits(got.y, scroll.y) &&
                sameBits(got.z, scroll.z));
}

TEST(Storm, LightFieldsAreTheTalksFormulas) {
    Scene s = stormScene(1.0f);
    s.stormLightDensityScale = 5.0f;
    s.stormAmbientScale = 3.0f;
    s.stormGlowStrength = 2.0f;
    s.stormGlowColour = {1.0f, 0.1f, 0.05f};
    s.stormGlowRadiusM = 5000.0f;
    s.stormGlowAltitudeM = 3000.0f;
    Fixture f(s);
    const cm::CloudParams& P = f.storm;
    auto at = [](float dx, float alt) { return glm::vec3(3000.0f + dx, alt, -2000.0f); };
    // Light-march density scale: full over the foot, pow(2 - d / (R / 2), 0.5) beyond, 1 at R.
    EXPECT_FLOAT_EQ(cm::stormLightDensityScale(at(1000.0f, 3000.0f), P), 5.0f);
    EXPECT_NEAR(cm::stormLightDensityScale(at(9000.0f, 3000.0f), P),
                1.0 + 4.0 * std::sqrt(2.0 - 9000.0 / 6000.0), 1e-4);
    EXPECT_EQ(cm::stormLightDensityScale(at(12500.0f, 3000.0f), P), 1.0f);
    // Ambient blend: field times the depth below the top, (d2 / h).
    EXPECT_NEAR(cm::stormAmbientFactor(at(1000.0f, 3000.0f), 0.25f, P), 1.0 + 2.0 * 0.75, 1e-5);
    EXPECT_EQ(cm::stormAmbientFactor(at(13000.0f, 3000.0f), 0.25f, P), 1.0f);
    // Glow: zero outside its radius, (1 - d / r)^12 along a line, lower in dense cloud.
    EXPECT_EQ(cm::stormGlowRadiance(at(5001.0f, 3000.0f), 0.2f, 0.0f, P), glm::vec3(0.0f));
    const float g0 = cm::stormGlowRadiance(at(1000.0f, 3000.0f), 0.2f, 0.0f, P).x;
    EXPECT_NEAR(g0, 2.0 * std::pow(1.0 - 1000.0 / 5000.0, 12.0) * 0.8, 1e-5);
    for (float d : {500.0f, 2000.0f, 3500.0f}) {
        const float g = cm::stormGlowRadiance(at(d, 3000.0f), 0.2f, 0.0f, P).x;
        EXPECT_NEAR(g / g0, std::pow((1.0 - d / 5000.0) / 0.8, 12.0), 1e-3) << d;
    }
    const glm::vec3 thin = cm::stormGlowRadiance(at(1000.0f, 3000.0f), 0.2f, 0.02f, P);
    const glm::vec3 dense = cm::stormGlowRadiance(at(1000.0f, 3000.0f), 0.2f, 0.15f, P);
    EXPECT_LT(dense.x, thin.x);
    EXPECT_NEAR(dense.x, g0 * 0.25f, 1e-5);
    EXPECT_NEAR(thin.y / thin.x, 0.1, 1e-6); // the key's colour
}

TEST(Storm, BadInputIsRefusedNamingTheKey) {
    const auto refuses = expectOverrideRefusedNaming;
    refuses("storm.radius_m=-5", "storm.radius_m");
    refuses("storm.x_m=nan", "storm.x_m");
    refuses("storm.z_m=NaN", "storm.z_m");
    refuses("storm.blend=1.5", "storm.blend");
    refuses("storm.glow_colour=[1,-1,0]", "storm.glow_colour");
    // A storm wider than half the (wrapping) map is refused while it is on.
    Scene s = stormScene();
    s.weatherExtentM = 20000.0f;
    EXPECT_THROW(cloudscape::validateScene(s, "test"), cloudscape::Error);
    try {
        cloudscape::validateScene(s, "test");
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("storm.radius_m"), std::string::npos);
    }
    s.stormBlend = 0.0f;
    EXPECT_NO_THROW(cloudscape::validateScene(s, "test"));
}
