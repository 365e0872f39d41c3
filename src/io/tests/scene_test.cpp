#include <cloudscape/error.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using cloudscape::Error;
using cloudscape::Scene;

namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Scene, NestedKeysOverrideDefaults) {
    const Scene s = cloudscape::parseScene(
        R"({"weather": {"coverage": 0.3}, "camera": {"position": [1, 50, 2]}, "seed": 7,
            "lighting": {"long_sample": false}})",
        "test.json");
    EXPECT_FLOAT_EQ(s.coverage, 0.3f);
    EXPECT_EQ(s.cameraPosition, glm::vec3(1, 50, 2));
    EXPECT_EQ(s.seed, 7);
    EXPECT_FALSE(s.longSample);
    EXPECT_EQ(s.width, Scene{}.width);
}

TEST(Scene, UnknownKeyNamesTheKey) {
    const std::string e =
        errorOf([] { cloudscape::parseScene(R"({"camera": {"fovv": 3}})", "a.json"); });
    EXPECT_NE(e.find("a.json"), std::string::npos) << e;
    EXPECT_NE(e.find("camera.fovv"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(Scene, WrongTypeNamesKeyAndExpectedType) {
    const std::string e =
        errorOf([] { cloudscape::parseScene(R"({"weather": {"coverage": "lots"}})", "b.json"); });
    EXPECT_NE(e.find("weather.coverage"), std::string::npos) << e;
    EXPECT_NE(e.find("number"), std::string::npos) << e;
    EXPECT_NE(errorOf([] {
                  cloudscape::parseScene(R"({"render": {"width": 12.5}})", "c");
              }).find("integer"),
              std::string::npos);
    EXPECT_NE(errorOf([] {
                  cloudscape::parseScene(R"({"camera": {"position": [1, 2]}})", "c");
              }).find("array of 3"),
              std::string::npos);
}

TEST(Scene, OutOfRangeGivesTheRange) {
    const std::string e =
        errorOf([] { cloudscape::parseScene(R"({"weather": {"coverage": 1.5}})", "d.json"); });
    EXPECT_NE(e.find("weather.coverage"), std::string::npos) << e;
    EXPECT_NE(e.find("[0, 1]"), std::string::npos) << e;
}

TEST(Scene, MalformedJsonAndNonObject) {
    EXPECT_NE(errorOf([] { cloudscape::parseScene("{\"seed\": ", "e.json"); }).find("malformed"),
              std::string::npos);
    EXPECT_NE(errorOf([] { cloudscape::parseScene("[1, 2]", "e.json"); }).find("object"),
              std::string::npos);
}

TEST(Scene, CrossKeyRules) {
    EXPECT_NE(errorOf([] {
                  cloudscape::parseScene(R"({"clouds": {"bottom_m": 5000, "top_m": 4000}})", "f");
              }).find("clouds.top_m"),
              std::string::npos);
    EXPECT_NE(errorOf([] {
                  cloudscape::parseScene(R"({"camera": {"position": [0, -5, 0]}})", "f");
              }).find("altitude"),
              std::string::npos);
}

TEST(Scene, SetOverrides) {
    Scene s;
    cloudscape::applyOverride(s, "weather.coverage=0.3");
    cloudscape::applyOverride(s, "sun.irradiance=[1,2,3]");
    cloudscape::applyOverride(s, "lighting.long_sample=false");
    cloudscape::applyOverride(s, "weather.image=maps/storm.png");
    EXPECT_FLOAT_EQ(s.coverage, 0.3f);
    EXPECT_EQ(s.sunIrradiance, glm::vec3(1, 2, 3));
    EXPECT_FALSE(s.longSample);
    EXPECT_EQ(s.weatherImage, "maps/storm.png");
    EXPECT_NE(errorOf([&] { cloudscape::applyOverride(s, "nope=1"); }).find("nope"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { cloudscape::applyOverride(s, "weather.coverage"); }).find("key=value"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { cloudscape::applyOverride(s, "render.width=0"); }).find("[16, 16384]"),
              std::string::npos);
}

TEST(Scene, MissingFileNamesThePath) {
    const std::string e = errorOf([] { cloudscape::loadScene("/nonexistent/scene.json"); });
    EXPECT_NE(e.find("/nonexistent/scene.json"), std::string::npos) << e;
}

TEST(Scene, EveryPresetLoads) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cloudscape::presetDirectory())) {
        if (entry.path().extension() != ".json")
            continue;
        EXPECT_NO_THROW(cloudscape::loadScene(entry.path().string())) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 7);
}

