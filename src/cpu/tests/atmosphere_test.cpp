// The atmosphere (src/model/atmosphere.glsl.h, sky.glsl.h) through its tables as the CPU backend
// reads them: against a direct integration written out here, and against what a clear sky looks
// like (blue overhead, a reddening low sun, the planet's shadow, distant clouds taking the sky's
// colour).
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "cpu/cpu_textures.h"
#include "model/ground.glsl.h"
#include "model/pixel.glsl.h"
#include "model/sky.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using cloudscape::Scene;
namespace cm = cloudscape::model;

namespace {

// A scene's sky with its tables, bound to this thread while it lives.
struct BoundSky {
    cm::CloudParams params;
    std::vector<glm::vec4> tables;
    cloudscape::cpu::TextureSet set;
    cloudscape::cpu::ScopedTextureBinding binding;

    explicit BoundSky(const Scene& scene)
        : params(makeParams(scene)), tables(cloudscape::computeAtmosphereLuts(params.sky)),
          set(textures(tables)), binding(set) {}

    static cm::CloudParams makeParams(const Scene& scene) {
        cm::CloudParams p = cloudscape::makeCloudParams(scene, 0.0f);
        p.sky.atmosphere.enabled = 1; // makeCloudParams(scene, bias) has no tables; these do
        return p;
    }
    static cloudscape::cpu::TextureSet textures(const std::vector<glm::vec4>& tables) {
        // Small noise and a weather map, for the ground's cloud shadow.
        static const cloudscape::NoiseTextures noise = [] {
            cloudscape::NoiseTextures n;
            n.base = cloudscape::generateBaseNoise(1, 32);
            n.detail = cloudscape::generateDetailNoise(1, 16);
            n.curl = cloudscape::generateCurlNoise(1, 32);
            return n;
        }();
        static const cloudscape::Texture2D weather = [] {
            cloudscape::WeatherParams w;
            w.resolution = 64;
            return cloudscape::generateWeatherMap(w);
        }();
        cloudscape::cpu::TextureSet t{&noise.base, &noise.detail, &noise.curl, &weather};
        t.atmosphere = tables.data();
        return t;
    }
    const cm::SkyParams& sky() const { return params.sky; }
};

Scene sunAt(float elevationDeg) {
    Scene s;
    s.sunElevationDeg = elevationDeg;
    s.sunHeadingDeg = 0.0f;
    return s;
}

// Optical depth from radius r along zenith cosine mu to the top, by the trapezoid rule in double
// precision with the Earth constants written out (Bruneton 2017, Hillaire 2020).
glm::dvec3 directOpticalDepth(double r, double mu, const Scene& s) {
    const double R = s.planetRadiusM, top = R + s.atmosphereTopM;
    const double length = -r * mu + std::sqrt(r * r * (mu * mu - 1.0) + top * top);
    const int n = 20000;
    glm::dvec3 depth(0.0);
    for (int i = 0; i <= n; ++i) {
        const double t = length * i / n;
        const double h = std::sqrt(r * r + t * t + 2.0 * r * mu * t) - R;
        const double rayleigh = std::exp(-h / 8000.0);
        const double mie = std::exp(-h / 1200.0);
        const double ozone = std::max(0.0, 1.0 - std::abs(h - 25000.0) / 15000.0);
        const glm::dvec3 sigma = glm::dvec3(5.802e-6, 13.558e-6, 33.1e-6) * rayleigh +
                                 glm::dvec3(4.44e-6 * mie) +
                                 glm::dvec3(0.650e-6, 1.881e-6, 0.085e-6) * ozone;
        depth += sigma * (length / n) * (i == 0 || i == n ? 0.5 : 1.0);
    }
    return depth;
}

double blueOverRed(glm::vec3 c) {
    return c.z / c.x;
}

} // namespace

TEST(Atmosphere, TransmittanceTableMatchesADirectIntegration) {
    const Scene s;
    const BoundSky sky(s);
    const cm::AtmosphereParams& a = sky.sky().atmosphere;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> altitude(0.0, 60000.0), zenith(-0.2, 1.0);
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
        const double r = s.planetRadiusM + altitude(rng);
        const double mu = zenith(rng);
        // Rays that meet the ground have no transmittance to the top; keep clear of the horizon,
        // where the table's rows change fastest.
        const double muHorizon = -std::sqrt(1.0 - std::pow(s.planetRadiusM / r, 2.0));
        if (mu < muHorizon + 0.02)
            continue;
        const glm::dvec3 expected = glm::exp(-directOpticalDepth(r, mu, s));
        const glm::vec3 got =
            cm::transmittanceToTop(static_cast<float>(r), static_cast<float>(mu), a);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c] / expected[c], 1.0, 0.005)
                << "altitude " << r - s.planetRadiusM << " mu " << mu << " channel " << c;
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

