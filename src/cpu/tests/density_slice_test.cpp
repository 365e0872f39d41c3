// The viewer's density slice (cpu_density_slice.h, the model's debugDensitySlice): its points
// lie where the slice says (checked in double against the plain geometry), it is drawn to scale
// with the cloud layer's band and the ground where the scene puts them, and its clouds are where
// the density is.
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_density_slice.h"
#include "cpu/cpu_model.h"
#include "model/debug_view.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace cm = cloudscape::model;

namespace {

cloudscape::Scene smallCumulus() {
    cloudscape::Scene s =
        cloudscape::loadScene(cloudscape::resolveScenePath("fair-weather-cumulus"));
    s.weatherResolution = 128;
    s.terrainResolution = 128;
    return s;
}

cloudscape::SceneResources resourcesFor(const cloudscape::Scene& s) {
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    cloudscape::prepareTerrain(s, r);
    return r;
}

bool sameColour(glm::vec3 a, glm::vec3 b) {
    return a == b;
}

} // namespace

TEST(DensitySlice, PointsLieAtTheirAltitudeAndDistanceFromTheCamera) {
    const float R = 6371000.0f;
    const glm::vec2 camera(1200.0f, -3400.0f);
    const glm::vec2 heading(0.6f, 0.8f);
    for (float along : {0.0f, 1000.0f, 30000.0f, 120000.0f})
        for (float altitude : {0.0f, 1500.0f, 8000.0f}) {
            const glm::vec3 p = cm::densitySlicePoint(camera, heading, along, altitude, R);
            // In double: the distance from the planet's centre (0, -R, 0) less the radius.
            const double dx = p.x, dy = double(p.y) + R, dz = p.z;
            const double a = std::sqrt(dx * dx + dy * dy + dz * dz) - R;
            EXPECT_NEAR(a, altitude, 0.05) << along << " m along";
            const double ax = p.x - camera.x, az = p.z - camera.y;
            EXPECT_NEAR(std::hypot(ax, az), along, 1e-3 * along + 0.01);
            EXPECT_NEAR(ax * 0.8 - az * 0.6, 0.0, 1e-3 * along + 0.01) << "along the heading";
        }
}

TEST(DensitySlice, IsDrawnToScaleWithTheLayerAndTheGroundInPlace) {
    cloudscape::Scene s = smallCumulus();
    const int width = 160, height = 90;
    const cloudscape::SceneResources r = resourcesFor(s);
    const std::vector<glm::vec3> slice = cloudscape::cpu::densitySlice(s, r, width, height);
    ASSERT_EQ(slice.size(), size_t(width) * height);
    const auto frame = cloudscape::cpu::densitySliceFrame(s, height);
    // 15 % over the layer's top (the camera is far below it), in equal metres across and up.
    EXPECT_FLOAT_EQ(frame.topAltitude, 1.15f * s.cloudTopM);
    EXPECT_FLOAT_EQ(frame.metresPerPixel * height, frame.topAltitude);

    // The layer's band: the rows whose centre altitude lies within clouds.bottom_m..top_m show
    // the layer's air (or cloud) at the image's right edge, far from the camera's hill.
    const glm::vec3 layerAir(0.12f, 0.18f, 0.32f), aboveAir(0.05f, 0.08f, 0.16f);
    int bandRows = 0, cloudPixels = 0;
    for (int y = 0; y < height; ++y) {
        const float altitude = frame.topAltitude - (y + 0.5f) * frame.metresPerPixel;
        const bool inBand = altitude >= s.cloudBottomM && altitude <= s.cloudTopM;
        bandRows += inBand ? 1 : 0;
        for (int x = 0; x < width; ++x) {
            const glm::vec3 c = slice[size_t(y) * width + x];
            if (altitude > s.cloudTopM + 1.0f) {
                EXPECT_TRUE(sameColour(c, aboveAir)) << "above the layer, row " << y;
            }
            if (inBand && !sameColour(c, layerAir)) {
                ++cloudPixels; // cloud: lighter than the layer's air in every channel
                EXPECT_GT(c.x, layerAir.x);
                EXPECT_GT(c.z, layerAir.z);
            }
        }
    }
    const float expectedRows = (s.cloudTopM - s.cloudBottomM) / frame.metresPerPixel;
    EXPECT_NEAR(bandRows, expectedRows, 1.0);
    std::printf("slice %dx%d: %.1f m per pixel, %d band rows, %d cloud pixels\n", width, height,
                frame.metresPerPixel, bandRows, cloudPixels);
    EXPECT_GT(cloudPixels, 20) << "the cumulus shows";

    // The bottom row at the left edge: the camera stands on a hill, so the ground is there.
    EXPECT_FALSE(sameColour(slice[size_t(height - 1) * width], aboveAir));
    EXPECT_FALSE(sameColour(slice[size_t(height - 1) * width], layerAir));
}

TEST(DensitySlice, CloudPixelsAreWhereTheDensityIs) {
    // Each band pixel is cloud exactly where the density at its point (computed here from the
    // slice's geometry) is positive, and brighter for more density.
    cloudscape::Scene s = smallCumulus();
    const int width = 96, height = 54;
    const cloudscape::SceneResources r = resourcesFor(s);
    const std::vector<glm::vec3> slice = cloudscape::cpu::densitySlice(s, r, width, height);
    const cm::CloudParams P = cloudscape::makeCloudParams(s, r);
    cloudscape::cpu::TextureSet set{&r.noise.base, &r.noise.detail, &r.noise.curl, &r.weather};
    set.terrain = r.terrain.heights.data();
    const cloudscape::cpu::ScopedTextureBinding bind(set);
    const auto frame = cloudscape::cpu::densitySliceFrame(s, height);
    const float h = glm::radians(s.cameraHeadingDeg);
    const glm::vec2 heading(std::sin(h), std::cos(h));
    int checked = 0, dense = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float altitude = frame.topAltitude - (y + 0.5f) * frame.metresPerPixel;
            if (altitude < s.cloudBottomM || altitude > s.cloudTopM)
                continue;
            const glm::vec3 p =
                cm::densitySlicePoint(glm::vec2(s.cameraPosition.x, s.cameraPosition.z), heading,
                                      (x + 0.5f) * frame.metresPerPixel, altitude, s.planetRadiusM);
            const float density = cm::cloudDensityAt(p, 0.0f, false, P);
            const glm::vec3 c = slice[size_t(y) * width + x];
            const float expected = 0.12f + (1.0f - 0.12f) * (1.0f - std::exp(-4.0f * density));
            EXPECT_NEAR(c.x, expected, 1e-5f) << x << "," << y;
            ++checked;
            dense += density > 0.0f ? 1 : 0;
        }
    EXPECT_GT(dense, 10);
    EXPECT_GT(checked, dense * 4);
}
