// Emission in the path tracer (integrator.h: collected at real collisions as the path weight
// times the source per unit optical depth S_e, whose emission coefficient is sigma_t S_e).
// Against closed forms in a non-scattering slab, thin and thick, with and without null
// collisions; and the storm's glow (the model's stormEmissionLit, through CloudMedium) against a
// fine quadrature of the integral of T sigma_t S_e along rays through a superstorm.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "cpu/cpu_textures.h"
#include "pathtrace/cloud_medium.h"
#include "pathtrace/integrator.h"
#include "pathtrace/slab_medium.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using cloudscape::pathtrace::Ground;
using cloudscape::pathtrace::PathCounters;
using cloudscape::pathtrace::PathLimits;
using cloudscape::pathtrace::Random;
using cloudscape::pathtrace::SunLight;

// A box whose source per unit optical depth rises linearly through its depth (along z):
// S_e = e0 + e1 (z - lower.z) / depth.
struct EmittingBox : cloudscape::pathtrace::BoxMedium {
    glm::vec3 e0{0.0f};
    glm::vec3 e1{0.0f};
    glm::vec3 emission(glm::vec3 p) const {
        return e0 + e1 * ((p.z - lower.z) / (upper.z - lower.z));
    }
};

struct Estimate {
    glm::dvec3 mean{0.0};
    glm::dvec3 standardError{0.0};
};

template <class Medium>
Estimate traceMany(const Medium& medium, glm::vec3 origin, glm::vec3 dir, int paths,
                   uint64_t seed) {
    const SunLight noSun; // disabled
    const Ground noGround;
    auto black = [](glm::vec3, bool) { return glm::vec3(0.0f); };
    PathLimits limits;
    PathCounters counters;
    glm::dvec3 sum(0.0);
    glm::dvec3 squares(0.0);
    for (int i = 0; i < paths; ++i) {
        Random random(seed + uint64_t(i), 11);
        const glm::dvec3 x(cloudscape::pathtrace::traceRadiance(
            medium, noSun, noGround, black, origin, dir, random, limits, counters));
        sum += x;
        squares += x * x;
    }
    Estimate e;
    e.mean = sum / double(paths);
    e.standardError =
        glm::sqrt(glm::max(squares / double(paths) - e.mean * e.mean, 0.0) / double(paths));
    return e;
}

} // namespace

// Straight through a non-scattering slab of depth D and extinction sigma (tau = sigma D), the
// emitted radiance is the integral over s of sigma e^(-sigma s) S_e(s):
//     e0 (1 - e^-tau) + e1 (1 - e^-tau (1 + tau)) / tau   (S_e = e0 + e1 s / D).
TEST(PathTraceEmission, ANonScatteringSlabEmitsTheClosedFormIntegral) {
    struct Case {
        float tau;
        float majorantScale;
    };
    for (const Case c :
         {Case{0.05f, 1.0f}, Case{0.05f, 3.0f}, Case{2.0f, 1.0f}, Case{2.0f, 2.0f}}) {
        EmittingBox box;
        box.lower = glm::vec3(-1e4f, -1e4f, 0.0f);
        box.upper = glm::vec3(1e4f, 1e4f, 10.0f);
        box.sigma = c.tau / 10.0f;
        box.singleScatteringAlbedo = 0.0f;
        box.majorantScale = c.majorantScale;
        box.e0 = glm::vec3(2.0f, 1.0f, 0.5f);
        box.e1 = glm::vec3(0.0f, 3.0f, -0.4f);
        // Into the slab's near face, along its depth: the source seen first is e0's.
        const Estimate e =
            traceMany(box, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 200000,
                      0xe1 + uint64_t(c.majorantScale * 100.0f + c.tau * 7.0f));
        const double tau = c.tau;
        const double a = 1.0 - std::exp(-tau);
        const double b = (1.0 - std::exp(-tau) * (1.0 + tau)) / tau;
        for (int ch = 0; ch < 3; ++ch) {
            const double expected = box.e0[ch] * a + box.e1[ch] * b;
            std::printf("tau %.2f majorant x%.0f channel %d: traced %.6f (se %.6f), exact %.6f\n",
                        c.tau, c.majorantScale, ch, e.mean[ch], e.standardError[ch], expected);
            EXPECT_NEAR(e.mean[ch], expected, 4.0 * e.standardError[ch]) << "tau " << c.tau;
            EXPECT_LT(e.standardError[ch], 0.02 * std::abs(expected));
        }
        // The thin slab is in the optically thin limit, tau e0 (+ tau e1 / 2): a check on the
        // closed form itself.
        if (c.tau < 0.1f) {
            EXPECT_NEAR(box.e0.x * a, box.e0.x * tau, 0.03 * box.e0.x * tau);
        }
    }
}

