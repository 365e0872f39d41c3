#pragma once
// Temporal reconstruction on the CPU backend: each frame marches one pixel in every 4x4 block
// (1/16 of the pixels) and rebuilds the rest from the previous frame by reprojection, the
// Horizon Zero Dawn scheme. A still camera converges to the full-resolution image in 16 frames.
#include <cloudscape/renderer.h>

#include <memory>

namespace cloudscape {

class TemporalRenderer {
public:
    explicit TemporalRenderer(const SceneResources& resources);
    ~TemporalRenderer();
    TemporalRenderer(const TemporalRenderer&) = delete;
    TemporalRenderer& operator=(const TemporalRenderer&) = delete;

    // Frame `frameIndex` of a sequence; the scene carries this frame's camera and time. The
    // history is used when the previous call was frame frameIndex - 1 at the same size.
    RenderResult renderFrame(const Scene& scene, int frameIndex);

    // Fraction of the last frame's pixels that were marched / reprojected / fell back.
    struct Breakdown {
        double marched = 0.0;
        double reprojected = 0.0;
        double fallback = 0.0;
    };
    Breakdown lastBreakdown() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace cloudscape
