// The key panels' contents and edits (view_panel_model.h).
#include "view_panel_model.h"

#include <cloudscape/error.h>

#include <algorithm>
#include <cstdio>

namespace cloudscape::cli {
namespace {

std::string sectionOf(const std::string& key) {
    const size_t dot = key.find('.');
    return dot == std::string::npos ? "general" : key.substr(0, dot);
}

} // namespace

std::string jsonNumber(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string jsonVector(const float (&v)[3]) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a chain of string + string.
    std::string text = "[";
    for (int i = 0; i < 3; ++i) {
        text += jsonNumber(v[i]);
        text += i < 2 ? "," : "]";
    }
    return text;
}

const std::vector<PanelSection>& keyPanelSections() {
    static const std::vector<PanelSection> sections = [] {
        std::vector<PanelSection> out;
        for (const SceneKeyInfo& k : sceneKeyInfos()) {
            const std::string name = sectionOf(k.key);
            auto it = std::find_if(out.begin(), out.end(),
                                   [&](const PanelSection& s) { return s.name == name; });
            if (it == out.end())
                it = out.insert(out.end(), PanelSection{name, {}});
            it->rows.push_back(
                {&k, k.key.substr(k.key.find('.') + 1) + " (" + k.unit + ")##" + k.key});
        }
        return out;
    }();
    return sections;
}

std::string panelTooltip(const SceneKeyInfo& k, const std::string& openedValue) {
    std::string text = k.key + "\n" + k.doc + "\nunit: " + k.unit;
    if (k.type == SceneKeyType::Integer || k.type == SceneKeyType::Number ||
        k.type == SceneKeyType::Vector3)
        text += "   range: [" + jsonNumber(k.min) + ", " + jsonNumber(k.max) + "]";
    if (k.type == SceneKeyType::Choice) {
        text += "   one of:";
        for (const std::string& c : k.choices)
            text += " " + c;
    }
    return text + "\ndefault: " + sceneKeyValue(defaultScene(), k.key) +
           "   opened with: " + openedValue;
}

std::string panelResetValue(const Scene& opened, const std::string& key) {
    return sceneKeyValue(opened, key);
}

bool applyPanelEdit(Scene& scene, const std::string& key, const std::string& jsonValue,
                    std::string& message) {
    Scene next = scene;
    try {
        applyOverride(next, key + "=" + jsonValue, "view");
        validateScene(next, "view");
    } catch (const Error& e) {
        message = e.what();
        return false;
    }
    scene = next;
    return true;
}

} // namespace cloudscape::cli
