#include "progress.h"

#include <cstdio>
#include <unistd.h>

namespace cloudscape::cli {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()),
      enabled_(isatty(fileno(stderr)) != 0) {}

void ProgressBar::update(double fraction) {
    if (!enabled_)
        return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < 1.0)
        return;
    const int permille = static_cast<int>(fraction * 1000.0);
    if (permille == lastPermille_)
        return;
    lastPermille_ = permille;
    constexpr int kWidth = 40;
    const int filled = static_cast<int>(fraction * kWidth);
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r%s [%.*s%*s] %5.1f%%  %.0fs elapsed, ~%.0fs left ", label_.c_str(),
                 filled, "########################################", kWidth - filled, "",
                 fraction * 100.0, elapsed, eta);
    std::fflush(stderr);
    shown_ = true;
}

void ProgressBar::finish() {
    if (shown_) {
        std::fprintf(stderr, "\r%*s\r", 100, "");
        std::fflush(stderr);
    }
}

} // namespace cloudscape::cli
