// The lighting terms against formulas written out here by hand from their sources: Wrenninge's
// multiple-scattering octaves (energy a^i, optical depth b^i, eccentricity c^i) over the two-lobe
// Henyey-Greenstein phase, Beer's-Powder of GPU Pro 7 4.4.4 with its view-dependent fade, and the
// Forbidden West ambient term. Each expectation uses only <cmath> and the scene's keys.
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "model/lighting.glsl.h"
#include "model/tests/hand_references.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

using cloudscape::hand::hg;
using cloudscape::hand::octaves;

Scene twoLobeScene() {
    Scene s;
    s.phaseFunction = cloudscape::PhaseFunctionKind::TwoLobe;
    return s;
}

} // namespace

TEST(Lighting, OctavesAreWrenningesSumWrittenOut) {
    // The shipped factors (4 octaves, a 0.6, b 0.3, c 0.5) and a second set with every factor
    // different, so that a factor used for the wrong quantity shows.
    Scene shipped = twoLobeScene();
    Scene other = twoLobeScene();
    other.scatteringOctaves = 3;
    other.octaveFactors = {0.45f, 0.7f, 0.2f};
    other.phaseG = 0.35f;
    other.silverG = 0.7f;
    other.silverWeight = 0.45f;
    other.powder = 0.6f;
    for (const Scene* s : {&shipped, &other}) {
        const cm::CloudParams P = cloudscape::makeCloudParams(*s, 0.0f);
        for (float depth : {0.0f, 0.3f, 2.0f, 7.0f, 25.0f})
            for (float cosTheta : {-1.0f, -0.4f, 0.0f, 0.5f, 0.95f, 1.0f}) {
                const double expected = octaves(*s, depth, cosTheta);
                EXPECT_NEAR(cm::directScattering(depth, cosTheta, P), expected,
                            2e-5 * expected + 1e-9)
                    << "octaves " << s->scatteringOctaves << " depth " << depth << " cos "
                    << cosTheta;
            }
    }
}

TEST(Lighting, OneOctaveIsPhaseTimesBeersPowder) {
    Scene s = twoLobeScene();
    s.scatteringOctaves = 1;
    const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
    // Sun behind the viewer, full powder: 2 e^-d (1 - e^-2d) * phase(-1).
    const double d = 0.8;
    const double phase = 0.7 * hg(-1.0, 0.2) + 0.3 * hg(-1.0, 0.85);
    EXPECT_NEAR(cm::directScattering(d, -1.0f, P),
                phase * 2.0 * std::exp(-d) * (1.0 - std::exp(-2.0 * d)), 1e-6);
    // Looking into the sun the powder term is gone: plain Beer's law.
    EXPECT_NEAR(cm::directScattering(d, 1.0f, P),
                (0.7 * hg(1.0, 0.2) + 0.3 * hg(1.0, 0.85)) * std::exp(-d), 1e-5);
    EXPECT_NEAR(cm::beerLambert(1.5f), std::exp(-1.5), 1e-7);
}

TEST(Lighting, AmbientAndAlbedoAsWrittenInTheTalk) {
    Scene s = twoLobeScene();
    s.ambientTop = {0.4f, 0.5f, 0.8f};
    s.ambientBottom = {0.1f, 0.2f, 0.05f};
    s.ambientStrength = 0.7f;
    s.albedo = 0.8f;
    s.sunIrradiance = {9.0f, 6.0f, 3.0f};
    const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
    const float h = 0.25f, base = 0.36f;
    // Bottom-to-top blend by height, times strength, times sqrt(1 - coarse density).
    const glm::vec3 p(100.0f, 3000.0f, -200.0f); // the gradient sky reads no position
    const glm::vec3 ambient = cm::ambientRadiance(p, h, base, P);
    const double depthFactor = std::sqrt(1.0 - 0.36);
    EXPECT_NEAR(ambient.x, (0.1 + 0.25 * (0.4 - 0.1)) * 0.7 * depthFactor, 1e-6);
    EXPECT_NEAR(ambient.y, (0.2 + 0.25 * (0.5 - 0.2)) * 0.7 * depthFactor, 1e-6);
    EXPECT_NEAR(ambient.z, (0.05 + 0.25 * (0.8 - 0.05)) * 0.7 * depthFactor, 1e-6);
    // Scattered radiance per unit extinction: albedo (sun * direct + ambient).
    const float depth = 1.2f, cosTheta = 0.3f;
    const double direct = octaves(s, depth, cosTheta);
    const glm::vec3 l = cm::scatteredRadiance(p, depth, cosTheta, h, base, P);
    EXPECT_NEAR(l.x, 0.8 * (9.0 * direct + ambient.x), 1e-5);
    EXPECT_NEAR(l.y, 0.8 * (6.0 * direct + ambient.y), 1e-5);
    EXPECT_NEAR(l.z, 0.8 * (3.0 * direct + ambient.z), 1e-5);
}
