#pragma once
// Output names of frame sequences: "frames/%04d.png" -> "frames/0007.png". The pattern is a
// user's string, so it is parsed here and never handed to printf: exactly one %d or %0Nd
// (N from 1 to 9) is the frame number, "%%" is a literal percent sign, and anything else after
// a '%' is an error that names the pattern.
#include <string>

namespace cloudscape {

class FramePattern {
public:
    // Throws cloudscape::Error naming the pattern and what was expected.
    explicit FramePattern(const std::string& pattern);

    // The file name of a frame (frame >= 0); the number is zero-padded to the pattern's width.
    std::string path(int frame) const;

private:
    std::string prefix_;
    std::string suffix_;
    int width_ = 0; // 0: no padding
};

} // namespace cloudscape
