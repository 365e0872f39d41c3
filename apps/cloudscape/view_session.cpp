// The viewer's frame loop and its scripted actions (view_session.h).
#include "view_session.h"

#include "view_presenter.h"
#include "view_ui.h"
#include "view_window.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/render_files.h>

#include "core/resources.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace cloudscape::cli {
namespace {

// Resident memory of this process in MiB (Linux /proc; lavapipe's "device" memory is host
// memory and is counted here too); -1 where it cannot be read.
double residentMiB() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f)
        return -1.0;
    long pages = 0, resident = 0;
    const int got = std::fscanf(f, "%ld %ld", &pages, &resident);
    std::fclose(f);
    return got == 2 ? resident * (sysconf(_SC_PAGESIZE) / 1048576.0) : -1.0;
}

bool samePath(const std::string& a, const std::string& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() && std::filesystem::equivalent(a, b, ec);
}

bool isExr(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

} // namespace

ViewSession::ViewSession(ViewWindow& window, Renderer& renderer, const Scene& scene,
                         std::vector<ViewAction> script, bool interactive, bool panels,
                         const std::string& watched, std::function<Scene()> reload,
                         const Renderer::DeviceHandles& presentOn)
    : window_(window), renderer_(renderer), scene_(scene), script_(std::move(script)),
      interactive_(interactive), hostFrames_(renderer.deviceHandles().device == 0),
      watch_(reload ? watched : std::string()), reload_(std::move(reload)) {
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    presenter_ =
        std::make_unique<ViewPresenter>(hostFrames_ ? presentOn : renderer_.deviceHandles(),
                                        std::max(width, 1), std::max(height, 1));
    if (panels)
        ui_ = std::make_unique<ViewUi>(window_, *presenter_, scene_, track_, painter_, debugView_);
}

ViewSession::~ViewSession() = default;

