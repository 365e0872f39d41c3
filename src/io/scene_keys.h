#pragma once
// The key table's checks for other readers of scene keys inside the library (the keyframe
// files of keyframes.cpp): the same parser limits, the same type and range checks and the same
// messages as scene files and --set, so a key is validated one way wherever it is given.
#include <cloudscape/scene.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cloudscape::io {

enum class SceneKeyKind { Integer, Number, Boolean, String, Vector3, Choice };

// The kind of a key of the table; nullopt for a key that is not in it.
std::optional<SceneKeyKind> sceneKeyKind(const std::string& key);

// Sets `key` from a JSON value with the table's type and range checks; `where` prefixes every
// message ("FILE: keyframes[2]"). Throws cloudscape::Error (also for an unknown key).
void assignSceneKey(Scene& scene, const std::string& key, const nlohmann::json& value,
                    const std::string& where);

// The text of a JSON input file, refused before reading if it is a directory or larger than
// scene files may be (16 MiB); `kind` names it in messages ("keyframe file").
std::string readJsonInputFile(const std::string& path, const std::string& kind);

// Parses JSON as scene files are parsed: nesting deeper than 16 levels and duplicate keys are
// refused while parsing, and every failure is a one-line cloudscape::Error naming `source`.
nlohmann::json parseCheckedJson(const std::string& text, const std::string& source);

// A user's text cut for a message, and a number as messages print it.
std::string shortenedForMessage(const std::string& text);
std::string numberForMessage(double value);
std::string jsonTypeForMessage(const nlohmann::json& value); // "a string", "an array of 2"

} // namespace cloudscape::io
