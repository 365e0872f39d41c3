// Keyframe files: parsed with the scene reader's limits, every value checked by the key table,
// and interpolated per key track (include/cloudscape/keyframes.h).
#include <cloudscape/error.h>
#include <cloudscape/keyframes.h>

#include "io/scene_keys.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cloudscape {

using io::SceneKeyKind;

namespace {

// A time-lapse needs tens of keyframes; the cap bounds the up-front cross-key checks (one per
// keyframe) of a hostile file.
constexpr size_t kMaxKeyframes = 10000;

// Keys a sequence has one value of: its image size and mode (the temporal history, the memory
// check and the frame files are sized once), and files, which would be read mid-sequence. time_s
// is the sequence's clock itself (the scene's time_s + frame / fps).
constexpr const char* kFixedKeys[] = {
    "render.width",      "render.height", "render.temporal",     "render.cloud_resolution",
    "render.depth_file", "weather.image", "weather.field_image", "time_s"};

struct Track {
    std::string key;
    SceneKeyKind kind = SceneKeyKind::Number;
    std::vector<double> times;          // increasing
    std::vector<nlohmann::json> values; // each checked by the key table
};

std::string exactNumber(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

// a + (b - a) u, kept between a and b (rounding must not step outside a validated range).
double lerp(double a, double b, double u) {
    const double v = a + (b - a) * u;
    return std::clamp(v, std::min(a, b), std::max(a, b));
}

nlohmann::json interpolate(const Track& t, size_t i, double u) {
    const nlohmann::json& a = t.values[i];
    const nlohmann::json& b = t.values[i + 1];
    switch (t.kind) {
    case SceneKeyKind::Number:
        return lerp(a.get<double>(), b.get<double>(), u);
    case SceneKeyKind::Integer:
        return std::round(lerp(a.get<double>(), b.get<double>(), u));
    case SceneKeyKind::Vector3: {
        nlohmann::json v = nlohmann::json::array();
        for (size_t c = 0; c < 3; ++c)
            v.push_back(lerp(a[c].get<double>(), b[c].get<double>(), u));
        return v;
    }
    default:
        return a; // booleans, strings and choices step
    }
}

nlohmann::json valueAt(const Track& t, double time) {
    if (!(time > t.times.front())) // also NaN
        return t.values.front();
    if (time >= t.times.back())
        return t.values.back();
    const size_t i = static_cast<size_t>(std::upper_bound(t.times.begin(), t.times.end(), time) -
                                         t.times.begin()) -
                     1;
    return interpolate(t, i, (time - t.times[i]) / (t.times[i + 1] - t.times[i]));
}

class Parser {
public:
    explicit Parser(const std::string& source) : source_(source) {}

    std::vector<Track> parse(const std::string& jsonText) {
        const nlohmann::json root = io::parseCheckedJson(jsonText, source_);
        const std::string shape =
            "expected {\"keyframes\": [{\"time_s\": seconds, \"set\": {key: value, ...}}, ...]}";
        if (!root.is_object())
            throw Error(source_ + ": " + shape + ", got " + io::jsonTypeForMessage(root));
        for (auto it = root.begin(); it != root.end(); ++it)
            if (it.key() != "keyframes")
                throw Error(source_ + ": unknown member '" + io::shortenedForMessage(it.key()) +
                            "'; " + shape);
        const auto list = root.find("keyframes");
        if (list == root.end() || !list->is_array() || list->empty())
            throw Error(source_ + ": " + shape + " with at least one keyframe");
        if (list->size() > kMaxKeyframes)
            throw Error(source_ + ": " + std::to_string(list->size()) + " keyframes; at most " +
                        std::to_string(kMaxKeyframes));
        for (size_t i = 0; i < list->size(); ++i)
            parseKeyframe((*list)[i], i);
        return std::move(tracks_);
    }

    const std::vector<double>& times() const { return times_; }

private:
    std::string at(size_t i) const { return source_ + ": keyframes[" + std::to_string(i) + "]"; }

    void parseKeyframe(const nlohmann::json& frame, size_t i) {
        const std::string where = at(i);
        if (!frame.is_object())
            throw Error(where + ": expected an object {\"time_s\": seconds, \"set\": {...}}, got " +
                        io::jsonTypeForMessage(frame));
        for (auto it = frame.begin(); it != frame.end(); ++it)
            if (it.key() != "time_s" && it.key() != "set")
                throw Error(where + ": unknown member '" + io::shortenedForMessage(it.key()) +
                            "' (expected time_s and set)");
        const double time = parseTime(frame, i);
        const auto set = frame.find("set");
        if (set == frame.end() || !set->is_object())
            throw Error(where + ": expected \"set\": an object of scene keys" +
                        (set == frame.end() ? "" : ", got " + io::jsonTypeForMessage(*set)));
        times_.push_back(time);
        addKeys(*set, "", time, where);
    }

    double parseTime(const nlohmann::json& frame, size_t i) {
        const auto it = frame.find("time_s");
        if (it == frame.end() || !it->is_number())
            throw Error(
                at(i) + ": time_s expects a number of seconds" +
                (it == frame.end() ? " (missing)" : ", got " + io::jsonTypeForMessage(*it)));
        const double t = it->get<double>();
        const KeyRange range = sceneKeyRange("time_s");
        if (!(t >= range.min && t <= range.max))
            throw Error(at(i) + ": time_s = " + io::numberForMessage(t) + " is out of range [" +
                        io::numberForMessage(range.min) + ", " + io::numberForMessage(range.max) +
                        "]");
        if (!times_.empty() && !(t > times_.back()))
            throw Error(at(i) + ": time_s = " + io::numberForMessage(t) +
                        (t == times_.back() ? " repeats" : " comes before") + " keyframes[" +
                        std::to_string(i - 1) + "]'s " + io::numberForMessage(times_.back()) +
                        "; times must increase");
        return t;
    }

    // The keys of a set, dotted ("weather.coverage") or nested ({"weather": {"coverage": ..}}).
    void addKeys(const nlohmann::json& object, const std::string& prefix, double time,
                 const std::string& where) {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
            if (it.value().is_object())
                addKeys(it.value(), key, time, where);
            else
                addKey(key, it.value(), time, where);
        }
    }

    void addKey(const std::string& key, const nlohmann::json& value, double time,
                const std::string& where) {
        const std::optional<SceneKeyKind> kind = io::sceneKeyKind(key);
        if (!kind)
            throw Error(where + ": unknown key '" + io::shortenedForMessage(key) +
                        "' (see docs/SCENE.md)");
        if (std::find(std::begin(kFixedKeys), std::end(kFixedKeys), key) != std::end(kFixedKeys))
            throw Error(where + ": " + key +
                        " cannot be animated (a sequence has one image size, temporal mode, "
                        "clock and set of files)");
        Scene scratch;
        io::assignSceneKey(scratch, key, value, where); // type and range, as in a scene file
        auto track = std::find_if(tracks_.begin(), tracks_.end(),
                                  [&](const Track& t) { return t.key == key; });
        if (track == tracks_.end()) {
            tracks_.push_back({key, *kind, {}, {}});
            track = tracks_.end() - 1;
        } else if (track->times.back() == time) {
            throw Error(where + ": " + key + " is set twice");
        }
        track->times.push_back(time);
        track->values.push_back(value);
    }

    std::string source_;
    std::vector<Track> tracks_;
    std::vector<double> times_;
};

std::string fingerprintOf(const std::vector<Track>& tracks) {
    std::string text;
    for (const Track& t : tracks) {
        text += t.key;
        for (size_t i = 0; i < t.times.size(); ++i)
            text.append(" ").append(exactNumber(t.times[i])).append(":").append(t.values[i].dump());
        text += '\n';
    }
    return text;
}

} // namespace

