#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <vector>

using cloudscape::Texture2D;
using cloudscape::WeatherParams;

namespace {

double mean(const Texture2D& t, int c) {
    double sum = 0.0;
    for (size_t i = c; i < t.mips[0].size(); i += 4)
        sum += t.mips[0][i];
    return sum / static_cast<double>(t.mips[0].size() / 4);
}

WeatherParams small() {
    WeatherParams p;
    p.resolution = 128;
    return p;
}

float quantized(float v) {
    return std::round(v * 255.0f) / 255.0f;
}

// Channel c of the map as the renderer reads it for a mean coverage (0 coverage, 1
// precipitation, 2 type).
std::vector<float> seen(const Texture2D& t, float coverage, int c) {
    const std::vector<float> all =
        cloudscape::weatherAsSeen(t, cloudscape::CoverageField(t).biasFor(coverage));
    std::vector<float> out;
    for (size_t i = c; i < all.size(); i += 3)
        out.push_back(all[i]);
    return out;
}

double average(const std::vector<float>& v) {
    double sum = 0.0;
    for (float x : v)
        sum += x;
    return sum / static_cast<double>(v.size());
}

// The wrap (texel n-1 next to texel 0) against ordinary neighbours, along x (axis 0) or y.
void expectWraps(const Texture2D& t, int channel, int axis) {
    const int n = t.width;
    auto value = [&](int a, int b) {
        return static_cast<double>(axis == 0 ? t.texel(0, a, b)[channel]
                                             : t.texel(0, b, a)[channel]);
    };
    std::vector<double> interior;
    double seamMean = 0.0, seamMax = 0.0, unrelated = 0.0;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a + 1 < n; ++a)
            interior.push_back(std::abs(value(a + 1, b) - value(a, b)));
        const double seam = std::abs(value(0, b) - value(n - 1, b));
        seamMean += seam / n;
        seamMax = std::max(seamMax, seam);
        unrelated += std::abs(value(n / 2, b) - value(0, b)) / n;
    }
    double interiorMean = 0.0;
    for (double d : interior)
        interiorMean += d / static_cast<double>(interior.size());
    std::nth_element(interior.begin(), interior.begin() + interior.size() * 99 / 100,
                     interior.end());
    const double p99 = interior[interior.size() * 99 / 100];
    const double step = 0.5 / 255.0;
    EXPECT_LT(seamMax, 3.0 * p99 + step) << "channel " << channel << " axis " << axis;
    EXPECT_LT(seamMean, 1.5 * interiorMean + step) << "channel " << channel << " axis " << axis;
    EXPECT_GT(unrelated, 2.0 * interiorMean) << "the check must be able to fail";
}

void expectUnorm8(const Texture2D& t) {
    for (const auto& level : t.mips)
        for (float x : level) {
            ASSERT_TRUE(std::isfinite(x));
            ASSERT_GE(x, 0.0f);
            ASSERT_LE(x, 1.0f);
            ASSERT_EQ(quantized(x), x);
        }
}

} // namespace

TEST(Weather, DefaultMapHasMipsAndUnorm8Values) {
    WeatherParams p;
    p.rainCells = 2;
    const Texture2D t = cloudscape::generateWeatherMap(p);
    ASSERT_EQ(t.width, 512);
    ASSERT_EQ(t.height, 512);
    ASSERT_EQ(t.levelCount(), 10); // 512 .. 1
    for (int l = 0; l < t.levelCount(); ++l)
        EXPECT_EQ(t.mips[l].size(), static_cast<size_t>(512 >> l) * (512 >> l) * 4) << l;
    expectUnorm8(t);
    // Rain cells only raise coverage above the map's mean (the precipitation rule).
    EXPECT_GE(average(seen(t, 0.45f, 0)), 0.45 - 1e-3);
    EXPECT_LT(average(seen(t, 0.45f, 0)), 0.5);
    for (int axis = 0; axis < 2; ++axis) {
        expectWraps(t, 0, axis);
        expectWraps(t, 2, axis);
    }
}

TEST(Weather, CoverageExtremesAreExact) {
    const Texture2D t = cloudscape::generateWeatherMap(small());
    for (float c : seen(t, 0.0f, 0))
        ASSERT_EQ(c, 0.0f);
    for (float c : seen(t, 1.0f, 0))
        ASSERT_EQ(c, 1.0f);
}

TEST(Weather, CoverageFieldMeanIsTheTexelMean) {
    // The distribution's mean (what the bias is chosen with) against the model's own decoding
    // of every texel, for biases across the whole range.
    const Texture2D t = cloudscape::generateWeatherMap(small());
    const cloudscape::CoverageField field(t);
    for (float bias : {-1.0f, -0.6f, -0.2f, 0.0f, 0.13f, 0.5f, 0.9f, 1.0f}) {
        double sum = 0.0;
        for (size_t i = 0; i < t.mips[0].size(); i += 4)
            sum += std::clamp(cloudscape::coverageFieldOf(&t.mips[0][i]) + bias, 0.0f, 1.0f);
        EXPECT_NEAR(field.meanCoverage(bias), sum / (t.mips[0].size() / 4), 1e-6) << bias;
    }
    EXPECT_TRUE(cloudscape::CoverageField().empty());
}