TEST(Atmosphere, TheClearSkyIsBluerOverheadThanAtTheHorizon) {
    const BoundSky sky(sunAt(60.0f));
    const glm::vec3 zenith = cm::skyBackground(glm::vec3(0.0f, 1.0f, 0.0f), sky.sky());
    // Along the horizon, away from the sun.
    const glm::vec3 horizon =
        cm::skyBackground(glm::normalize(glm::vec3(0.0f, 0.02f, -1.0f)), sky.sky());
    EXPECT_GT(blueOverRed(zenith), 1.3 * blueOverRed(horizon));
    EXPECT_GT(zenith.z, zenith.y);
    EXPECT_GT(zenith.y, zenith.x);
    // Plausible magnitudes for a clear day: the zenith sky is a few percent of the sun's
    // irradiance per steradian (Hillaire 2020's figure 11 is about 0.04-0.07 in blue).
    const double ratio = zenith.z / sky.sky().sunIrradiance.z;
    EXPECT_GT(ratio, 0.01);
    EXPECT_LT(ratio, 0.2);
}

TEST(Atmosphere, ALowSunReddensMonotonically) {
    double previous = 0.0;
    for (float elevation : {60.0f, 40.0f, 25.0f, 15.0f, 10.0f, 6.0f, 4.0f, 2.0f}) {
        const BoundSky sky(sunAt(elevation));
        const glm::vec3 sun =
            cm::sunIrradianceAt(glm::vec3(0.0f, 2.0f, 0.0f), sky.sky()) / sky.sky().sunIrradiance;
        const double redOverBlue = sun.x / sun.z;
        EXPECT_GT(redOverBlue, previous) << "elevation " << elevation;
        EXPECT_GT(sun.x, 0.0f);
        previous = redOverBlue;
    }
    EXPECT_GT(previous, 3.0) << "a sun 2 degrees up is deep orange";
}

TEST(Atmosphere, AfterSunsetThePlanetShadowsLowCloudsFirst) {
    const BoundSky sky(sunAt(-3.0f));
    const glm::vec3 low = cm::sunIrradianceAt(glm::vec3(0.0f, 1500.0f, 0.0f), sky.sky());
    const glm::vec3 high = cm::sunIrradianceAt(glm::vec3(0.0f, 8000.0f, 0.0f), sky.sky());
    EXPECT_EQ(low, glm::vec3(0.0f));
    // The sun is 0.1 degree below the geometric horizon of 8 km; the refraction of a grazing ray
    // (about 1.1 degrees) still shows it, deep red through the longest air path there is.
    EXPECT_GT(high.x, 1e-4f * sky.sky().sunIrradiance.x) << "tops still lit";
    EXPECT_GT(high.x, 5.0f * high.z) << "in red";
    // And the sky is dark but not black: twilight.
    const glm::vec3 zenith = cm::skyBackground(glm::vec3(0.0f, 1.0f, 0.0f), sky.sky());
    const BoundSky noon(sunAt(60.0f));
    const glm::vec3 noonZenith = cm::skyBackground(glm::vec3(0.0f, 1.0f, 0.0f), noon.sky());
    EXPECT_GT(zenith.z, 0.0f);
    EXPECT_LT(zenith.z, 0.2f * noonZenith.z);
}

TEST(Atmosphere, DistantCloudsTakeTheSkysColour) {
    const Scene s = sunAt(30.0f);
    const BoundSky sky(s);
    cm::FrameParams frame = cloudscape::makeFrameParams(s);
    frame.cameraPosition = glm::vec3(0.0f, 2.0f, 0.0f);
    // An opaque white cloud seen just above the horizon, at 5 and at 50 km.
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, 0.05f, -1.0f));
    const glm::vec3 cloud(1.0f);
    const glm::vec3 behind = cm::skyRadiance(dir, sky.sky());
    const float geometry = 1e9f; // no scene geometry
    auto distanceToSky = [&](float depth) {
        const glm::vec3 c =
            cm::compositeCloud(cloud, 0.0f, depth, dir, geometry, frame, sky.params);
        return glm::length(c - behind);
    };
    for (float d : {5000.0f, 50000.0f}) {
        const glm::vec3 c = cm::compositeCloud(cloud, 0.0f, d, dir, geometry, frame, sky.params);
        const cm::AirLight air = cm::aerialPerspective(frame.cameraPosition, dir, d, sky.sky());
        std::printf("cloud at %.0f km: (%.3f %.3f %.3f), air T (%.3f %.3f %.3f) light (%.3f %.3f "
                    "%.3f); sky (%.3f %.3f %.3f)\n",
                    d / 1000.0f, c.x, c.y, c.z, air.transmittance.x, air.transmittance.y,
                    air.transmittance.z, air.inScattered.x, air.inScattered.y, air.inScattered.z,
                    behind.x, behind.y, behind.z);
    }
    EXPECT_LT(distanceToSky(50000.0f), 0.9f * distanceToSky(5000.0f));
    // The air dims more over 50 km than over 5, and blue more than red (Rayleigh).
    const cm::AirLight near5 = cm::aerialPerspective(frame.cameraPosition, dir, 5000.0f, sky.sky());
    const cm::AirLight far50 =
        cm::aerialPerspective(frame.cameraPosition, dir, 50000.0f, sky.sky());
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(far50.transmittance[c], near5.transmittance[c]);
    EXPECT_LT(far50.transmittance.z, 0.5f * far50.transmittance.x);
    // Without aerial perspective the distance does not matter.
    BoundSky plain(s);
    plain.params.sky.atmosphere.aerialPerspective = 0;
    const glm::vec3 near =
        cm::compositeCloud(cloud, 0.0f, 5000.0f, dir, geometry, frame, plain.params);
    const glm::vec3 far =
        cm::compositeCloud(cloud, 0.0f, 50000.0f, dir, geometry, frame, plain.params);
    EXPECT_EQ(near, far);
}

