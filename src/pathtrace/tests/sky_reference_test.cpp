// The path-traced atmosphere (src/pathtrace/atmosphere_medium.h, sky_reference.h) against what
// can be computed another way: its transmittance against the model's optical depth, its single
// scattering against a quadrature written out here, its Rayleigh sampling against the CDF; and
// one thing any clear sky shows: a noon zenith bluer than the horizon.
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "model/atmosphere.glsl.h"
#include "pathtrace/atmosphere_medium.h"
#include "pathtrace/sky_reference.h"
#include "pathtrace/tracking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace cm = cloudscape::model;
namespace pt = cloudscape::pathtrace;

namespace {

cm::SkyParams skyWithSunAt(float elevationDeg) {
    cloudscape::Scene scene;
    scene.sunElevationDeg = elevationDeg;
    scene.sunHeadingDeg = 0.0f;
    return cloudscape::makeSkyParams(scene);
}

glm::dvec3 upAt(double altitude, const cm::AtmosphereParams& a) {
    return glm::dvec3(0.0, double(a.bottomRadius) + altitude, 0.0);
}

// A direction at an elevation in the x-y plane.
glm::dvec3 elevated(double degrees) {
    const double e = glm::radians(degrees);
    return glm::dvec3(std::cos(e), std::sin(e), 0.0);
}

// Optical depth along a ray relative to the centre, midpoint rule in double.
double opticalDepth(const pt::AtmosphereMedium& m, glm::dvec3 p, glm::dvec3 dir, double length,
                    int steps) {
    double depth = 0.0;
    const double dt = length / steps;
    for (int i = 0; i < steps; ++i)
        depth += m.sigmaT(p + dir * ((i + 0.5) * dt)) * dt;
    return depth;
}

} // namespace

TEST(SkyReference, TransmittanceMatchesTheModelsOpticalDepth) {
    const cm::AtmosphereParams a = skyWithSunAt(30.0f).atmosphere;
    const uint64_t before = pt::majorantViolations().load();
    const uint64_t beforeControl = pt::minorantViolations().load();
    struct Case {
        double altitude;
        double elevationDeg;
    };
    for (const Case& k : {Case{0.0, 90.0}, Case{0.0, 20.0}, Case{1500.0, 5.0}, Case{8000.0, 0.0}}) {
        const glm::dvec3 p = upAt(k.altitude, a);
        const glm::dvec3 dir = elevated(k.elevationDeg);
        for (int channel = 0; channel < 3; ++channel) {
            const pt::AtmosphereMedium medium(a, channel);
            const pt::AtmosphereMedium::Exit out = medium.exit(p, dir);
            ASSERT_FALSE(out.ground);
            pt::Random random(7 + channel, 11);
            const int n = 10000;
            double sum = 0.0;
            double squares = 0.0;
            for (int i = 0; i < n; ++i) {
                const double t =
                    pt::estimateAtmosphereTransmittance(medium, p, dir, out.distance, random);
                sum += t;
                squares += t * t;
            }
            const double mean = sum / n;
            const double se = std::sqrt((squares / n - mean * mean) / (n - 1));
            const float r = float(glm::length(p));
            const double expected =
                std::exp(-double(cm::opticalDepthToTop(r, float(dir.y), a)[channel]));
            SCOPED_TRACE(testing::Message() << "altitude " << k.altitude << " elevation "
                                            << k.elevationDeg << " channel " << channel);
            EXPECT_LT(se / mean, 0.0015); // precise enough for the 0.5 % to mean something
            EXPECT_NEAR(mean / expected, 1.0, 0.005);
            std::printf("transmittance %g m %g deg channel %d: %.5f (s.e. %.5f) / model %.5f\n",
                        k.altitude, k.elevationDeg, channel, mean, se, expected);
        }
    }
    EXPECT_EQ(pt::majorantViolations().load(), before);
    EXPECT_EQ(pt::minorantViolations().load(), beforeControl);
}

