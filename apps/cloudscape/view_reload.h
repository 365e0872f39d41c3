#pragma once
// Hot reload: the viewer watches the scene file it opened and, when the file on disk changes
// (its modification time or size), loads it again. A file that does not load (an editor half
// way through writing it, a typo) leaves the scene as it was and says why, once per change.
#include <cstdint>
#include <string>

namespace cloudscape::cli {

class SceneFileWatch {
public:
    explicit SceneFileWatch(std::string path); // empty: nothing watched
    const std::string& path() const { return path_; }
    // True once for each change on disk since the last call (or since markCurrent()).
    bool changed();
    // The file as it is now counts as seen (the viewer wrote it itself).
    void markCurrent();

private:
    struct Stamp {
        bool exists = false;
        int64_t modified = 0; // file clock ticks (libstdc++'s epoch is 2174: negative now)
        int64_t size = -1;
        bool operator==(const Stamp&) const = default;
    };
    Stamp stampNow() const;

    std::string path_;
    Stamp seen_;
};

} // namespace cloudscape::cli
