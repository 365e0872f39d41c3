#pragma once
// The viewer's camera beyond flying (view_ui.h): orbiting a point ahead of the camera, playing
// the `render --frames --camera-path` paths, and recording the camera frame by frame to play it
// back or to save it as a keyframe file that `render --frames A:B --keyframes FILE` follows.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include <string>
#include <vector>

namespace cloudscape::cli {

// Turns the camera around the point `distance` metres ahead of it along the view: heading and
// pitch change by the given degrees and the camera keeps looking at that point (pitch held
// within +-89 deg, heading kept within +-360 deg as the key's range asks).
void orbitCamera(Scene& scene, float distanceM, float dHeadingDeg, float dPitchDeg);

// The view direction of camera.glsl.h: heading 0 looks along +z, turning towards +x.
glm::vec3 viewForward(float headingDeg, float pitchDeg);

class CameraTrack {
public:
    // Recording: every frame rendered while on adds the camera it was rendered with.
    void setRecording(bool on);
    bool recording() const { return recording_; }
    void noteFrame(const Scene& rendered);
    size_t recordedFrames() const { return recorded_.size(); }

    // Playback: the next frames take their cameras from the queue, one a frame.
    void playRecording();
    // `frames` frames of a `render --camera-path` path (cameraPathNames()) from `from`'s camera;
    // throws cloudscape::Error for an unknown name.
    void playPath(const Scene& from, const std::string& path, int frames);
    void stop() { queue_.clear(), next_ = 0; }
    bool playing() const { return next_ < queue_.size(); }
    // Sets the next queued camera on `scene`; false when nothing is playing.
    bool advance(Scene& scene);

    // The recording as keyframes ({"keyframes": [{"time_s", "set": {camera keys}}]}), one
    // keyframe a recorded frame at `fps`; written atomically. Throws cloudscape::Error when
    // nothing was recorded.
    void saveKeyframes(const std::string& path, float fps) const;

private:
    std::vector<Camera> recorded_;
    std::vector<Camera> queue_;
    size_t next_ = 0;
    bool recording_ = false;
};

} // namespace cloudscape::cli
