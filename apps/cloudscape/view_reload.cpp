// Watching the scene file (view_reload.h).
#include "view_reload.h"

#include <filesystem>

namespace cloudscape::cli {

SceneFileWatch::SceneFileWatch(std::string path) : path_(std::move(path)) {
    markCurrent();
}

SceneFileWatch::Stamp SceneFileWatch::stampNow() const {
    Stamp s;
    if (path_.empty())
        return s;
    std::error_code ec;
    const auto modified = std::filesystem::last_write_time(path_, ec);
    if (ec)
        return s; // gone for now (an editor replacing it): no change until it is back
    const auto size = std::filesystem::file_size(path_, ec);
    s.exists = true;
    s.modified = static_cast<int64_t>(modified.time_since_epoch().count());
    s.size = ec ? -1 : static_cast<int64_t>(size);
    return s;
}

bool SceneFileWatch::changed() {
    const Stamp now = stampNow();
    if (!now.exists || now == seen_)
        return false;
    seen_ = now;
    return true;
}

void SceneFileWatch::markCurrent() {
    seen_ = stampNow();
}

} // namespace cloudscape::cli
