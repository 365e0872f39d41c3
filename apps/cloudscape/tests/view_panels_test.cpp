// CPU category: the viewer's key panels as view_ui.cpp draws them (view_panel_model.h, no window
// needed): every key of the table in exactly one section with its unit, range, choices and
// documentation; a row's reset puts back the value the session opened with and nothing else;
// and an edit from a row remakes only what that key touches on a live Renderer (a coverage drag
// remakes no noise and no weather map).
#include "view_panel_model.h"

#include <cloudscape/error.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

using namespace cloudscape;
using namespace cloudscape::cli;

namespace {

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

// Values a row's widget could send for `k` other than its current one, most likely accepted
// first (the middle of the range, then the ends, then a nudge); none for strings (paths).
std::vector<std::string> otherValues(const SceneKeyInfo& k, const Scene& scene) {
    const std::string current = sceneKeyValue(scene, k.key);
    std::vector<std::string> out;
    auto add = [&](const std::string& v) {
        if (v != current)
            out.push_back(v);
    };
    switch (k.type) {
    case SceneKeyType::Number:
    case SceneKeyType::Integer: {
        const bool whole = k.type == SceneKeyType::Integer;
        const double lo = std::max(k.min, -1e6), hi = std::min(k.max, 1e6);
        for (double v : {0.5 * (lo + hi), lo + 0.25 * (hi - lo), hi, lo})
            add(whole ? std::to_string(std::lround(v)) : number(v));
        const double c = std::stod(current);
        add(whole ? std::to_string(std::lround(c) + 1) : number(c * 1.1 + 0.01));
        break;
    }
    case SceneKeyType::Boolean:
        add(current == "true" ? "false" : "true");
        break;
    case SceneKeyType::Choice:
        for (const std::string& c : k.choices)
            add("\"" + c + "\"");
        break;
    case SceneKeyType::Vector3: {
        const double lo = std::max(k.min, -1e6), hi = std::min(k.max, 1e6);
        const std::string mid = number(0.5 * (lo + hi)), quarter = number(lo + 0.25 * (hi - lo));
        add("[" + mid + "," + quarter + "," + mid + "]");
        add("[" + quarter + "," + quarter + "," + quarter + "]");
        break;
    }
    case SceneKeyType::String:
        break;
    }
    return out;
}

// The first of otherValues the panel accepts that changes the key (0 and 0.0 are one value);
// false when none is (a key tied to others).
bool editKey(Scene& scene, const SceneKeyInfo& k) {
    const std::string before = sceneKeyValue(scene, k.key);
    std::string message;
    for (const std::string& v : otherValues(k, scene)) {
        Scene next = scene;
        if (applyPanelEdit(next, k.key, v, message) && sceneKeyValue(next, k.key) != before) {
            scene = next;
            return true;
        }
    }
    return false;
}

// A scene that differs from the defaults in several sections: what "opened with" means.
Scene opened() {
    Scene s;
    for (const char* set : {"weather.coverage=0.62", "sun.elevation_deg=21", "clouds.top_m=4200",
                            "terrain.enabled=true", "lighting.powder=0.3", "render.width=48",
                            "camera.position=[0, 25000, 0]"})
        applyOverride(s, set);
    validateScene(s, "test");
    return s;
}

} // namespace

TEST(ViewPanels, EveryKeyInExactlyOneSectionWithItsUnitRangeAndDoc) {
    std::map<std::string, int> rows;
    std::set<std::string> names;
    for (const PanelSection& section : keyPanelSections()) {
        EXPECT_TRUE(names.insert(section.name).second) << "section " << section.name << " twice";
        EXPECT_FALSE(section.rows.empty()) << section.name;
        for (const PanelRow& row : section.rows) {
            const SceneKeyInfo& k = *row.key;
            ++rows[k.key];
            const size_t dot = k.key.find('.');
            EXPECT_EQ(section.name, dot == std::string::npos ? "general" : k.key.substr(0, dot));
            // ImGui's id after ##: unique per key, so two rows never share a widget's state.
            EXPECT_NE(row.label.find("(" + k.unit + ")##" + k.key), std::string::npos) << row.label;
            const std::string tip = panelTooltip(k, "OPENED");
            EXPECT_EQ(tip.rfind(k.key + "\n" + k.doc + "\nunit: " + k.unit, 0), 0u) << tip;
            EXPECT_FALSE(k.doc.empty()) << k.key << " has no documentation for its tooltip";
            if (k.type == SceneKeyType::Number || k.type == SceneKeyType::Integer ||
                k.type == SceneKeyType::Vector3) {
                EXPECT_NE(tip.find("range: [" + number(k.min) + ", " + number(k.max) + "]"),
                          std::string::npos)
                    << tip;
            }
            for (const std::string& c : k.choices)
                EXPECT_NE(tip.find(" " + c), std::string::npos) << tip;
            EXPECT_NE(tip.find("default: " + sceneKeyValue(defaultScene(), k.key)),
                      std::string::npos)
                << tip;
            EXPECT_NE(tip.find("opened with: OPENED"), std::string::npos) << tip;
        }
    }
    size_t keys = 0;
    for (const SceneKeyInfo& k : sceneKeyInfos()) {
        ++keys;
        EXPECT_EQ(rows[k.key], 1) << k.key << " in " << rows[k.key] << " rows";
    }
    EXPECT_EQ(rows.size(), keys) << "a row for a key the table does not have";
    EXPECT_GT(keys, 150u);
}

