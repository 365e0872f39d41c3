// The key table as data (sceneKeyInfos, sceneKeyValue) and a scene written back as a scene file
// (sceneJson), which the viewer's panels and its `save` use.
#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace cloudscape;

TEST(SceneJson, DefaultsWriteAnEmptyObject) {
    EXPECT_EQ(sceneJson(Scene{}), "{}\n");
}

TEST(SceneJson, ExactlyTheChangedKeysAndTheyReadBack) {
    Scene s;
    applyOverride(s, "weather.coverage=0.6123457");
    applyOverride(s, "camera.position=[10.5,300.25,-7]");
    applyOverride(s, "sky.model=gradient");
    applyOverride(s, "render.temporal=false");
    applyOverride(s, "clouds.extinction_per_m=0.0312345678");
    const std::string text = sceneJson(s);
    EXPECT_NE(text.find("\"coverage\""), std::string::npos) << text;
    EXPECT_EQ(text.find("\"fov_deg\""), std::string::npos) << "an unchanged key: " << text;
    const Scene back = parseScene(text, "saved");
    EXPECT_EQ(sceneSettingsText(back), sceneSettingsText(s)) << text;
    // Five keys changed, five leaves written.
    size_t leaves = 0;
    for (const SceneKeyInfo& k : sceneKeyInfos())
        leaves += sceneKeyValue(back, k.key) != sceneKeyValue(Scene{}, k.key);
    EXPECT_EQ(leaves, 5u);
}

TEST(SceneJson, EveryPresetRoundTrips) {
    for (const char* preset : {"rain-storm", "dawn", "inside-cloud", "overcast-stratus"}) {
        const Scene s = loadScene(resolveScenePath(preset));
        const Scene back = parseScene(sceneJson(s), preset);
        EXPECT_EQ(sceneSettingsText(back), sceneSettingsText(s)) << preset;
    }
}

TEST(SceneKeyInfos, DescribeEveryKeyOfTheTable) {
    std::set<std::string> keys;
    for (const SceneKeyInfo& k : sceneKeyInfos()) {
        EXPECT_TRUE(keys.insert(k.key).second) << k.key;
        EXPECT_FALSE(k.doc.empty()) << k.key;
        EXPECT_FALSE(k.unit.empty()) << k.key;
        if (k.type == SceneKeyType::Choice) {
            EXPECT_GE(k.choices.size(), 2u) << k.key;
        }
        if (k.type == SceneKeyType::Number || k.type == SceneKeyType::Integer) {
            EXPECT_LE(k.min, k.max) << k.key;
            // The value reads back through --set unchanged.
            Scene s;
            applyOverride(s, k.key + "=" + sceneKeyValue(Scene{}, k.key));
            EXPECT_EQ(sceneSettingsText(s), sceneSettingsText(Scene{})) << k.key;
        }
    }
    // Every line of the fingerprint text is a key of the table.
    const std::string text = sceneSettingsText(Scene{});
    EXPECT_EQ(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')), keys.size());
    EXPECT_THROW(sceneKeyValue(Scene{}, "no.such_key"), Error);
}