TEST(Weather, MeanCoverageFollowsTheParameter) {
    for (float c : {0.05f, 0.2f, 0.45f, 0.7f, 0.95f})
        for (float feature : {6000.0f, 7000.0f, 20000.0f}) {
            WeatherParams p = small();
            p.featureScaleM = feature; // 60 km / 7 km is not whole: the period rounds to 9
            const Texture2D t = cloudscape::generateWeatherMap(p);
            const std::vector<float> coverage = seen(t, c, 0);
            EXPECT_NEAR(average(coverage), c, 1e-3) << c << " " << feature;
            // Not a constant: the field varies, with soft edges between clear and cloudy.
            float lo = 1, hi = 0;
            size_t partial = 0;
            for (float v : coverage) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                partial += v > 0.0f && v < 1.0f;
            }
            EXPECT_GT(hi - lo, 0.3f) << c << " " << feature;
            EXPECT_GT(partial, coverage.size() / 4) << c << " " << feature;
        }
}

TEST(Weather, FeatureScaleSetsTheSizeOfFeatures) {
    // Mean neighbour difference of coverage: smaller features vary faster.
    auto roughness = [](float featureScaleM) {
        WeatherParams p = small();
        p.featureScaleM = featureScaleM;
        const Texture2D t = cloudscape::generateWeatherMap(p);
        double sum = 0.0;
        for (int y = 0; y < t.height; ++y)
            for (int x = 0; x + 1 < t.width; ++x)
                sum += std::abs(t.texel(0, x + 1, y)[0] - t.texel(0, x, y)[0]);
        return sum;
    };
    EXPECT_GT(roughness(3000.0f), 1.5 * roughness(15000.0f));
}

TEST(Weather, TypeFollowsMeanAndVariation) {
    WeatherParams p = small();
    p.typeMean = 0.5f;
    p.typeVariation = 0.0f;
    const Texture2D flat = cloudscape::generateWeatherMap(p);
    for (size_t i = 2; i < flat.mips[0].size(); i += 4)
        ASSERT_EQ(flat.mips[0][i], quantized(0.5f));
    p.typeVariation = 0.3f;
    const Texture2D varied = cloudscape::generateWeatherMap(p);
    EXPECT_NEAR(mean(varied, 2), 0.5, 0.05);
    float lo = 1, hi = 0;
    for (size_t i = 2; i < varied.mips[0].size(); i += 4) {
        lo = std::min(lo, varied.mips[0][i]);
        hi = std::max(hi, varied.mips[0][i]);
    }
    EXPECT_LT(lo, 0.35f);
    EXPECT_GT(hi, 0.65f);
    EXPECT_GE(lo, 0.5f - 0.3f - 1.0f / 255.0f);
    EXPECT_LE(hi, 0.5f + 0.3f + 1.0f / 255.0f);
}

TEST(Weather, RainCellsForceCumulonimbusAndCoverage) {
    WeatherParams p = small();
    p.typeMean = 0.3f;
    p.rainCells = 3;
    p.rainCellRadiusM = 5000.0f;
    const Texture2D t = cloudscape::generateWeatherMap(p);
    const std::vector<float> coverage = seen(t, 0.2f, 0);
    size_t full = 0, wet = 0;
    for (size_t i = 0; i < t.mips[0].size(); i += 4) {
        const float rain = t.mips[0][i + 1], type = t.mips[0][i + 2];
        wet += rain > 0.0f;
        if (rain >= 0.999f) {
            ++full;
            ASSERT_GE(coverage[i / 4], 0.7f - 1e-6f); // the rule, applied after the bias
            ASSERT_EQ(type, 1.0f);                    // in the map itself
        }
    }
    EXPECT_GE(full, 3u) << "each cell has a full-precipitation centre";
    // Bumps of radius 5 km on a 60 km map: 3 cells cover at most 3 pi (5/60)^2 = 6.5 %.
    const size_t texels = t.mips[0].size() / 4;
    EXPECT_GT(wet, texels / 100);
    EXPECT_LE(wet, texels * 7 / 100);

    p.rainCells = 0;
    EXPECT_EQ(mean(cloudscape::generateWeatherMap(p), 1), 0.0);
}

TEST(Weather, RainCellsWrapAroundTheMap) {
    // Large cells, so some certainly straddle the edges; a bump cut at the edge instead of
    // continuing on the other side would jump by far more than any neighbour step inside.
    WeatherParams p = small();
    p.rainCells = 8;
    p.rainCellRadiusM = 15000.0f;
    const Texture2D t = cloudscape::generateWeatherMap(p);
    const int n = t.width;
    for (int axis = 0; axis < 2; ++axis) {
        auto rain = [&](int a, int b) {
            return axis == 0 ? t.texel(0, a, b)[1] : t.texel(0, b, a)[1];
        };
        float seamMax = 0.0f, interiorMax = 0.0f, edgeRain = 0.0f;
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a + 1 < n; ++a)
                interiorMax = std::max(interiorMax, std::abs(rain(a + 1, b) - rain(a, b)));
            seamMax = std::max(seamMax, std::abs(rain(0, b) - rain(n - 1, b)));
            edgeRain = std::max(edgeRain, rain(0, b));
        }
        EXPECT_GT(edgeRain, 0.5f) << "a cell must straddle the edge for the check to mean much";
        EXPECT_LE(seamMax, 1.5f * interiorMax + 1.0f / 255.0f) << "axis " << axis;
    }
}

