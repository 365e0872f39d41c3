#pragma once
// The Vulkan renderers' per-pass GPU timestamps summed over frames, and the `--stats` line that
// reports their mean per frame: `render --stats` and `view --stats` print the same breakdown, so
// a window's frame can be taken apart as a sequence's is.
#include <cloudscape/renderer.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace cloudscape::cli {

class GpuPassTimes {
public:
    // A frame's timestamps; frames without them (the CPU backend) are not counted.
    void add(const RenderStats& s) {
        if (s.gpuMarchMs < 0.0)
            return;
        ++frames_;
        const double grid = std::max(s.gpuShaftGridMs, 0.0);
        const double upsample = std::max(s.gpuUpsampleMs, 0.0);
        shadow_ += s.gpuShadowMs;
        background_ += std::max(s.gpuBackgroundMs, 0.0);
        march_ += s.gpuMarchMs;
        grid_ += grid;
        upsample_ += upsample;
        // resolveSeconds is the whole resolve submission, which holds the grid and the upsample.
        resolve_ += 1000.0 * s.resolveSeconds - grid - upsample;
    }

    bool timed() const { return frames_ > 0; }
    // The march's GPU time summed over the timed frames (ms).
    double marchMsTotal() const { return march_; }

    // "gpu per frame: shadow map ... ms, ..." (the means over the timed frames).
    std::string line() const {
        const double n = frames_ > 0 ? double(frames_) : 1.0;
        char text[256];
        std::snprintf(text, sizeof text,
                      "gpu per frame: shadow map %.1f ms, background %.1f ms, march %.1f ms, "
                      "shafts grid %.1f ms, resolve %.1f ms, upsample %.1f ms",
                      shadow_ / n, background_ / n, march_ / n, grid_ / n, resolve_ / n,
                      upsample_ / n);
        return text;
    }

private:
    long frames_ = 0;
    double shadow_ = 0.0, background_ = 0.0, march_ = 0.0, grid_ = 0.0, resolve_ = 0.0,
           upsample_ = 0.0;
};

} // namespace cloudscape::cli
