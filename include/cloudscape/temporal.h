#pragma once
// Temporal reconstruction: each frame marches one pixel in every 4x4 block (1/16 of the pixels)
// and rebuilds the rest from the previous frame by reprojection, the Horizon Zero Dawn scheme. A
// still camera converges to the full-resolution image in 16 frames. Runs on the CPU backend or on
// the Vulkan backend (which keeps its device, textures and history between frames).
#include <cloudscape/backend.h>
#include <cloudscape/renderer.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cloudscape {

// Everything the reconstruction carries from one frame to the next, as it stands after frame
// `frameIndex`: a renderer given it continues the sequence exactly as the one that saved it
// would have (bit for bit on the CPU backend). The history is at the cloud pass size
// (render.cloud_resolution), which can be smaller than the output. The march's jitter is a
// function of the frame index, so the index is its whole state.
struct TemporalState {
    int frameIndex = -1; // the last frame rendered; -1: no history
    float timeS = 0.0f;  // that frame's scene time
    int width = 0;
    int height = 0;
    std::vector<uint8_t> frameParams; // that frame's camera and jitter (the model's FrameParams)
    std::vector<float> cloud;         // 4 per pixel: premultiplied radiance RGB, transmittance
    std::vector<float> depth;         // distance to the first cloud (m)
    std::vector<float> weight;        // marches accumulated in each pixel
    std::vector<float> flash; // the masked lightning flash (its own channel, lightning.glsl.h)
                              // per pixel; empty: none (read as zeros)
    // The moving camera's ring of earlier marches (render.moving_gather_frames; empty: none):
    // the frames' FrameParams by ring position, and their marches as the model's CloudTexel
    // (8 floats), the 2x2 block grid's count a position, followed by the entering ring's
    // records (enteringRingRecords; sample_gather.glsl.h).
    std::vector<uint8_t> gatherFrames;
    std::vector<float> gatherRing;
    bool empty() const { return frameIndex < 0; }
};

// What made each pixel of the last temporal frame, for looking at (the viewer's debug views), at
// the cloud pass's size: where its value came from (the model's TEMPORAL_SOURCE_*) and how many
// density samples its block's march took that frame.
enum class TemporalSource : uint8_t { Marched = 0, Reprojected = 1, Fallback = 2 };
struct TemporalDebugImage {
    int width = 0;
    int height = 0;
    std::vector<TemporalSource> source;
    std::vector<float> samples;
    bool empty() const { return source.empty(); }
};

class TemporalRenderer {
public:
    // On the CPU backend.
    explicit TemporalRenderer(const SceneResources& resources);
    // On the chosen backend. Auto picks as renderScene does (any Vulkan device, else the CPU, and
    // `notice` says why); Vulkan throws cloudscape::Error if the device cannot be opened. The
    // resources must outlive the renderer, and their textures stay as they were (the Vulkan
    // backend uploads them once; both keep a shadow map made from them): a scene whose textures
    // change as it runs renders through cloudscape::Renderer, which is told of every change.
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

    // The state after the last frame (empty before the first), and continuing from one: the
    // next renderFrame(scene, state.frameIndex + 1) uses it as its history. restoreState throws
    // cloudscape::Error for a state whose sizes do not agree.
    TemporalState saveState() const;
    void restoreState(const TemporalState& state);
    // What renders: "cpu" or "vulkan: <device name>", as in RenderStats::backend.
    std::string backendName() const;

    // One backend's implementation (src/core/temporal_impl.h).
    class Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace cloudscape
