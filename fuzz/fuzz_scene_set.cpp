// Harness: `--set key=value` overrides. The input is one assignment per line, applied in order
// to the default scene, then the cross-key validation, as SceneOptions::load does.
#include "fuzz_support.h"

#include <cloudscape/scene.h>

#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        cloudscape::Scene scene;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);)
            cloudscape::applyOverride(scene, line);
        cloudscape::validateScene(scene, "fuzz");
    });
    return 0;
}
