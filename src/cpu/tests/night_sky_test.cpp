// The night sky (issue 11): the moon as a second source of the atmosphere's tables, the night
// sky's floor, and the clouds' direct light switching from the sun to the moon. Model functions
// through the CPU backend's reads of the tables, and small CPU renders.
#include <cloudscape/error.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "cpu/cpu_textures.h"
#include "model/pixel.glsl.h"
#include "model/sky.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using cloudscape::Scene;
namespace cm = cloudscape::model;

namespace {

// A scene's sky (with the moon, as makeCloudParams(scene, resources) sets it) and its tables,
// bound to this thread while it lives.
struct NightSky {
    cm::SkyParams sky;
    std::vector<glm::vec4> tables;
    cloudscape::cpu::TextureSet set;
    cloudscape::cpu::ScopedTextureBinding binding;

    explicit NightSky(const Scene& scene)
        : sky(cloudscape::makeSkyParams(scene)), tables(cloudscape::computeAtmosphereLuts(sky)),
          set(textures(tables)), binding(set) {
        sky.moonLightsClouds =
            cm::moonOutshinesSun(scene.cameraPosition, scene.cloudTopM, scene.maxDistanceM, sky)
                ? 1
                : 0;
    }
    static cloudscape::cpu::TextureSet textures(const std::vector<glm::vec4>& tables) {
        cloudscape::cpu::TextureSet t{};
        t.atmosphere = tables.data();
        return t;
    }
};

Scene night(float sunElevation, float moonElevation, float phase = 1.0f) {
    Scene s;
    s.sunElevationDeg = sunElevation;
    s.sunHeadingDeg = 20.0f;
    s.moonEnabled = true;
    s.moonElevationDeg = moonElevation;
    s.moonHeadingDeg = 200.0f;
    s.moonPhase = phase;
    return s;
}

double luminance(glm::vec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Directions over the upper sky (and a few just below the horizon), away from both discs.
std::vector<glm::vec3> skyDirections() {
    std::vector<glm::vec3> dirs;
    for (float elevation : {-5.0f, 2.0f, 10.0f, 30.0f, 60.0f, 85.0f})
        for (float heading = 0.0f; heading < 360.0f; heading += 40.0f)
            dirs.push_back(cloudscape::directionFromAngles(heading, elevation));
    return dirs;
}

} // namespace

TEST(NightSky, TheMoonsIrradianceFollowsItsAlbedoSizeAndPhase) {
    // Full moon at the Moon's albedo and size: 2.4e-6 of the sun, the difference of their
    // magnitudes (-12.74 against -26.74 gives 2.5e-6).
    const cm::SkyParams full = cloudscape::makeSkyParams(night(-20.0f, 40.0f));
    ASSERT_EQ(full.moonEnabled, 1);
    const double ratio = full.moonIrradiance.y / full.sunIrradiance.y;
    EXPECT_NEAR(ratio, 2.45e-6, 0.1e-6);
    EXPECT_NEAR(glm::degrees(2.0 * full.moonAngularRadius), 0.52, 1e-4);
    // Quarter: phase angle 90 degrees, Allen's law 10^(-0.4 (2.34 + 0.26)) = 0.0912.
    const cm::SkyParams quarter = cloudscape::makeSkyParams(night(-20.0f, 40.0f, 0.5f));
    EXPECT_NEAR(glm::degrees(quarter.moonPhaseAngle), 90.0, 1e-3);
    EXPECT_NEAR(quarter.moonIrradiance.y / full.moonIrradiance.y, 0.0912, 0.0005);
    // New moon: no light.
    const cm::SkyParams dark = cloudscape::makeSkyParams(night(-20.0f, 40.0f, 0.0f));
    EXPECT_LT(dark.moonIrradiance.y, 1e-3f * full.moonIrradiance.y);
    // Off, or far below the horizon: the whole moon block is zero.
    Scene off = night(-20.0f, 40.0f);
    off.moonEnabled = false;
    EXPECT_EQ(cloudscape::makeSkyParams(off).moonEnabled, 0);
    EXPECT_EQ(cloudscape::makeSkyParams(off).moonIrradiance, glm::vec3(0.0f));
    EXPECT_EQ(cloudscape::makeSkyParams(night(-20.0f, -30.0f)).moonEnabled, 0);
}

TEST(NightSky, AMoonlitSkyIsTheDaySkyWithTheSunWhereTheMoonIsScaledByItsIrradiance) {
    // Sun 20 degrees down (astronomical night), full moon 40 degrees up: the sky is the sky of a
    // sun in the moon's place, times the moon's irradiance over the sun's, and the sun's own
    // twilight adds (almost) nothing.
    const Scene nightScene = night(-20.0f, 40.0f);
    Scene dayScene;
    dayScene.sunElevationDeg = nightScene.moonElevationDeg;
    dayScene.sunHeadingDeg = nightScene.moonHeadingDeg;
    dayScene.sunAngularDiameterDeg = nightScene.moonAngularDiameterDeg;
    double worst = 0.0;
    std::vector<glm::vec3> nightSky, daySky;
    {
        const NightSky n(nightScene);
        for (glm::vec3 d : skyDirections())
            nightSky.push_back(cm::skyBackground(d, n.sky));
    }
    double scale = 0.0;
    {
        const NightSky n(nightScene);
        scale = n.sky.moonIrradiance.y / n.sky.sunIrradiance.y;
        const NightSky day(dayScene);
        for (glm::vec3 d : skyDirections())
            daySky.push_back(cm::skyBackground(d, day.sky));
    }
    for (size_t i = 0; i < nightSky.size(); ++i) {
        ASSERT_TRUE(std::isfinite(nightSky[i].x) && std::isfinite(nightSky[i].z));
        for (int c = 0; c < 3; ++c) {
            ASSERT_GT(nightSky[i][c], 0.0f) << "direction " << i;
            worst = std::max(worst, std::abs(nightSky[i][c] / (daySky[i][c] * scale) - 1.0));
        }
    }
    std::printf("moonlit sky / (day sky x %.3g): worst relative difference %.4f over %zu "
                "directions\n",
                scale, worst, nightSky.size());
    // Measured 0.021: the sun's last twilight at -20 degrees (below) on the moonlit sky.
    EXPECT_LT(worst, 0.03);
}

TEST(NightSky, WithTheMoonDownOnlyTheNightSkysFloorIsLeft) {
    Scene s = night(-20.0f, -30.0f);
    s.nightRadiance = 1.35e-9f;
    Scene black = s;
    black.nightRadiance = 0.0f;
    const NightSky withFloor(s);
    const glm::vec3 floorRadiance = withFloor.sky.nightRadiance;
    double worstTwilight = 0.0;
    for (glm::vec3 d : skyDirections()) {
        if (d.y < 0.0f)
            continue;
        const glm::vec3 sky = cm::skyBackground(d, withFloor.sky);
        ASSERT_TRUE(std::isfinite(sky.x));
        // The floor through the air: between its value dimmed along a grazing path and itself.
        EXPECT_LE(luminance(sky), 1.01 * luminance(floorRadiance)) << d.y;
        EXPECT_GT(luminance(sky), 0.05 * luminance(floorRadiance)) << d.y;
        if (d.y > 0.5f) {
            EXPECT_GT(luminance(sky), 0.7 * luminance(floorRadiance));
        }
    }
    // What the sun 20 degrees down still adds, against the floor: astronomical twilight ends at
    // -18 degrees, where by definition the last of it fades into the night sky's own light, so
    // toward the sun's horizon a little is left; overhead almost nothing.
    double worstOverhead = 0.0;
    {
        const NightSky without(black);
        for (glm::vec3 d : skyDirections()) {
            if (d.y <= 0.0f)
                continue;
            const double t =
                luminance(cm::skyBackground(d, without.sky)) / luminance(floorRadiance);
            worstTwilight = std::max(worstTwilight, t);
            if (d.y > 0.5f)
                worstOverhead = std::max(worstOverhead, t);
        }
    }
    std::printf("sun -20 deg, no moon: twilight at most %.3g of the night floor (%.3g above 30 "
                "deg)\n",
                worstTwilight, worstOverhead);
    EXPECT_LT(worstTwilight, 1.0);
    EXPECT_LT(worstOverhead, 0.02);
}

TEST(NightSky, TheMoonsPhaseScalesItsLightAndShapesItsDisc) {
    const Scene fullScene = night(-20.0f, 40.0f, 1.0f);
    const Scene halfScene = night(-20.0f, 40.0f, 0.5f);
    const glm::vec3 zenith(0.0f, 1.0f, 0.0f);
    const glm::vec3 moon = cloudscape::directionFromAngles(200.0f, 40.0f);
    glm::vec3 fullSky, halfSky, fullAmbient, halfAmbient;
    const glm::vec3 p(0.0f, 5000.0f, 0.0f);
    {
        const NightSky n(fullScene);
        fullSky = cm::skyBackground(zenith, n.sky);
        fullAmbient = cm::skyAmbientAt(p, 1.0f, n.sky);
    }
    const NightSky n(halfScene);
    halfSky = cm::skyBackground(zenith, n.sky);
    halfAmbient = cm::skyAmbientAt(p, 1.0f, n.sky);
    const double law = cloudscape::moonPhaseBrightness(90.0);
    EXPECT_NEAR(halfSky.y / fullSky.y, law, 0.01 * law);
    EXPECT_NEAR(halfAmbient.y / fullAmbient.y, law, 0.01 * law);
    // The half moon's disc: its half toward the sun (the bright limb) lit, the other dark.
    const float offset = 0.5f * n.sky.moonAngularRadius;
    const glm::vec3 towardLimb = glm::normalize(moon + n.sky.moonBrightLimb * offset);
    const glm::vec3 awayFromLimb = glm::normalize(moon - n.sky.moonBrightLimb * offset);
    ASSERT_TRUE(cm::insideMoonDisc(towardLimb, n.sky));
    ASSERT_TRUE(cm::insideMoonDisc(awayFromLimb, n.sky));
    EXPECT_GT(luminance(cm::moonDiscSeen(towardLimb, n.sky)), 100.0 * luminance(halfSky));
    EXPECT_EQ(cm::moonDiscSeen(awayFromLimb, n.sky), glm::vec3(0.0f));
    // The bright limb faces the sun: its direction leans toward the sun's.
    EXPECT_GT(glm::dot(n.sky.moonBrightLimb, n.sky.sunDirection), 0.0f);
}

TEST(NightSky, TheMoonsDiscDeliversItsIrradianceAtEveryPhase) {
    // The disc's radiance over its solid angle is the moon's irradiance (at its phase) through
    // the air toward it, at full moon as at a gibbous one: the lit part's radiance is that
    // irradiance spread over the lit fraction (1 + cos alpha) / 2 of the disc. Summed over an
    // area-uniform polar grid of the disc.
    for (float phase : {1.0f, 0.75f}) {
        const NightSky n(night(-20.0f, 40.0f, phase));
        const cm::SkyParams& S = n.sky;
        const glm::vec3 moon = S.moonDirection;
        const glm::vec3 e1 = S.moonBrightLimb;
        const glm::vec3 e2 = glm::normalize(glm::cross(moon, e1));
        const double radius = S.moonAngularRadius;
        const int rings = 200, spokes = 64;
        glm::dvec3 sum(0.0);
        for (int i = 0; i < rings; ++i)
            for (int j = 0; j < spokes; ++j) {
                const double rho = std::sqrt((i + 0.5) / rings) * radius * 0.999;
                const double phi = 2.0 * 3.14159265358979 * (j + 0.5) / spokes;
                const glm::vec3 dir =
                    glm::normalize(moon + static_cast<float>(std::tan(rho)) *
                                              (static_cast<float>(std::cos(phi)) * e1 +
                                               static_cast<float>(std::sin(phi)) * e2));
                sum += glm::dvec3(cm::moonDiscSeen(dir, S));
            }
        const double solidAngle = 3.14159265358979 * radius * radius;
        const glm::dvec3 delivered = sum * (solidAngle / (rings * spokes));
        const float air =
            cm::sunTransmittance(cm::skyViewRadius(S.atmosphere), moon.y, 0.0f, S.atmosphere).y;
        EXPECT_NEAR(delivered.y, S.moonIrradiance.y * air, 0.03 * S.moonIrradiance.y * air)
            << "phase " << phase;
    }
}

TEST(NightSky, TheCloudsTakeTheirLightFromTheMoonOnlyOnceTheSunLightsThemLess) {
    // Sun up: the sun. Sun 20 down with the moon up: the moon. Across the switch the light of the
    // source given up is below the other's everywhere on the layer (figures printed).
    EXPECT_EQ(NightSky(night(5.0f, 40.0f)).sky.moonLightsClouds, 0);
    EXPECT_EQ(NightSky(night(-20.0f, 40.0f)).sky.moonLightsClouds, 1);
    EXPECT_EQ(NightSky(night(-20.0f, -30.0f)).sky.moonLightsClouds, 0) << "no moon, no switch";
    float switchAt = 99.0f;
    for (float e = 0.0f; e >= -12.0f; e -= 0.25f) {
        const NightSky n(night(e, 40.0f));
        // The sun's light on the layer's top above the camera and 60 km toward the sun, against
        // the moon's, at the last sun elevation before the switch and the first after.
        const glm::vec3 top(0.0f, n.sky.moonEnabled ? 8000.0f : 0.0f, 0.0f);
        const double sunHere = luminance(cm::sunIrradianceAt(top, n.sky));
        const double moonHere = luminance(cm::moonIrradianceAt(top, n.sky));
        if (n.sky.moonLightsClouds != 0) {
            switchAt = e;
            std::printf("clouds' light switches to the moon at sun %.2f deg: sun on the top above "
                        "the camera %.3g, moon %.3g (of the sun's irradiance)\n",
                        e, sunHere / luminance(n.sky.sunIrradiance),
                        moonHere / luminance(n.sky.sunIrradiance));
            EXPECT_LE(sunHere, moonHere);
            break;
        }
    }
    EXPECT_LT(switchAt, -2.0f) << "not while the sun still lights the tops";
    EXPECT_GT(switchAt, -8.0f);
}

TEST(NightSky, AMoonlitNightRendersLitCloudsAndSky) {
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("night"));
    s.width = 64;
    s.height = 36;
    const cloudscape::SceneResources resources = cloudscape::prepareResources(s);
    const cloudscape::RenderResult r = cloudscape::renderCpu(s, resources);
    double cloudLight = 0.0, sky = 0.0;
    int cloudPixels = 0, skyPixels = 0;
    for (int i = 0; i < s.width * s.height; ++i) {
        const float* c = &r.composite[static_cast<size_t>(i) * 4];
        const float* cloud = &r.cloud[static_cast<size_t>(i) * 4];
        ASSERT_TRUE(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]));
        const double l = luminance(glm::vec3(c[0], c[1], c[2]));
        if (cloud[3] < 0.5f) { // mostly cloud
            cloudLight += luminance(glm::vec3(cloud[0], cloud[1], cloud[2]));
            ++cloudPixels;
        } else if (cloud[3] > 0.999f) {
            sky += l;
            ++skyPixels;
        }
    }
    ASSERT_GT(cloudPixels, 20);
    ASSERT_GT(skyPixels, 20);
    const double sunIrradiance = luminance(s.sunIrradiance);
    std::printf("night preset: mean cloud light %.3g, sky %.3g (of the sun's irradiance)\n",
                cloudLight / cloudPixels / sunIrradiance, sky / skyPixels / sunIrradiance);
    // Moonlit: about 2.4e-6 of a day's light; far from black, far from daylight.
    EXPECT_GT(cloudLight / cloudPixels, 1e-9 * sunIrradiance);
    EXPECT_LT(cloudLight / cloudPixels, 1e-4 * sunIrradiance);
    EXPECT_GT(sky / skyPixels, 1e-9 * sunIrradiance);
    EXPECT_LT(sky / skyPixels, 1e-4 * sunIrradiance);
}