TEST(SkyReference, RayleighSamplingFollowsItsDistribution) {
    // CDF of (1 + mu^2) on [-1, 1]: (mu + mu^3 / 3 + 4 / 3) / (8 / 3).
    for (int i = 1; i < 20; ++i) {
        const float u = float(i) / 20.0f;
        const float mu = pt::sampleRayleighCos(u);
        const double cdf = (mu + mu * mu * mu / 3.0 + 4.0 / 3.0) / (8.0 / 3.0);
        EXPECT_NEAR(cdf, u, 1e-5) << "u " << u;
    }
    EXPECT_NEAR(pt::sampleRayleighCos(0.0f), -1.0f, 1e-5f);
}

TEST(SkyReference, SingleScatteringMatchesAQuadrature) {
    // Sun 30 degrees up, looking 5 degrees up across the sun's azimuth: a path that stays lit.
    const cm::SkyParams sky = skyWithSunAt(30.0f);
    const cm::AtmosphereParams& a = sky.atmosphere;
    const glm::dvec3 sun = glm::normalize(glm::dvec3(sky.sunDirection));
    const glm::dvec3 view = glm::normalize(glm::dvec3(0.3, std::sin(glm::radians(5.0)), 1.0));
    const glm::dvec3 start = upAt(2.0, a);
    pt::SkyReferenceOptions options;
    options.singleScattering = true;
    options.seed = 3;
    const pt::SkyReferenceEstimate e =
        pt::traceSkyReference(sky, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(view), 60000, options);
    const float cosTheta = float(glm::dot(view, sun));
    for (int channel = 0; channel < 3; ++channel) {
        const pt::AtmosphereMedium m(a, channel);
        const double length = m.exit(start, view).distance;
        const int steps = 3000;
        const double dt = length / steps;
        double transmittance = 1.0;
        double radiance = 0.0;
        for (int i = 0; i < steps; ++i) {
            const glm::dvec3 p = start + view * ((i + 0.5) * dt);
            const pt::AtmosphereMedium::Coefficients c = m.at(p);
            const double half = std::exp(-0.5 * c.extinction * dt); // to the midpoint and on
            transmittance *= half;
            const double toSun = std::exp(-opticalDepth(m, p, sun, m.exit(p, sun).distance, 400));
            const double phase =
                c.rayleigh * cm::rayleighPhase(cosTheta) + c.mie * cm::miePhase(cosTheta, a.mieG);
            radiance += transmittance * phase * toSun * dt;
            transmittance *= half;
        }
        radiance *= sky.sunIrradiance[channel];
        SCOPED_TRACE(testing::Message() << "channel " << channel);
        EXPECT_LT(e.standardError[channel] / e.radiance[channel], 0.01);
        EXPECT_NEAR(e.radiance[channel], radiance,
                    4.0 * e.standardError[channel] + 0.003 * radiance);
    }
}

TEST(SkyReference, TheNoonZenithIsBluerThanTheHorizon) {
    const cm::SkyParams sky = skyWithSunAt(70.0f);
    const glm::vec3 camera(0.0f, 2.0f, 0.0f);
    const pt::SkyReferenceEstimate zenith =
        pt::traceSkyReference(sky, camera, glm::vec3(0.0f, 1.0f, 0.0f), 6000);
    const glm::vec3 horizonDir = glm::normalize(glm::vec3(0.0f, 0.02f, 1.0f));
    const pt::SkyReferenceEstimate horizon = pt::traceSkyReference(sky, camera, horizonDir, 6000);
    for (const pt::SkyReferenceEstimate* e : {&zenith, &horizon})
        for (int c = 0; c < 3; ++c)
            ASSERT_LT(e->standardError[c], 0.1 * e->radiance[c]);
    const double zenithBlueness = zenith.radiance.z / zenith.radiance.x;
    const double horizonBlueness = horizon.radiance.z / horizon.radiance.x;
    EXPECT_GT(zenithBlueness, 1.3 * horizonBlueness);
    EXPECT_EQ(zenith.truncated + horizon.truncated, 0u);
}
