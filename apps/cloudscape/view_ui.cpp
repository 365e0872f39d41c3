// The viewer's panels and fly camera (view_ui.h).
#include "view_ui.h"

#include "view_window.h"

#include <cloudscape/error.h>

#include <imgui.h>
#include <imgui_stdlib.h>
#include <nlohmann/json.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <utility>

// Debian's libimgui builds its GLFW platform backend in; only its header is missing a path.
bool ImGui_ImplGlfw_InitForVulkan(GLFWwindow* window, bool install_callbacks);
void ImGui_ImplGlfw_Shutdown();
void ImGui_ImplGlfw_NewFrame();

namespace cloudscape::cli {
namespace {

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(presetDirectory(), ec))
        if (entry.path().extension() == ".json")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A drag's speed: a thousandth of a bounded range, else a hundredth of the value's size.
float dragSpeed(const SceneKeyInfo& k, double value) {
    if (k.max - k.min < 1e6)
        return static_cast<float>((k.max - k.min) / 1000.0);
    return static_cast<float>(std::max(std::abs(value) * 0.01, 1e-3));
}

// One key's widget; true with `json` set when the user changed it.
bool keyWidget(const PanelRow& row, const Scene& scene, std::string& json) {
    const SceneKeyInfo& k = *row.key;
    const std::string& label = row.label;
    const std::string current = sceneKeyValue(scene, k.key);
    switch (k.type) {
    case SceneKeyType::Integer: {
        int v = std::stoi(current);
        if (!ImGui::DragInt(label.c_str(), &v, std::max(dragSpeed(k, v), 0.05f),
                            static_cast<int>(std::max(k.min, -2e9)),
                            static_cast<int>(std::min(k.max, 2e9)), "%d",
                            ImGuiSliderFlags_AlwaysClamp))
            return false;
        json = std::to_string(v);
        return true;
    }
    case SceneKeyType::Number: {
        float v = std::stof(current);
        if (!ImGui::DragFloat(label.c_str(), &v, dragSpeed(k, v), static_cast<float>(k.min),
                              static_cast<float>(k.max), "%.4g", ImGuiSliderFlags_AlwaysClamp))
            return false;
        json = jsonNumber(v);
        return true;
    }
    case SceneKeyType::Boolean: {
        bool v = current == "true";
        if (!ImGui::Checkbox(label.c_str(), &v))
            return false;
        json = v ? "true" : "false";
        return true;
    }
    case SceneKeyType::Vector3: {
        float v[3] = {};
        std::sscanf(current.c_str(), "[%f,%f,%f]", &v[0], &v[1], &v[2]);
        if (!ImGui::DragFloat3(label.c_str(), v, dragSpeed(k, std::max({v[0], v[1], v[2]})),
                               static_cast<float>(k.min), static_cast<float>(k.max), "%.4g",
                               ImGuiSliderFlags_AlwaysClamp))
            return false;
        json = jsonVector(v);
        return true;
    }
    case SceneKeyType::Choice: {
        int chosen = 0;
        for (size_t i = 0; i < k.choices.size(); ++i)
            if ("\"" + k.choices[i] + "\"" == current)
                chosen = static_cast<int>(i);
        if (!ImGui::BeginCombo(label.c_str(), k.choices[chosen].c_str()))
            return false;
        bool changed = false;
        for (size_t i = 0; i < k.choices.size(); ++i)
            if (ImGui::Selectable(k.choices[i].c_str(), static_cast<int>(i) == chosen)) {
                json = "\"" + k.choices[i] + "\"";
                changed = static_cast<int>(i) != chosen;
            }
        ImGui::EndCombo();
        return changed;
    }
    case SceneKeyType::String: {
        // Applied on Enter: a path half typed is not a file to load.
        static std::map<std::string, std::string> editing;
        const std::string value = nlohmann::json::parse(current).get<std::string>();
        auto [it, fresh] = editing.try_emplace(k.key, value);
        const bool entered =
            ImGui::InputText(label.c_str(), &it->second, ImGuiInputTextFlags_EnterReturnsTrue);
        if (!entered) {
            if (!ImGui::IsItemActive()) // not being edited: show the scene's value
                it->second = value;
            return false;
        }
        json = nlohmann::json(it->second).dump();
        return true;
    }
    }
    return false;
}

} // namespace

ViewUi::ViewUi(ViewWindow& window, ViewPresenter& presenter, const Scene& opened,
               CameraTrack& track, WeatherPainter& painter, DebugView& debugView)
    : window_(window), opened_(opened), track_(track), painter_(painter), debugView_(debugView) {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini written beside the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window_.handle(), true);
    vulkan_ = std::make_unique<ImGuiVulkan>(presenter.physicalDevice(), presenter.device(),
                                            presenter.queue(), presenter.commandPool(),
                                            presenter.renderPass());
    lastTime_ = glfwGetTime();
}