// The air between the camera and a point, integrated with `steps` steps (the reference for the
// volume), in the frame aerialPerspective integrates in.
cm::AirLight integratedAir(glm::vec3 origin, glm::vec3 dir, float distance, int steps,
                           const cm::SkyParams& S) {
    const glm::vec2 rMu = cm::atmospherePosition(origin, S);
    const float r = std::min(rMu.x, S.atmosphere.topRadius - 1.0f);
    const glm::vec3 up = (origin - glm::vec3(0.0f, -S.atmosphere.bottomRadius, 0.0f)) / rMu.x;
    const float mu = glm::dot(dir, up);
    const glm::vec3 side = dir - up * mu;
    const glm::vec3 x = glm::length(side) > 1e-6f ? glm::normalize(side) : glm::vec3(1, 0, 0);
    const glm::vec3 z = glm::cross(up, x);
    const glm::vec3 localSun(glm::dot(S.sunDirection, x), glm::dot(S.sunDirection, up),
                             glm::dot(S.sunDirection, z));
    const cm::ScatteredLight l =
        cm::scatterAlongRay(r, glm::vec3(glm::length(side), mu, 0.0f), localSun, distance, false,
                            steps, false, S.sunAngularRadius, S.atmosphere);
    return {l.radiance * S.sunIrradiance, l.transmittance};
}

TEST(Atmosphere, TheAerialPerspectiveVolumeMatchesTheIntegral) {
    // Every composite reads the air from the volume (cameraAerialPerspective). Against a 128-step
    // integral of the same air, over directions above and below the horizon (toward the sun and
    // away) and distances from 100 m to 300 km: within 1.5 % in the mean and 5 % of the brightest
    // air light at worst (the 8-step per-pixel integral it replaced: 0.1-0.6 % and up to 4.5 %),
    // and its transmittance closer than that integral's (16 steps a texel against 8).
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const float elevation : {30.0f, 5.0f, -3.0f}) {
        for (const float altitude : {2.0f, 3000.0f}) {
            Scene s = sunAt(elevation);
            s.cameraPosition = glm::vec3(0.0f, altitude, 0.0f);
            const BoundSky sky(s);
            const glm::vec3 camera = s.cameraPosition;
            // Sums of |error| and of the truth (air light, green), the largest air light, and the
            // worst errors: air light (absolute) and transmittance, for the volume and the steps.
            double volumeSum = 0.0, stepsSum = 0.0, truthSum = 0.0, brightest = 0.0;
            glm::dvec2 worstLight(0.0), worstT(0.0);
            const int n = 400;
            for (int i = 0; i < n; ++i) {
                const float azimuth = 6.2831853f * unit(rng);
                // Most directions near the horizon, where the air is thickest.
                const float elevationView =
                    0.6f * std::pow(unit(rng), 3.0f) * (unit(rng) < 0.3f ? -0.3f : 1.0f);
                const glm::vec3 dir(std::cos(elevationView) * std::sin(azimuth),
                                    std::sin(elevationView),
                                    std::cos(elevationView) * std::cos(azimuth));
                const float extent = cm::rayExtent(cm::atmospherePosition(camera, sky.sky()).x,
                                                   dir.y, sky.sky().atmosphere)
                                         .x;
                const float d = std::min(100.0f * std::pow(3000.0f, unit(rng)), 0.999f * extent);
                const cm::AirLight truth = integratedAir(camera, dir, d, 128, sky.sky());
                const cm::AirLight volume = cm::cameraAerialPerspective(dir, d, sky.sky());
                const cm::AirLight steps = cm::aerialPerspective(camera, dir, d, sky.sky());
                const double ev = std::abs(volume.inScattered.y - truth.inScattered.y);
                const double es = std::abs(steps.inScattered.y - truth.inScattered.y);
                volumeSum += ev;
                stepsSum += es;
                truthSum += truth.inScattered.y;
                brightest = std::max(brightest, double(truth.inScattered.y));
                worstLight = glm::max(worstLight, glm::dvec2(ev, es));
                worstT = glm::max(
                    worstT, glm::dvec2(glm::length(volume.transmittance - truth.transmittance),
                                       glm::length(steps.transmittance - truth.transmittance)));
            }
            std::printf("sun %5.1f camera %5.0f m, volume (8-step integral): air light mean error "
                        "%.4f (%.4f), worst %.4f (%.4f) of the brightest; transmittance worst "
                        "%.4f (%.4f)\n",
                        elevation, altitude, volumeSum / truthSum, stepsSum / truthSum,
                        worstLight.x / brightest, worstLight.y / brightest, worstT.x, worstT.y);
            EXPECT_LT(volumeSum / truthSum, 0.015) << "sun " << elevation << " alt " << altitude;
            EXPECT_LT(worstLight.x / brightest, 0.05) << "sun " << elevation << " alt " << altitude;
            EXPECT_LT(worstT.x, 0.02) << "sun " << elevation << " alt " << altitude;
            EXPECT_LT(worstT.x, worstT.y) << "sun " << elevation << " alt " << altitude;
        }
    }
}