TEST(NightSky, BadMoonKeysAreOneLineErrors) {
    for (const char* bad :
         {"moon.phase=1.5", "moon.albedo=-0.1", "moon.elevation_deg=91",
          "moon.angular_diameter_deg=0", "sky.night_radiance=-1", "moon.enabled=maybe"}) {
        Scene s;
        try {
            cloudscape::applyOverride(s, bad);
            cloudscape::validateScene(s, "--set");
            ADD_FAILURE() << bad << " was accepted";
        } catch (const cloudscape::Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            const std::string key = std::string(bad).substr(0, std::string(bad).find('='));
            EXPECT_NE(message.find(key), std::string::npos) << message;
        }
    }
}

TEST(NightSky, TwilightFadesIntoMoonlightWithoutAJump) {
    // The night preset with the sun from 2 degrees up to 12 down, a degree at a time: the mean
    // luminance of the image falls through sunset, the switch of the clouds' light to the moon
    // and into the moonlit night (figures printed; docs/ARCHITECTURE.md).
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("night"));
    s.width = 48;
    s.height = 27;
    cloudscape::SceneResources resources = cloudscape::prepareResources(s);
    auto meanAt = [&](float elevation, int& moonLights) {
        s.sunElevationDeg = elevation;
        cloudscape::prepareAtmosphere(s, resources);
        moonLights = cloudscape::makeCloudParams(s, resources).sky.moonLightsClouds;
        const cloudscape::RenderResult r = cloudscape::renderCpu(s, resources);
        double sum = 0.0;
        for (int i = 0; i < s.width * s.height; ++i) {
            const float* c = &r.composite[static_cast<size_t>(i) * 4];
            sum += luminance(glm::vec3(c[0], c[1], c[2]));
        }
        return sum / (s.width * s.height);
    };
    std::vector<double> means;
    double worst = 1.0;
    float sunLast = 99.0f; // the lowest whole degree at which the sun still lights the clouds
    for (int e = 2; e >= -12; --e) {
        int moonLights = 0;
        means.push_back(meanAt(float(e), moonLights));
        ASSERT_TRUE(std::isfinite(means.back()));
        ASSERT_GT(means.back(), 0.0);
        if (moonLights == 0)
            sunLast = float(e);
        const double ratio = means.size() > 1 ? means[means.size() - 2] / means.back() : 1.0;
        worst = std::max(worst, ratio);
        std::printf("sun %3d deg: mean luminance %.4g (x 1/%.2f), clouds lit by the %s\n", e,
                    means.back(), ratio, moonLights ? "moon" : "sun");
    }
    // It only ever darkens, and smoothly: no degree more than 5 times darker than the one before
    // (measured at most x 1/4.1, -6 to -7). With the sun's axis of the multiple-scattering and
    // ambient tables linear in its cosine (a texel every 3.6 degrees) the last of the exponential
    // fade ended at a texel as a straight line to near zero, and -8 -> -9 degrees fell x 1/9.6; the
    // axis is now denser through twilight (sunAxisU: a texel every 1.6 degrees at -9).
    for (size_t i = 1; i < means.size(); ++i)
        EXPECT_LE(means[i], means[i - 1] * 1.0001) << "sun " << 2 - int(i);
    EXPECT_LT(worst, 5.0);
    // The switch itself, found to 1/16 degree: the image just before and just after it.
    ASSERT_LT(sunLast, 2.0f);
    ASSERT_GT(sunLast, -12.0f);
    float sunSide = sunLast, moonSide = sunLast - 1.0f;
    while (sunSide - moonSide > 1.0f / 16.0f) {
        const float middle = 0.5f * (sunSide + moonSide);
        int moonLights = 0;
        meanAt(middle, moonLights);
        (moonLights ? moonSide : sunSide) = middle;
    }
    int flag = 0;
    const double before = meanAt(sunSide, flag);
    ASSERT_EQ(flag, 0);
    const double after = meanAt(moonSide, flag);
    ASSERT_EQ(flag, 1);
    // The twilight's own fade over the same 1/16 degree, just before it, with the sun lighting
    // the clouds on both sides.
    const double earlier = meanAt(sunSide + (sunSide - moonSide), flag);
    ASSERT_EQ(flag, 0);
    const double fade = before / earlier;
    std::printf("the clouds' light switches to the moon between sun %.4f and %.4f deg: mean "
                "luminance %.4g -> %.4g (x %.4f; the twilight's own fade over the step before "
                "is x %.4f)\n",
                sunSide, moonSide, before, after, after / before, fade);
    EXPECT_NEAR((after / before) / fade, 1.0, 0.03);
}
