// Keyframe files (render --frames --keyframes): each key's track interpolates or steps as
// documented, every bad file is a one-line error naming the file, the keyframe and the key, and a
// time-lapse of the time of day and the coverage regenerates no texture between frames.
#include <cloudscape/error.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/solar_position.h>

#include "core/resources.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using cloudscape::Keyframes;
using cloudscape::Scene;

namespace {

Keyframes parse(const std::string& json, const Scene& base = Scene{}) {
    return cloudscape::parseKeyframes(json, "day.json", base);
}

std::string errorOf(const std::string& json, const Scene& base = Scene{}) {
    try {
        parse(json, base);
    } catch (const cloudscape::Error& e) {
        return e.what();
    }
    return "";
}

// {"keyframes": [{"time_s": t, "set": {...}}, ...]} from (time, set) pairs.
std::string file(const std::vector<std::pair<std::string, std::string>>& frames) {
    std::string text = R"({"keyframes": [)";
    for (size_t i = 0; i < frames.size(); ++i)
        text += (i ? ", " : "") + std::string(R"({"time_s": )") + frames[i].first + R"(, "set": )" +
                frames[i].second + "}";
    return text + "]}";
}

} // namespace

TEST(Keyframes, NumbersAndVectorsInterpolateAndHoldOutsideTheirKeyframes) {
    const Keyframes k =
        parse(file({{"10", R"({"weather.coverage": 0.2, "sun.irradiance": [0, 0, 0]})"},
                    {"20", R"({"weather.coverage": 0.6, "sun.irradiance": [10, 20, 30]})"}}));
    EXPECT_EQ(k.keyframeCount(), 2);
    EXPECT_EQ(k.animatedKeys(), (std::vector<std::string>{"sun.irradiance", "weather.coverage"}));
    const Scene base;
    EXPECT_FLOAT_EQ(k.sceneAt(base, 0.0).coverage, 0.2f) << "held before the first";
    EXPECT_FLOAT_EQ(k.sceneAt(base, 10.0).coverage, 0.2f);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 15.0).coverage, 0.4f);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 12.5).coverage, 0.3f);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 20.0).coverage, 0.6f);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 1e6).coverage, 0.6f) << "held after the last";
    const glm::vec3 quarter = k.sceneAt(base, 12.5).sunIrradiance;
    EXPECT_FLOAT_EQ(quarter.x, 2.5f);
    EXPECT_FLOAT_EQ(quarter.y, 5.0f);
    EXPECT_FLOAT_EQ(quarter.z, 7.5f);
    // Keys the file does not name keep the base scene's values.
    Scene other;
    other.erosion = 0.7f;
    EXPECT_EQ(k.sceneAt(other, 15.0).erosion, 0.7f);
    EXPECT_TRUE(Keyframes{}.empty());
    EXPECT_EQ(Keyframes{}.sceneAt(other, 3.0).erosion, 0.7f);
}

TEST(Keyframes, IntegersRoundAndBooleansStringsAndChoicesStep) {
    const Keyframes k = parse(file(
        {{"0",
          R"({"lighting.light_samples": 2, "lighting.phase": "two-lobe", "march.blue_noise": false})"},
         {"10",
          R"({"lighting.light_samples": 6, "lighting.phase": "hg-draine", "march.blue_noise": true})"}}));
    const Scene base;
    EXPECT_EQ(k.sceneAt(base, 4.0).lightSamples, 4); // 3.6
    EXPECT_EQ(k.sceneAt(base, 3.0).lightSamples, 3); // 3.2
    EXPECT_EQ(k.sceneAt(base, 9.99).phaseFunction, cloudscape::PhaseFunctionKind::TwoLobe);
    EXPECT_FALSE(k.sceneAt(base, 9.99).blueNoise);
    EXPECT_EQ(k.sceneAt(base, 10.0).phaseFunction, cloudscape::PhaseFunctionKind::HgDraine);
    EXPECT_TRUE(k.sceneAt(base, 10.0).blueNoise);
}

TEST(Keyframes, EachKeyFollowsOnlyTheKeyframesThatSetIt) {
    // Coverage is set at 0 and 20 only: at 10, where only the sun is keyed, it is halfway.
    const Keyframes k =
        parse(file({{"0", R"({"weather.coverage": 0.2})"},
                    {"10", R"({"sun.elevation_deg": 30})"},
                    {"20", R"({"weather": {"coverage": 0.6}, "sun": {"elevation_deg": 50}})"}}));
    const Scene base;
    EXPECT_FLOAT_EQ(k.sceneAt(base, 10.0).coverage, 0.4f);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 0.0).sunElevationDeg, 30.0f) << "held before its first";
    EXPECT_FLOAT_EQ(k.sceneAt(base, 15.0).sunElevationDeg, 40.0f);
    // Dotted and nested keys are the same key: the same tracks, the same fingerprint.
    const Keyframes dotted =
        parse(file({{"0", R"({"weather.coverage": 0.2})"},
                    {"10", R"({"sun.elevation_deg": 30})"},
                    {"20", R"({"weather.coverage": 0.6, "sun.elevation_deg": 50})"}}));
    EXPECT_EQ(dotted.fingerprintText(), k.fingerprintText());
    EXPECT_NE(parse(file({{"0", R"({"weather.coverage": 0.2})"}})).fingerprintText(),
              parse(file({{"0", R"({"weather.coverage": 0.21})"}})).fingerprintText());
    EXPECT_NE(parse(file({{"0", R"({"weather.coverage": 0.2})"}})).fingerprintText(),
              parse(file({{"1", R"({"weather.coverage": 0.2})"}})).fingerprintText());
}

