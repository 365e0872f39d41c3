#pragma once
// Subcommands of the cloudscape tool. Each registers itself on the app and runs from its
// callback; errors are thrown as cloudscape::Error and reported by main.
#include <CLI/CLI.hpp>

namespace cloudscape::cli {

void addRenderCommand(CLI::App& app);
void addNoiseCommand(CLI::App& app);
void addWeatherCommand(CLI::App& app);
void addSceneDocCommand(CLI::App& app);
void addDevicesCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addPathTraceCommand(CLI::App& app);
void addViewCommand(CLI::App& app);

} // namespace cloudscape::cli
