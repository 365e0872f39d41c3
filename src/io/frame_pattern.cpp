// Frame-name patterns, parsed by hand so a user's string is never a printf format.
#include <cloudscape/error.h>
#include <cloudscape/frame_pattern.h>

namespace cloudscape {
namespace {

constexpr int kMaxWidth = 9; // enough digits for any frame number the CLI accepts

[[noreturn]] void refuse(const std::string& pattern, const std::string& why) {
    throw Error("output name '" + pattern + "': " + why +
                "; a frame sequence needs exactly one %d or %0Nd (N from 1 to " +
                std::to_string(kMaxWidth) + "), and %% for a literal %");
}

} // namespace

FramePattern::FramePattern(const std::string& pattern) {
    bool found = false;
    std::string* out = &prefix_;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            *out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            *out += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        int width = 0;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            while (j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9' &&
                   width <= kMaxWidth)
                width = width * 10 + (pattern[j++] - '0');
            if (width < 1 || width > kMaxWidth)
                refuse(pattern, "the width after %0 must be 1 to " + std::to_string(kMaxWidth));
        }
        if (j >= pattern.size() || pattern[j] != 'd')
            refuse(pattern, "'%" + pattern.substr(i + 1, j - i) + "' is not a frame number");
        if (found)
            refuse(pattern, "more than one frame number");
        found = true;
        width_ = width;
        out = &suffix_;
        i = j;
    }
    if (!found)
        refuse(pattern, "no frame number");
}

std::string FramePattern::path(int frame) const {
    if (frame < 0)
        throw Error("frame " + std::to_string(frame) + ": frame numbers start at 0");
    std::string digits = std::to_string(frame);
    if (static_cast<int>(digits.size()) < width_)
        digits.insert(0, static_cast<size_t>(width_) - digits.size(), '0');
    return prefix_ + digits + suffix_;
}

} // namespace cloudscape
