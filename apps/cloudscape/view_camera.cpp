// Orbiting, camera paths and recordings (view_camera.h).
#include "view_camera.h"

#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace cloudscape::cli {

glm::vec3 viewForward(float headingDeg, float pitchDeg) {
    const float heading = glm::radians(headingDeg);
    const float pitch = glm::radians(pitchDeg);
    return {std::sin(heading) * std::cos(pitch), std::sin(pitch),
            std::cos(heading) * std::cos(pitch)};
}

void orbitCamera(Scene& scene, float distanceM, float dHeadingDeg, float dPitchDeg) {
    const glm::vec3 pivot = scene.cameraPosition +
                            viewForward(scene.cameraHeadingDeg, scene.cameraPitchDeg) * distanceM;
    scene.cameraHeadingDeg = std::fmod(scene.cameraHeadingDeg + dHeadingDeg, 360.0f);
    scene.cameraPitchDeg = std::clamp(scene.cameraPitchDeg + dPitchDeg, -89.0f, 89.0f);
    scene.cameraPosition =
        pivot - viewForward(scene.cameraHeadingDeg, scene.cameraPitchDeg) * distanceM;
}

void CameraTrack::setRecording(bool on) {
    if (on && !recording_)
        recorded_.clear(); // a new recording
    recording_ = on;
}

void CameraTrack::noteFrame(const Scene& rendered) {
    if (recording_)
        recorded_.push_back(cameraOf(rendered));
}

void CameraTrack::playRecording() {
    queue_ = recorded_;
    next_ = 0;
}

void CameraTrack::playPath(const Scene& from, const std::string& path, int frames) {
    const CameraPath which = parseCameraPath(path);
    queue_.clear();
    next_ = 0;
    for (int f = 1; f <= frames; ++f) { // frame 0 is where the camera is
        Camera c = cameraOf(sceneOnPath(from, which, f, 24.0f));
        c.headingDeg = std::fmod(c.headingDeg, 360.0f); // within the key's range, however long
        queue_.push_back(c);
    }
}

bool CameraTrack::advance(Scene& scene) {
    if (!playing())
        return false;
    scene = withCamera(scene, queue_[next_++], scene.timeS);
    return true;
}

void CameraTrack::saveKeyframes(const std::string& path, float fps) const {
    if (recorded_.empty())
        throw Error(path + ": no camera recorded to save (record on, move, record off first)");
    std::vector<float> headings;
    for (const Camera& c : recorded_)
        headings.push_back(c.headingDeg);
    headings = continuousHeadings(headings); // the fly camera's heading wraps at 360
    nlohmann::json frames = nlohmann::json::array();
    for (size_t i = 0; i < recorded_.size(); ++i) {
        const Camera& c = recorded_[i];
        frames.push_back({{"time_s", static_cast<double>(i) / fps},
                          {"set",
                           {{"camera.position", {c.position.x, c.position.y, c.position.z}},
                            {"camera.heading_deg", headings[i]},
                            {"camera.pitch_deg", c.pitchDeg},
                            {"camera.fov_deg", c.fovDeg}}}});
    }
    const std::string text = nlohmann::json{{"keyframes", frames}}.dump(1) + "\n";
    writeFileAtomic(path, text.data(), text.size());
}

} // namespace cloudscape::cli
