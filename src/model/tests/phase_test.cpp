// The model's analytic pieces, through their C++ compilation.
#include "model/lighting.glsl.h"
#include "model/phase.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

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

namespace {

// 2 pi * integral of p(mu) mu^moment over [lo, hi], for phase functions with peaks as narrow
// as 1e-6 in mu at mu = 1: Simpson's rule in v = log(1 - mu), which spreads the peak out (the
// stretch below 1 - mu = 1e-12 holds nothing measurable).
double integratePeaked(const std::function<double(double)>& phase, double lo, double hi,
                       int moment = 0) {
    const double v0 = std::log(1.0 - lo);
    const double v1 = std::log(std::max(1.0 - hi, 1e-12));
    const int n = 4000;
    const double h = (v1 - v0) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double v = v0 + i * h;
        const double mu = 1.0 - std::exp(v);
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * phase(mu) * std::pow(mu, moment) * std::exp(v);
    }
    return -2.0 * M_PI * sum * h / 3.0; // dmu = -e^v dv, and h < 0
}

} // namespace

TEST(Phase, DraineAndHgDraineIntegrateToOne) {
    for (float g : {0.1f, 0.5f, 0.8f}) {
        for (float alpha : {0.0f, 1.0f, 27.0f}) {
            const double integral = integrateOverSphere([g, alpha](double mu) {
                return cm::drainePhase(static_cast<float>(mu), g, alpha);
            });
            EXPECT_NEAR(integral, 1.0, 2e-3) << "g " << g << " alpha " << alpha;
        }
    }
    for (float d : {5.0f, 10.0f, 20.0f, 50.0f}) {
        const glm::vec4 params = cm::hgDraineParameters(d);
        const double integral = integratePeaked(
            [params](double mu) { return cm::hgDrainePhase(static_cast<float>(mu), params); }, -1.0,
            1.0);
        EXPECT_NEAR(integral, 1.0, 3e-3) << "diameter " << d;
    }
}

TEST(Phase, HgDraineFitMatchesThePaperAtTwentyMicrometres) {
    // Jendersie and d'Eon 2023, eqs. 4-7 evaluated at d = 20 um by hand.
    const glm::vec4 p = cm::hgDraineParameters(20.0f);
    EXPECT_NEAR(p.x, std::exp(-0.0990567 / (20.0 - 1.67154)), 1e-5);
    EXPECT_NEAR(p.y, std::exp(-2.20679 / (20.0 + 3.91029) - 0.428934), 1e-5);
    EXPECT_NEAR(p.z, std::exp(3.62489 - 8.29288 / (20.0 + 5.52825)), 1e-3);
    EXPECT_NEAR(p.w, std::exp(-0.599085 / (20.0 - 0.641583) - 0.665888), 1e-5);
    // Mie scattering by cloud droplets is strongly forward-peaked with a backward glory.
    EXPECT_GT(cm::hgDrainePhase(1.0f, p), 1000.0f * cm::hgDrainePhase(0.0f, p));
    EXPECT_GT(cm::hgDrainePhase(-1.0f, p), cm::hgDrainePhase(-0.7f, p));
}

// Sampling: the histogram of sampled cosines matches the phase function's integral over each
// bin, for every kind. 400k samples in 40 bins: each bin's relative error is ~1/sqrt(count); the
// bound allows 5 standard deviations (or 2e-4 absolute for nearly empty bins).
TEST(Phase, ImportanceSamplingFollowsThePhaseFunction) {
    const std::vector<cm::PhaseFunction> phases = {
        cm::makePhaseFunction(cm::PHASE_ISOTROPIC, glm::vec4(0.0f)),
        cm::makePhaseFunction(cm::PHASE_HG, glm::vec4(0.7f, 0, 0, 0)),
        cm::makePhaseFunction(cm::PHASE_HG, glm::vec4(-0.4f, 0, 0, 0)),
        cm::makePhaseFunction(cm::PHASE_TWO_LOBE, glm::vec4(0.2f, 0.85f, 0.3f, 0.0f)),
        cm::makePhaseFunction(cm::PHASE_HG_DRAINE, cm::hgDraineParameters(10.0f)),
        cm::makePhaseFunction(cm::PHASE_HG_DRAINE, cm::hgDraineParameters(30.0f)),
    };
    constexpr int kBins = 40;
    constexpr int kSamples = 400000;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (size_t k = 0; k < phases.size(); ++k) {
        const cm::PhaseFunction& f = phases[k];
        std::vector<int> histogram(kBins, 0);
        double meanCos = 0.0;
        for (int i = 0; i < kSamples; ++i) {
            const float uLobe = uniform(rng); // one draw per statement: a call's arguments
            const float u = uniform(rng);     // have no evaluation order
            const float c = cm::samplePhaseCos(f, uLobe, u);
            ASSERT_GE(c, -1.0f);
            ASSERT_LE(c, 1.0f);
            histogram[std::min(kBins - 1, static_cast<int>((c + 1.0f) * 0.5f * kBins))] += 1;
            meanCos += c;
        }
        meanCos /= kSamples;
        double expectedMean = 0.0;
        for (int b = 0; b < kBins; ++b) {
            const double lo = -1.0 + 2.0 * b / kBins;
            const double hi = -1.0 + 2.0 * (b + 1) / kBins;
            auto p = [&f](double mu) { return cm::evaluatePhase(f, static_cast<float>(mu)); };
            const double probability = integratePeaked(p, lo, hi);
            expectedMean += integratePeaked(p, lo, hi, 1);
            const double observed = static_cast<double>(histogram[b]) / kSamples;
            const double sd = std::sqrt(probability * (1.0 - probability) / kSamples);
            EXPECT_NEAR(observed, probability, 5.0 * sd + 2e-4) << "phase " << k << " bin " << b;
        }
        EXPECT_NEAR(meanCos, expectedMean, 0.006) << "phase " << k;
    }
}

TEST(Phase, DirectionAroundHasTheRequestedAngle) {
    for (const glm::vec3 axis :
         {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(0.3f, -0.8f, 0.1f))}) {
        for (float c : {-0.9f, 0.0f, 0.5f, 0.99f}) {
            for (float phi : {0.0f, 1.0f, 4.0f}) {
                const glm::vec3 d = cm::directionAround(axis, c, phi);
                EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
                EXPECT_NEAR(glm::dot(d, axis), c, 1e-5f);
            }
        }
    }
}