void ViewSession::run() {
    const auto start = std::chrono::steady_clock::now();
    while (!window_.closeRequested()) {
        glfwPollEvents();
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        if (width == 0 || height == 0) { // minimised: nothing to draw into, nothing rendered
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        reloadIfChanged();
        if (!runScriptUntilFrame())
            break;
        renderAndPresent(width, height);
    }
    wallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs actions up to the next one that needs a frame (wait, screenshot); false at quit, or at
// the end of a script that is not followed by interactive use.
bool ViewSession::runScriptUntilFrame() {
    if (!capture_.empty())
        return true; // a capture not yet taken
    if (track_.advance(scene_))
        return true; // a path or a recording playing: a camera a frame
    if (waitFrames_ > 0) {
        --waitFrames_;
        return true;
    }
    if (awaitingReload())
        return true;
    while (next_ < script_.size()) {
        const ViewAction& a = script_[next_++];
        switch (a.kind) {
        case ViewAction::Kind::Wait:
            if (a.frames == 0)
                continue;
            waitFrames_ = a.frames - 1; // this frame is the first
            return true;
        case ViewAction::Kind::Screenshot:
        case ViewAction::Kind::Capture:
            (a.kind == ViewAction::Kind::Capture ? capture_ : screenshots_.emplace_back()) = a.key;
            if (next_ < script_.size() && (script_[next_].kind == ViewAction::Kind::Screenshot ||
                                           script_[next_].kind == ViewAction::Kind::Capture))
                continue; // the same frame
            return true;
        case ViewAction::Kind::Save:
            saveScene(a.key);
            continue;
        case ViewAction::Kind::AwaitReload:
            awaiting_ = &a;
            awaitFrom_ = reloads_;
            awaitDeadline_ = std::chrono::steady_clock::now() +
                             std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(a.numbers[0]));
            return true;
        case ViewAction::Kind::Path:
            track_.playPath(scene_, a.key, a.frames);
            if (!track_.advance(scene_))
                continue; // 0 frames
            return true;
        case ViewAction::Kind::Record:
            track_.setRecording(a.key == "on");
            continue;
        case ViewAction::Kind::Play:
            track_.playRecording();
            if (!track_.advance(scene_))
                continue;
            return true;
        case ViewAction::Kind::SavePath:
            track_.saveKeyframes(a.key, 24.0f);
            continue;
        case ViewAction::Kind::Paint:
            updateRenderer(); // the map the stroke goes on is the scene's
            painter_.paint(renderer_, scene_, strokeOf(a));
            frameIndex_ = 0; // other clouds: a new sequence
            continue;
        case ViewAction::Kind::Undo:
            if (painter_.undo(renderer_, scene_))
                frameIndex_ = 0;
            continue;
        case ViewAction::Kind::SaveWeather:
            updateRenderer();
            WeatherPainter::saveImage(renderer_.resources().weather, a.key);
            continue;
        case ViewAction::Kind::SaveField:
            updateRenderer();
            WeatherPainter::saveFieldImage(renderer_.resources().dataField, a.key);
            continue;
        case ViewAction::Kind::CheckWeather: {
            const size_t texels = checkDeviceWeather(renderer_, a.where);
            if (texels == 0)
                std::printf("view check-weather: nothing to compare (the %s backend keeps the map "
                            "on the host only)\n",
                            renderer_.backendName().c_str());
            else
                std::printf("view check-weather: the device's weather map is the host's (%zu "
                            "texels, every level)\n",
                            texels);
            std::fflush(stdout);
            continue;
        }
        case ViewAction::Kind::DebugView:
            debugView_ = parseDebugView(a.key);
            continue;
        case ViewAction::Kind::Memory:
            std::printf("view memory: frame %ld, resident %.1f MiB, device %.1f MiB (the "
                        "renderer's allocations; textures %.1f MiB)\n",
                        framesRendered_, residentMiB(), last_.stats.gpuMemoryBytes / 1048576.0,
                        last_.stats.gpuTextureBytes / 1048576.0);
            std::fflush(stdout);
            continue;
        case ViewAction::Kind::Quit:
            return false;
        case ViewAction::Kind::Camera:
        case ViewAction::Kind::Move:
        case ViewAction::Kind::Turn:
        case ViewAction::Kind::Orbit:
            applyViewAction(scene_, a); // the sequence goes on: the history is reprojected
            continue;
        default:
            if (!changedAt_)
                changedAt_ = std::chrono::steady_clock::now();
            applyViewAction(scene_, a);
            frameIndex_ = 0; // a new scene: a new sequence
            if (updateRenderer().weather)
                painter_.forget(); // a new map: the strokes are gone
            continue;
        }
    }
    return interactive_;
}

bool ViewSession::awaitingReload() {
    if (!awaiting_)
        return false;
    if (reloads_ > awaitFrom_) {
        awaiting_ = nullptr;
        return false;
    }
    if (std::chrono::steady_clock::now() > awaitDeadline_)
        throw Error(awaiting_->where + ": await-reload: " +
                    (watch_.path().empty() ? std::string("no scene file to watch")
                                           : watch_.path() + " did not change") +
                    " within " + std::to_string(static_cast<int>(awaiting_->numbers[0])) + " s");
    return true;
}

// Hot reload. The window keeps its size (as with a preset); a file that does not load leaves
// the scene as it is and says why (in the panel, and on stderr) until the file changes again.
void ViewSession::reloadIfChanged() {
    if (!reload_ || !watch_.changed())
        return;
    try {
        Scene loaded = reload_();
        loaded.width = scene_.width;
        loaded.height = scene_.height;
        scene_ = loaded;
        frameIndex_ = 0;
        ++reloads_;
        if (updateRenderer().weather)
            painter_.forget();
        if (ui_)
            ui_->noteReload(scene_, "reloaded " + watch_.path());
    } catch (const Error& e) {
        std::fprintf(stderr, "cloudscape: view: not reloaded: %s\n", e.what());
        if (ui_)
            ui_->noteMessage(std::string("not reloaded: ") + e.what());
    }
}

UpdateReport ViewSession::updateRenderer() {
    constexpr float kClearanceM = 3.0f; // over the float rounding of a planet-sized altitude
    UpdateReport first;
    if (scene_.terrainEnabled && resourceChanges(renderer_.scene(), scene_).terrain) {
        Scene above = scene_; // the new height field first, made with the camera clear of it
        above.cameraPosition.y = std::max(above.cameraPosition.y, 100000.0f);
        first = renderer_.update(above);
    }
    if (liftCameraAboveTerrain(scene_, renderer_.resources(), kClearanceM) && ui_)
        ui_->noteMessage("camera kept above the terrain");
    UpdateReport report = renderer_.update(scene_);
    report.noise |= first.noise; // what either update remade
    report.noiseClearance |= first.noiseClearance;
    report.dataField |= first.dataField;
    report.weather |= first.weather;
    report.depth |= first.depth;
    report.terrain |= first.terrain;
    report.atmosphere |= first.atmosphere;
    report.seconds += first.seconds;
    return report;
}

void ViewSession::saveScene(const std::string& path) {
    const std::string text = sceneJson(scene_);
    writeFileAtomic(path, text.data(), text.size());
    if (samePath(path, watch_.path()))
        watch_.markCurrent(); // what the window shows already: no reload of our own save
}

void ViewSession::renderAndPresent(int width, int height) {
    if (ui_) {
        const auto before = std::chrono::steady_clock::now();
        const Scene sceneBefore = scene_;
        const ViewUi::Change change = ui_->update(scene_, renderer_, last_, width, height);
        if (change == ViewUi::Change::Scene) {
            if (!changedAt_)
                changedAt_ = before;
            frameIndex_ = 0;
            try {
                const UpdateReport report = updateRenderer();
                if (report.weather)
                    painter_.forget();   // a new map: the strokes are gone
                ui_->noteUpdate(report); // what the change remade, and how long
            } catch (const Error& e) {
                // A value the scene check passes but the renderer cannot use (a weather.image
                // or depth file that does not load): the window goes back to the scene it had
                // (the renderer with it, below) and says why.
                scene_ = sceneBefore;
                ui_->noteMessage(std::string("not applied: ") + e.what());
            }
        }
        ViewUi::Requests asked = ui_->takeRequests();
        try {
            if (!asked.saveScene.empty())
                saveScene(asked.saveScene);
            if (!asked.screenshot.empty())
                screenshots_.push_back(asked.screenshot);
            if (!asked.savePath.empty())
                track_.saveKeyframes(asked.savePath, 24.0f);
            if (!asked.saveWeather.empty())
                WeatherPainter::saveImage(renderer_.resources().weather, asked.saveWeather);
            if (!asked.saveField.empty())
                WeatherPainter::saveFieldImage(renderer_.resources().dataField, asked.saveField);
            if (asked.painted)
                frameIndex_ = 0;
            if (!asked.saveScene.empty() || !asked.savePath.empty() || !asked.saveWeather.empty() ||
                !asked.saveField.empty())
                ui_->noteMessage("saved " + asked.saveScene + asked.savePath + asked.saveWeather +
                                 asked.saveField);
        } catch (const Error& e) {
            ui_->noteMessage(e.what()); // the session goes on
        }
    }
    const bool debug = debugView_ != DebugView::Picture;
    Readback readback = screenshots_.empty() && !debug ? Readback::None : Readback::All;
    if (hostFrames_ && readback == Readback::None)
        readback = Readback::Display; // the composite, to copy into the presenter
    updateRenderer();                 // a camera flown or scripted this frame
    const RenderResult result = renderer_.renderFrame(scene_, frameIndex_++, readback);
    for (const std::string& m : result.stats.validationMessages)
        std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());
    renderSeconds_ += result.stats.seconds;
    gpuTimes_.add(result.stats);
    ++framesRendered_;
    track_.noteFrame(scene_);
    for (const std::string& path : screenshots_) {
        if (!ui_) {
            writeScreenshot(path, result);
            continue;
        }
        try { // asked for in the panel: a bad path is a message there, not the end
            writeScreenshot(path, result);
            ui_->noteMessage("saved " + path);
        } catch (const Error& e) {
            ui_->noteMessage(e.what());
        }
    }
    screenshots_.clear();
    last_.stats = result.stats;
    ViewPresenter::Overlay overlay;
    if (ui_)
        overlay = [this](vk::CommandBuffer cmd) { ui_->draw(cmd); };
    ViewPresenter::Capture capture;
    Renderer::DeviceImage shown = renderer_.deviceImage();
    if (debug) {
        float* pixels = nullptr;
        shown = presenter_->hostImage(result.width, result.height, &pixels);
        fillDebugView(debugView_, result, renderer_, pixels);
    } else if (hostFrames_) { // the CPU backend's composite, linear: the same pass tone-maps it
        float* pixels = nullptr;
        shown = presenter_->hostImage(result.width, result.height, &pixels);
        std::copy(result.composite.begin(), result.composite.end(), pixels);
    }
    presenter_->setDisplayValues(debug);
    presenter_->present(shown, scene_.exposure, width, height, overlay,
                        capture_.empty() ? nullptr : &capture);
    const auto presented = std::chrono::steady_clock::now();
    if (!firstPresented_)
        firstPresented_ = presented;
    else
        ++framesAfterFirst_;
    lastPresented_ = presented;
    if (changedAt_) {
        const double s = std::chrono::duration<double>(presented - *changedAt_).count();
        ++changes_;
        changeSeconds_ += s;
        worstChangeSeconds_ = std::max(worstChangeSeconds_, s);
        changedAt_.reset();
    }
    if (capture.width > 0) { // else the swapchain was being rebuilt: the next frame captures
        writePng(capture_, capture.width, capture.height, capture.rgba);
        capture_.clear();
    }
}

