#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>

#include "core/model_params.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace cloudscape {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

// Far along a path (a large frame index, a tiny --fps) a frame can leave the ranges the scene
// keys document, and the model then samples the clouds at infinite or meaningless wind offsets:
// with --fps 1e-40, frame 1 fell at t = inf (found by fuzz_camera_path). Such a frame is
// refused, naming it, rather than rendered.
void requireFrameWithinKeyRanges(const Scene& s, CameraPath path, int frame, float fps) {
    const std::string which = "--camera-path " + cameraPathNames()[static_cast<size_t>(path)] +
                              ": frame " + std::to_string(frame) + " at --fps " + number(fps);
    const auto [tMin, tMax] = sceneKeyRange("time_s");
    if (!(s.timeS >= tMin && s.timeS <= tMax))
        throw Error(which + " falls at time_s = " + number(s.timeS) + " s, outside [" +
                    number(tMin) + ", " + number(tMax) + "]");
    const auto [pMin, pMax] = sceneKeyRange("camera.position");
    for (int i = 0; i < 3; ++i)
        if (!(s.cameraPosition[i] >= pMin && s.cameraPosition[i] <= pMax))
            throw Error(which + " puts the camera at " + number(s.cameraPosition[i]) +
                        " m on axis " + "xyz"[i] + ", outside camera.position's [" + number(pMin) +
                        ", " + number(pMax) + "]");
}

} // namespace

const std::vector<std::string>& cameraPathNames() {
    static const std::vector<std::string> names = {"still", "slow-pan", "fast-pan", "fly-forward",
                                                   "fly-through"};
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
    case CameraPath::FlyThrough: {
        const glm::vec3 forward = directionFromAngles(base.cameraHeadingDeg, 0.0f);
        const float start = base.cloudBottomM - 500.0f;
        const float climb = (base.cloudTopM - base.cloudBottomM + 1000.0f) / kFlyThroughFrames;
        s.cameraPosition = base.cameraPosition + forward * (40.0f * f);
        s.cameraPosition.y = start + climb * f;
        break;
    }
    }
    requireFrameWithinKeyRanges(s, path, frame, fps);
    return s;
}

Scene sceneOnPath(const Scene& base, const std::string& path, int frame, float fps) {
    return sceneOnPath(base, parseCameraPath(path), frame, fps);
}

std::vector<float> continuousHeadings(const std::vector<float>& headingsDeg) {
    std::vector<float> out;
    out.reserve(headingsDeg.size());
    for (float h : headingsDeg)
        out.push_back(out.empty() ? h : out.back() + std::remainder(h - out.back(), 360.0f));
    if (out.empty())
        return out;
    // Whole turns off only where the run leaves the range: a recording that stays in it keeps
    // its headings as recorded.
    const auto [low, high] = std::minmax_element(out.begin(), out.end());
    float shift = 0.0f;
    if (*high > 360.0f)
        shift = -360.0f * std::ceil((*high - 360.0f) / 360.0f);
    else if (*low < -360.0f)
        shift = 360.0f * std::ceil((-360.0f - *low) / 360.0f);
    for (float& h : out) {
        h += shift;
        while (h > 360.0f)
            h -= 360.0f;
        while (h < -360.0f)
            h += 360.0f;
    }
    return out;
}

} // namespace cloudscape
