// Harness: keyframe files (render/bench --keyframes) on arbitrary JSON text: the checked parser,
// the key table's checks per keyframe, the cross-key checks at every keyframe, and the
// interpolation, whose scenes must stay within every key's range (it is re-applied through the
// table, which throws otherwise) at any sequence time.
#include "fuzz_support.h"

#include <cloudscape/keyframes.h>
#include <cloudscape/scene.h>

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    cloudscape::Keyframes keyframes;
    bool parsed = false;
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        keyframes = cloudscape::parseKeyframes(text, "fuzz.json", cloudscape::Scene{});
        parsed = true;
    });
    if (!parsed)
        return 0;
    // A parsed file's scenes are valid at any time: a throw here is a finding.
    try {
        for (double t :
             {0.0, 0.5, 1.0, 59.99, 1e3, 1e8, -1.0, std::numeric_limits<double>::quiet_NaN()})
            cloudscape::validateScene(keyframes.sceneAt(cloudscape::Scene{}, t), "fuzz");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: a parsed keyframe file gave an invalid scene: %s\n", e.what());
        std::abort();
    }
    return 0;
}
