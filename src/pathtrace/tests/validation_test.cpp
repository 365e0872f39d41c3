// The path tracer against published radiative-transfer solutions for plane-parallel slabs,
// modelled as very wide boxes and rendered by the same integrator as the clouds.
//
// Tolerances: every estimate is a mean of independent path samples, so its standard error (SE)
// is measured from the samples themselves. A test passes when |estimate - published| <= 4 SE
// (false-failure probability about 6e-5 per comparison for a correct tracer) plus the
// published tables' rounding, and it also requires SE to be small (below 0.4-1% of the value),
// so a pass means the tracer really is that close. Seeds are fixed, so runs are reproducible.
#include "pathtrace/integrator.h"
#include "pathtrace/slab_medium.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace pt = cloudscape::pathtrace;
namespace cm = cloudscape::model;

namespace {

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
};

// Mean and standard error of n samples drawn by sample(random), in parallel chunks with their
// own streams (deterministic for a seed).
Estimate estimate(int n, uint64_t seed, const std::function<double(pt::Random&)>& sample) {
    constexpr int kChunks = 64;
    std::vector<double> sum(kChunks, 0.0);
    std::vector<double> sumSq(kChunks, 0.0);
    tbb::parallel_for(0, kChunks, [&](int chunk) {
        pt::Random random(pt::mixBits(seed), static_cast<uint64_t>(chunk));
        for (int i = chunk; i < n; i += kChunks) {
            const double v = sample(random);
            sum[chunk] += v;
            sumSq[chunk] += v * v;
        }
    });
    double s = 0.0;
    double s2 = 0.0;
    for (int c = 0; c < kChunks; ++c) {
        s += sum[c];
        s2 += sumSq[c];
    }
    Estimate e;
    e.mean = s / n;
    const double variance = std::max(s2 / n - e.mean * e.mean, 0.0) * n / (n - 1);
    e.standardError = std::sqrt(variance / n);
    return e;
}

// A slab of optical thickness tau between y = 0 and y = tau (sigma = 1), 10^5 optical depths
// wide: far wider than any path wanders, so it is plane-parallel for the estimates.
pt::BoxMedium slab(float tau, cm::PhaseFunction phase) {
    pt::BoxMedium box;
    box.lower = glm::vec3(-1e5f, 0.0f, -1e5f);
    box.upper = glm::vec3(1e5f, tau, 1e5f);
    box.sigma = 1.0f;
    box.singleScatteringAlbedo = 1.0f;
    box.phaseFunction = phase;
    return box;
}

void expectMatches(const Estimate& e, double published, double rounding, double maxRelativeSe,
                   const std::string& what) {
    // The figures go to the log too: docs/QUALITY.md quotes them.
    std::printf("  %-34s published %-10.6g estimate %-10.6g +- %.2g\n", what.c_str(), published,
                e.mean, e.standardError);
    EXPECT_NEAR(e.mean, published, 4.0 * e.standardError + rounding)
        << what << ": estimate " << e.mean << " +- " << e.standardError;
    EXPECT_LT(e.standardError, maxRelativeSe * published) << what << ": too noisy to judge";
}

const pt::Ground kNoGround{};
const pt::SunLight kNoSun{};

} // namespace

TEST(PathTraceValidation, SlabTransmittanceIsExpMinusTau) {
    for (float tau : {0.25f, 1.0f, 3.0f}) {
        for (float mu : {1.0f, 0.5f}) {
            pt::BoxMedium box = slab(tau, cm::makePhaseFunction(cm::PHASE_ISOTROPIC, {}));
            const glm::vec3 dir(std::sqrt(1.0f - mu * mu), -mu, 0.0f);
            const glm::vec3 origin(0.0f, tau + 1.0f, 0.0f);
            const double expected = std::exp(-tau / mu);
            // Delta tracking: the fraction of rays that cross without a collision.
            const Estimate crossed = estimate(200000, 11, [&](pt::Random& r) {
                return pt::sampleCollision(box, origin, dir, pt::kInfinity, r) == pt::kInfinity
                           ? 1.0
                           : 0.0;
            });
            // Judged by the Bernoulli SE of the expected value, so the band cannot widen.
            const double bernoulli = std::sqrt(expected * (1.0 - expected) / 200000.0);
            EXPECT_NEAR(crossed.mean, expected, 4.0 * bernoulli + 1e-6)
                << "delta tracking, tau " << tau << " mu " << mu;
            // Ratio tracking with a loose majorant (three quarters of the tentative collisions
            // are null), so the null-collision weights are exercised.
            box.majorantScale = 4.0f;
            const Estimate ratio = estimate(50000, 12, [&](pt::Random& r) {
                return pt::estimateTransmittance(box, origin, dir, pt::kInfinity, r, 0.0f);
            });
            EXPECT_NEAR(ratio.mean, expected, 4.0 * ratio.standardError + 1e-5)
                << "ratio tracking, tau " << tau << " mu " << mu;
            EXPECT_LT(ratio.standardError, 0.01 * expected);
            box.majorantScale = 4.0f;
            const Estimate crossedLoose = estimate(100000, 13, [&](pt::Random& r) {
                return pt::sampleCollision(box, origin, dir, pt::kInfinity, r) == pt::kInfinity
                           ? 1.0
                           : 0.0;
            });
            EXPECT_NEAR(crossedLoose.mean, expected,
                        4.0 * std::sqrt(expected * (1.0 - expected) / 100000.0) + 1e-6)
                << "delta tracking with null collisions, tau " << tau << " mu " << mu;
        }
    }
}

