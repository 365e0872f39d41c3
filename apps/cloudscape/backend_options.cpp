#include "backend_options.h"

namespace cloudscape::cli {

void BackendArgs::addTo(CLI::App& command, const std::string& backendHelp) {
    command.add_option("--backend", backend, backendHelp);
    command.add_option("--device", device, "Vulkan device index (see `cloudscape devices`)")
        ->check(CLI::Range(0, 255));
#ifndef NDEBUG
    validation = true; // debug builds always run under the validation layers
#endif
    command.add_flag("--vulkan-validation", validation,
                     "Enable the Vulkan validation layers and report their messages");
}

BackendOptions BackendArgs::options() const {
    BackendOptions o;
    o.choice = parseBackendChoice(backend);
    o.device = device;
    o.validation = validation;
    return o;
}

} // namespace cloudscape::cli
