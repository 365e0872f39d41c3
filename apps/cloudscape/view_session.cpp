// The viewer's frame loop and its scripted actions (view_session.h).
#include "view_session.h"

#include "view_presenter.h"
#include "view_ui.h"
#include "view_window.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/render_files.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace cloudscape::cli {
namespace {

bool isExr(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

} // namespace

ViewSession::ViewSession(ViewWindow& window, Renderer& renderer, const Scene& scene,
                         std::vector<ViewAction> script, bool interactive, bool panels)
    : window_(window), renderer_(renderer), scene_(scene), script_(std::move(script)),
      interactive_(interactive) {
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    presenter_ = std::make_unique<ViewPresenter>(renderer_.deviceHandles(), std::max(width, 1),
                                                 std::max(height, 1));
    if (panels)
        ui_ = std::make_unique<ViewUi>(window_, *presenter_, scene_);
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
    if (waitFrames_ > 0) {
        --waitFrames_;
        return true;
    }
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
        case ViewAction::Kind::Save: {
            const std::string text = sceneJson(scene_);
            writeFileAtomic(a.key, text.data(), text.size());
            continue;
        }
        case ViewAction::Kind::Quit:
            return false;
        case ViewAction::Kind::Camera:
        case ViewAction::Kind::Move:
        case ViewAction::Kind::Turn:
            applyViewAction(scene_, a); // the sequence goes on: the history is reprojected
            continue;
        default:
            applyViewAction(scene_, a);
            frameIndex_ = 0; // a new scene: a new sequence
            continue;
        }
    }
    return interactive_;
}

void ViewSession::renderAndPresent(int width, int height) {
    if (ui_) {
        const ViewUi::Change change = ui_->update(scene_, renderer_, last_, width, height);
        if (change == ViewUi::Change::Scene) {
            frameIndex_ = 0;
            ui_->noteUpdate(renderer_.update(scene_)); // what the change remade, and how long
        }
    }
    const Readback readback = screenshots_.empty() ? Readback::None : Readback::All;
    const RenderResult result = renderer_.renderFrame(scene_, frameIndex_++, readback);
    for (const std::string& m : result.stats.validationMessages)
        std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());
    renderSeconds_ += result.stats.seconds;
    ++framesRendered_;
    for (const std::string& path : screenshots_)
        writeScreenshot(path, result);
    screenshots_.clear();
    last_.stats = result.stats;
    ViewPresenter::Overlay overlay;
    if (ui_)
        overlay = [this](vk::CommandBuffer cmd) { ui_->draw(cmd); };
    ViewPresenter::Capture capture;
    presenter_->present(renderer_.deviceImage(), scene_.exposure, width, height, overlay,
                        capture_.empty() ? nullptr : &capture);
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
    char line[256];
    std::snprintf(line, sizeof line,
                  "view: %ld frames at %dx%d, %.1f fps in the window (%.1f ms rendering a "
                  "frame), %s",
                  framesRendered_, scene_.width, scene_.height,
                  wallSeconds_ > 0.0 ? framesRendered_ / wallSeconds_ : 0.0,
                  framesRendered_ ? 1000.0 * renderSeconds_ / framesRendered_ : 0.0,
                  renderer_.backendName().c_str());
    return line;
}

} // namespace cloudscape::cli
