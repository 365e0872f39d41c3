#pragma once
// The upsample pass's descriptor set (upsample_clouds.comp, interface.glsl.h's UPSAMPLE_*),
// written in one place for both renderers that bring reduced-resolution clouds up to the output:
// the full-frame renderer (vulkan_still.cpp) and the temporal one (vulkan_temporal.cpp).
// Plumbing only.
#include "vulkan/model_textures.h"
#include "vulkan/vulkan_resources.h"

namespace cloudscape::vulkan {

// What the upsample reads and writes besides the textures.
struct UpsampleBuffers {
    const Buffer* cloudParams = nullptr;    // CloudParams
    const Buffer* frameParams = nullptr;    // FrameParams at the output's size
    const Buffer* inCloud = nullptr;        // CloudTexel per pass pixel
    const Buffer* sceneDepth = nullptr;     // float per output pixel
    const Buffer* outCloud = nullptr;       // CloudTexel per output pixel
    const Buffer* outComposite = nullptr;   // vec4 per output pixel
    const Buffer* cloudShadow = nullptr;    // the renderer's shadow map
    const Buffer* background = nullptr;     // BackgroundLight per output pixel
    const Buffer* backgroundSeen = nullptr; // BackgroundTexel per output pixel
    const Buffer* shafts = nullptr;         // the shafts' grid (one texel when unused)
    const Buffer* groundFallback = nullptr; // the ground fallback's list
    // BackgroundTexel per pass pixel: read only by a moving temporal frame whose background is
    // made at the pass's size (PASS_UPSAMPLED_BACKGROUND); any such buffer otherwise.
    const Buffer* passBackgroundSeen = nullptr;
};

void writeUpsampleSet(const Context& ctx, vk::DescriptorSet set, const ModelTextures& textures,
                      const UpsampleBuffers& buffers);

} // namespace cloudscape::vulkan
