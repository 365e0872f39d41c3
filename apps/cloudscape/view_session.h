#pragma once
// One viewing session: the frame loop of `cloudscape view`. Every frame renders the next frame
// of the temporal sequence on the device and draws it into the window; a change of a scene key
// restarts the sequence (frame 0: no history to blend), a camera move continues it (the history
// is reprojected). Scripted actions run between frames; interactive input comes from the panels
// (view_ui.h) and the camera controls.
#include "gpu_pass_times.h"
#include "view_camera.h"
#include "view_debug.h"
#include "view_paint.h"
#include "view_reload.h"
#include "view_script.h"

#include <cloudscape/persistent_renderer.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cloudscape::cli {

class ViewWindow;
class ViewPresenter;
class ViewUi;

class ViewSession {
public:
    // Interactive sessions go on after the script (if any) until the window is closed, scripted
    // ones close when it ends; the panels are shown when asked for. `reload` loads the scene as
    // the command line describes it again (hot reload) when the file at `watched` changes.
    // A renderer with no device of its own (the CPU backend) has its frames drawn on
    // `presentOn` (a PresentationDevice's): read back each frame and copied into the presenter.
    ViewSession(ViewWindow& window, Renderer& renderer, const Scene& scene,
                std::vector<ViewAction> script, bool interactive, bool panels,
                const std::string& watched = "", std::function<Scene()> reload = {},
                const Renderer::DeviceHandles& presentOn = {});
    ~ViewSession();

    void run();
    std::string statsLine() const;

private:
    bool runScriptUntilFrame(); // false: quit
    bool awaitingReload();      // an await-reload still waiting (throws when it is too late)
    void reloadIfChanged();
    void saveScene(const std::string& path);
    // renderer_.update(scene_) with the camera kept above the terrain (a fly into a hill walks
    // over it; `render` refuses such a camera instead).
    UpdateReport updateRenderer();
    void renderAndPresent(int width, int height);
    void writeScreenshot(const std::string& path, const RenderResult& result) const;

    ViewWindow& window_;
    Renderer& renderer_;
    Scene scene_;
    std::vector<ViewAction> script_;
    bool interactive_;
    bool hostFrames_ = false; // the renderer's frames are on the host (the CPU backend)
    std::unique_ptr<ViewPresenter> presenter_;
    std::unique_ptr<ViewUi> ui_;
    RenderResult last_; // the previous frame's statistics, for the panels
    CameraTrack track_;
    WeatherPainter painter_;
    DebugView debugView_ = DebugView::Picture;
    SceneFileWatch watch_;
    std::function<Scene()> reload_;
    long reloads_ = 0;
    const ViewAction* awaiting_ = nullptr; // an await-reload, until reloads_ passes awaitFrom_
    long awaitFrom_ = 0;
    std::chrono::steady_clock::time_point awaitDeadline_;

    size_t next_ = 0;    // the next script action
    int waitFrames_ = 0; // frames a `wait` still asks for
    // Written from the frame about to be rendered (consecutive screenshot and capture lines
    // share one frame): its layers, and the window's pixels once presented.
    std::vector<std::string> screenshots_;
    std::string capture_;
    int frameIndex_ = 0; // in the current temporal sequence
    long framesRendered_ = 0;
    // From a scene change (a script's set or tier, an edit in the panels) to the end of
    // presenting the first frame that shows it: the latency a person sees after a slider move.
    std::optional<std::chrono::steady_clock::time_point> changedAt_;
    long changes_ = 0;
    double changeSeconds_ = 0.0;
    double worstChangeSeconds_ = 0.0;
    double renderSeconds_ = 0.0;
    double wallSeconds_ = 0.0;
    // The first and the latest frame presented: the rate after the first frame leaves out the
    // session's set-up (pipelines built and textures uploaded for the first frame).
    std::optional<std::chrono::steady_clock::time_point> firstPresented_;
    std::chrono::steady_clock::time_point lastPresented_;
    long framesAfterFirst_ = 0;
    GpuPassTimes gpuTimes_; // per pass, for --stats
};

} // namespace cloudscape::cli
