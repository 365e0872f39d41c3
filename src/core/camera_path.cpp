#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>

#include "core/model_params.h"

namespace cloudscape {

const std::vector<std::string>& cameraPathNames() {
    static const std::vector<std::string> names = {"still", "slow-pan", "fast-pan", "fly-forward"};
    return names;
}

CameraPath parseCameraPath(const std::string& name) {
    const std::vector<std::string>& names = cameraPathNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return static_cast<CameraPath>(i);
    std::string known;
    for (const std::string& n : names)
        known += (known.empty() ? "" : ", ") + n;
    throw Error("--camera-path '" + name + "': unknown path, expected one of " + known);
}

Scene sceneOnPath(const Scene& base, CameraPath path, int frame, float fps) {
    Scene s = base;
    const float f = static_cast<float>(frame);
    s.timeS = base.timeS + f / fps;
    switch (path) {
    case CameraPath::Still:
        break;
    case CameraPath::SlowPan:
        s.cameraHeadingDeg = base.cameraHeadingDeg + 0.25f * f;
        break;
    case CameraPath::FastPan:
        s.cameraHeadingDeg = base.cameraHeadingDeg + 3.0f * f;
        break;
    case CameraPath::FlyForward: {
        const glm::vec3 forward = directionFromAngles(base.cameraHeadingDeg, 0.0f);
        s.cameraPosition = base.cameraPosition + forward * (40.0f * f);
        break;
    }
    }
    return s;
}

Scene sceneOnPath(const Scene& base, const std::string& path, int frame, float fps) {
    return sceneOnPath(base, parseCameraPath(path), frame, fps);
}

} // namespace cloudscape
