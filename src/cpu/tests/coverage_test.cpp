// weather.coverage as a uniform: it changes the image without regenerating the weather map, and
// works on a painted map as on the procedural one.
#include <cloudscape/image_io.h>
#include <cloudscape/renderer.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"

#include <gtest/gtest.h>

#include <filesystem>

using cloudscape::Scene;

namespace {

cloudscape::SceneResources paintedResources() {
    // A painted map: a band of full coverage across clear sky, mean 0.25.
    // One directory per test: ctest runs the tests of this file in parallel processes.
    const auto dir = std::filesystem::temp_directory_path() /
                     (std::string("cloudscape_coverage_") +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "band.png").string();
    std::vector<uint8_t> pixels(16 * 16 * 3, 0);
    for (int y = 0; y < 16; ++y)
        for (int x = 4; x < 8; ++x)
            pixels[(y * 16 + x) * 3] = 255;
    cloudscape::writePngChannels(path, 16, 16, 3, pixels);
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::loadWeatherImage(path);
    r.weatherCoverage = cloudscape::CoverageField(r.weather);
    std::filesystem::remove_all(dir);
    return r;
}

double meanTransmittance(const cloudscape::RenderResult& r) {
    double sum = 0.0;
    for (size_t i = 3; i < r.cloud.size(); i += 4)
        sum += r.cloud[i];
    return sum / static_cast<double>(r.cloud.size() / 4);
}

} // namespace

TEST(Coverage, APaintedMapKeepsItsValuesAtItsOwnMean) {
    const cloudscape::SceneResources r = paintedResources();
    EXPECT_NEAR(r.weatherCoverage.meanCoverage(0.0f), 0.25, 1e-9);
    EXPECT_NEAR(r.weatherCoverage.biasFor(0.25f), 0.0f, 1e-6f);
    Scene s;
    s.coverage = 0.25f;
    EXPECT_NEAR(cloudscape::makeCloudParams(s, r).coverageBias, 0.0f, 1e-6f);
}

TEST(Coverage, ChangesThePaintedImageWithoutTouchingTheMap) {
    const cloudscape::SceneResources r = paintedResources();
    const std::vector<std::vector<float>> before = r.weather.mips;
    Scene s;
    s.width = 48;
    s.height = 27;
    s.cameraPitchDeg = 20.0f;
    double previous = 2.0;
    for (float coverage : {0.1f, 0.25f, 0.6f, 0.9f}) {
        s.coverage = coverage;
        const double t = meanTransmittance(cloudscape::renderCpu(s, r));
        EXPECT_LT(t, previous) << "more coverage, less light through, at " << coverage;
        previous = t;
    }
    EXPECT_EQ(r.weather.mips, before);
}