// The time-lapse the keys were made for: the sun rises and sets over one minute while the
// coverage builds up, and no frame regenerates a texture (both are uniforms).
TEST(Keyframes, ADawnToDuskTimeLapseMovesTheSunAndRegeneratesNothing) {
    Scene base;
    cloudscape::applyOverride(base, "sun.from_time=true");
    cloudscape::applyOverride(base, "sun.latitude_deg=47");
    cloudscape::applyOverride(base, "sun.day_of_year=172");
    const Keyframes k =
        parse(file({{"0", R"({"sun.local_solar_time_h": 3.5, "weather.coverage": 0.2})"},
                    {"60", R"({"sun.local_solar_time_h": 20.5, "weather.coverage": 0.6})"}}),
              base);
    double previousElevation = -90.0;
    Scene previous = k.sceneAt(base, 0.0);
    EXPECT_LT(cloudscape::sunAnglesOf(previous).elevationDeg, 0.0) << "night at 3:30";
    for (int f = 1; f <= 24; ++f) {
        const Scene s = k.sceneAt(base, f * 60.0 / 24.0);
        const double elevation = cloudscape::sunAnglesOf(s).elevationDeg;
        if (s.sunLocalSolarTimeH <= 12.0f) {
            EXPECT_GT(elevation, previousElevation) << "the sun rises until noon, frame " << f;
        }
        previousElevation = elevation;
        EXPECT_GT(s.coverage, previous.coverage) << f;
        const cloudscape::ResourceChanges c = cloudscape::resourceChanges(previous, s);
        EXPECT_FALSE(c.noise || c.weather || c.depth) << "frame " << f;
        previous = s;
    }
    EXPECT_GT(cloudscape::sunAnglesOf(k.sceneAt(base, 30.0)).elevationDeg, 60.0) << "noon";
    EXPECT_LT(cloudscape::sunAnglesOf(k.sceneAt(base, 60.0)).elevationDeg, 0.0) << "dusk is over";
}

// The example the documentation gives (scenes/keyframes/dawn-to-dusk.json) stays valid and
// does what it says: night before dawn, the sun high at midday, down again at the end.
TEST(Keyframes, TheShippedDawnToDuskExampleIsADay) {
    const Scene base;
    const Keyframes k = cloudscape::loadKeyframes(
        std::string(CLOUDSCAPE_SOURCE_DIR) + "/scenes/keyframes/dawn-to-dusk.json", base);
    EXPECT_EQ(k.keyframeCount(), 3);
    auto elevationAt = [&](double t) {
        return cloudscape::sunAnglesOf(k.sceneAt(base, t)).elevationDeg;
    };
    EXPECT_LT(elevationAt(0.0), 0.0);
    EXPECT_GT(elevationAt(30.0), 60.0);
    EXPECT_LT(elevationAt(60.0), 0.0);
    EXPECT_FLOAT_EQ(k.sceneAt(base, 30.0).coverage, 0.5f);
}

struct BadFile {
    std::string json;
    std::string expected; // in the one-line message
};

