#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using cloudscape::Texture2D;
using cloudscape::WeatherParams;

namespace {

double mean(const Texture2D& t, int c) {
    double sum = 0.0;
    for (size_t i = c; i < t.mips[0].size(); i += 4)
        sum += t.mips[0][i];
    return sum / (t.mips[0].size() / 4);
}

WeatherParams small() {
    WeatherParams p;
    p.resolution = 128;
    return p;
}

} // namespace

TEST(Weather, CoverageExtremesAreExact) {
    WeatherParams p = small();
    p.coverage = 0.0f;
    const Texture2D none = cloudscape::generateWeatherMap(p);
    for (size_t i = 0; i < none.mips[0].size(); i += 4)
        ASSERT_EQ(none.mips[0][i], 0.0f);
    p.coverage = 1.0f;
    const Texture2D full = cloudscape::generateWeatherMap(p);
    for (size_t i = 0; i < full.mips[0].size(); i += 4)
        ASSERT_EQ(full.mips[0][i], 1.0f);
}

TEST(Weather, MeanCoverageFollowsTheParameter) {
    for (float c : {0.2f, 0.45f, 0.7f}) {
        WeatherParams p = small();
        p.coverage = c;
        const Texture2D t = cloudscape::generateWeatherMap(p);
        EXPECT_NEAR(mean(t, 0), c, 0.02) << c;
        // Not a constant: the field varies.
        float lo = 1, hi = 0;
        for (size_t i = 0; i < t.mips[0].size(); i += 4) {
            lo = std::min(lo, t.mips[0][i]);
            hi = std::max(hi, t.mips[0][i]);
        }
        EXPECT_GT(hi - lo, 0.5f) << c;
    }
}

TEST(Weather, RainCellsForceCumulonimbusAndCoverage) {
    WeatherParams p = small();
    p.coverage = 0.2f;
    p.typeMean = 0.3f;
    p.rainCells = 3;
    p.rainCellRadiusM = 5000.0f;
    const Texture2D t = cloudscape::generateWeatherMap(p);
    int rainy = 0;
    for (size_t i = 0; i < t.mips[0].size(); i += 4) {
        if (t.mips[0][i + 1] >= 0.999f) {
            ++rainy;
            EXPECT_GE(t.mips[0][i], 0.7f - 1.0f / 255.0f);
            EXPECT_EQ(t.mips[0][i + 2], 1.0f);
        }
    }
    EXPECT_GE(rainy, 3) << "each cell has a full-precipitation centre";
    p.rainCells = 0;
    EXPECT_EQ(mean(cloudscape::generateWeatherMap(p), 1), 0.0);
}

TEST(Weather, DeterministicSeededAndWrapping) {
    WeatherParams p = small();
    const Texture2D a = cloudscape::generateWeatherMap(p);
    EXPECT_EQ(a.mips, cloudscape::generateWeatherMap(p).mips);
    p.seed = 2;
    EXPECT_NE(a.mips, cloudscape::generateWeatherMap(p).mips);
    // Opposite edges continue each other like interior neighbours do.
    const int n = a.width;
    double seam = 0.0, interior = 0.0;
    for (int y = 0; y < n; ++y) {
        seam += std::abs(a.texel(0, 0, y)[0] - a.texel(0, n - 1, y)[0]);
        interior += std::abs(a.texel(0, n / 2, y)[0] - a.texel(0, n / 2 - 1, y)[0]);
    }
    EXPECT_LT(seam, 2.0 * interior + n / 255.0);
}

TEST(Weather, InvalidParametersNameTheParameter) {
    WeatherParams p = small();
    p.coverage = 1.5f;
    try {
        cloudscape::generateWeatherMap(p);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("coverage"), std::string::npos);
    }
    p = small();
    p.resolution = 4;
    EXPECT_THROW(cloudscape::generateWeatherMap(p), cloudscape::Error);
}

TEST(Weather, PaintedImageOverride) {
    const auto dir = std::filesystem::temp_directory_path() / "cloudscape_weather_test";
    std::filesystem::create_directories(dir);
    const std::string rgb = (dir / "rgb.png").string();
    // Left half clear, right half raining stratus (the rule turns it into cumulonimbus).
    std::vector<uint8_t> pixels(8 * 4 * 3, 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 4; x < 8; ++x) {
            pixels[(y * 8 + x) * 3 + 0] = 50;
            pixels[(y * 8 + x) * 3 + 1] = 255;
            pixels[(y * 8 + x) * 3 + 2] = 0;
        }
    cloudscape::writePngChannels(rgb, 8, 4, 3, pixels);
    const Texture2D t = cloudscape::loadWeatherImage(rgb);
    EXPECT_EQ(t.width, 8);
    EXPECT_EQ(t.texel(0, 0, 0)[0], 0.0f);
    EXPECT_FLOAT_EQ(t.texel(0, 6, 1)[0], std::round(0.7f * 255.0f) / 255.0f);
    EXPECT_EQ(t.texel(0, 6, 1)[2], 1.0f);

    const std::string gray = (dir / "gray.png").string();
    cloudscape::writePngChannels(gray, 2, 2, 1, std::vector<uint8_t>(4, 9));
    try {
        cloudscape::loadWeatherImage(gray);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("gray.png"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("1 channels"), std::string::npos);
    }
    EXPECT_THROW(cloudscape::loadWeatherImage((dir / "missing.png").string()), cloudscape::Error);
    std::filesystem::remove_all(dir);
}
