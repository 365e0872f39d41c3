#pragma once
// The textures the model samples, on the device: base, detail and curl noise, the weather map
// (RGBA8 with their whole mip chains) and the blue-noise map, behind one REPEAT / LINEAR /
// LINEAR-mip sampler (the sampler the CPU backend emulates). Uploaded once and kept; the staging
// copies are freed as soon as the upload has completed. Plumbing only.
#include <cloudscape/renderer.h>

#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <memory>

namespace cloudscape::vulkan {

class ModelTextures {
public:
    // Uploads the scene's textures; throws cloudscape::Error if one exceeds the device's limits.
    ModelTextures(Context& ctx, const SceneResources& resources);

    const Image& baseNoise() const { return *base_; }
    const Image& detailNoise() const { return *detail_; }
    const Image& curlNoise() const { return *curl_; }
    const Image& weatherMap() const { return *weather_; }
    const Image& blueNoise() const { return *blue_; }
    vk::Sampler sampler() const { return *sampler_; }

    uint64_t deviceBytes() const { return set_->deviceBytes(); }
    uint64_t textureBytes() const { return set_->textureBytes(); }
    double uploadMs() const { return uploadMs_; } // GPU time of the upload; -1 without timestamps

private:
    std::unique_ptr<ResourceSet> set_;
    vk::UniqueSampler sampler_;
    const Image* base_ = nullptr;
    const Image* detail_ = nullptr;
    const Image* curl_ = nullptr;
    const Image* weather_ = nullptr;
    const Image* blue_ = nullptr;
    double uploadMs_ = -1.0;
};

} // namespace cloudscape::vulkan
