#pragma once
// The viewer's panels (Dear ImGui), generated from the scene key table: a section per key
// prefix, each key with its unit, range and documentation (tooltip) and a reset to the value the
// session opened with; a preset menu, the quality tier, temporal on/off, render scale; and the
// fly camera (right mouse button held: look; W A S D to move, Q E down and up, the wheel sets the
// speed, Shift four times faster), or the orbit camera (left button held: turn around the point
// the orbit distance ahead; the wheel sets the distance); a camera panel (numeric entry, the
// `render --camera-path` paths, recording and playing the camera, the time of day) and a save
// panel (the scene as JSON, a screenshot, the recorded camera as keyframes). Every edit goes
// through the key table's own checks.
#include "view_camera.h"
#include "view_debug.h"
#include "view_imgui_vulkan.h"
#include "view_paint.h"
#include "view_panel_model.h"
#include "view_presenter.h"

#include <cloudscape/persistent_renderer.h>

#include <memory>
#include <string>

namespace cloudscape::cli {

class ViewWindow;

class ViewUi {
public:
    ViewUi(ViewWindow& window, ViewPresenter& presenter, const Scene& opened, CameraTrack& track,
           WeatherPainter& painter, DebugView& debugView);
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
    // The scene was reloaded from its file: its values are what "reset" goes back to.
    void noteReload(const Scene& scene, const std::string& message);
    void noteMessage(const std::string& message) { message_ = message; }

    // What the panels asked the session to write since the last call (empty: nothing).
    struct Requests {
        std::string saveScene;
        std::string screenshot;
        std::string savePath;
        std::string saveWeather;
        std::string saveField;
        bool painted = false; // a stroke or an undo: the clouds changed
    };
    Requests takeRequests();

private:
    Change keyPanels(Scene& scene);
    void frameFigures(const Renderer& renderer, const RenderResult& last) const;
    Change keyRow(Scene& scene, const PanelRow& row);
    Change sessionPanel(Scene& scene, Renderer& renderer, const RenderResult& last, int windowWidth,
                        int windowHeight);
    Change cameraPanel(Scene& scene);
    void savePanel();
    void paintPanel(Scene& scene, Renderer& renderer, int windowWidth, int windowHeight);
    bool paintWithMouse(Scene& scene, Renderer& renderer, int windowWidth, int windowHeight);
    bool flyCamera(Scene& scene);
    bool orbitWithMouse(Scene& scene);
    bool apply(Scene& scene, const std::string& key, const std::string& jsonValue);

    ViewWindow& window_;
    Scene opened_;
    CameraTrack& track_;
    WeatherPainter& painter_;
    DebugView& debugView_;
    bool painting_ = false; // the left button paints instead of steering the camera
    BrushStroke brush_;
    Requests requests_;
    int cameraMode_ = 0;            // 0: fly, 1: orbit (ImGui radio buttons)
    float orbitDistance_ = 3000.0f; // metres ahead of the camera
    int pathChoice_ = 1;
    int pathFrames_ = 240;
    std::string scenePath_ = "scene.json";
    std::string shotPath_ = "screenshot.exr";
    std::string cameraPath_ = "camera.json";
    std::string weatherPath_ = "weather.png";
    std::string fieldPath_ = "field.png";
    std::unique_ptr<ImGuiVulkan> vulkan_;
    std::string message_; // the last refused edit, or what the last change remade
    float renderScale_ = 1.0f;
    bool followWindow_ = false; // render size = window size x renderScale_
    float flySpeed_ = 50.0f;    // metres a second
    double lastTime_ = 0.0;
};

} // namespace cloudscape::cli