// Each key in turn: changed from its row, then reset: the scene is again the one opened, every
// key of it (a reset to the default, or one that touched another key, fails).
TEST(ViewPanels, ResetPutsBackTheOpenedValueOfThatKeyOnly) {
    const Scene start = opened();
    int edited = 0, fixed = 0;
    for (const PanelSection& section : keyPanelSections())
        for (const PanelRow& row : section.rows) {
            const std::string& key = row.key->key;
            Scene scene = start;
            if (!editKey(scene, *row.key)) {
                ++fixed;
                continue;
            }
            ++edited;
            ASSERT_TRUE(sceneSettingsText(scene) != sceneSettingsText(start)) << key;
            std::string message;
            ASSERT_TRUE(applyPanelEdit(scene, key, panelResetValue(start, key), message))
                << key << ": " << message;
            EXPECT_TRUE(sceneSettingsText(scene) == sceneSettingsText(start))
                << key << " reset to " << panelResetValue(start, key);
        }
    std::printf("reset: %d keys edited and reset, %d not editable alone (strings, tied keys)\n",
                edited, fixed);
    EXPECT_GT(edited, 150);
}

// A refused edit leaves the scene as it was and says why in one line.
TEST(ViewPanels, ARefusedEditLeavesTheSceneAndSaysWhy) {
    Scene scene = opened();
    const std::string before = sceneSettingsText(scene);
    std::string message;
    EXPECT_FALSE(applyPanelEdit(scene, "clouds.bottom_m", "9000", message)); // over the top
    EXPECT_TRUE(sceneSettingsText(scene) == before);
    EXPECT_NE(message.find("clouds"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// The camera panel's and the vector rows' edits: three floats as a JSON array that the scene
// reads back to the same floats, bit for bit.
TEST(ViewPanels, AVectorEditReadsBackToTheSameFloats) {
    const float position[3] = {0.1f, 1234.5677f, -1.0e-7f};
    std::string expected = "[";
    for (int i = 0; i < 3; ++i)
        expected += number(position[i]) + (i < 2 ? "," : "]");
    EXPECT_EQ(jsonVector(position), expected);
    Scene scene = opened();
    std::string message;
    ASSERT_TRUE(applyPanelEdit(scene, "camera.position", jsonVector(position), message)) << message;
    EXPECT_EQ(scene.cameraPosition.x, position[0]);
    EXPECT_EQ(scene.cameraPosition.y, position[1]);
    EXPECT_EQ(scene.cameraPosition.z, position[2]);
}

// Every key edited from its row on a live Renderer (CPU backend, small textures): what the
// update remakes is exactly what ARCHITECTURE.md's list says that key touches; everything else
// is a uniform. weatherMapVersion() counts the maps made whole, independently of the report.
TEST(ViewPanels, AnEditRemakesOnlyWhatItsKeyTouches) {
    Scene base = opened();
    for (const char* set : {"weather.resolution=64", "terrain.resolution=64",
                            "sky.model=\"gradient\"", "render.height=27"})
        applyOverride(base, set);
    BackendOptions cpu;
    cpu.choice = BackendChoice::Cpu;
    Renderer renderer(base, cpu);
    const std::set<std::string> noise = {"seed"};
    const std::set<std::string> weather = {"seed",
                                           "weather.image",
                                           "weather.resolution",
                                           "weather.extent_m",
                                           "weather.feature_scale_m",
                                           "weather.type",
                                           "weather.type_variation",
                                           "weather.rain_cells",
                                           "weather.rain_cell_radius_m"};
    const std::set<std::string> dataField = {"seed",
                                             "weather.field_image",
                                             "weather.extent_m",
                                             "weather.feature_scale_m",
                                             "weather.bottom_type",
                                             "weather.base_variation",
                                             "weather.top_variation"};
    const std::set<std::string> terrain = {"seed",
                                           "terrain.enabled",
                                           "terrain.file",
                                           "terrain.extent_m",
                                           "terrain.height_m",
                                           "terrain.height_min_m",
                                           "terrain.feature_size_m",
                                           "terrain.resolution"};
    int checked = 0;
    for (const PanelSection& section : keyPanelSections())
        for (const PanelRow& row : section.rows) {
            const std::string& key = row.key->key;
            if (key == "render.width" || key == "render.height" || key == "weather.resolution" ||
                key == "terrain.resolution" || key == "cloud_shadow.resolution")
                continue; // sizes: slow at the range's middle, and no texture of their own here
            Scene scene = base;
            if (!editKey(scene, *row.key))
                continue;
            const uint64_t version = renderer.weatherMapVersion();
            UpdateReport report;
            try {
                report = renderer.update(scene);
            } catch (const Error&) {
                renderer.update(base); // a camera under the edited terrain: refused, as render
                continue;
            }
            ++checked;
            EXPECT_EQ(report.noise, noise.count(key) > 0) << key;
            EXPECT_EQ(report.weather, weather.count(key) > 0) << key;
            EXPECT_EQ(renderer.weatherMapVersion() != version, weather.count(key) > 0) << key;
            EXPECT_EQ(report.terrain, terrain.count(key) > 0) << key;
            EXPECT_EQ(report.dataField, dataField.count(key) > 0) << key;
            EXPECT_FALSE(report.depth) << key;
            if (key == "weather.coverage") {
                EXPECT_FALSE(report.noise || report.weather || report.terrain || report.depth ||
                             report.atmosphere || report.dataField)
                    << "a coverage drag is a uniform";
            }
            renderer.update(base);
        }
    std::printf("%d keys edited on a live renderer\n", checked);
    EXPECT_GT(checked, 140);
}
