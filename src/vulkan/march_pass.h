#pragma once
// render_clouds.comp (the model's renderPixel) as one object per device, shared by the
// full-frame renderer (src/vulkan/vulkan_still.cpp) and the temporal renderer
// (src/vulkan/vulkan_temporal.cpp): the pipeline built from interface.glsl.h's MARCH_* table,
// descriptor sets for each user, and the tiled dispatches of both modes. Plumbing only.
#include "model/interface.glsl.h"
#include "vulkan/compute_pass.h"
#include "vulkan/model_textures.h"

namespace cloudscape::vulkan {

class MarchPass {
public:
    explicit MarchPass(const Context& ctx);

    vk::DescriptorSet allocateSet() const { return pass_.allocateSet(); }

    // What the march reads and writes besides the textures.
    struct Buffers {
        const Buffer* cloudParams = nullptr;  // CloudParams
        const Buffer* frameParams = nullptr;  // FrameParams
        const Buffer* sceneDepth = nullptr;   // float per pixel, or one float when unused
        const Buffer* outCloud = nullptr;     // CloudTexel per pixel (or per block)
        const Buffer* outComposite = nullptr; // vec4 per pixel (full frames; any in block mode)
        const Buffer* counters = nullptr;     // FrameCounters
        const Buffer* cloudShadow = nullptr;  // the renderer's shadow map (CloudShadowMap)
        // Block mode of a gathering frame: the previous frame's FrameParams and the entering
        // ring (sample_gather.glsl.h); any FrameParams and any CloudTexel buffer otherwise.
        const Buffer* previousFrame = nullptr;
        const Buffer* outEntering = nullptr;
    };
    void bind(const Context& ctx, vk::DescriptorSet set, const ModelTextures& textures,
              const Buffers& buffers) const;

    // Full frames: every pixel of rows [y0, y1) of a width-pixel image, in tiles.
    // `features`: modelFeaturesFor(the frame's CloudParams and camera), the pipeline's
    // specialisation.
    void recordRows(vk::CommandBuffer cmd, vk::DescriptorSet set, int width, int y0, int y1,
                    int features) const;
    // Block mode: one pixel of each of blocksX x blocksY 4x4 blocks, for the temporal frame
    // FrameParams.sequenceFrame.
    void recordBlocks(vk::CommandBuffer cmd, vk::DescriptorSet set, int blocksX, int blocksY,
                      int features) const;

    // Builds block mode's pipeline for `features` now (ComputePass::prepare), so that a frame
    // that asks for it later does not stall on the compile.
    void prepareBlocks(int features) const { pass_.prepare(blockModeFeatures(features)); }

    // Pixels (or blocks) per side of one dispatch; the shaders find a workgroup's place in its tile
    // from this (dispatch_order.glsl).
    static constexpr int kTile = model::MARCH_TILE_WORKGROUPS * model::PASS_WORKGROUP_SIDE;

private:
    // Block mode leaves the composite out: the resolve composites, the march's would be lost.
    static int blockModeFeatures(int features) { return features & ~model::FEATURE_COMPOSITE; }
    void recordTiles(vk::CommandBuffer cmd, vk::DescriptorSet set, int x1, int y0, int y1,
                     bool blockMode, int features) const;

    ComputePass pass_;
};

// Sets a FrameCounters buffer to zero before a frame's passes add to it.
void resetCounters(vk::CommandBuffer cmd, const Buffer& counters);
// Reads a FrameCounters buffer after the frame's submission has completed.
model::FrameCounters readCounters(const Context& ctx, const Buffer& counters);
uint64_t densitySamples(const model::FrameCounters& c);
uint64_t lightSamples(const model::FrameCounters& c);
uint64_t cloudSamples(const model::FrameCounters& c);
uint64_t emptySkips(const model::FrameCounters& c);

// A compute pass over every pixel of a width x height image (8x8 workgroups).
void dispatchImage(vk::CommandBuffer cmd, int width, int height);

} // namespace cloudscape::vulkan