TEST(Scene, DocumentationIsGeneratedFromTheTable) {
    const std::string path = std::string(CLOUDSCAPE_SOURCE_DIR) + "/docs/SCENE.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), cloudscape::sceneDocumentationMarkdown())
        << "docs/SCENE.md is stale: run `build/cloudscape scene-doc -o docs/SCENE.md`";
}

TEST(Scene, QualityTiers) {
    Scene low, high, reference;
    cloudscape::applyTier(low, "low");
    cloudscape::applyTier(high, "high");
    cloudscape::applyTier(reference, "reference");
    EXPECT_EQ(low.lightSamples, 6);
    EXPECT_EQ(low.zenithSteps, 60);
    EXPECT_EQ(low.horizonSteps, 90);
    EXPECT_EQ(low.lightMipBias, 1);
    EXPECT_EQ(high.lightSamples, 10);
    EXPECT_EQ(high.horizonSteps, 180);
    EXPECT_EQ(high.lightMipBias, 0);
    EXPECT_FALSE(reference.temporal);
    EXPECT_EQ(reference.coarseStepFactor, 1);
    EXPECT_GE(reference.cheapLightAlpha, 1.0f);
    EXPECT_GT(reference.horizonSteps, high.horizonSteps);
    // Every tier is a valid scene.
    EXPECT_NO_THROW(cloudscape::validateScene(low, "low"));
    EXPECT_NO_THROW(cloudscape::validateScene(reference, "reference"));
    Scene s;
    EXPECT_NE(errorOf([&] { cloudscape::applyTier(s, "ultra"); }).find("low, high or reference"),
              std::string::npos);
}

TEST(Scene, EnumerationsAreEnumsPastTheParser) {
    Scene s;
    EXPECT_EQ(s.phaseFunction, cloudscape::PhaseFunctionKind::HgDraine);
    cloudscape::applyOverride(s, "lighting.phase=two-lobe");
    EXPECT_EQ(s.phaseFunction, cloudscape::PhaseFunctionKind::TwoLobe);
    const std::string message =
        errorOf([&] { cloudscape::applyOverride(s, "lighting.phase=mie"); });
    EXPECT_NE(message.find("lighting.phase 'mie'"), std::string::npos) << message;
    EXPECT_NE(message.find("\"two-lobe\" or \"hg-draine\""), std::string::npos) << message;
    EXPECT_NE(errorOf([&] { cloudscape::applyOverride(s, "lighting.phase=3"); }).find("'3'"),
              std::string::npos);
}

TEST(Scene, OneTableGivesDefaultsAndRangesToTheGenerators) {
    const cloudscape::WeatherParams w;
    const Scene& d = cloudscape::defaultScene();
    EXPECT_EQ(w.typeVariation, d.typeVariation); // 0.15 in the generator, 0.12 in the scene before
    EXPECT_EQ(w.typeMean, d.cloudType);
    EXPECT_EQ(w.featureScaleM, d.featureScaleM);
    EXPECT_EQ(w.resolution, d.weatherResolution);
    EXPECT_EQ(w.extentM, d.weatherExtentM);
    const cloudscape::KeyRange r = cloudscape::sceneKeyRange("weather.type_variation");
    EXPECT_EQ(r.min, 0.0);
    EXPECT_EQ(r.max, 1.0);
    EXPECT_THROW(cloudscape::sceneKeyRange("weather.nonsense"), cloudscape::Error);
    // The generator refuses what the table refuses, naming the key.
    cloudscape::WeatherParams tooFine;
    tooFine.featureScaleM = 50.0f; // the table's minimum is 100 m
    const std::string message = errorOf([&] { cloudscape::generateWeatherMap(tooFine); });
    EXPECT_NE(message.find("weather.feature_scale_m"), std::string::npos) << message;
}

TEST(Scene, TiersAreOverlaysThroughTheKeyTable) {
    for (const std::string& name : cloudscape::tierNames()) {
        Scene s;
        cloudscape::applyTier(s, name);
        EXPECT_NO_THROW(cloudscape::validateScene(s, name));
    }
    // A tier is applied before --set, and --set wins.
    Scene s;
    cloudscape::applyTier(s, "low");
    cloudscape::applyOverride(s, "lighting.light_samples=9");
    EXPECT_EQ(s.lightSamples, 9);
    EXPECT_NE(
        cloudscape::sceneDocumentationMarkdown().find("`low` | `render.cloud_resolution=0.5`"),
        std::string::npos);
}
