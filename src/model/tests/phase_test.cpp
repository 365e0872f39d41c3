// The model's analytic pieces, through their C++ compilation.
#include "model/lighting.glsl.h"
#include "model/phase.glsl.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cm = cloudscape::model;

namespace {

// Integral of a phase function over the sphere: 2 pi * int_{-1}^{1} p(mu) dmu, by Simpson's rule
// on a fine grid (the strongly forward-peaked lobes need it).
double integrateOverSphere(const std::function<double(double)>& phase) {
    const int n = 200000; // even
    const double h = 2.0 / n;
    double sum = phase(-1.0) + phase(1.0);
    for (int i = 1; i < n; ++i)
        sum += phase(-1.0 + i * h) * (i % 2 ? 4.0 : 2.0);
    return 2.0 * M_PI * sum * h / 3.0;
}

} // namespace

TEST(Phase, HenyeyGreensteinIntegratesToOne) {
    for (float g : {-0.9f, -0.5f, 0.0f, 0.2f, 0.5f, 0.8f, 0.9f}) {
        const double integral = integrateOverSphere(
            [g](double mu) { return cm::henyeyGreenstein(static_cast<float>(mu), g); });
        EXPECT_NEAR(integral, 1.0, 2e-3) << "g = " << g;
    }
}

TEST(Phase, HenyeyGreensteinIsotropicAtZeroAndForwardPeaked) {
    EXPECT_NEAR(cm::henyeyGreenstein(0.3f, 0.0f), 1.0 / (4.0 * M_PI), 1e-7);
    EXPECT_GT(cm::henyeyGreenstein(1.0f, 0.6f), cm::henyeyGreenstein(-1.0f, 0.6f) * 50.0f);
    // Closed form at cos = 1: (1 - g^2) / (4 pi (1 - g)^3) = (1 + g) / (4 pi (1 - g)^2).
    EXPECT_NEAR(cm::henyeyGreenstein(1.0f, 0.5f), 1.5 / (4.0 * M_PI * 0.25), 1e-4);
}

TEST(Phase, TwoLobeStaysNormalised) {
    const double integral = integrateOverSphere(
        [](double mu) { return cm::twoLobePhase(static_cast<float>(mu), 0.2f, 0.85f, 0.3f); });
    EXPECT_NEAR(integral, 1.0, 2e-3);
}

TEST(Lighting, BeerLambertThroughHomogeneousSlab) {
    // A slab of extinction sigma and thickness L transmits exp(-sigma L); summing the optical
    // depth of N equal steps gives the same answer as one step.
    const float sigma = 0.035f;
    const float thickness = 120.0f;
    float depth = 0.0f;
    const int steps = 37;
    for (int i = 0; i < steps; ++i)
        depth += sigma * thickness / steps;
    EXPECT_NEAR(cm::beerLambert(depth), std::exp(-sigma * thickness), 1e-6);
    EXPECT_FLOAT_EQ(cm::beerLambert(0.0f), 1.0f);
}

TEST(Lighting, BeerPowderMatchesTheSeedAndFadesTowardTheSun) {
    const float d = 0.7f;
    // Full strength looking away from the sun is the GPU Pro 7 formula.
    const float seed = 2.0f * std::exp(-d) * (1.0f - std::exp(-2.0f * d));
    EXPECT_NEAR(cm::beerPowder(d, -1.0f, 1.0f), seed, 1e-6);
    // Looking into the sun there are no dark edges: plain Beer.
    EXPECT_NEAR(cm::beerPowder(d, 1.0f, 1.0f), std::exp(-d), 1e-6);
    // Strength 0 is plain Beer everywhere; the sun-facing surface (d -> 0) goes dark.
    EXPECT_NEAR(cm::beerPowder(d, -1.0f, 0.0f), std::exp(-d), 1e-6);
    EXPECT_LT(cm::beerPowder(0.01f, -1.0f, 1.0f), 0.05f);
}

TEST(Compat, Remap) {
    EXPECT_FLOAT_EQ(cm::remap(0.5f, 0.0f, 1.0f, 10.0f, 20.0f), 15.0f);
    EXPECT_FLOAT_EQ(cm::remap(0.25f, 0.25f, 0.75f, 0.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(cm::remap(1.0f, 0.0f, 0.5f, 0.0f, 1.0f), 2.0f); // not clamped
    EXPECT_FLOAT_EQ(cm::remap(-1.0f, -2.0f, 0.0f, 1.0f, 0.0f), 0.5f);
    EXPECT_FLOAT_EQ(cm::remap(0.3f, 1.0f, 1.0f, 0.0f, 1.0f), 1.0f); // degenerate: newMax
    EXPECT_FLOAT_EQ(cm::saturate(1.5f), 1.0f);
    EXPECT_FLOAT_EQ(cm::saturate(-0.5f), 0.0f);
}
