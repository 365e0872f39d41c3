// Lightning in the renders (lightning.glsl.h): the flash is zero outside its radius; a still is
// the same with the flash mask or without it (the mask only moves the flash to its own channel);
// a ground discharge draws a bright bolt; and the talk's point: a flash of 4-8 frames keeps at
// least 90 % of its full-resolution brightness through the 16-frame temporal reconstruction with
// the flash mask, and measurably less without it.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>
#include <cloudscape/weather.h>

#include "core/lightning.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "core/tests/storm_scene.h"
#include "model/lightning.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

const cloudscape::SceneResources& smallResources() {
    static const cloudscape::SceneResources r = [] {
        cloudscape::SceneResources res;
        res.noise.base = cloudscape::generateBaseNoise(1, 32);
        res.noise.detail = cloudscape::generateDetailNoise(1, 16);
        res.noise.curl = cloudscape::generateCurlNoise(1, 32);
        Scene s;
        s.weatherResolution = 64;
        res.weather = cloudscape::prepareWeather(s);
        return res;
    }();
    return r;
}

// Under a storm, looking up at it (the under-the-storm preset's storm, a small image).
Scene underTheStorm() {
    return cloudscape::testing::underALightningStorm();
}

// The start of the first flash after `from` that is a ground discharge (or any flash).
cloudscape::LightningState firstFlash(const Scene& s, float from, bool ground) {
    for (float t = from; t < from + 120.0f; t += 0.005f) {
        const cloudscape::LightningState l = cloudscape::lightningStateAt(s, t);
        if (l.peak > 0.0f && l.startS > from + 1.0f && l.ground == ground)
            return l;
    }
    ADD_FAILURE() << "no flash found";
    return {};
}

double luminanceSum(const std::vector<float>& rgba) {
    double sum = 0.0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4)
        sum += 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    return sum;
}

} // namespace

TEST(Lightning, TheFlashIsZeroOutsideItsRadiusAndFallsAsItsPotential) {
    Scene s = underTheStorm();
    const cloudscape::LightningState l = firstFlash(s, 0.0f, false);
    s.timeS = l.startS + 0.003f;
    const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
    ASSERT_EQ(P.lightning.enabled, 1);
    ASSERT_GT(P.lightning.flashIntensity, 0.0f);
    const glm::vec3 c = P.lightning.flashPosition;
    const float r = P.lightning.flashRadius;
    EXPECT_EQ(cm::lightningFlashUnit(c + glm::vec3(r * 1.001f, 0, 0), 0.3f, 0.0f, P), 0.0f);
    EXPECT_EQ(cm::lightningFlashUnit(c + glm::vec3(0, 0, -2.0f * r), 0.3f, 0.0f, P), 0.0f);
    // Along a line, (1 - d / r)^12 as the glow's potential; lower in dense cloud.
    const float at0 = cm::lightningFlashUnit(c, 0.3f, 0.0f, P);
    ASSERT_GT(at0, 0.0f);
    for (float f : {0.1f, 0.3f, 0.6f}) {
        const float v = cm::lightningFlashUnit(c + glm::vec3(f * r, 0, 0), 0.3f, 0.0f, P);
        EXPECT_NEAR(v / at0, std::pow(1.0f - f, 12.0f), 1e-4f) << f;
    }
    EXPECT_LT(cm::lightningFlashUnit(c, 0.3f, 0.15f, P), at0);
}

TEST(Lightning, AStillIsTheSameWithTheFlashMaskOrWithout) {
    Scene s = underTheStorm();
    const cloudscape::LightningState l = firstFlash(s, 0.0f, false);
    s.timeS = l.startS + 0.003f;
    const cloudscape::RenderResult masked = cloudscape::renderCpu(s, smallResources());
    Scene direct = s;
    direct.stormLightningFlashMask = false;
    const cloudscape::RenderResult unmasked = cloudscape::renderCpu(direct, smallResources());
    Scene dark = s;
    dark.stormLightning = false;
    const cloudscape::RenderResult off = cloudscape::renderCpu(dark, smallResources());
    const double flash = luminanceSum(masked.composite) - luminanceSum(off.composite);
    std::printf("flash adds %.1f%% to the frame's luminance\n",
                100.0 * flash / luminanceSum(off.composite));
    EXPECT_GT(flash, 0.05 * luminanceSum(off.composite)) << "the flash should be visible";
    EXPECT_NEAR(luminanceSum(unmasked.composite) - luminanceSum(off.composite), flash,
                1e-3 * flash);
}