TEST(Keyframes, BadFilesFailWithOneLineNamingTheFileKeyframeAndKey) {
    std::string tooMany = R"({"keyframes": [)";
    for (int i = 0; i <= 10000; ++i)
        tooMany.append(i ? "," : "")
            .append(R"({"time_s": )")
            .append(std::to_string(i))
            .append(R"(, "set": {}})");
    tooMany += "]}";
    std::string deep = R"({"keyframes": [{"time_s": 0, "set": )";
    for (int i = 0; i < 40; ++i)
        deep += R"({"a": )";
    deep += "1" + std::string(40, '}') + "}]}";
    const std::vector<BadFile> cases = {
        {file({{"0", R"({"weather.coverag": 0.3})"}}),
         "day.json: keyframes[0]: unknown key 'weather.coverag'"},
        {file({{"0", R"({"weather.coverage": 0.3})"}, {"5", R"({"weather.coverage": 1.5})"}}),
         "day.json: keyframes[1]: weather.coverage = 1.5 is out of range [0, 1]"},
        {file({{"0", R"({"weather.coverage": "lots"})"}}),
         "day.json: keyframes[0]: weather.coverage expects number, got a string"},
        {file({{"0", R"({"sun.irradiance": [1, 2]})"}}),
         "keyframes[0]: sun.irradiance expects array of 3 numbers"},
        {file({{"0", R"({"lighting.light_samples": 2.5})"}}),
         "keyframes[0]: lighting.light_samples expects an integer, got 2.5"},
        {file({{"0", R"({"lighting.phase": "mie"})"}}), "keyframes[0]: lighting.phase 'mie'"},
        {file({{"0", R"({"sun.from_time": 1})"}}), "keyframes[0]: sun.from_time expects boolean"},
        {file({{"0", R"({"sun.local_solar_time_h": 25})"}}),
         "keyframes[0]: sun.local_solar_time_h = 25 is out of range [0, 24]"},
        {file({{"10", "{}"}, {"5", "{}"}}),
         "day.json: keyframes[1]: time_s = 5 comes before keyframes[0]'s 10; times must increase"},
        {file({{"10", "{}"}, {"10", "{}"}}),
         "day.json: keyframes[1]: time_s = 10 repeats keyframes[0]'s 10"},
        {file({{"-1", "{}"}}), "keyframes[0]: time_s = -1 is out of range [0, 1e+08]"},
        {file({{"\"noon\"", "{}"}}),
         "keyframes[0]: time_s expects a number of seconds, got a string"},
        {R"({"keyframes": [{"set": {}}]})",
         "keyframes[0]: time_s expects a number of seconds (missing)"},
        {R"({"keyframes": [{"time_s": 0}]})", "keyframes[0]: expected \"set\": an object"},
        {R"({"keyframes": [{"time_s": 0, "set": {}, "ease": "in"}]})",
         "keyframes[0]: unknown member 'ease' (expected time_s and set)"},
        {R"({"keyframes": [3]})", "keyframes[0]: expected an object"},
        {R"({"keyframes": []})", "with at least one keyframe"},
        {R"({"frames": []})", "day.json: unknown member 'frames'"},
        {R"([1, 2])", "day.json: expected {\"keyframes\""},
        {file({{"0", R"({"weather.coverage": 0.3, "weather": {"coverage": 0.4}})"}}),
         "keyframes[0]: weather.coverage is set twice"},
        {file({{"0", R"({"render.width": 64})"}}), "keyframes[0]: render.width cannot be animated"},
        {file({{"0", R"({"time_s": 64})"}}), "keyframes[0]: time_s cannot be animated"},
        {file({{"0", R"({"weather.image": "storm.png"})"}}),
         "keyframes[0]: weather.image cannot be animated"},
        // A cross-key rule broken at a keyframe: the cloud top below the base scene's bottom.
        {file({{"0", R"({"clouds.top_m": 8000})"}, {"30", R"({"clouds.top_m": 1000})"}}),
         "day.json: keyframes[1] (time_s = 30): clouds.top_m (1000) must be at least 10 m above"},
        {file({{"0", R"({"weather.coverage": 0.3, "weather.coverage": 0.4})"}}),
         "duplicate key 'keyframes.set.weather.coverage'"},
        {R"({"keyframes": [{"time_s": 1e999, "set": {}}]})", "a number too large for a double"},
        {R"({"keyframes": )", "day.json: malformed JSON"},
        {deep, "day.json: nested deeper than 16 levels"},
        {tooMany, "day.json: 10001 keyframes; at most 10000"},
    };
    for (const BadFile& c : cases) {
        const std::string e = errorOf(c.json);
        EXPECT_NE(e.find(c.expected), std::string::npos)
            << "expected '" << c.expected << "' in: " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        EXPECT_LE(e.size(), 400u) << e;
    }
}

TEST(Keyframes, FilesAreReadWithTheSceneFilesLimits) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("cloudscape_keyframes_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir / "a-directory.json");
    auto errorOfFile = [](const std::string& path) -> std::string {
        try {
            cloudscape::loadKeyframes(path, Scene{});
        } catch (const cloudscape::Error& e) {
            return e.what();
        }
        return "";
    };
    const std::string big = (dir / "big.json").string();
    std::ofstream(big) << R"({"keyframes": [{"time_s": 0, "set": {}}]})";
    EXPECT_EQ(errorOfFile(big), "");
    std::filesystem::resize_file(big, 17u << 20); // sparse
    EXPECT_NE(errorOfFile(big).find("is too large for a keyframe file"), std::string::npos);
    EXPECT_NE(errorOfFile((dir / "a-directory.json").string()).find("is a directory"),
              std::string::npos);
    EXPECT_NE(
        errorOfFile((dir / "none.json").string()).find("none.json: cannot open keyframe file"),
        std::string::npos);
    std::filesystem::remove_all(dir);
}
