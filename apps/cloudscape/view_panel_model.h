#pragma once
// What the viewer's key panels show and do, apart from drawing them (view_ui.cpp draws with Dear
// ImGui; this part has no ImGui, so tests run it without a window): the panels generated from
// the scene key table, a section per key prefix, each row a key with its label (name and unit),
// its tooltip (the key, its documentation, unit, range, default and the value the session opened
// with), its reset (back to the opened value) and an edit applied through the table's checks.
#include <cloudscape/scene.h>

#include <string>
#include <vector>

namespace cloudscape::cli {

struct PanelRow {
    const SceneKeyInfo* key = nullptr; // into sceneKeyInfos()
    std::string label;                 // "coverage (fraction)##weather.coverage": ImGui's id
};

struct PanelSection {
    std::string name; // the part of the key before the first dot ("general" without one)
    std::vector<PanelRow> rows;
};

// The sections in the key table's order of first appearance, every key in its own section's
// rows, in table order.
const std::vector<PanelSection>& keyPanelSections();

// The hover text of a key's row.
std::string panelTooltip(const SceneKeyInfo& key, const std::string& openedValue);

// The value a row's reset puts back: the key's value in the scene the session opened (or last
// reloaded), as JSON text.
std::string panelResetValue(const Scene& opened, const std::string& key);

// An edit from a row: `key` = `jsonValue` applied to a copy of the scene and validated as a scene
// file would be; on success the scene takes it, else it is left as it was and `message` says
// why (one line). True when applied.
bool applyPanelEdit(Scene& scene, const std::string& key, const std::string& jsonValue,
                    std::string& message);

// A number as JSON text that reads back to the same float (what the panels' edits send).
std::string jsonNumber(double v);
// A vector of three as a JSON array of such numbers.
std::string jsonVector(const float (&v)[3]);

} // namespace cloudscape::cli
