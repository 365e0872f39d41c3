#pragma once
// What the full-frame and the temporal renderers share besides the passes: the parameter blocks
// and frame counters every frame uploads and sums into, the readback of only what is asked for,
// and reading the frame's timestamps. Plumbing only.
#include <cloudscape/renderer.h>

#include "model/params.glsl.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <memory>
#include <vector>

namespace cloudscape::vulkan {

// The uniform blocks (CloudParams; FrameParams of the pass, of the previous frame and of the
// output) and the FrameCounters buffer, host-visible for the renderer's life.
struct FrameBlocks {
    explicit FrameBlocks(Context& ctx);
    std::unique_ptr<ResourceSet> set;
    Buffer* cloud = nullptr;
    Buffer* frame = nullptr;
    Buffer* previous = nullptr;
    Buffer* output = nullptr;
    Buffer* counters = nullptr;
};

// The temporal resolve's per-frame values (FrameParams.sequenceFrame, secondsSincePrevious).
struct TemporalStep {
    int sequenceFrame = 0;
    float secondsSincePrevious = 0.0f;
    int temporalBlock = 0; // the frame's temporal block side (temporalBlockFor); 0: the default
    int gatherValid = 0;   // ring positions holding the sequence's frames (gatherValidFor)
};

// Uploads the frame parameters of `scene` (FrameParams for `jitterFrame`, with hasSceneDepth set)
// into `ubo` and its scene depth buffer, if any, into `depth`; returns the parameters.
model::FrameParams uploadFrame(Buffer& ubo, Buffer& depth, const Scene& scene,
                               const SceneResources& resources, int jitterFrame,
                               TemporalStep step = {});

// Copies the composite (Display, All) and the cloud layer and depth (All) of an image of
// `pixels` pixels from their device buffers (vec4, CloudTexel) into `out`.
void readBack(const Context& ctx, const Buffer& composite, const Buffer& cloud, size_t pixels,
              Readback readback, RenderResult& out);

// Milliseconds from the first timestamp of a pool to each of the others; empty if the queue
// has no timestamps or they are not available.
std::vector<double> timestampsMs(const Context& ctx, vk::QueryPool queries, uint32_t count);

} // namespace cloudscape::vulkan