TEST(Lightning, ABoltSegmentsProfileIsAGaussianOfItsWidthOrThePixelsFootprint) {
    // A vertical segment 1000 m ahead, `off` metres beside the ray: brightness
    // (w / s) exp(-(off / (s / 2))^2) with s = max(w, pixel angle x 1000 m), written out.
    const float width = 20.0f;
    for (float pixelAngle : {1e-5f, 0.1f}) { // a core wider than the pixel, then narrower
        const float spread = std::max(width, pixelAngle * 1000.0f);
        for (float off : {0.0f, 5.0f, 10.0f, 20.0f, 40.0f}) {
            float t = 0.0f;
            const float got = cm::boltSegmentLight(
                glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(off, 500.0f, 1000.0f),
                glm::vec3(off, -500.0f, 1000.0f), pixelAngle, 1e9f, width, t);
            const float x = off / (0.5f * spread);
            EXPECT_NEAR(got, (width / spread) * std::exp(-x * x), 1e-5f)
                << "pixel angle " << pixelAngle << ", " << off << " m beside";
            EXPECT_NEAR(t, 1000.0f, 1e-2f);
        }
    }
}

TEST(Lightning, AGroundDischargeDrawsABoltAndLightsTheUnderside) {
    Scene s = underTheStorm();
    s.cameraPitchDeg = 5.0f; // the bolt below the cloud base
    const cloudscape::LightningState l = firstFlash(s, 0.0f, true);
    s.timeS = l.startS + 0.003f;
    std::printf("first ground discharge at time_s %.3f\n", l.startS);
    const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
    ASSERT_GT(P.lightning.boltIntensity, 0.5f);
    ASSERT_GT(P.lightning.flashExternal, 0.0f);
    // A ray aimed at the middle of the bolt meets it; one aimed 300 m beside it does not.
    const glm::vec3 camera = s.cameraPosition;
    const glm::vec3 mid = cm::boltVertex(cm::BOLT_SEGMENTS / 2, P);
    float t = 0.0f;
    const glm::vec3 toMid = glm::normalize(mid - camera);
    EXPECT_GT(cm::boltBrightness(camera, toMid, 1e-4f, 1e9f, P, t), 0.5f);
    EXPECT_NEAR(t, glm::length(mid - camera), 50.0f);
    const glm::vec3 beside = glm::normalize(mid + glm::vec3(300.0f, 0, 0) - camera);
    EXPECT_LT(cm::boltBrightness(camera, beside, 1e-4f, 1e9f, P, t), 0.01f);
    // Geometry in front of it hides it.
    EXPECT_EQ(cm::boltBrightness(camera, toMid, 1e-4f, 100.0f, P, t), 0.0f);
    // In the image: some pixels far brighter than the same frame without lightning.
    const cloudscape::RenderResult lit = cloudscape::renderCpu(s, smallResources());
    Scene dark = s;
    dark.stormLightning = false;
    const cloudscape::RenderResult off = cloudscape::renderCpu(dark, smallResources());
    double brightest = 0.0;
    for (size_t i = 0; i < lit.composite.size(); i += 4)
        brightest = std::max(brightest, double(lit.composite[i + 1] - off.composite[i + 1]));
    EXPECT_GT(brightest, 1.0);
}

// The talk's problem and its solution: frames 1/24 s apart (a flash spans 6-8 of them), a camera
// at rest, the sequence started 2 s before the flash so its mask is built; the flash's light in
// each frame (the frame minus the same frame without lightning) against the full-resolution
// render's.
TEST(Lightning, AFlashOfAFewFramesKeepsItsBrightnessWithTheFlashMask) {
    Scene s = underTheStorm();
    const cloudscape::LightningState l = firstFlash(s, 0.0f, false);
    const float dt = 1.0f / 24.0f;
    const int before = 48, during = 8;
    auto frameTime = [&](int i) { return l.startS + 0.003f + float(i - before) * dt; };
    auto temporalFlash = [&](bool lightning, bool mask) {
        cloudscape::TemporalRenderer renderer(smallResources());
        std::vector<double> sums;
        for (int i = 0; i < before + during; ++i) {
            Scene f = s;
            f.timeS = frameTime(i);
            f.stormLightning = lightning;
            f.stormLightningFlashMask = mask;
            const cloudscape::RenderResult r = renderer.renderFrame(f, i);
            if (i >= before)
                sums.push_back(luminanceSum(r.composite));
        }
        return sums;
    };
    const std::vector<double> masked = temporalFlash(true, true);
    const std::vector<double> unmasked = temporalFlash(true, false);
    const std::vector<double> dark = temporalFlash(false, true);
    double reference = 0.0, withMask = 0.0, withoutMask = 0.0;
    for (int i = 0; i < during; ++i) {
        Scene f = s;
        f.timeS = frameTime(before + i);
        const double lit = luminanceSum(cloudscape::renderCpu(f, smallResources()).composite);
        f.stormLightning = false;
        const double off = luminanceSum(cloudscape::renderCpu(f, smallResources()).composite);
        reference += lit - off;
        withMask += masked[i] - dark[i];
        withoutMask += unmasked[i] - dark[i];
    }
    std::printf("flash brightness against full resolution: %.1f%% with the mask, %.1f%% without\n",
                100.0 * withMask / reference, 100.0 * withoutMask / reference);
    ASSERT_GT(reference, 0.0);
    EXPECT_GE(withMask / reference, 0.9);
    EXPECT_LE(withMask / reference, 1.1);
    EXPECT_LT(withoutMask / reference, 0.75);
}

