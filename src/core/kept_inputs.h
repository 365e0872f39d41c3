#pragma once
// A pass's output kept while its inputs stay: the inputs of the last time it was made, compared as
// bytes (the shadow map on both backends, the Vulkan background). Plumbing only.
#include <cstring>
#include <optional>

namespace cloudscape {

// Plain-data inputs compared as bytes (zero them, padding included, before filling them in).
template <class Inputs> class KeptInputs {
public:
    // True when `now` differs from what is kept (or nothing is); from then on `now` is kept.
    bool changed(const Inputs& now) {
        if (holds_ && std::memcmp(&*holds_, &now, sizeof now) == 0)
            return false;
        holds_ = now;
        return true;
    }
    void invalidate() { holds_.reset(); }

private:
    std::optional<Inputs> holds_;
};

} // namespace cloudscape
