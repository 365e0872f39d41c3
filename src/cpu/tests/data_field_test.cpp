// The data field's channels (model/data_field.glsl.h, the Forbidden West talk's Nubis data
// field): a neutral field changes nothing and is switched off; the minimum and maximum heights
// confine the clouds to the region's layer; the bottom type relaxes only the bottom gradient (the
// profile is the product of a bottom and a top gradient); a painted anvil coverage spreads cloud
// at the top of the layer only where painted; the generator and the painted image fill the
// regions as documented; a persistent Renderer remakes the field without touching the textures.
#include <cloudscape/backend.h>
#include <cloudscape/data_field.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/noise.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_model.h"
#include "model/data_field.glsl.h"
#include "small_resources.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>

#include <unistd.h>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

const cloudscape::NoiseTextures& testNoise() {
    static const cloudscape::NoiseTextures noise = [] {
        cloudscape::NoiseTextures n;
        n.base = cloudscape::generateBaseNoise(3, 32);
        n.detail = cloudscape::generateDetailNoise(4, 16);
        n.curl = cloudscape::generateCurlNoise(5, 32);
        return n;
    }();
    return noise;
}

constexpr size_t kRegions = size_t(cm::DATA_FIELD_GRID) * cm::DATA_FIELD_GRID;

// Cloud parameters over a 64^2 weather map with the field `cells` (empty: none), and the CPU
// textures bound while it lives.
struct Fixture {
    cloudscape::Texture2D weather;
    cloudscape::cpu::TextureSet set;
    cm::CloudParams P;
    std::unique_ptr<cloudscape::cpu::ScopedTextureBinding> bind;

    Fixture(const Scene& s, const std::vector<glm::vec4>& cells) {
        cloudscape::WeatherParams w;
        w.resolution = 64;
        w.typeMean = s.cloudType;
        w.typeVariation = 0.0f;
        weather = cloudscape::generateWeatherMap(w);
        set.baseNoise = &testNoise().base;
        set.detailNoise = &testNoise().detail;
        set.curlNoise = &testNoise().curl;
        set.weatherMap = &weather;
        P = cloudscape::makeCloudParams(s, cloudscape::CoverageField(weather).biasFor(s.coverage));
        if (!cells.empty()) {
            std::copy(cells.begin(), cells.end(), P.dataField);
            P.dataFieldEnabled = 1;
        }
        bind = std::make_unique<cloudscape::cpu::ScopedTextureBinding>(set);
    }

    // A point at height fraction h of the layer over world (x, z).
    glm::vec3 at(float x, float z, float h) const {
        const float a = P.layerBottom + h * (P.layerTop - P.layerBottom);
        const float r = P.planetRadius + a;
        return {x, std::sqrt(r * r - x * x - z * z) - P.planetRadius, z};
    }
};

std::vector<glm::vec4> uniformField(glm::vec4 value) {
    return std::vector<glm::vec4>(kRegions, value);
}

Scene overcastCumulonimbus() {
    Scene s;
    s.coverage = 0.9f;
    s.cloudType = 1.0f;
    return s;
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST(DataField, ANeutralFieldIsSwitchedOffAndChangesNoDensity) {
    // The generator at its defaults makes the neutral field, which makeCloudParams leaves off.
    EXPECT_TRUE(cloudscape::isNeutralDataField(cloudscape::generateDataField({})));
    cloudscape::SceneResources r;
    cloudscape::WeatherParams w;
    w.resolution = 64;
    r.weather = cloudscape::generateWeatherMap(w);
    r.dataField = cloudscape::generateDataField({});
    EXPECT_EQ(cloudscape::makeCloudParams(Scene{}, r).dataFieldEnabled, 0);
    r.dataField[7].w = 0.9f;
    EXPECT_EQ(cloudscape::makeCloudParams(Scene{}, r).dataFieldEnabled, 1);
    // Switched on with the neutral value everywhere, the density is the same to the bit.
    Scene s;
    s.coverage = 0.6f;
    const Fixture off(s, {});
    const Fixture on(s, uniformField(cm::neutralDataField()));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f), h(0.0f, 1.0f);
    int cloudy = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p = off.at(xz(rng), xz(rng), h(rng));
        const float a = cm::cloudDensityAt(p, 0.0f, false, off.P);
        const float b = cm::cloudDensityAt(p, 0.0f, false, on.P);
        ASSERT_TRUE(sameBits(a, b)) << i;
        cloudy += a > 0.0f ? 1 : 0;
    }
    EXPECT_GT(cloudy, 500);
}