struct Keyframes::Data {
    std::vector<Track> tracks;
    int keyframes = 0;
    std::string fingerprint;
};

Keyframes::Keyframes() : data_(std::make_shared<const Data>()) {}
Keyframes::~Keyframes() = default;
Keyframes::Keyframes(const Keyframes&) = default;
Keyframes& Keyframes::operator=(const Keyframes&) = default;

bool Keyframes::empty() const {
    return data_->keyframes == 0;
}

int Keyframes::keyframeCount() const {
    return data_->keyframes;
}

std::vector<std::string> Keyframes::animatedKeys() const {
    std::vector<std::string> keys;
    for (const Track& t : data_->tracks)
        keys.push_back(t.key);
    return keys;
}

Scene Keyframes::sceneAt(const Scene& base, double sequenceTimeS) const {
    Scene scene = base;
    for (const Track& t : data_->tracks)
        io::assignSceneKey(scene, t.key, valueAt(t, sequenceTimeS), "keyframes");
    return scene;
}

const std::string& Keyframes::fingerprintText() const {
    return data_->fingerprint;
}

Keyframes parseKeyframes(const std::string& jsonText, const std::string& source,
                         const Scene& base) {
    Parser parser(source);
    auto data = std::make_shared<Keyframes::Data>();
    data->tracks = parser.parse(jsonText);
    std::sort(data->tracks.begin(), data->tracks.end(),
              [](const Track& a, const Track& b) { return a.key < b.key; });
    data->keyframes = static_cast<int>(parser.times().size());
    data->fingerprint = fingerprintOf(data->tracks);
    Keyframes keyframes;
    keyframes.data_ = data;
    // Every track is linear or constant between keyframe times and the cross-key rules are
    // linear inequalities, so a scene valid at every keyframe is valid at every time between.
    for (size_t i = 0; i < parser.times().size(); ++i) {
        const double t = parser.times()[i];
        validateScene(keyframes.sceneAt(base, t), source + ": keyframes[" + std::to_string(i) +
                                                      "] (time_s = " + io::numberForMessage(t) +
                                                      ")");
    }
    return keyframes;
}

