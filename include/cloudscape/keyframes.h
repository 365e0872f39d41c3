#pragma once
// Key animation for frame sequences (`render --frames --keyframes FILE`, `bench --keyframes`):
// scene keys set at keyframe times and interpolated in between, so that a time-lapse (the sun
// from dawn to dusk, the coverage building up) is one command. A keyframe file is JSON:
//
//   {"keyframes": [
//       {"time_s": 0,  "set": {"sun.local_solar_time_h": 5.5, "weather.coverage": 0.3}},
//       {"time_s": 60, "set": {"sun.local_solar_time_h": 19, "weather": {"coverage": 0.6}}}]}
//
// Times are seconds of the sequence's own clock: frame f is at f / fps, whatever the scene's
// time_s (which keeps driving the wind). Each key is a track of the keyframes that set it:
// numbers interpolate linearly (integers rounded to the nearest), 3-vectors per component,
// booleans, strings and choices step (a keyframe's value holds until the next one that sets the
// key); before a key's first keyframe and after its last, its value there holds. Keys are
// checked by the scene key table exactly as in scene files and --set; the image size, the
// temporal switch, the cloud resolution and file paths are refused (a sequence has one of
// each). The frame's scene is the base scene (file, --tier, --set) with the tracks applied,
// then moved along the camera path.
#include <cloudscape/scene.h>

#include <memory>
#include <string>
#include <vector>

namespace cloudscape {

class Keyframes {
public:
    Keyframes(); // none: sceneAt is the base scene
    ~Keyframes();
    Keyframes(const Keyframes&);
    Keyframes& operator=(const Keyframes&);

    bool empty() const;
    int keyframeCount() const;
    // The keys the file animates, sorted by name.
    std::vector<std::string> animatedKeys() const;

    // `base` with every track's value at `sequenceTimeS` (seconds since frame 0). Values lie
    // between two validated keyframes', so the keys stay in range and, for a base that passed
    // the load's cross-key check, the scene stays valid.
    Scene sceneAt(const Scene& base, double sequenceTimeS) const;

    // Every track with its exact times and values, one line each: equal texts animate equally
    // (part of a sequence checkpoint's fingerprint).
    const std::string& fingerprintText() const;

    struct Data; // the tracks (keyframes.cpp)

private:
    std::shared_ptr<const Data> data_;
    friend Keyframes parseKeyframes(const std::string&, const std::string&, const Scene&);
};

// Parses a keyframe file's text. Every problem is a one-line cloudscape::Error naming `source`
// and, where it has one, the keyframe (keyframes[i], counted from 0) and the key: malformed or
// too deeply nested JSON, duplicate keys, unknown members, no keyframes or more than 10000, a
// time that is missing, negative, beyond time_s's range or not after the previous keyframe's,
// an unknown key, a wrong type, a value out of range, a key that cannot be animated, and a
// cross-key rule (validateScene) broken by the base scene with the tracks at some keyframe.
Keyframes parseKeyframes(const std::string& jsonText, const std::string& source, const Scene& base);
// Reads the file (refused if it is a directory or over 16 MiB, as scene files) and parses it.
Keyframes loadKeyframes(const std::string& path, const Scene& base);

// The sections of docs/SCENE.md on the sun from a place and a time, and on keyframe files.
std::string keyframeDocumentationMarkdown();

} // namespace cloudscape
