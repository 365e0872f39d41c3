// cloudscape: the command-line tool. Every failure prints one line, "cloudscape: error: ...",
// and exits with status 1; outputs are written atomically so nothing partial is left behind.
#include "commands.h"

#include <cloudscape/error.h>

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace {

std::vector<CLI::App*> commands(CLI::App& app) {
    return app.get_subcommands([](CLI::App*) { return true; });
}

bool isCommand(CLI::App& app, const std::string& name) {
    for (CLI::App* c : commands(app))
        if (c->get_name() == name)
            return true;
    return false;
}

std::string commandNames(CLI::App& app) {
    std::string names;
    for (CLI::App* c : commands(app))
        names += (names.empty() ? "" : ", ") + c->get_name();
    return names;
}

// A user's word quoted in a message, cut to a readable length.
std::string shortened(const std::string& text) {
    return text.size() <= 40 ? text : text.substr(0, 40) + "...";
}

// Every frame of a sequence or the viewer's readback gets new image-sized buffers (a 1280x720
// composite is 15 MB). glibc serves blocks that large with a fresh mmap each time and returns
// them to the system when freed, so each frame the kernel faulted the pages in again: 31-48 ms
// of a 1280x720 frame's 15 MB readback on lavapipe, against about 1 ms when the heap keeps them.
// Blocks up to glibc's ceiling for this setting (32 MB) now come from the heap, and up to 512 MB
// of free heap is kept; a 4K frame's buffers still come from mmap.
void keepImageBuffersInTheHeap() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

} // namespace

int main(int argc, char** argv) {
    keepImageBuffersInTheHeap();
    CLI::App app{
        "Cloudscape: real-time volumetric cloudscapes (Nubis model), CPU and Vulkan backends"};
    app.require_subcommand(1);
    cloudscape::cli::addRenderCommand(app);
    cloudscape::cli::addNoiseCommand(app);
    cloudscape::cli::addWeatherCommand(app);
    cloudscape::cli::addSceneDocCommand(app);
    cloudscape::cli::addDevicesCommand(app);
    cloudscape::cli::addCompareCommand(app);
    cloudscape::cli::addBenchCommand(app);
    cloudscape::cli::addPathTraceCommand(app);
    cloudscape::cli::addViewCommand(app);
    if (argc > 1 && argv[1][0] != '-' && !isCommand(app, argv[1])) {
        std::fprintf(stderr,
                     "cloudscape: error: unknown command '%s'; expected one of %s (see --help)\n",
                     shortened(argv[1]).c_str(), commandNames(app).c_str());
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, like every other failure, instead of CLI11's usage dump.
        std::fprintf(stderr, "cloudscape: error: %s (see --help)\n", e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "cloudscape: error: out of memory; try a smaller --width/--height "
                             "or weather.resolution\n");
        return 1;
    } catch (const cloudscape::Error& e) {
        std::fprintf(stderr, "cloudscape: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cloudscape: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