// Garcia and Siewert (1982): isotropic scattering, albedo 1, optical thickness 5, unit isotropic
// radiance incident on the top. By reciprocity the reflected intensity at exit cosine mu is the
// radiance a camera above the slab sees looking down at that cosine with the sky (directions
// with y > 0) at radiance 1 and nothing below; the transmitted one (direct beam included) is
// what a camera below sees looking up.
TEST(PathTraceValidation, GarciaSiewertIsotropicSlab) {
    const double mus[] = {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    const double reflected[] = {0.897797, 0.887836, 0.869581, 0.852299, 0.835503, 0.818996,
                                0.802676, 0.786493, 0.770429, 0.754496, 0.738721};
    const double transmitted[] = {0.102202, 0.112164, 0.130419, 0.147701, 0.164497, 0.181004,
                                  0.197324, 0.213507, 0.229571, 0.245504, 0.261279};
    const pt::BoxMedium box = slab(5.0f, cm::makePhaseFunction(cm::PHASE_ISOTROPIC, {}));
    auto sky = [](glm::vec3 dir, bool) { return glm::vec3(dir.y > 0.0f ? 1.0f : 0.0f); };
    const pt::PathLimits limits;
    for (int i = 0; i < 11; ++i) {
        const float mu = static_cast<float>(mus[i]);
        const float side = std::sqrt(1.0f - mu * mu);
        const Estimate r = estimate(300000, 100 + i, [&](pt::Random& random) {
            pt::PathCounters counters;
            const double l =
                pt::traceRadiance(box, kNoSun, kNoGround, sky, glm::vec3(0.0f, 6.0f, 0.0f),
                                  glm::vec3(side, -mu, 0.0f), random, limits, counters)
                    .x;
            return counters.truncated == 0 ? l : std::nan(""); // truncation would be bias
        });
        const Estimate t = estimate(300000, 200 + i, [&](pt::Random& random) {
            pt::PathCounters counters;
            const double l =
                pt::traceRadiance(box, kNoSun, kNoGround, sky, glm::vec3(0.0f, -1.0f, 0.0f),
                                  glm::vec3(side, mu, 0.0f), random, limits, counters)
                    .x;
            return counters.truncated == 0 ? l : std::nan("");
        });
        expectMatches(r, reflected[i], 1e-6, 0.004, "reflected at mu " + std::to_string(mu));
        expectMatches(t, transmitted[i], 1e-6, 0.01, "transmitted at mu " + std::to_string(mu));
    }
}

// Van de Hulst (1980): Henyey-Greenstein g = 0.75, albedo 1, normal incidence with flux pi on the
// top. Fluxes are cosine-weighted integrals of radiance, so a camera with cosine-distributed
// directions estimates them as pi times its mean radiance; the sun (irradiance pi at the zenith,
// a 0.05 degree disc) is reached only by next-event estimation, so the cameras see the diffuse
// light alone and the direct beam is estimated separately by ratio tracking.
TEST(PathTraceValidation, VanDeHulstHenyeyGreensteinSlab) {
    struct Case {
        float tau;
        double up;
        double down;
        double direct;
    };
    const Case cases[] = {{1.0f, 0.247374, 1.73849, 1.15573}, {8.0f, 1.59096, 1.54958, 1.05389e-3}};
    for (const Case& c : cases) {
        pt::BoxMedium box = slab(c.tau, cm::makePhaseFunction(cm::PHASE_HG, glm::vec4(0.75f)));
        // Built as the cloud renderer builds its sun, at the smallest disc a scene allows
        // (0.05 degrees across), where a careless 1 - cos(r) in float is 25% off.
        const pt::SunLight sun = pt::makeSunLight(glm::vec3(0.0f, 1.0f, 0.0f), glm::radians(0.025f),
                                                  glm::vec3(glm::pi<float>()));
        auto dark = [](glm::vec3, bool) { return glm::vec3(0.0f); };
        const pt::PathLimits limits;
        auto flux = [&](glm::vec3 origin, glm::vec3 normal, uint64_t seed) {
            return estimate(400000, seed, [&](pt::Random& random) {
                pt::PathCounters counters;
                const glm::vec3 dir = pt::sampleCosineDirection(normal, random);
                const double l =
                    glm::pi<double>() * pt::traceRadiance(box, sun, kNoGround, dark, origin, dir,
                                                          random, limits, counters)
                                            .x;
                return counters.truncated == 0 ? l : std::nan("");
            });
        };
        // Upward flux leaving the top: cameras just above it looking down.
        const Estimate up = flux(glm::vec3(0.0f, c.tau + 1.0f, 0.0f), glm::vec3(0, -1, 0), 300);
        // Diffuse downward flux leaving the bottom: cameras below looking up.
        const Estimate down = flux(glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0, 1, 0), 301);
        // A loose majorant makes ratio tracking's estimate of a small transmittance precise
        // (relative variance exp(tau / scale) - 1), and no roulette.
        box.majorantScale = 8.0f;
        const Estimate direct = estimate(100000, 302, [&](pt::Random& random) {
            return glm::pi<double>() * pt::estimateTransmittance(box, glm::vec3(0.0f, -1.0f, 0.0f),
                                                                 glm::vec3(0, 1, 0), pt::kInfinity,
                                                                 random, 0.0f);
        });
        const std::string tau = "tau " + std::to_string(c.tau);
        expectMatches(up, c.up, 1e-5, 0.006, "upward flux, " + tau);
        expectMatches(down, c.down, 1e-5, 0.005, "diffuse downward flux, " + tau);
        expectMatches(direct, c.direct, 1e-8, 0.01, "direct flux, " + tau);
        // And the energy balance the three published numbers themselves satisfy.
        EXPECT_NEAR(up.mean + down.mean + direct.mean, glm::pi<double>(),
                    4.0 * (up.standardError + down.standardError + direct.standardError))
            << tau;
    }
}