TEST(Lightning, TheEmissionsOctavesAreWrenningesSumOnTheViewSide) {
    // A step of optical depth dtau whose emission is seen through view transmittance T = e^-tau:
    //   T (1 - e^-dtau) + sum_{i=1}^{n-1} albedo a^i e^(-b^i tau) (1 - e^(-b^i dtau)) / b^i
    // (the seeds' step form: dtau in place of each step integral). Written out from the factors.
    Scene shipped = underTheStorm();
    Scene other = shipped;
    other.scatteringOctaves = 3;
    other.octaveFactors = {0.45f, 0.7f, 0.2f};
    other.albedo = 0.9f;
    for (const Scene& s : {shipped, other})
        for (bool exact : {true, false}) {
            cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
            P.energyConservingSteps = exact ? 1 : 0;
            for (float tau : {0.0f, 0.3f, 2.0f, 7.0f})
                for (float dtau : {0.01f, 0.5f, 3.0f}) {
                    const float T = std::exp(-tau);
                    double expected = T * (exact ? 1.0 - std::exp(-dtau) : dtau);
                    double a = s.albedo, b = 1.0;
                    for (int i = 1; i < s.scatteringOctaves; ++i) {
                        a *= s.octaveFactors.x;
                        b *= s.octaveFactors.y;
                        const double step = exact ? (1.0 - std::exp(-b * dtau)) / b : dtau;
                        expected += a * std::exp(-b * tau) * step;
                    }
                    EXPECT_NEAR(cm::emissionStepWeight(T, dtau, P), expected, 2e-5 * expected)
                        << "tau " << tau << " dtau " << dtau << " exact " << exact;
                }
            // One octave, or a cloud that absorbs all it intercepts: the emission alone.
            P.scatteringOctaves = 1;
            EXPECT_EQ(cm::emissionStepWeight(0.2f, 0.5f, P),
                      0.2f * (exact ? 1.0f - std::exp(-0.5f) : 0.5f));
            P.scatteringOctaves = 4;
            P.albedo = 0.0f;
            EXPECT_EQ(cm::emissionStepWeight(0.2f, 0.5f, P),
                      0.2f * (exact ? 1.0f - std::exp(-0.5f) : 0.5f));
        }
}

TEST(Lightning, TheCloudScattersTheFlashOut) {
    // The flash's light in a rendered still (with the flash less without), with the scene's 4
    // octaves against the emission alone (1 octave, which changes the sun's light too: hence the
    // differences). The cloud's scattering adds light; with albedo 0 there is none to add.
    Scene s = underTheStorm();
    const cloudscape::LightningState l = firstFlash(s, 0.0f, false);
    s.timeS = l.startS + 0.003f;
    auto flashLight = [](const Scene& scene) {
        Scene dark = scene;
        dark.stormLightning = false;
        return luminanceSum(cloudscape::renderCpu(scene, smallResources()).composite) -
               luminanceSum(cloudscape::renderCpu(dark, smallResources()).composite);
    };
    Scene single = s;
    single.scatteringOctaves = 1;
    const double withOctaves = flashLight(s), alone = flashLight(single);
    std::printf("flash light: %d octaves %.4g, emission alone %.4g (x%.2f)\n", s.scatteringOctaves,
                withOctaves, alone, withOctaves / alone);
    ASSERT_GT(alone, 0.0);
    EXPECT_GT(withOctaves, 1.5 * alone);
    Scene black = s;
    black.albedo = 0.0f;
    Scene blackSingle = black;
    blackSingle.scatteringOctaves = 1;
    EXPECT_EQ(cloudscape::renderCpu(black, smallResources()).composite,
              cloudscape::renderCpu(blackSingle, smallResources()).composite);
}
