#pragma once
// `cloudscape view SCENE --script FILE`: a list of actions the viewer carries out in its window,
// one a frame, for tests and demos. One action a line; blank lines and lines starting with # are
// skipped:
//   set KEY VALUE          a scene key, VALUE as in --set (JSON, or a bare word)
//   tier NAME              a quality tier (low, high, reference) over the current scene
//   camera X Y Z HEADING PITCH   the camera (metres, degrees)
//   move DX DY DZ          the camera moved by metres
//   turn DHEADING DPITCH   the camera turned by degrees
//   wait N                 N more frames rendered (the temporal path converges in 16)
//   screenshot FILE        the next frame written as .png (tone-mapped) or .exr (every layer)
//   capture FILE           what the window shows (picture and panels) as a .png
//                          (screenshot and capture lines in a row are all of the same frame)
//   save FILE              the scene written as JSON (the keys that differ from the defaults)
//   quit                   close the window (the end of the script does too)
// The whole script is read and checked before the window opens, against the scene it starts
// from: an unknown action, a wrong argument or a bad value is a one-line error naming the line.
#include <cloudscape/scene.h>

#include <string>
#include <vector>

namespace cloudscape::cli {

struct ViewAction {
    enum class Kind { Set, Tier, Camera, Move, Turn, Wait, Screenshot, Capture, Save, Quit };
    Kind kind = Kind::Quit;
    std::string where; // "FILE:LINE", for messages
    std::string key;   // Set: the key; Tier: the name; Screenshot/Capture/Save: the path
    std::string value; // Set: the value text
    float numbers[5] = {};
    int frames = 0; // Wait
};

// Reads and checks the script; throws cloudscape::Error naming FILE:LINE.
std::vector<ViewAction> loadViewScript(const std::string& path, const Scene& start);

// Applies a Set, Tier, Camera, Move or Turn action to the scene; throws cloudscape::Error.
void applyViewAction(Scene& scene, const ViewAction& action);

} // namespace cloudscape::cli
