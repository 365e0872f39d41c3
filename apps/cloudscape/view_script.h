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
//   await-reload SECONDS   frames go on until the scene file changes on disk and is reloaded
//                          (hot reload); an error if that takes longer than SECONDS
//   orbit DISTANCE DHEADING DPITCH   the camera turned around the point DISTANCE m ahead
//   path NAME FRAMES       FRAMES frames along a `render --camera-path` path (still, slow-pan,
//                          fast-pan, fly-forward, fly-through) from the current camera, one
//                          a frame
//   record on|off          record the camera of every frame rendered (on starts anew)
//   play                   the recorded cameras played back, one a frame
//   save-path FILE         the recording as a keyframe file (`render --frames --keyframes`)
//   paint CHANNEL X Z RADIUS STRENGTH   a brush stroke on the weather map (coverage,
//                          precipitation or type) or the data field (bottom_type, anvil,
//                          min_height, max_height) centred at world X, Z m; STRENGTH in [-1, 1]
//   undo                   the last stroke taken back
//   save-weather FILE      the painted weather map as the PNG weather.image reads
//   save-field FILE        the painted data field as the PNG weather.field_image reads
//   view NAME              show a debug view: picture, transmittance, depth, weather
//   memory                 print a line: frames so far, resident memory (the soak benchmark)
//   quit                   close the window (the end of the script does too)
// The whole script is read and checked before the window opens, against the scene it starts
// from: an unknown action, a wrong argument or a bad value is a one-line error naming the line.
#include "view_paint.h"

#include <cloudscape/scene.h>

#include <string>
#include <vector>

namespace cloudscape::cli {

struct ViewAction {
    enum class Kind {
        Set,
        Tier,
        Camera,
        Move,
        Turn,
        Orbit,
        Wait,
        Screenshot,
        Capture,
        Save,
        AwaitReload,
        Path,
        Record,
        Play,
        SavePath,
        Paint,
        Undo,
        SaveWeather,
        SaveField,
        CheckWeather,
        DebugView,
        Memory,
        Quit
    };
    Kind kind = Kind::Quit;
    std::string where; // "FILE:LINE", for messages
    std::string key;   // Set: the key; Tier, Path: the name; Record: on or off; Paint: the
                       // channel; Screenshot, Capture, Save, SavePath, SaveWeather, SaveField:
                       // the file
    std::string value; // Set: the value text
    float numbers[5] = {};
    int frames = 0; // Wait, Path
};

// A Paint action's stroke.
BrushStroke strokeOf(const ViewAction& action);

// Reads and checks the script; throws cloudscape::Error naming FILE:LINE.
std::vector<ViewAction> loadViewScript(const std::string& path, const Scene& start);

// Applies a Set, Tier, Camera, Move, Turn or Orbit action to the scene, and a Path action's
// last frame; throws cloudscape::Error.
void applyViewAction(Scene& scene, const ViewAction& action);

} // namespace cloudscape::cli