// Emission is collected at every collision of a path, not only the first: in a slab of uniform
// source, albedo 1 keeps the light that albedo 0 absorbs, so the radiance leaving it is higher
// (albedo 0: the closed form above).
TEST(PathTraceEmission, ScatteredPathsCollectMoreEmissionThanStraightOnes) {
    EmittingBox box;
    box.lower = glm::vec3(-1e4f, -1e4f, 0.0f);
    box.upper = glm::vec3(1e4f, 1e4f, 10.0f);
    box.sigma = 0.05f; // tau 0.5
    box.e0 = glm::vec3(1.0f);
    box.singleScatteringAlbedo = 0.0f;
    const Estimate straight =
        traceMany(box, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 50000, 0x51);
    box.singleScatteringAlbedo = 1.0f;
    const Estimate scattered =
        traceMany(box, glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 50000, 0x52);
    EXPECT_NEAR(straight.mean.x, 1.0 - std::exp(-0.5), 4.0 * straight.standardError.x);
    EXPECT_GT(scattered.mean.x, straight.mean.x + 4.0 * scattered.standardError.x);
}

// The storm's glow through the cloud medium: with no sun, no sky and albedo 0, the path tracer's
// radiance along a ray is the integral of T sigma_t S_e, S_e the model's stormEmissionLit at the
// sample's height fraction and full density. Against a 4 m midpoint quadrature of the same field.
TEST(PathTraceEmission, TheStormGlowMatchesAQuadratureOfTheModel) {
    cloudscape::Scene s;
    s.cloudTopM = 12000.0f;
    s.coverage = 0.06f;
    s.cloudType = 0.45f;
    s.weatherExtentM = 60000.0f;
    s.weatherResolution = 128;
    s.stormBlend = 1.0f;
    s.stormXM = 0.0f;
    s.stormZM = 0.0f;
    s.stormRadiusM = 15000.0f;
    s.stormGlowStrength = 6.0f;
    s.stormGlowRadiusM = 9000.0f;
    s.albedo = 0.0f; // non-scattering: emission and absorption only
    s.extinctionPerM = 0.004f;
    s.cameraPosition = {-9000.0f, 2.0f, -9000.0f};
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    const cloudscape::model::CloudParams params = cloudscape::makeCloudParams(s, r);
    cloudscape::cpu::TextureSet textures;
    textures.baseNoise = &r.noise.base;
    textures.detailNoise = &r.noise.detail;
    textures.curlNoise = &r.noise.curl;
    textures.weatherMap = &r.weather;
    const cloudscape::cpu::ScopedTextureBinding bind(textures);
    const cloudscape::pathtrace::CloudMedium medium(params, s.cameraPosition, r.weather);
    ASSERT_TRUE(medium.emits());

    int glowing = 0;
    for (int k = 0; k < 4; ++k) {
        // Toward the glow's centre (2500 m over the storm), and around it.
        const glm::vec3 target(800.0f * float(k % 2), 1500.0f + 900.0f * float(k), 0.0f);
        const glm::vec3 dir = glm::normalize(target - s.cameraPosition);
        // The quadrature: T sigma_t S_e dt over the layer's span, T from the same samples.
        const glm::vec4 spans = cloudscape::model::shellIntervals(
            s.cameraPosition, dir, params.planetRadius, params.layerBottom, params.layerTop);
        ASSERT_GT(spans.y, spans.x);
        const double dt = 4.0;
        double opticalDepth = 0.0;
        glm::dvec3 quadrature(0.0);
        for (double t = spans.x + 0.5 * dt; t < spans.y; t += dt) {
            const glm::vec3 p = s.cameraPosition + dir * float(t);
            const double sigma = medium.sigmaT(p);
            if (sigma > 0.0) {
                // Exact over the step for a constant source: e^-depth (1 - e^-sigma dt).
                const double weight = std::exp(-opticalDepth) * -std::expm1(-sigma * dt);
                quadrature += glm::dvec3(medium.emission(p)) * weight;
            }
            opticalDepth += sigma * dt;
        }
        const Estimate e = traceMany(medium, s.cameraPosition, dir, 6000, 0x9a + uint64_t(k));
        std::printf("ray %d: optical depth %.2f, traced %.5f %.5f %.5f (se %.5f), quadrature "
                    "%.5f %.5f %.5f\n",
                    k, opticalDepth, e.mean.x, e.mean.y, e.mean.z, e.standardError.x, quadrature.x,
                    quadrature.y, quadrature.z);
        if (quadrature.x > 1e-3)
            ++glowing;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(e.mean[c], quadrature[c],
                        4.0 * e.standardError[c] + 0.01 * quadrature[c] + 1e-6)
                << "ray " << k << " channel " << c;
    }
    EXPECT_GE(glowing, 2); // the rays must see the glow, or the test says nothing
}
