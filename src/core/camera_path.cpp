#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>

#include "core/model_params.h"

namespace cloudscape {

const std::vector<std::string>& cameraPathNames() {
    static const std::vector<std::string> names = {"still", "slow-pan", "fast-pan", "fly-forward"};
    return names;
}

Scene sceneOnPath(const Scene& base, const std::string& path, int frame, float fps) {
    Scene s = base;
    const float f = static_cast<float>(frame);
    s.timeS = base.timeS + f / fps;
    if (path == "still") {
    } else if (path == "slow-pan") {
        s.cameraHeadingDeg = base.cameraHeadingDeg + 0.25f * f;
    } else if (path == "fast-pan") {
        s.cameraHeadingDeg = base.cameraHeadingDeg + 3.0f * f;
    } else if (path == "fly-forward") {
        const glm::vec3 forward = directionFromAngles(base.cameraHeadingDeg, 0.0f);
        s.cameraPosition = base.cameraPosition + forward * (40.0f * f);
    } else {
        std::string known;
        for (const std::string& n : cameraPathNames())
            known += (known.empty() ? "" : ", ") + n;
        throw Error("--camera-path '" + path + "': unknown path, expected one of " + known);
    }
    return s;
}

} // namespace cloudscape
