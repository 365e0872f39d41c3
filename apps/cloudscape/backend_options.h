#pragma once
// The backend options every rendering command takes, declared once: --backend, --device and
// --vulkan-validation.
#include <cloudscape/backend.h>

#include <CLI/CLI.hpp>

#include <string>

namespace cloudscape::cli {

struct BackendArgs {
    std::string backend = "auto";
    int device = -1;
    bool validation = false;

    // `backendHelp` says what the choice applies to and which is the default.
    void addTo(CLI::App& command, const std::string& backendHelp);
    BackendOptions options() const; // throws cloudscape::Error for an unknown --backend
};

} // namespace cloudscape::cli