TEST(DataField, TheMinimumAndMaximumHeightsHoldTheCloudsInTheRegionsLayer) {
    // Overcast cumulonimbus fill the layer; a field with base 0.3 and top 0.6 must hold every
    // cloud between them, and the same scene without it has cloud outside.
    const Scene s = overcastCumulonimbus();
    const Fixture free(s, {});
    const Fixture held(s, uniformField(glm::vec4(0.0f, 0.0f, 0.3f, 0.6f)));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f), h(0.0f, 1.0f);
    int heldCloudy = 0, freeOutside = 0;
    for (int i = 0; i < 20000; ++i) {
        const float x = xz(rng), z = xz(rng), f = h(rng);
        const float inside = cm::cloudDensityAt(held.at(x, z, f), 0.0f, false, held.P);
        const float outside = cm::cloudDensityAt(free.at(x, z, f), 0.0f, false, free.P);
        if (inside > 0.0f) {
            ++heldCloudy;
            ASSERT_GT(f, 0.3f) << "cloud below the region's base";
            ASSERT_LT(f, 0.6f) << "cloud above the region's top";
        }
        freeOutside += (outside > 0.0f && (f < 0.3f || f > 0.6f)) ? 1 : 0;
    }
    EXPECT_GT(heldCloudy, 1000);
    EXPECT_GT(freeOutside, 1000);
}

TEST(DataField, TheProfileIsABottomGradientByBottomTypeTimesATopGradientByType) {
    for (float type : {0.0f, 0.5f, 2.0f / 3.0f, 1.0f}) {
        const glm::vec4 p = cm::profileForType(type);
        for (float h = 0.0f; h <= 1.0f; h += 0.01f) {
            // Bottom type 0 is the type's own profile.
            EXPECT_EQ(cm::splitVerticalProfile(h, type, 0.0f), cm::verticalProfile(h, type));
            // Above the bottom gradient's relaxed band only the top gradient acts: the bottom
            // type changes nothing there.
            if (h >= std::min(p.y + cm::BOTTOM_RELAX, p.z)) {
                EXPECT_FLOAT_EQ(cm::splitVerticalProfile(h, type, 1.0f),
                                cm::verticalProfile(h, type));
            }
            // Below it the relaxed bottom thins the underside (never thickens it).
            EXPECT_LE(cm::splitVerticalProfile(h, type, 1.0f), cm::verticalProfile(h, type));
        }
        const float low = p.x + 0.5f * (p.y - p.x);
        EXPECT_LT(cm::splitVerticalProfile(low, type, 1.0f), 0.8f * cm::verticalProfile(low, type));
    }
    // In the model: a ragged bottom type leaves less cloud low in the layer.
    const Scene s = overcastCumulonimbus();
    const Fixture flat(s, {});
    const Fixture ragged(s, uniformField(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f), h(0.0f, 0.15f);
    double flatSum = 0.0, raggedSum = 0.0;
    for (int i = 0; i < 5000; ++i) {
        const float x = xz(rng), z = xz(rng), f = h(rng);
        flatSum += cm::cloudDensityAt(flat.at(x, z, f), 0.0f, false, flat.P);
        raggedSum += cm::cloudDensityAt(ragged.at(x, z, f), 0.0f, false, ragged.P);
    }
    EXPECT_GT(flatSum, 50.0);
    EXPECT_LT(raggedSum, 0.7 * flatSum);
}

TEST(DataField, APaintedAnvilCoverageSpreadsCloudAtTheTopOnlyWherePainted) {
    // No coverage at all, and the anvil channel painted in one block of regions: cloud appears
    // in that block, high in the layer, and nowhere else.
    Scene s;
    s.coverage = 0.0f;
    std::vector<glm::vec4> cells = uniformField(cm::neutralDataField());
    for (int j = 24; j < 40; ++j)
        for (int i = 24; i < 40; ++i)
            cells[size_t(j) * cm::DATA_FIELD_GRID + i].y = 1.0f;
    const Fixture f(s, cells);
    const float region = f.P.weatherExtent / float(cm::DATA_FIELD_GRID);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> xz(-0.5f * f.P.weatherExtent, 0.5f * f.P.weatherExtent);
    std::uniform_real_distribution<float> h(0.0f, 1.0f);
    int inside = 0;
    for (int i = 0; i < 40000; ++i) {
        const float x = xz(rng), z = xz(rng), hf = h(rng);
        if (cm::cloudDensityAt(f.at(x, z, hf), 0.0f, false, f.P) <= 0.0f)
            continue;
        ++inside;
        // Regions 24..39 span [-8, 8) regions about the centre; bilinear reads spread the paint
        // half a region further.
        ASSERT_LT(std::abs(x), 8.5f * region) << x;
        ASSERT_LT(std::abs(z), 8.5f * region) << z;
        ASSERT_GT(hf, 1.0f - cm::anvilProfile().w) << "anvil cloud below the layer's top band";
    }
    EXPECT_GT(inside, 100);
}

TEST(DataField, TheGeneratorStaysInItsRangesIsSeededAndRefusesBadKeys) {
    cloudscape::DataFieldParams d;
    d.bottomType = 0.4f;
    d.baseVariation = 0.2f;
    d.topVariation = 0.5f;
    const std::vector<glm::vec4> a = cloudscape::generateDataField(d);
    ASSERT_EQ(a.size(), kRegions);
    EXPECT_EQ(a, cloudscape::generateDataField(d));
    float lowBase = 1.0f, highBase = 0.0f, lowTop = 1.0f, highTop = 0.0f, highBottom = 0.0f;
    for (const glm::vec4& c : a) {
        EXPECT_GE(c.x, 0.0f);
        EXPECT_LE(c.x, 1.0f);
        EXPECT_EQ(c.y, 0.0f);
        lowBase = std::min(lowBase, c.z);
        highBase = std::max(highBase, c.z);
        lowTop = std::min(lowTop, c.w);
        highTop = std::max(highTop, c.w);
        highBottom = std::max(highBottom, c.x);
    }
    EXPECT_GE(lowBase, 0.0f);
    EXPECT_LE(highBase, 0.2f);
    EXPECT_GT(highBase - lowBase, 0.1f) << "the base must vary across regions";
    EXPECT_GE(lowTop, 0.5f);
    EXPECT_LE(highTop, 1.0f);
    EXPECT_GT(highTop - lowTop, 0.25f) << "the top must vary across regions";
    EXPECT_GT(highBottom, 0.6f);
    d.seed = 2;
    EXPECT_NE(a, cloudscape::generateDataField(d));
    d.baseVariation = 0.7f;
    try {
        cloudscape::generateDataField(d);
        ADD_FAILURE() << "a base variation of 0.7 must be refused";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("weather.base_variation"), std::string::npos)
            << e.what();
    }
}

