// Harness: scripted camera paths (--camera-path, --frames, --fps of `render` and `bench`). Any
// path name, any frame the CLI accepts (0 to INT_MAX) and any positive rate must give either a
// cloudscape::Error or a scene whose camera and time are finite (else the render is NaN).
//
// Input: 1 byte base scene, 4 bytes frame, 4 bytes fps (a float's bits), 1 byte path choice,
// then the path name when the choice byte is odd.
#include "fuzz_support.h"

#include <cloudscape/camera_path.h>
#include <cloudscape/scene.h>

#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

const std::vector<cloudscape::Scene>& baseScenes() {
    static const std::vector<cloudscape::Scene> scenes = [] {
        std::vector<cloudscape::Scene> s{cloudscape::Scene{}};
        for (const char* preset : {"sunset", "above-the-deck", "inside-cloud"})
            s.push_back(cloudscape::loadScene(cloudscape::resolveScenePath(preset)));
        return s;
    }();
    return scenes;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 10)
        return -1;
    const cloudscape::Scene& base = baseScenes()[data[0] % baseScenes().size()];
    uint32_t frameBits = 0;
    float fps = 0.0f;
    std::memcpy(&frameBits, data + 1, 4);
    std::memcpy(&fps, data + 5, 4);
    const int frame = static_cast<int>(frameBits & INT_MAX);
    const auto& names = cloudscape::cameraPathNames();
    const std::string path = data[9] % 2 == 0
                                 ? names[data[9] / 2 % names.size()]
                                 : std::string(reinterpret_cast<const char*>(data + 10), size - 10);
    if (!(fps > 0.0f))
        return -1; // both commands refuse these before any path is evaluated
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::Scene s = cloudscape::sceneOnPath(base, path, frame, fps);
        if (!finite(s.cameraPosition) || !std::isfinite(s.cameraHeadingDeg) ||
            !std::isfinite(s.cameraPitchDeg) || !std::isfinite(s.timeS)) {
            std::fprintf(stderr,
                         "fuzz: path '%s' frame %d fps %g gives a non-finite camera or time "
                         "(t = %g)\n",
                         path.c_str(), frame, static_cast<double>(fps),
                         static_cast<double>(s.timeS));
            std::abort();
        }
        cloudscape::validateScene(s, "fuzz");
    });
    return 0;
}
