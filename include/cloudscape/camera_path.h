#pragma once
// Scripted camera paths for benchmarks and sequences: the scene at frame f of a path, with time
// advancing 1/fps a frame so the clouds move with the wind.
#include <cloudscape/scene.h>

#include <string>
#include <vector>

namespace cloudscape {

// "still", "slow-pan" (0.25 deg a frame), "fast-pan" (3 deg a frame), "fly-forward"
// (40 m a frame toward the view direction, level), "fly-through" (through the cloud layer from
// below to above: kFlyThroughFrames frames from 500 m under clouds.bottom_m to 500 m over
// clouds.top_m, climbing steadily while flying 40 m a frame along the heading, the view's pitch
// the scene's); the names index CameraPath.
enum class CameraPath { Still, SlowPan, FastPan, FlyForward, FlyThrough };
inline constexpr int kFlyThroughFrames = 96;
const std::vector<std::string>& cameraPathNames();

// Throws cloudscape::Error naming the path and the known ones if it does not exist.
CameraPath parseCameraPath(const std::string& name);

Scene sceneOnPath(const Scene& base, CameraPath path, int frame, float fps);
// The same for a path name (parsed first).
Scene sceneOnPath(const Scene& base, const std::string& path, int frame, float fps);

// A recorded sequence of camera headings (deg) made continuous for keyframes, which interpolate
// angles linearly without wrapping: the same directions, each within 180 degrees of the one
// before (so a recording that turns across north keeps turning the short way between frames),
// as recorded where that stays within camera.heading_deg's range [-360, 360], else shifted by
// whole turns into it. Only a recording turning through more than two whole turns must step
// back a turn, once for each turn beyond those.
std::vector<float> continuousHeadings(const std::vector<float>& headingsDeg);

} // namespace cloudscape