TEST(DataField, APaintedImageIsAveragedOntoTheRegionsAndABadOneIsRefused) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("cloudscape-field-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    // 128 x 32 RGBA: the left half (bottom 1, anvil 0, base 0.2, top 0.8), the right half zero;
    // each region averages 2 x 0.5 pixels: every region lies in one half.
    const int w = 128, h = 32;
    std::vector<uint8_t> rgba(size_t(w) * h * 4, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w / 2; ++x) {
            uint8_t* px = &rgba[(size_t(y) * w + x) * 4];
            px[0] = 255;
            px[2] = 51;
            px[3] = 204;
        }
    const std::string painted = (dir / "field.png").string();
    cloudscape::writePng(painted, w, h, rgba);
    const std::vector<glm::vec4> field = cloudscape::loadDataFieldImage(painted);
    ASSERT_EQ(field.size(), kRegions);
    EXPECT_EQ(field[5], glm::vec4(1.0f, 0.0f, 0.2f, 0.8f));
    EXPECT_EQ(field[size_t(40) * cm::DATA_FIELD_GRID + 10], glm::vec4(1.0f, 0.0f, 0.2f, 0.8f));
    EXPECT_EQ(field[size_t(40) * cm::DATA_FIELD_GRID + 50], glm::vec4(0.0f));
    // A grey image is refused, naming the file.
    const std::string grey = (dir / "grey.png").string();
    cloudscape::writePngChannels(grey, 4, 4, 1, std::vector<uint8_t>(16, 100));
    try {
        cloudscape::loadDataFieldImage(grey);
        ADD_FAILURE() << "a one-channel data field must be refused";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("grey.png"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("channels"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

TEST(DataField, ARendererRemakesTheFieldAloneAndTheImageFollows) {
    Scene s;
    s.width = 48;
    s.height = 27;
    s.coverage = 0.6f;
    s.cameraPitchDeg = 20.0f;
    cloudscape::BackendOptions cpu;
    cpu.choice = cloudscape::BackendChoice::Cpu;
    cloudscape::Renderer renderer(s, cloudscape::test::smallResources(s), cpu);
    const cloudscape::RenderResult before = renderer.render(s);
    Scene raised = s;
    raised.baseVariation = 0.4f;
    raised.topVariation = 0.6f;
    const cloudscape::UpdateReport report = renderer.update(raised);
    EXPECT_TRUE(report.dataField);
    EXPECT_FALSE(report.weather);
    EXPECT_FALSE(report.noise);
    const cloudscape::RenderResult after = renderer.render(raised);
    EXPECT_NE(before.composite, after.composite);
    // Back to the defaults: the neutral field again, and the first image.
    EXPECT_TRUE(renderer.update(s).dataField);
    EXPECT_EQ(renderer.render(s).composite, before.composite);
}

TEST(DataField, TheFieldDriftsWithTheWeatherMap) {
    // Issue 14 item 1: the data field moves with the weather map (weather.drift_ratio): at a
    // later time the same regions are read that much further downwind.
    cloudscape::DataFieldParams d;
    d.baseVariation = 0.4f;
    d.topVariation = 0.5f;
    const std::vector<glm::vec4> cells = cloudscape::generateDataField(d);
    Scene s;
    s.weatherDriftRatio = 1.0f;
    s.windSpeedMps = 10.0f;
    s.timeS = 0.0f;
    const Fixture early(s, cells);
    s.timeS = 300.0f;
    const Fixture late(s, cells);
    const glm::vec2 moved = late.P.weatherOrigin - early.P.weatherOrigin;
    EXPECT_NEAR(glm::length(moved), 3000.0f, 1.0f);
    for (float x = -20000.0f; x <= 20000.0f; x += 3700.0f) {
        const glm::vec2 here(x, 0.37f * x);
        const glm::vec4 a = cm::dataFieldAt(here, early.P);
        const glm::vec4 b = cm::dataFieldAt(here + moved, late.P);
        EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-4f) << x;
    }
}