TEST(Weather, DeterministicSeededAndWrapping) {
    WeatherParams p = small();
    const Texture2D a = cloudscape::generateWeatherMap(p);
    EXPECT_EQ(a.mips, cloudscape::generateWeatherMap(p).mips);
    for (int axis = 0; axis < 2; ++axis) {
        expectWraps(a, 0, axis);
        expectWraps(a, 2, axis);
    }
    p.seed = 2;
    const Texture2D b = cloudscape::generateWeatherMap(p);
    double diff = 0.0;
    for (size_t i = 0; i < a.mips[0].size(); i += 4)
        diff += std::abs(a.mips[0][i] - b.mips[0][i]);
    EXPECT_GT(diff / (a.mips[0].size() / 4), 0.05);
}

TEST(Weather, InvalidParametersNameTheParameter) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<std::pair<std::string, std::function<void(WeatherParams&)>>> cases = {
        {"resolution", [](WeatherParams& p) { p.resolution = 15; }},
        {"resolution", [](WeatherParams& p) { p.resolution = 8193; }},
        {"extent_m", [](WeatherParams& p) { p.extentM = 0.0f; }},
        {"extent_m", [nan](WeatherParams& p) { p.extentM = nan; }},
        {"type", [nan](WeatherParams& p) { p.typeMean = nan; }},
        {"feature_scale_m", [](WeatherParams& p) { p.featureScaleM = -5.0f; }},
        {"type", [](WeatherParams& p) { p.typeMean = 1.2f; }},
        {"type_variation", [](WeatherParams& p) { p.typeVariation = -0.2f; }},
        {"rain_cells", [](WeatherParams& p) { p.rainCells = -1; }},
        {"rain_cell_radius_m", [](WeatherParams& p) { p.rainCellRadiusM = 0.0f; }},
    };
    for (const auto& [name, mutate] : cases) {
        WeatherParams p = small();
        mutate(p);
        try {
            cloudscape::generateWeatherMap(p);
            ADD_FAILURE() << name << " was accepted";
        } catch (const cloudscape::Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(name), std::string::npos) << message;
            EXPECT_NE(message.find('['), std::string::npos) << "names the range: " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        }
    }
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
    EXPECT_EQ(t.height, 4);
    ASSERT_EQ(t.levelCount(), 4); // 8x4, 4x2, 2x1, 1x1
    EXPECT_EQ(t.mips.back().size(), 4u);
    expectUnorm8(t);
    EXPECT_EQ(t.texel(0, 0, 0)[0], 0.0f);
    // The painted coverage is the field exactly (low byte = high byte in alpha).
    EXPECT_FLOAT_EQ(cloudscape::coverageFieldOf(t.texel(0, 6, 1)), 50.0f / 255.0f);
    EXPECT_EQ(t.texel(0, 6, 1)[1], 1.0f);
    EXPECT_EQ(t.texel(0, 6, 1)[2], 1.0f);
    // As read with no bias: as painted, and the rule raises the raining half to 0.7.
    const std::vector<float> asPainted = cloudscape::weatherAsSeen(t, 0.0f);
    EXPECT_EQ(asPainted[0], 0.0f);
    EXPECT_FLOAT_EQ(asPainted[(1 * 8 + 6) * 3], 0.7f);

    // RGBA: the image's alpha is ignored, values are taken as linear 8-bit.
    const std::string rgba = (dir / "rgba.png").string();
    cloudscape::writePngChannels(rgba, 2, 2, 4,
                                 {10, 0, 200, 7, 20, 0, 100, 7, 30, 0, 0, 7, 40, 0, 50, 7});
    const Texture2D u = cloudscape::loadWeatherImage(rgba);
    EXPECT_FLOAT_EQ(cloudscape::coverageFieldOf(u.texel(0, 1, 0)), 20.0f / 255.0f);
    EXPECT_FLOAT_EQ(u.texel(0, 0, 0)[2], 200.0f / 255.0f);
    EXPECT_EQ(u.texel(0, 1, 1)[3], u.texel(0, 1, 1)[0]);

    const std::string gray = (dir / "gray.png").string();
    cloudscape::writePngChannels(gray, 2, 2, 1, std::vector<uint8_t>(4, 9));
    try {
        cloudscape::loadWeatherImage(gray);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("gray.png"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("1 channels"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("expected 3 (RGB) or 4 (RGBA)"), std::string::npos);
    }
    EXPECT_THROW(cloudscape::loadWeatherImage((dir / "missing.png").string()), cloudscape::Error);
    std::filesystem::remove_all(dir);
}
