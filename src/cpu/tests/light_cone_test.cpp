// The light march's sample positions against GPU Pro 7 4.5.3: the sun's optical depth is gathered
// by a few samples in a cone that opens toward the sun (a kernel of offsets in [-1, 1]^3 whose
// magnitude grows with the distance from the point, scaled by the length of a light step), plus
// one long-distance sample at three cone lengths for the shadows of distant clouds. Our march
// takes the cone samples at the middle of each step. The expected optical depth is summed here
// from those positions, written out independently, over the real density field.
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "model/tests/hand_references.h"

#include <gtest/gtest.h>

#include <random>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

struct Field {
    cloudscape::NoiseTextures noise;
    cloudscape::Texture2D weather;
    cloudscape::cpu::TextureSet set;
    Field() {
        noise.base = cloudscape::generateBaseNoise(2, 32);
        noise.detail = cloudscape::generateDetailNoise(2, 16);
        noise.curl = cloudscape::generateCurlNoise(2, 32);
        cloudscape::WeatherParams w;
        w.resolution = 64;
        weather = cloudscape::generateWeatherMap(w);
        set = {&noise.base, &noise.detail, &noise.curl, &weather};
        coverageBias = cloudscape::CoverageField(weather).biasFor(0.7f);
    }
    float coverageBias = 0.0f; // for a mean coverage of 0.7
};

const Field& field() {
    static const Field f;
    return f;
}

// The optical depth the hand-written cone positions gather over the real density field.
double expectedDepth(const Scene& s, const cm::CloudParams& P, glm::vec3 p, float lod, bool cheap,
                     double stepPosition) {
    double depth = 0.0;
    for (const auto& q : cloudscape::hand::coneSamples(s, glm::dvec3(glm::vec3(P.sky.sunDirection)),
                                                       glm::dvec3(p), cm::coneKernel, stepPosition))
        depth += s.extinctionPerM *
                 cm::cloudDensityAt(glm::vec3(q.position), lod, cheap || q.longSample, P) *
                 q.weight;
    return depth;
}

} // namespace

TEST(LightCone, KernelIsSixOffsetsInTheUnitCube) {
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 k = cm::coneKernel(i);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(k[c], -1.0f);
            EXPECT_LE(k[c], 1.0f);
        }
        EXPECT_GT(glm::length(k), 0.3f) << "an offset that spreads the cone";
        for (int j = 0; j < i; ++j)
            EXPECT_GT(glm::length(k - cm::coneKernel(j)), 0.3f) << i << " vs " << j;
    }
}

TEST(LightCone, SamplesSitAtStepMiddlesInAWideningCone) {
    const Field& f = field();
    cloudscape::cpu::ScopedTextureBinding bind(f.set);
    std::mt19937 rng(5);
    struct Variant {
        int samples;
        float spread;
        bool longSample;
        float longDistance;
        float sunElevation;
    };
    // The shipped cone (6 samples, spread 1, long sample at 3 cone lengths), the high tier's 10
    // samples (the kernel repeats), a wider cone, and no long sample.
    const Variant variants[] = {{6, 1.0f, true, 3.0f, 38.0f},
                                {10, 1.0f, true, 3.0f, 60.0f},
                                {6, 2.5f, true, 5.0f, 15.0f},
                                {4, 1.0f, false, 3.0f, 80.0f}};
    for (const Variant& v : variants) {
        Scene s;
        s.lightSamples = v.samples;
        s.coneSpread = v.spread;
        s.longSample = v.longSample;
        s.longSampleDistance = v.longDistance;
        s.sunElevationDeg = v.sunElevation;
        s.rainAbsorption = 2.5f;
        const cm::CloudParams P = cloudscape::makeCloudParams(s, field().coverageBias);
        std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f);
        std::uniform_real_distribution<float> alt(s.cloudBottomM, s.cloudBottomM + 3000.0f);
        int lit = 0, distinguishable = 0;
        for (int n = 0; n < 300; ++n) {
            // Braces: drawn left to right (a call's arguments have no order).
            const glm::vec3 p{xz(rng), alt(rng), xz(rng)};
            const bool cheap = n % 3 == 0;
            const float lod = n % 2 == 0 ? 0.0f : 1.0f;
            const float precipitation = n % 4 == 0 ? 0.5f : 0.0f;
            const cm::LightSample got = cm::sunOpticalDepth(p, precipitation, lod, cheap, P);
            const double expected =
                expectedDepth(s, P, p, lod, cheap, 0.5) * (1.0 + s.rainAbsorption * precipitation);
            // Positions are rounded to float in the model (a few mm at 20 km), which can move a
            // small density at a cloud's edge by 2 % (3e-4 of optical depth, seen).
            ASSERT_NEAR(got.opticalDepth, expected, 1e-3 * expected + 1e-3)
                << v.samples << " samples, point " << n;
            EXPECT_EQ(got.densitySamples, v.samples + (v.longSample ? 1 : 0));
            lit += expected > 0.05;
            // The test can tell midpoints from step ends here.
            const double atEnds =
                expectedDepth(s, P, p, lod, cheap, 1.0) * (1.0 + s.rainAbsorption * precipitation);
            distinguishable += std::abs(atEnds - expected) > 1e-2 * expected + 1e-2;
        }
        EXPECT_GT(lit, 60) << "the points must see cloud toward the sun";
        EXPECT_GT(distinguishable, 30);
    }
}