std::string keyframeDocumentationMarkdown() {
    std::string fixed;
    for (const char* key : kFixedKeys)
        fixed.append(fixed.empty() ? "" : ", ").append("`").append(key).append("`");
    return R"(
## The sun from a place and a time

With `sun.from_time=true` the sun stands where it does at `sun.latitude_deg` on
`sun.day_of_year` at `sun.local_solar_time_h` (Spencer's declination, the hour angle, no
refraction; include/cloudscape/solar_position.h), and `sun.elevation_deg`/`sun.heading_deg` are
ignored, whatever order the keys were set in. Local *solar* time: 12 is when the sun is highest.
For example `--set sun.from_time=true --set sun.latitude_deg=52 --set sun.day_of_year=172
--set sun.local_solar_time_h=12` puts the sun 61.4 deg up, due south. The sun may be below the
horizon (down to -90 deg): with the atmosphere (`sky.model` "atmosphere", the default) the
planet's shadow leaves the low clouds first while the tops stay lit, red, until the sun is about
4 deg down, and the sky darkens through twilight to night: black unless `moon.enabled` puts a
moon up (it lights the sky and, once it outshines the sun's last light on the layer, the clouds)
or `sky.night_radiance` gives the night sky its own faint light (the `night` preset has both and
an exposure of 6e4: moonlight is 2.4e-6 of sunlight). The placeholder
`gradient` sky keeps its daylight colours and lights the clouds as if through the planet.

## Keyframes

`render --frames A:B --keyframes FILE` (and `bench --keyframes FILE`) animates scene keys over a
sequence. The file is JSON:

```json
{"keyframes": [
    {"time_s": 0,  "set": {"sun.from_time": true, "sun.local_solar_time_h": 3.5,
                           "weather.coverage": 0.3}},
    {"time_s": 30, "set": {"sun": {"local_solar_time_h": 12}, "weather": {"coverage": 0.5}}},
    {"time_s": 60, "set": {"sun.local_solar_time_h": 20.5, "weather.coverage": 0.35}}]}
```

A dawn-to-dusk time-lapse of a June day at 47 N, one minute at 24 frames a second:

```sh
build/cloudscape render --frames 0:1439 --fps 24 -o lapse/%04d.png     --keyframes scenes/keyframes/dawn-to-dusk.json
```

- `time_s` is seconds of the sequence's own clock: frame f is at f / fps (the scene's `time_s`
  still drives the wind). Times must increase from one keyframe to the next.
- `set` holds scene keys, dotted or nested as in a scene file. Each key is a track of the
  keyframes that set it: numbers interpolate linearly (integers rounded to the nearest), arrays
  per component, booleans, strings and choices step (a value holds until the next keyframe that
  sets the key). Before a key's first keyframe and after its last, the value there holds. Keys no
  keyframe sets keep the scene's (file, `--tier`, `--set`) values. Angles and times do not wrap:
  23 h to 1 h runs backwards through the day.
- Every value is checked by the key table as in a scene file, and the cross-key rules at every
  keyframe (the tracks are linear in between, so that covers every frame). Not animatable: )" +
           fixed + R"( (a sequence has one image size, temporal mode, clock and set of files).
- The keyframes are part of a sequence checkpoint's fingerprint: a rerun with other keyframes
  refuses to resume (`--force` starts over).
- The temporal path keeps still pixels' history, so the image follows keyed changes with a lag:
  a still pixel is marched every 16 frames and blended in with weight 1 /
  `render.temporal_accumulation` (8), a time constant of about 8 x 16 = 128 frames; with 1 the
  lag is at most 16 frames. A time-lapse can set it to 1 in its first keyframe, as the example
  does (docs/ARCHITECTURE.md, "Keyframes", has the measured difference).
)";
}

Keyframes loadKeyframes(const std::string& path, const Scene& base) {
    return parseKeyframes(io::readJsonInputFile(path, "keyframe file"), path, base);
}

} // namespace cloudscape
