// The viewer's camera and save panels and the orbit camera (view_ui.h).
#include "view_ui.h"

#include "view_window.h"

#include "core/model_params.h"
#include "model/camera.glsl.h"

#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>

#include <imgui.h>
#include <imgui_stdlib.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace cloudscape::cli {
namespace {

// The right-hand column of panels, beside the window's right edge (the key panels are on the
// left), or at 440 in a narrow window.
float rightColumn() {
    return std::max(440.0f, ImGui::GetIO().DisplaySize.x - 350.0f);
}

} // namespace

ViewUi::Change ViewUi::cameraPanel(Scene& scene) {
    Change change = Change::None;
    ImGui::SetNextWindowPos(ImVec2(rightColumn(), 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Camera");
    ImGui::RadioButton("fly (right button)", &cameraMode_, 0);
    ImGui::SameLine();
    ImGui::RadioButton("orbit (left button)", &cameraMode_, 1);
    if (cameraMode_ == 1)
        ImGui::SliderFloat("orbit distance (m)", &orbitDistance_, 10.0f, 100000.0f, "%.0f",
                           ImGuiSliderFlags_Logarithmic);

    // Numeric entry, applied on Enter through the key table's checks.
    const ImGuiInputTextFlags enter = ImGuiInputTextFlags_EnterReturnsTrue;
    float position[3] = {scene.cameraPosition.x, scene.cameraPosition.y, scene.cameraPosition.z};
    if (ImGui::InputFloat3("position (m)", position, "%.1f", enter) &&
        apply(scene, "camera.position", jsonVector(position)))
        change = Change::Camera;
    struct Angle {
        const char* label;
        const char* key;
        float value;
    };
    for (Angle a : {Angle{"heading (deg)", "camera.heading_deg", scene.cameraHeadingDeg},
                    Angle{"pitch (deg)", "camera.pitch_deg", scene.cameraPitchDeg},
                    Angle{"fov (deg)", "camera.fov_deg", scene.cameraFovDeg}})
        if (ImGui::InputFloat(a.label, &a.value, 0.0f, 0.0f, "%.2f", enter) &&
            apply(scene, a.key, jsonNumber(a.value)))
            change = Change::Camera;

    // The paths of `render --frames --camera-path`, from here, one frame each.
    const std::vector<std::string>& paths = cameraPathNames();
    pathChoice_ = std::clamp(pathChoice_, 0, static_cast<int>(paths.size()) - 1);
    ImGui::SetNextItemWidth(120);
    if (ImGui::BeginCombo("##path", paths[static_cast<size_t>(pathChoice_)].c_str())) {
        for (size_t i = 0; i < paths.size(); ++i)
            if (ImGui::Selectable(paths[i].c_str(), static_cast<int>(i) == pathChoice_))
                pathChoice_ = static_cast<int>(i);
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    ImGui::InputInt("frames##path", &pathFrames_, 0);
    pathFrames_ = std::clamp(pathFrames_, 1, 100000);
    ImGui::SameLine();
    if (ImGui::Button(track_.playing() ? "stop" : "play path")) {
        if (track_.playing())
            track_.stop();
        else
            track_.playPath(scene, paths[static_cast<size_t>(pathChoice_)], pathFrames_);
    }

    if (ImGui::Button(track_.recording() ? "stop recording" : "record"))
        track_.setRecording(!track_.recording());
    ImGui::SameLine();
    ImGui::Text("%zu frames", track_.recordedFrames());
    ImGui::SameLine();
    if (ImGui::Button("play recording") && track_.recordedFrames() > 0) {
        track_.setRecording(false);
        track_.playRecording();
    }

    // The time of day: the sun placed from sun.latitude_deg and sun.day_of_year.
    bool fromTime = scene.sunFromTime;
    if (ImGui::Checkbox("sun from time of day", &fromTime) &&
        apply(scene, "sun.from_time", fromTime ? "true" : "false"))
        change = Change::Scene;
    if (scene.sunFromTime) {
        float hours = scene.sunLocalSolarTimeH;
        if (ImGui::SliderFloat("local solar time (h)", &hours, 0.0f, 24.0f, "%.2f") &&
            apply(scene, "sun.local_solar_time_h", jsonNumber(hours)))
            change = Change::Scene;
    }
    ImGui::End();
    return change;
}

void ViewUi::savePanel() {
    ImGui::SetNextWindowPos(ImVec2(rightColumn(), 250), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Save");
    ImGui::InputText("##scene", &scenePath_);
    ImGui::SameLine();
    if (ImGui::Button("save scene"))
        requests_.saveScene = scenePath_;
    ImGui::InputText("##shot", &shotPath_);
    ImGui::SameLine();
    if (ImGui::Button("screenshot"))
        requests_.screenshot = shotPath_;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(".png: tone-mapped; .exr: every layer, as `cloudscape render` writes");
    ImGui::InputText("##camera", &cameraPath_);
    ImGui::SameLine();
    if (ImGui::Button("save recording"))
        requests_.savePath = cameraPath_;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("keyframes at 24 fps: render --frames 0:N --keyframes FILE");
    ImGui::End();
}

// Left button held over the picture: the camera turns around the point orbitDistance_ ahead;
// the wheel scales that distance.
bool ViewUi::orbitWithMouse(Scene& scene) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse)
        return false;
    if (io.MouseWheel != 0.0f)
        orbitDistance_ =
            std::clamp(orbitDistance_ * std::pow(0.9f, io.MouseWheel), 10.0f, 100000.0f);
    if (glfwGetMouseButton(window_.handle(), GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS ||
        (io.MouseDelta.x == 0.0f && io.MouseDelta.y == 0.0f))
        return false;
    Scene next = scene;
    orbitCamera(next, orbitDistance_, 0.25f * io.MouseDelta.x, -0.25f * io.MouseDelta.y);
    try {
        validateScene(next, "orbit");
    } catch (const Error& e) { // below the ground: stay
        message_ = e.what();
        return false;
    }
    scene = next;
    return true;
}

} // namespace cloudscape::cli

namespace cloudscape::cli {

void ViewUi::paintPanel(Scene& scene, Renderer& renderer, int, int) {
    ImGui::SetNextWindowPos(ImVec2(rightColumn(), 360), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Paint the weather");
    ImGui::Checkbox("paint (left button on the picture)", &painting_);
    const char* channel = brushChannelName(brush_.channel);
    if (ImGui::BeginCombo("channel", channel)) {
        for (BrushStroke::Channel c : brushChannels())
            if (ImGui::Selectable(brushChannelName(c), c == brush_.channel))
                brush_.channel = c;
        ImGui::EndCombo();
    }
    ImGui::SliderFloat("radius (m)", &brush_.radiusM, 100.0f, scene.weatherExtentM, "%.0f",
                       ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("strength", &brush_.strength, -1.0f, 1.0f, "%.2f");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("toward full (> 0) or none (< 0), a stroke a frame while held");
    if (ImGui::Button("undo") && painter_.undo(renderer, scene))
        requests_.painted = true;
    ImGui::SameLine();
    ImGui::Text("%zu steps, %d strokes", painter_.undoSteps(), painter_.strokes());
    ImGui::InputText("##weather", &weatherPath_);
    ImGui::SameLine();
    if (ImGui::Button("save map"))
        requests_.saveWeather = weatherPath_;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the PNG weather.image reads (coverage, precipitation, type)");
    ImGui::InputText("##field", &fieldPath_);
    ImGui::SameLine();
    if (ImGui::Button("save field"))
        requests_.saveField = fieldPath_;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the PNG weather.field_image reads (bottom type, anvil coverage, "
                          "minimum and maximum height)");
    ImGui::End();
}

// The point under the mouse where its view ray meets the cloud layer's base (a flat plane at
// clouds.bottom_m: near enough for a brush), painted once a frame while the left button is held.
bool ViewUi::paintWithMouse(Scene& scene, Renderer& renderer, int windowWidth, int windowHeight) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse ||
        glfwGetMouseButton(window_.handle(), GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS)
        return false;
    // The picture is letterboxed into the window (view_presenter.cpp): window pixels to image.
    const float scale = std::min(static_cast<float>(windowWidth) / scene.width,
                                 static_cast<float>(windowHeight) / scene.height);
    const float x = (io.MousePos.x * io.DisplayFramebufferScale.x -
                     0.5f * (windowWidth - scale * scene.width)) /
                        scale -
                    0.5f;
    const float y = (io.MousePos.y * io.DisplayFramebufferScale.y -
                     0.5f * (windowHeight - scale * scene.height)) /
                        scale -
                    0.5f;
    if (x < -0.5f || y < -0.5f || x > scene.width - 0.5f || y > scene.height - 0.5f)
        return false;
    const glm::vec3 dir = model::cameraRayDirection(makeFrameParams(scene), x, y);
    const float rise = scene.cloudBottomM - scene.cameraPosition.y;
    if (std::abs(dir.y) < 1e-4f || rise / dir.y <= 0.0f) {
        message_ = "paint: the cloud base is not under the mouse";
        return false;
    }
    const glm::vec3 hit = scene.cameraPosition + dir * (rise / dir.y);
    BrushStroke stroke = brush_;
    stroke.xM = hit.x;
    stroke.zM = hit.z;
    try {
        checkStroke(scene, stroke, "paint");
        painter_.paint(renderer, scene, stroke);
    } catch (const Error& e) {
        message_ = e.what();
        return false;
    }
    return true;
}

} // namespace cloudscape::cli
