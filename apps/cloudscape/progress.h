#pragma once
// A progress bar on stderr, shown only on a terminal and only once a task has run for more
// than a second, so quick runs and pipes stay quiet.
#include <chrono>
#include <string>

namespace cloudscape::cli {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    void update(double fraction); // thread-compatible: callers serialise
    void finish();

private:
    std::string label_;
    std::chrono::steady_clock::time_point start_;
    bool enabled_;
    bool shown_ = false;
    int lastPermille_ = -1;
};

} // namespace cloudscape::cli