void ViewSession::writeScreenshot(const std::string& path, const RenderResult& result) const {
    if (isExr(path))
        writeRenderExr(path, result);
    else
        writePng(path, result.width, result.height, toneMapToSrgb8(result, scene_.exposure));
}

std::string ViewSession::statsLine() const {
    const double steadySeconds =
        firstPresented_ ? std::chrono::duration<double>(lastPresented_ - *firstPresented_).count()
                        : 0.0;
    char line[512];
    std::snprintf(line, sizeof line,
                  "view: %ld frames at %dx%d, %.1f fps in the window (%.1f after the first "
                  "frame; %.1f ms rendering a frame), %s; a scene change to its first frame "
                  "presented: %.1f ms on average, %.1f ms at worst (%ld changes)",
                  framesRendered_, scene_.width, scene_.height,
                  wallSeconds_ > 0.0 ? framesRendered_ / wallSeconds_ : 0.0,
                  steadySeconds > 0.0 ? framesAfterFirst_ / steadySeconds : 0.0,
                  framesRendered_ ? 1000.0 * renderSeconds_ / framesRendered_ : 0.0,
                  renderer_.backendName().c_str(),
                  changes_ ? 1000.0 * changeSeconds_ / changes_ : 0.0, 1000.0 * worstChangeSeconds_,
                  changes_);
    std::string text = line;
    if (gpuTimes_.timed())
        text += "; " + gpuTimes_.line();
    if (painter_.edits() > 0) { // a brush stroke or undo, to the map updated on the device
        std::snprintf(line, sizeof line, "; %d brush edits (strokes and undos), %.2f ms each",
                      painter_.edits(), 1000.0 * painter_.editSeconds() / painter_.edits());
        text += line;
    }
    return text;
}

} // namespace cloudscape::cli
