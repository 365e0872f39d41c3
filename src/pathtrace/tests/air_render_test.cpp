// pathtrace.atmosphere: the path tracer's images with the air traced as a medium (air_integrator.h)
// against the real-time renderer's sky tables, which docs/QUALITY.md section 6 measures at
// 0.9-1.0 of the traced sky for a sun 30 degrees up, and with clouds in that air against the
// clouds lit through the tables (pathtrace.atmosphere off).
#include <cloudscape/noise.h>
#include <cloudscape/pathtrace.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

cloudscape::Scene smallScene(float coverage) {
    cloudscape::Scene s;
    s.width = 8;
    s.height = 6;
    s.sunElevationDeg = 30.0f;
    s.cameraFovDeg = 50.0f;
    s.cameraPitchDeg = 25.0f;
    s.cameraHeadingDeg = s.sunHeadingDeg + 150.0f; // the sun behind, off to one side
    s.coverage = coverage;
    s.weatherResolution = 64;
    s.pathAtmosphere = true;
    cloudscape::validateScene(s, "air test");
    return s;
}

cloudscape::SceneResources resourcesFor(const cloudscape::Scene& s) {
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    cloudscape::prepareAtmosphere(s, r);
    return r;
}

glm::dvec3 channelMeans(const std::vector<float>& pixels, int stride, int rowBegin, int rowEnd,
                        int width) {
    glm::dvec3 sum(0.0);
    for (int y = rowBegin; y < rowEnd; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                sum[c] += pixels[(size_t(y) * width + x) * stride + c];
    return sum / double((rowEnd - rowBegin) * width);
}

} // namespace

TEST(PathTraceAtmosphere, AClearSkyAgreesWithTheTablesAndIsBluerHigherUp) {
    const cloudscape::Scene scene = smallScene(0.0f);
    const cloudscape::SceneResources res = resourcesFor(scene);
    const cloudscape::RenderResult rt = cloudscape::renderCpu(scene, res);
    cloudscape::PathTraceImage pt;
    const cloudscape::PathTraceStats stats = cloudscape::pathTrace(scene, res, pt, 48);
    EXPECT_EQ(stats.majorantViolations, 0u);
    EXPECT_EQ(stats.truncated, 0u);
    const glm::dvec3 traced = channelMeans(pt.mean, 3, 0, scene.height, scene.width);
    const glm::dvec3 table = channelMeans(rt.composite, 4, 0, scene.height, scene.width);
    for (int c = 0; c < 3; ++c) {
        SCOPED_TRACE(testing::Message() << "channel " << c);
        EXPECT_GT(traced[c], 0.0);
        EXPECT_NEAR(table[c] / traced[c], 0.95, 0.1);
    }
    // Row 0 is the top of the image.
    const glm::dvec3 top = channelMeans(pt.mean, 3, 0, 2, scene.width);
    const glm::dvec3 bottom = channelMeans(pt.mean, 3, scene.height - 2, scene.height, scene.width);
    EXPECT_GT(top.z / top.x, 1.1 * (bottom.z / bottom.x));
}

// Pixel means clamped at 2 (well above a cloud's radiance here): next-event estimation through
// the droplets' forward peak gives rare samples a thousand times the mean, which at 16 samples per
// pixel would decide the comparison alone (docs/QUALITY.md clamps the same way).
glm::dvec3 clampedMeans(const std::vector<float>& pixels) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < pixels.size(); ++i)
        sum[i % 3] += std::min(double(pixels[i]), 2.0);
    return sum / double(pixels.size() / 3);
}

TEST(PathTraceAtmosphere, CloudsInTheAirAreLitAsThroughTheTables) {
    cloudscape::Scene scene = smallScene(0.6f);
    const cloudscape::SceneResources res = resourcesFor(scene);
    cloudscape::PathTraceImage withAir;
    const cloudscape::PathTraceStats stats = cloudscape::pathTrace(scene, res, withAir, 16);
    EXPECT_EQ(stats.majorantViolations, 0u);
    EXPECT_EQ(stats.truncated, 0u);
    const std::string fingerprintWithAir = cloudscape::pathTraceFingerprint(scene, res);
    scene.pathAtmosphere = false;
    EXPECT_NE(cloudscape::pathTraceFingerprint(scene, res), fingerprintWithAir);
    cloudscape::PathTraceImage tabled;
    cloudscape::pathTrace(scene, res, tabled, 16);
    const glm::dvec3 a = clampedMeans(withAir.mean);
    const glm::dvec3 b = clampedMeans(tabled.mean);
    // And the clear sky with the air: the clouds are there (white, where the sky is blue).
    const cloudscape::Scene clear = smallScene(0.0f);
    const cloudscape::SceneResources clearRes = resourcesFor(clear);
    cloudscape::PathTraceImage clearAir;
    cloudscape::pathTrace(clear, clearRes, clearAir, 8);
    const glm::dvec3 sky = clampedMeans(clearAir.mean);
    for (int c = 0; c < 3; ++c) {
        SCOPED_TRACE(testing::Message() << "channel " << c);
        ASSERT_TRUE(std::isfinite(a[c]));
        EXPECT_NEAR(a[c] / b[c], 1.0, 0.35);
    }
    EXPECT_GT(a.x, 1.5 * sky.x);
}
