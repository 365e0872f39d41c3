#pragma once
// The textures the model samples, on the device: base, detail and curl noise, the high-altitude
// layer's texture, the weather map
// (RGBA8 with their whole mip chains) and the blue-noise map, behind one REPEAT / LINEAR /
// LINEAR-mip sampler (the sampler the CPU backend emulates). Uploaded once and kept for a
// renderer's life; the noise or the weather map can be replaced alone (a new seed, a new weather
// map), and generation() tells the owners of descriptor sets that sample them to rewrite them.
// Staging copies are freed as soon as an upload has completed. Plumbing only.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/renderer.h>

#include "model/params.glsl.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <glm/vec4.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace cloudscape::vulkan {

class ModelTextures {
public:
    // Uploads the scene's textures; throws cloudscape::Error if one exceeds the device's limits.
    ModelTextures(Context& ctx, const SceneResources& resources);

    // Replace the noise textures or the weather map (waits for the device to be idle first).
    void replaceNoise(const NoiseTextures& noise);
    void replaceWeather(const Texture2D& weather);
    // Copies the texels of `weather` inside the footprints of `rects` (level 0; every level's
    // footprint, weatherFootprint) into the weather image in place, through a staging buffer kept
    // for the next edit: the image and the descriptor sets that sample it stay (no generation).
    void updateWeather(const Texture2D& weather, const std::vector<TexelRect>& rects);
    // The weather image's texels, every level back to back from level 0 (RGBA8).
    std::vector<uint8_t> readWeather() const;
    // Rewrites the atmosphere's tables in place (a fixed-size host-visible storage buffer, so the
    // descriptor sets that read it stay valid); empty tables (the gradient sky) leave zeros.
    void replaceAtmosphere(const std::vector<glm::vec4>& tables);
    // Replaces the terrain's height field (a new host-visible storage buffer of its size; one
    // zero float when there is no terrain, since a binding needs a buffer).
    void replaceTerrain(const std::vector<float>& heights);

    const Image& baseNoise() const { return *base_; }
    const Image& detailNoise() const { return *detail_; }
    const Image& curlNoise() const { return *curl_; }
    const Image& weatherMap() const { return *weather_; }
    const Image& highClouds() const { return *highClouds_; }
    const Image& blueNoise() const { return *blue_; }
    vk::Sampler sampler() const { return *sampler_; }
    const Buffer& atmosphere() const { return *atmosphere_; }
    const Buffer& terrain() const { return *terrain_; }
    // The base noise's clearance field (NoiseTextures::baseClearance; one zero when empty or
    // beyond the device's texel-buffer limit, and then the march must not read it).
    const Buffer& noiseClearance() const { return *clearance_; }
    void restrictToBound(model::CloudParams& p) const {
        if (!clearanceBound_)
            p.noiseClearanceSize = 0;
    }
    uint64_t generation() const { return generation_; } // changes with every replacement
    // Changes with every change of what the textures hold: a replacement or an edit in place.
    uint64_t contentVersion() const { return contentVersion_; }
    // Changes with what the background behind the clouds reads: the terrain and the air's tables.
    uint64_t backgroundVersion() const { return backgroundVersion_; }

    uint64_t deviceBytes() const;
    uint64_t textureBytes() const;
    double uploadMs() const { return uploadMs_; } // GPU time of the last upload; -1 untimed

private:
    // Uploads with timestamps around the copies; `record` adds the images to `set`.
    void upload(ResourceSet& set, const std::function<void(vk::CommandBuffer)>& record);

    Context& ctx_;
    vk::UniqueSampler sampler_;
    std::unique_ptr<ResourceSet> noise_, weatherSet_, blueSet_, atmosphereSet_, terrainSet_;
    std::unique_ptr<ResourceSet> editSet_; // the edits' staging buffer, grown as needed
    Buffer* editStaging_ = nullptr;
    uint32_t weatherWidth_ = 0, weatherHeight_ = 0, weatherLevels_ = 0;
    Buffer* atmosphere_ = nullptr;
    Buffer* terrain_ = nullptr;
    Buffer* clearance_ = nullptr; // in noise_'s set
    bool clearanceBound_ = false;
    const Image* base_ = nullptr;
    const Image* detail_ = nullptr;
    const Image* curl_ = nullptr;
    const Image* weather_ = nullptr;
    const Image* highClouds_ = nullptr;
    const Image* blue_ = nullptr;
    uint64_t generation_ = 0;
    uint64_t contentVersion_ = 0;
    uint64_t backgroundVersion_ = 0;
    double uploadMs_ = -1.0;
};

} // namespace cloudscape::vulkan
