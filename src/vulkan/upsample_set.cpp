#include "vulkan/upsample_set.h"

#include "model/interface.glsl.h"
#include "vulkan/compute_pass.h"

namespace cloudscape::vulkan {

void writeUpsampleSet(const Context& ctx, vk::DescriptorSet set, const ModelTextures& textures,
                      const UpsampleBuffers& b) {
    const vk::Sampler sampler = textures.sampler();
    DescriptorWriter(model::UPSAMPLE_PASS, set)
        .buffer(model::UPSAMPLE_CLOUD_PARAMS, *b.cloudParams)
        .buffer(model::UPSAMPLE_FRAME_PARAMS, *b.frameParams)
        .buffer(model::UPSAMPLE_IN_CLOUD, *b.inCloud)
        .buffer(model::UPSAMPLE_SCENE_DEPTH, *b.sceneDepth)
        .buffer(model::UPSAMPLE_OUT_CLOUD, *b.outCloud)
        .buffer(model::UPSAMPLE_OUT_COMPOSITE, *b.outComposite)
        .buffer(model::UPSAMPLE_ATMOSPHERE, textures.atmosphere())
        .buffer(model::UPSAMPLE_TERRAIN, textures.terrain())
        .buffer(model::UPSAMPLE_CLOUD_SHADOW, *b.cloudShadow)
        .buffer(model::UPSAMPLE_BACKGROUND, *b.background)
        .buffer(model::UPSAMPLE_BACKGROUND_SEEN, *b.backgroundSeen)
        .buffer(model::UPSAMPLE_SHAFTS, *b.shafts)
        .buffer(model::UPSAMPLE_GROUND_FALLBACK, *b.groundFallback)
        .buffer(model::UPSAMPLE_PASS_BACKGROUND_SEEN, *b.passBackgroundSeen)
        .image(model::UPSAMPLE_BASE_NOISE, sampler, textures.baseNoise())
        .image(model::UPSAMPLE_WEATHER_MAP, sampler, textures.weatherMap())
        .image(model::UPSAMPLE_HIGH_CLOUDS, sampler, textures.highClouds())
        .commit(ctx.device);
}

} // namespace cloudscape::vulkan
