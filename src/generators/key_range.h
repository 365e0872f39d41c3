#pragma once
// The weather generators' parameter check: the key table's range for a weather.* key
// (cloudscape/scene.h), so a generator called directly refuses what a scene file would.
#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include <sstream>

namespace cloudscape {

// Throws cloudscape::Error "weather parameter KEY = VALUE is out of range [MIN, MAX]".
inline void requireWeatherKeyRange(const char* key, double value) {
    const KeyRange range = sceneKeyRange(key);
    if (!(value >= range.min && value <= range.max)) {
        std::ostringstream s;
        s << "weather parameter " << key << " = " << value << " is out of range [" << range.min
          << ", " << range.max << "]";
        throw Error(s.str());
    }
}

} // namespace cloudscape
