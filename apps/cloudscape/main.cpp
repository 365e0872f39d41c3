// cloudscape: the command-line tool. Every failure prints one line, "cloudscape: error: ...",
// and exits with status 1; outputs are written atomically so nothing partial is left behind.
#include "commands.h"

#include <cloudscape/error.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
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
    } catch (const cloudscape::Error& e) {
        std::fprintf(stderr, "cloudscape: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cloudscape: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
