// Reading and checking the viewer's scripts (view_script.h).
#include "view_script.h"

#include "view_camera.h"
#include "view_debug.h"
#include "view_paint.h"

#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cloudscape::cli {
namespace {

using Kind = ViewAction::Kind;

struct ActionSyntax {
    const char* name;
    Kind kind;
    int arguments;
    const char* usage;
};

constexpr ActionSyntax kActions[] = {
    {"set", Kind::Set, 2, "set KEY VALUE"},
    {"tier", Kind::Tier, 1, "tier NAME"},
    {"camera", Kind::Camera, 5, "camera X Y Z HEADING PITCH"},
    {"move", Kind::Move, 3, "move DX DY DZ"},
    {"turn", Kind::Turn, 2, "turn DHEADING DPITCH"},
    {"wait", Kind::Wait, 1, "wait FRAMES"},
    {"screenshot", Kind::Screenshot, 1, "screenshot FILE.png|FILE.exr"},
    {"capture", Kind::Capture, 1, "capture FILE.png"},
    {"save", Kind::Save, 1, "save FILE.json"},
    {"await-reload", Kind::AwaitReload, 1, "await-reload SECONDS"},
    {"orbit", Kind::Orbit, 3, "orbit DISTANCE DHEADING DPITCH"},
    {"path", Kind::Path, 2, "path NAME FRAMES"},
    {"record", Kind::Record, 1, "record on|off"},
    {"play", Kind::Play, 0, "play"},
    {"save-path", Kind::SavePath, 1, "save-path FILE.json"},
    {"paint", Kind::Paint, 5, "paint CHANNEL X Z RADIUS STRENGTH"},
    {"undo", Kind::Undo, 0, "undo"},
    {"save-weather", Kind::SaveWeather, 1, "save-weather FILE.png"},
    {"save-field", Kind::SaveField, 1, "save-field FILE.png"},
    {"check-weather", Kind::CheckWeather, 0, "check-weather"},
    {"view", Kind::DebugView, 1,
     "view picture|transmittance|depth|weather|shadow-map|density-slice|temporal-source|samples"},
    {"memory", Kind::Memory, 0, "memory"},
    {"quit", Kind::Quit, 0, "quit"},
};

// A user's text in a message, cut short.
std::string quotedText(const std::string& text) {
    return "'" + (text.size() <= 60 ? text : text.substr(0, 60) + "...") + "'";
}

float numberArgument(const std::string& text, const std::string& where, const char* usage) {
    try {
        size_t used = 0;
        const float x = std::stof(text, &used);
        if (used == text.size() && std::isfinite(x))
            return x;
    } catch (const std::exception&) {
    }
    throw Error(where + ": " + quotedText(text) + " is not a number (" + usage + ")");
}

std::string extensionOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

int frameCount(const std::string& text, const std::string& where, const ActionSyntax* syntax) {
    const float n = numberArgument(text, where, syntax->usage);
    if (n != std::floor(n) || n < 0.0f || n > 1e6f)
        throw Error(where + ": " + syntax->name + " " + quotedText(text) +
                    ": expected a whole number of frames in [0, 1000000]");
    return static_cast<int>(n);
}

ViewAction parseLine(const std::vector<std::string>& words, const std::string& where) {
    const ActionSyntax* syntax = nullptr;
    for (const ActionSyntax& s : kActions)
        if (words[0] == s.name)
            syntax = &s;
    if (!syntax)
        throw Error(where + ": unknown action " + quotedText(words[0]) +
                    " (expected set, tier, camera, move, turn, orbit, wait, screenshot, capture, "
                    "save, await-reload, path, record, play, save-path, paint, undo, save-weather, "
                    "save-field, check-weather, view, memory or quit)");
    // set's value may hold spaces ([1, 2, 3]): everything after the key is the value.
    const bool restIsValue = syntax->kind == Kind::Set && words.size() > 3;
    if (static_cast<int>(words.size()) - 1 != syntax->arguments && !restIsValue)
        throw Error(where + ": " + syntax->name + " takes " + std::to_string(syntax->arguments) +
                    " argument" + (syntax->arguments == 1 ? "" : "s") + ", got " +
                    std::to_string(words.size() - 1) + " (" + syntax->usage + ")");
    ViewAction a;
    a.kind = syntax->kind;
    a.where = where;
    switch (a.kind) {
    case Kind::Set:
        a.key = words[1];
        for (size_t i = 2; i < words.size(); ++i)
            a.value += (i > 2 ? " " : "") + words[i];
        break;
    case Kind::Tier:
        a.key = words[1];
        break;
    case Kind::Camera:
    case Kind::Move:
    case Kind::Turn:
    case Kind::Orbit:
        for (int i = 0; i < syntax->arguments; ++i)
            a.numbers[i] = numberArgument(words[static_cast<size_t>(i) + 1], where, syntax->usage);
        break;
    case Kind::Wait:
        a.frames = frameCount(words[1], where, syntax);
        break;
    case Kind::Path:
        a.key = words[1];
        try {
            parseCameraPath(a.key);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        a.frames = frameCount(words[2], where, syntax);
        break;
    case Kind::AwaitReload:
        a.numbers[0] = numberArgument(words[1], where, syntax->usage);
        if (!(a.numbers[0] > 0.0f && a.numbers[0] <= 3600.0f))
            throw Error(where + ": await-reload " + quotedText(words[1]) +
                        ": expected seconds in (0, 3600]");
        break;
    case Kind::Record:
        a.key = words[1];
        if (a.key != "on" && a.key != "off")
            throw Error(where + ": record " + quotedText(a.key) + ": expected on or off");
        break;
    case Kind::Screenshot:
        a.key = words[1];
        if (extensionOf(a.key) != ".png" && extensionOf(a.key) != ".exr")
            throw Error(where + ": screenshot " + quotedText(a.key) +
                        ": expected a .png or .exr file");
        break;
    case Kind::Capture:
        a.key = words[1];
        if (extensionOf(a.key) != ".png")
            throw Error(where + ": capture " + quotedText(a.key) + ": expected a .png file");
        break;
    case Kind::Save:
    case Kind::SavePath:
        a.key = words[1];
        if (extensionOf(a.key) != ".json")
            throw Error(where + ": " + syntax->name + " " + quotedText(a.key) +
                        ": expected a .json file");
        break;
    case Kind::Paint:
        try {
            brushChannel(words[1]);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        a.key = words[1];
        for (int i = 0; i < 4; ++i)
            a.numbers[i] = numberArgument(words[static_cast<size_t>(i) + 2], where, syntax->usage);
        break;
    case Kind::DebugView:
        a.key = words[1];
        try {
            parseDebugView(a.key);
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        break;
    case Kind::SaveWeather:
    case Kind::SaveField:
        a.key = words[1];
        if (extensionOf(a.key) != ".png")
            throw Error(where + ": " + words[0] + " " + quotedText(a.key) +
                        ": expected a .png file");
        break;
    case Kind::Undo:
    case Kind::CheckWeather:
    case Kind::Play:
    case Kind::Memory:
    case Kind::Quit:
        break;
    }
    return a;
}

} // namespace

BrushStroke strokeOf(const ViewAction& a) {
    BrushStroke s;
    s.channel = brushChannel(a.key);
    s.xM = a.numbers[0];
    s.zM = a.numbers[1];
    s.radiusM = a.numbers[2];
    s.strength = a.numbers[3];
    return s;
}

void applyViewAction(Scene& scene, const ViewAction& a) {
    switch (a.kind) {
    case Kind::Set:
        applyOverride(scene, a.key + "=" + a.value, a.where);
        break;
    case Kind::Tier:
        try {
            applyTier(scene, a.key);
        } catch (const Error& e) {
            throw Error(a.where + ": " + e.what());
        }
        break;
    case Kind::Camera:
        scene.cameraPosition = {a.numbers[0], a.numbers[1], a.numbers[2]};
        scene.cameraHeadingDeg = a.numbers[3];
        scene.cameraPitchDeg = a.numbers[4];
        break;
    case Kind::Move:
        scene.cameraPosition += glm::vec3(a.numbers[0], a.numbers[1], a.numbers[2]);
        break;
    case Kind::Turn:
        scene.cameraHeadingDeg += a.numbers[0];
        scene.cameraPitchDeg += a.numbers[1];
        break;
    case Kind::Orbit:
        orbitCamera(scene, a.numbers[0], a.numbers[1], a.numbers[2]);
        break;
    case Kind::Path:
        try { // the paths only move further with each frame: the last is the one to check
            scene = withCamera(scene, cameraOf(sceneOnPath(scene, a.key, a.frames, 24.0f)),
                               scene.timeS);
            scene.cameraHeadingDeg = std::fmod(scene.cameraHeadingDeg, 360.0f); // as played
        } catch (const Error& e) {
            throw Error(a.where + ": " + e.what());
        }
        break;
    default:
        return;
    }
    // The same checks as a scene file: a camera moved below ground is refused here too.
    validateScene(scene, a.where);
    for (const char* key : {"camera.heading_deg", "camera.pitch_deg"}) {
        const KeyRange range = sceneKeyRange(key);
        const double v = std::stod(sceneKeyValue(scene, key));
        if (v < range.min || v > range.max)
            throw Error(a.where + ": " + key + " would be " + sceneKeyValue(scene, key) +
                        ", out of range [" + std::to_string(range.min) + ", " +
                        std::to_string(range.max) + "]");
    }
}

std::vector<ViewAction> loadViewScript(const std::string& path, const Scene& start) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(path + ": is a directory; expected a view script");
    std::ifstream in(path);
    if (!in)
        throw Error(path + ": cannot open the view script");
    std::vector<ViewAction> actions;
    Scene scene = start; // each action is checked against the scene it will change
    bool recording = false;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (number > 100000)
            throw Error(path + ": more than 100000 lines; expected a short list of actions");
        std::istringstream words(line);
        std::vector<std::string> parts;
        for (std::string w; words >> w;)
            parts.push_back(w);
        if (parts.empty() || parts[0][0] == '#')
            continue;
        const std::string where = path + ":" + std::to_string(number);
        ViewAction a = parseLine(parts, where);
        applyViewAction(scene, a);
        if (a.kind == Kind::Record && a.key == "on")
            recording = true;
        if ((a.kind == Kind::Play || a.kind == Kind::SavePath) && !recording)
            throw Error(where + ": " + parts[0] + " before any 'record on': nothing recorded");
        if (a.kind == Kind::Paint)
            checkStroke(scene, strokeOf(a), where);
        if (a.kind == Kind::Screenshot || a.kind == Kind::Capture || a.kind == Kind::Save ||
            a.kind == Kind::SavePath || a.kind == Kind::SaveWeather || a.kind == Kind::SaveField)
            checkOutputWritable(a.key);
        actions.push_back(std::move(a));
    }
    return actions;
}

} // namespace cloudscape::cli
