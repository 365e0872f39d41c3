#pragma once
// Temporal reconstruction: each frame marches one pixel in every 4x4 block (1/16 of the pixels)
// and rebuilds the rest from the previous frame by reprojection, the Horizon Zero Dawn scheme. A
// still camera converges to the full-resolution image in 16 frames. Runs on the CPU backend or on
// the Vulkan backend (which keeps its device, textures and history between frames).
#include <cloudscape/backend.h>
#include <cloudscape/renderer.h>

#include <memory>
#include <string>

namespace cloudscape {

class TemporalRenderer {
public:
    // On the CPU backend.
    explicit TemporalRenderer(const SceneResources& resources);
    // On the chosen backend. Auto picks as renderScene does (any Vulkan device, else the CPU, and
    // `notice` says why); Vulkan throws cloudscape::Error if the device cannot be opened. The
    // resources must outlive the renderer.
    TemporalRenderer(const SceneResources& resources, const BackendOptions& options,
                     std::string* notice = nullptr);
    ~TemporalRenderer();
    TemporalRenderer(const TemporalRenderer&) = delete;
    TemporalRenderer& operator=(const TemporalRenderer&) = delete;

    // Frame `frameIndex` of a sequence; the scene carries this frame's camera and time. The
    // history is used when the previous call was frame frameIndex - 1 at the same size.
    RenderResult renderFrame(const Scene& scene, int frameIndex, Readback readback = Readback::All);

    // Fraction of the last frame's pixels that were marched / reprojected / fell back.
    struct Breakdown {
        double marched = 0.0;
        double reprojected = 0.0;
        double fallback = 0.0;
    };
    Breakdown lastBreakdown() const;

    // One backend's implementation (src/core/temporal_impl.h).
    class Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace cloudscape
