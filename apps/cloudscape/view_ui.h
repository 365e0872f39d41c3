#pragma once
// The viewer's panels (Dear ImGui), generated from the scene key table: a section per key
// prefix, each key with its unit, range and documentation (tooltip) and a reset to the value the
// session opened with; a preset menu, the quality tier, temporal on/off, render scale; and the
// fly camera (right mouse button held: look; W A S D to move, Q E down and up, the wheel sets the
// speed, Shift four times faster). Every edit goes through the key table's own checks.
#include "view_imgui_vulkan.h"
#include "view_presenter.h"

#include <cloudscape/persistent_renderer.h>

#include <memory>
#include <string>

namespace cloudscape::cli {

class ViewWindow;

class ViewUi {
public:
    ViewUi(ViewWindow& window, ViewPresenter& presenter, const Scene& opened);
    ~ViewUi();
    ViewUi(const ViewUi&) = delete;
    ViewUi& operator=(const ViewUi&) = delete;

    enum class Change { None, Camera, Scene };
    // Builds this frame's panels over `scene` and applies the user's edits and camera motion to
    // it; `last` is the previous frame's result (for the overlay's figures).
    Change update(Scene& scene, Renderer& renderer, const RenderResult& last, int windowWidth,
                  int windowHeight);
    // Shows what the renderer remade for the last change (noise, weather, ...) and its time.
    void noteUpdate(const UpdateReport& report);
    // Records the panels built by update() (inside the presenter's render pass).
    void draw(vk::CommandBuffer cmd);

private:
    Change keyPanels(Scene& scene);
    Change keyRow(Scene& scene, const SceneKeyInfo& key);
    Change sessionPanel(Scene& scene, Renderer& renderer, const RenderResult& last, int windowWidth,
                        int windowHeight);
    bool flyCamera(Scene& scene);
    bool apply(Scene& scene, const std::string& key, const std::string& jsonValue);

    ViewWindow& window_;
    Scene opened_;
    std::unique_ptr<ImGuiVulkan> vulkan_;
    std::string message_; // the last refused edit, or what the last change remade
    float renderScale_ = 1.0f;
    bool followWindow_ = false; // render size = window size x renderScale_
    float flySpeed_ = 50.0f;    // metres a second
    double lastTime_ = 0.0;
};

} // namespace cloudscape::cli