ViewUi::~ViewUi() {
    vulkan_.reset();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool ViewUi::apply(Scene& scene, const std::string& key, const std::string& jsonValue) {
    return applyPanelEdit(scene, key, jsonValue, message_);
}

ViewUi::Change ViewUi::update(Scene& scene, Renderer& renderer, const RenderResult& last,
                              int windowWidth, int windowHeight) {
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    Change change = sessionPanel(scene, renderer, last, windowWidth, windowHeight);
    const Change keys = keyPanels(scene);
    change = std::max(change, keys);
    change = std::max(change, cameraPanel(scene));
    savePanel();
    paintPanel(scene, renderer, windowWidth, windowHeight);
    if (painting_)
        requests_.painted |= paintWithMouse(scene, renderer, windowWidth, windowHeight);
    if (cameraMode_ == 1 && !painting_ ? orbitWithMouse(scene) : flyCamera(scene))
        change = std::max(change, Change::Camera);
    ImGui::Render();
    return change;
}

void ViewUi::noteUpdate(const UpdateReport& r) {
    std::string remade;
    for (auto [done, name] :
         {std::pair{r.noise, "noise"}, std::pair{r.noiseClearance, "noise clearance field"},
          std::pair{r.weather, "weather map"}, std::pair{r.depth, "depth"},
          std::pair{r.atmosphere, "atmosphere"}, std::pair{r.terrain, "terrain"},
          std::pair{r.dataField, "data field"}})
        if (done)
            remade += (remade.empty() ? "" : ", ") + std::string(name);
    char text[160];
    std::snprintf(text, sizeof text, "last change remade: %s (%.1f ms)",
                  remade.empty() ? "nothing (uniforms only)" : remade.c_str(), 1000.0 * r.seconds);
    message_ = text;
}

void ViewUi::noteReload(const Scene& scene, const std::string& message) {
    opened_ = scene;
    message_ = message;
}

ViewUi::Requests ViewUi::takeRequests() {
    return std::exchange(requests_, Requests{});
}

void ViewUi::draw(vk::CommandBuffer cmd) {
    vulkan_->draw(ImGui::GetDrawData(), cmd);
}

// The overlay of the last frame's figures: the renderer's own times, the GPU timestamps of its
// passes, samples per ray, where the temporal path took each pixel from, and device memory.
void ViewUi::frameFigures(const Renderer& renderer, const RenderResult& last) const {
    if (!ImGui::CollapsingHeader("frame figures", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    const RenderStats& st = last.stats;
    ImGui::Text("host: march %.1f ms, resolve %.1f ms", 1000.0 * st.marchSeconds,
                1000.0 * st.resolveSeconds);
    if (st.gpuMarchMs >= 0.0 && st.gpuUploadMs >= 0.0)
        ImGui::Text("GPU timestamps: upload %.2f ms, march %.2f ms", st.gpuUploadMs, st.gpuMarchMs);
    else if (st.gpuMarchMs >= 0.0)
        ImGui::Text("GPU timestamps: march %.2f ms (no upload this frame)", st.gpuMarchMs);
    else
        ImGui::Text("GPU timestamps: not available on this queue");
    const double rays = std::max<double>(1.0, static_cast<double>(st.rays));
    ImGui::Text("samples a ray: %.1f density, %.1f light", st.densitySamples / rays,
                st.lightSamples / rays);
    const TemporalRenderer::Breakdown b = renderer.lastBreakdown();
    ImGui::Text("pixels: %.0f%% marched, %.0f%% reprojected, %.0f%% fallback", 100.0 * b.marched,
                100.0 * b.reprojected, 100.0 * b.fallback);
    ImGui::Text("device memory: %.1f MiB, of it textures %.1f MiB", st.gpuMemoryBytes / 1048576.0,
                st.gpuTextureBytes / 1048576.0);
}

ViewUi::Change ViewUi::sessionPanel(Scene& scene, Renderer& renderer, const RenderResult& last,
                                    int windowWidth, int windowHeight) {
    Change change = Change::None;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Cloudscape");
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::Text("%.1f fps, %.1f ms rendering a frame", io.Framerate, 1000.0 * last.stats.seconds);
    ImGui::Text("%dx%d, %s", scene.width, scene.height, renderer.backendName().c_str());
    frameFigures(renderer, last);
    if (ImGui::BeginCombo("preset", "open a preset")) {
        for (const std::string& name : presetNames())
            if (ImGui::Selectable(name.c_str())) {
                try {
                    Scene loaded = loadScene(resolveScenePath(name));
                    loaded.width = scene.width; // the window keeps its size
                    loaded.height = scene.height;
                    scene = loaded;
                    opened_ = loaded;
                    change = Change::Scene;
                } catch (const Error& e) {
                    message_ = e.what();
                }
            }
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("tier", "apply a tier")) {
        for (const std::string& name : tierNames())
            if (ImGui::Selectable(name.c_str())) {
                applyTier(scene, name);
                change = Change::Scene;
            }
        ImGui::EndCombo();
    }
    const std::vector<std::string>& views = debugViewNames();
    if (ImGui::BeginCombo("view", views[static_cast<size_t>(debugView_)].c_str())) {
        for (size_t i = 0; i < views.size(); ++i)
            if (ImGui::Selectable(views[i].c_str(), static_cast<size_t>(debugView_) == i))
                debugView_ = static_cast<DebugView>(i);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("a debug view instead of the picture (read back each frame: slower)");
    if (ImGui::Checkbox("temporal", &scene.temporal))
        change = Change::Scene;
    ImGui::Checkbox("render at window size x", &followWindow_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    ImGui::SliderFloat("##scale", &renderScale_, 0.25f, 1.0f, "%.2f");
    if (followWindow_) {
        const int w = std::max(16, static_cast<int>(std::lround(windowWidth * renderScale_)));
        const int h = std::max(16, static_cast<int>(std::lround(windowHeight * renderScale_)));
        if (w != scene.width || h != scene.height) {
            scene.width = w;
            scene.height = h;
            change = Change::Scene;
        }
    }
    ImGui::SliderFloat("fly speed (m/s)", &flySpeed_, 1.0f, 2000.0f, "%.0f",
                       ImGuiSliderFlags_Logarithmic);
    if (!message_.empty())
        ImGui::TextWrapped("%s", message_.c_str());
    ImGui::End();
    return change;
}

ViewUi::Change ViewUi::keyPanels(Scene& scene) {
    Change change = Change::None;
    ImGui::SetNextWindowPos(ImVec2(10, 330), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, 370), ImGuiCond_FirstUseEver);
    ImGui::Begin("Scene keys");
    for (const PanelSection& section : keyPanelSections()) {
        // The weather is what one tunes first: open from the start.
        if (!ImGui::CollapsingHeader(section.name.c_str(), section.name == "weather"
                                                               ? ImGuiTreeNodeFlags_DefaultOpen
                                                               : 0))
            continue;
        for (const PanelRow& row : section.rows)
            change = std::max(change, keyRow(scene, row));
    }
    ImGui::End();
    return change;
}

ViewUi::Change ViewUi::keyRow(Scene& scene, const PanelRow& row) {
    const SceneKeyInfo& k = *row.key;
    Change change = Change::None;
    const std::string openedValue = panelResetValue(opened_, k.key);
    std::string json;
    bool changed = keyWidget(row, scene, json);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", panelTooltip(k, openedValue).c_str());
    if (sceneKeyValue(scene, k.key) != openedValue) {
        ImGui::SameLine();
        if (ImGui::SmallButton(("reset##" + k.key).c_str())) {
            json = openedValue;
            changed = true;
        }
    }
    if (changed && apply(scene, k.key, json)) {
        const bool camera = k.key.rfind("camera.", 0) == 0;
        change = std::max(change, camera ? Change::Camera : Change::Scene);
    }
    return change;
}

// Right mouse button held over the picture: the mouse looks around; W A S D move along the view
// and sideways, Q E down and up, Shift four times faster; the wheel scales the speed.
bool ViewUi::flyCamera(Scene& scene) {
    const double now = glfwGetTime();
    const float dt = static_cast<float>(std::min(now - lastTime_, 0.25));
    lastTime_ = now;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || io.WantCaptureKeyboard)
        return false;
    GLFWwindow* w = window_.handle();
    bool moved = false;
    if (io.MouseWheel != 0.0f)
        flySpeed_ = std::clamp(flySpeed_ * std::pow(1.2f, io.MouseWheel), 1.0f, 2000.0f);
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS &&
        (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
        scene.cameraHeadingDeg =
            std::fmod(scene.cameraHeadingDeg + 0.15f * io.MouseDelta.x, 360.0f);
        const KeyRange pitch = sceneKeyRange("camera.pitch_deg");
        scene.cameraPitchDeg = std::clamp(scene.cameraPitchDeg - 0.15f * io.MouseDelta.y,
                                          static_cast<float>(std::max(pitch.min, -89.0)),
                                          static_cast<float>(std::min(pitch.max, 89.0)));
        moved = true;
    }
    const float heading = glm::radians(scene.cameraHeadingDeg);
    const glm::vec3 forward = viewForward(scene.cameraHeadingDeg, scene.cameraPitchDeg);
    const glm::vec3 right(std::cos(heading), 0.0f, -std::sin(heading));
    glm::vec3 step(0.0f);
    auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
    step += forward * static_cast<float>(held(GLFW_KEY_W) - held(GLFW_KEY_S));
    step += right * static_cast<float>(held(GLFW_KEY_D) - held(GLFW_KEY_A));
    step.y += static_cast<float>(held(GLFW_KEY_E) - held(GLFW_KEY_Q));
    if (step != glm::vec3(0.0f)) {
        const float boost = held(GLFW_KEY_LEFT_SHIFT) ? 4.0f : 1.0f;
        glm::vec3 next = scene.cameraPosition + step * (flySpeed_ * boost * dt);
        next.y = std::max(next.y, 0.5f); // above the ground, as validateScene requires
        scene.cameraPosition = next;
        moved = true;
    }
    return moved;
}

} // namespace cloudscape::cli
