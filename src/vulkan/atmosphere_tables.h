#pragma once
// The atmosphere's tables made on the device: atmosphere_tables.comp (the model's
// atmosphereTableTexel) dispatched once per table in the model's order (atmosphere.glsl.h's
// ATMOSPHERE_TABLE_*), a barrier after each since each reads those before it, straight into
// ModelTextures' atmosphere buffer, which the march, resolve and upsample sets already bind.
// One per device. Plumbing only: the texels are the model's.
#include "model/atmosphere.glsl.h"
#include "model/params.glsl.h"
#include "vulkan/compute_pass.h"
#include "vulkan/vulkan_resources.h"

#include <glm/vec4.hpp>

#include <array>
#include <vector>

namespace cloudscape::vulkan {

class AtmosphereTables {
public:
    // The pipeline, a buffer for the sky's parameters and the set that binds `tables` (a buffer
    // of ATMOSPHERE_LUT_TEXELS vec4 that outlives this object: ModelTextures::atmosphere()).
    AtmosphereTables(Context& ctx, const Buffer& tables);

    // Makes every table for the sky's atmosphere, sun and moon, and waits for them; waits first
    // for the device to be idle, since the passes that read the buffer may still be running.
    void fill(const model::SkyParams& sky);
    // The buffer's texels (after fill: the tables the device renders with).
    std::vector<glm::vec4> texels() const;

    // GPU time of the last fill (ms), in all and per table; negative without timestamps.
    double gpuMs() const { return gpuMs_; }
    const std::array<double, model::ATMOSPHERE_TABLE_COUNT>& tableMs() const { return tableMs_; }

private:
    void record(vk::CommandBuffer cmd) const;

    Context& ctx_;
    const Buffer& tables_;
    ComputePass pass_;
    ResourceSet resources_;
    Buffer* params_ = nullptr;
    vk::DescriptorSet set_;
    vk::UniqueQueryPool queries_;
    double gpuMs_ = -1.0;
    std::array<double, model::ATMOSPHERE_TABLE_COUNT> tableMs_{};
};

} // namespace cloudscape::vulkan