TEST(Atmosphere, TheGroundIsLitBySunAndSkyAndShadowedByClouds) {
    const BoundSky high(sunAt(50.0f)), low(sunAt(5.0f)), below(sunAt(-8.0f));
    const glm::vec3 p(0.0f, 0.0f, 0.0f);
    auto ground = [&](const BoundSky& s, float extinction) {
        cm::CloudParams P = s.params;
        P.extinction = extinction;
        return cm::groundRadiance(p, P);
    };
    // Clear air (clouds of no extinction): a high sun lights the ground more than a low one,
    // and after sunset only the sky does.
    EXPECT_GT(ground(high, 0.0f).y, 2.0f * ground(low, 0.0f).y);
    EXPECT_GT(ground(low, 0.0f).y, ground(below, 0.0f).y);
    EXPECT_GT(ground(below, 0.0f).y, 0.0f);
    // A thick overcast in the way leaves the sky's light alone.
    cm::CloudParams overcast = high.params;
    overcast.coverageBias = 1.0f;
    overcast.extinction = 1.0f;
    const glm::vec3 shadowed = cm::groundRadiance(p, overcast);
    EXPECT_LT(shadowed.y, 0.5f * ground(high, 0.0f).y);
    EXPECT_GT(shadowed.y, 0.0f);
}

TEST(Atmosphere, TheLimbDarkenedSunDiscStillDeliversTheSunsIrradiance) {
    // I(mu) = 1 - u (1 - mu) averages 1 - u / 3 over the disc's area (mu = sqrt(1 - rho^2), whose
    // area mean is 2/3), so the normalised darkening must average 1: the disc's radiance times
    // its solid angle stays the sun's irradiance. Averaged over an area-uniform polar grid.
    Scene s;
    ASSERT_GT(s.sunLimbDarkening, 0.2f) << "the test needs a darkened limb";
    const cm::SkyParams sky = cloudscape::makeCloudParams(s, 0.0f).sky;
    const glm::vec3 sun = sky.sunDirection;
    const glm::vec3 e1 = glm::normalize(glm::cross(sun, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 e2 = glm::cross(sun, e1);
    const double radius = sky.sunAngularRadius;
    const int rings = 200, spokes = 64;
    double sum = 0.0;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < spokes; ++j) {
            const double rho = std::sqrt((i + 0.5) / rings) * radius;
            const double phi = 2.0 * 3.14159265358979 * (j + 0.5) / spokes;
            const glm::vec3 dir = glm::normalize(
                sun + static_cast<float>(std::tan(rho)) * (static_cast<float>(std::cos(phi)) * e1 +
                                                           static_cast<float>(std::sin(phi)) * e2));
            ASSERT_TRUE(cm::insideSunDisc(dir, sky));
            sum += cm::sunLimbDarkening(dir, sky);
        }
    EXPECT_NEAR(sum / (rings * spokes), 1.0, 0.003);
    // Brightest at the centre, darkest at the limb, as the law says.
    const double u = s.sunLimbDarkening;
    EXPECT_NEAR(cm::sunLimbDarkening(sun, sky), 1.0 / (1.0 - u / 3.0), 1e-3);
}
