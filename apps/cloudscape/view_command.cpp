// `cloudscape view [SCENE]`: the scene rendered continuously through the temporal renderer on
// the Vulkan backend, in a window, drawn from the device without a round trip through the host;
// with --script FILE, a list of actions carried out in that window (view_script.h).
#include "commands.h"
#include "scene_options.h"
#include "validate_only.h"
#include "view_presenter.h"
#include "view_script.h"
#include "view_session.h"
#include "view_window.h"

#include <cloudscape/error.h>
#include <cloudscape/persistent_renderer.h>

#include <cstdio>
#include <memory>

namespace cloudscape::cli {
namespace {

struct ViewArgs {
    SceneOptions scene;
    std::string script;
    std::string backend = "vulkan";
    int device = -1;
    bool validation = false;
    bool stats = false;
    bool panels = false;
};

void runView(const ViewArgs& args) {
    Scene scene = args.scene.load();
    std::vector<ViewAction> actions;
    if (!args.script.empty())
        actions = loadViewScript(args.script, scene);
    stopIfValidatingOnly();

    ViewWindow window(scene.width, scene.height, "cloudscape view");
    BackendOptions backend;
    backend.choice = args.backend == "cpu" ? BackendChoice::Cpu : BackendChoice::Vulkan;
    backend.device = args.device;
    backend.validation = args.validation;
    backend.presentation = window.presentationTarget();
    backend.interactive = true;
    // The CPU backend renders on the host; the window still needs a Vulkan device (any, lavapipe
    // included) to present on, opened here for that alone.
    std::unique_ptr<PresentationDevice> presentOn;
    if (backend.choice == BackendChoice::Cpu)
        presentOn = std::make_unique<PresentationDevice>(backend);
    Renderer renderer(scene, backend);
    const bool interactive = args.script.empty();
    // Hot reload: the scene file (or the preset's file) loaded again as the command line
    // describes it, --set and --tier included.
    const std::string watched = args.scene.scene.empty() ? "" : resolveScenePath(args.scene.scene);
    ViewSession session(
        window, renderer, scene, std::move(actions), interactive, interactive || args.panels,
        watched, [&args]() { return args.scene.load(); },
        presentOn ? presentOn->handles() : Renderer::DeviceHandles{});
    session.run();
    if (presentOn)
        for (const std::string& m : presentOn->takeValidationMessages())
            std::fprintf(stderr, "cloudscape: vulkan validation: %s\n", m.c_str());
    if (args.stats)
        std::printf("%s\n", session.statsLine().c_str());
}

} // namespace

void addViewCommand(CLI::App& app) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* cmd = app.add_subcommand(
        "view", "Open a window rendering the scene live on the Vulkan backend, with panels for "
                "every scene key (or run a --script of actions in it)");
    args->scene.addTo(*cmd, true);
    cmd->add_option("--script", args->script,
                    "Carry out the actions of FILE (set, tier, camera, move, turn, orbit, wait, "
                    "screenshot, capture, save, await-reload, path, record, play, save-path, "
                    "paint, undo, save-weather, save-field, check-weather, view, memory, quit) "
                    "and close");
    cmd->add_option("--backend", args->backend,
                    "Render on the Vulkan device (vulkan, the default) or on the CPU (cpu: each "
                    "frame is copied to the window, which still presents through a Vulkan "
                    "device, e.g. lavapipe)")
        ->check(CLI::IsMember({"vulkan", "cpu"}));
    cmd->add_option("--device", args->device, "Vulkan device index (see `cloudscape devices`)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--vulkan-validation", args->validation,
                  "Run under the Vulkan validation layers and print their messages");
    cmd->add_flag("--panels", args->panels, "Show the panels in a --script session too (capture)");
    cmd->add_flag("--stats", args->stats, "Print frames rendered and frames per second at the end");
    cmd->callback([args]() { runView(*args); });
}

} // namespace cloudscape::cli