// A white furnace: with albedo 1 and the same radiance 1 arriving from every direction, the
// radiance is 1 everywhere whatever the medium; with albedo below 1 it is lower, and matches
// the closed form for a single-scattering-free view through a slab when albedo is 0.
TEST(PathTraceValidation, WhiteFurnaceConservesEnergy) {
    pt::BoxMedium box = slab(4.0f, cm::makePhaseFunction(cm::PHASE_HG, glm::vec4(0.6f)));
    box.majorantScale = 1.5f;
    auto white = [](glm::vec3, bool) { return glm::vec3(1.0f); };
    const pt::PathLimits limits;
    auto view = [&](uint64_t seed) {
        return estimate(40000, seed, [&](pt::Random& random) {
            pt::PathCounters counters;
            return pt::traceRadiance(box, kNoSun, kNoGround, white, glm::vec3(0.0f, 2.0f, 0.0f),
                                     glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), random, limits,
                                     counters)
                .x;
        });
    };
    const Estimate conserving = view(400);
    EXPECT_NEAR(conserving.mean, 1.0, 4.0 * conserving.standardError + 1e-6);
    EXPECT_LT(conserving.standardError, 0.01);
    box.singleScatteringAlbedo = 0.0f;
    // From the middle of the slab: only unscattered light arrives, exp(-tau / mu) from above at
    // depth 2 along the ray's cosine.
    const Estimate absorbing = view(401);
    const double mu = 1.0 / glm::length(glm::vec3(0.3f, -1.0f, 0.2f));
    EXPECT_NEAR(absorbing.mean, std::exp(-2.0 / mu), 4.0 * absorbing.standardError + 1e-4);
    box.singleScatteringAlbedo = 0.8f;
    const Estimate grey = view(402);
    EXPECT_LT(grey.mean, conserving.mean - 10.0 * grey.standardError);
    EXPECT_GT(grey.mean, absorbing.mean + 10.0 * grey.standardError);
}
