#pragma once
// Everything the Vulkan backend keeps for a renderer's life on one device: the context, the
// model's textures, and one pipeline per pass (the march shared by the full-frame and the
// temporal renderers, the temporal resolve, the upsample of reduced-resolution clouds, the
// clouds' shadow map, the atmosphere's tables). Built once; renders on it reuse it all. Plumbing
// only.
#include <cloudscape/backend.h>
#include <cloudscape/renderer.h>

#include "vulkan/atmosphere_tables.h"
#include "vulkan/compute_pass.h"
#include "vulkan/march_pass.h"
#include "vulkan/model_textures.h"
#include "vulkan/vulkan_context.h"

#include <memory>

namespace cloudscape::vulkan {

class VulkanDevice {
public:
    // Opens the device and uploads the textures; throws cloudscape::Error with what failed.
    VulkanDevice(const BackendOptions& options, const SceneResources& resources);
    ~VulkanDevice();
    VulkanDevice(const VulkanDevice&) = delete;
    VulkanDevice& operator=(const VulkanDevice&) = delete;

    Context& context() { return ctx_; }
    const Context& context() const { return ctx_; }
    ModelTextures& textures() { return *textures_; }
    const MarchPass& march() const { return *march_; }
    const ComputePass& resolve() const { return *resolve_; }
    const ComputePass& upsample() const { return *upsample_; }
    const ComputePass& cloudShadow() const { return *cloudShadow_; }
    // Makes the atmosphere's tables in textures().atmosphere() on the device; its pipeline is
    // built on first use, so a device that is handed host-made tables never compiles it.
    AtmosphereTables& atmosphereTables();
    std::string deviceName() const { return ctx_.properties.deviceName.data(); }
    // BackendOptions::interactive: build a moving camera's pipelines before the camera moves.
    bool interactive() const { return interactive_; }

private:
    Context ctx_; // first, so it is destroyed last
    bool interactive_ = false;
    std::unique_ptr<MarchPass> march_;
    std::unique_ptr<ComputePass> resolve_;
    std::unique_ptr<ComputePass> upsample_;
    std::unique_ptr<ComputePass> cloudShadow_;
    std::unique_ptr<ModelTextures> textures_;
    std::unique_ptr<AtmosphereTables> atmosphereTables_; // writes into textures_' buffer
};

// Checks that an image's per-pixel buffers fit the device; throws cloudscape::Error naming the
// size and the limit.
void checkImageSize(const Context& ctx, int width, int height);

// Checks, before they are allocated, that a width x height render's host-visible buffers
// (`bytes` in all) fit the memory heap they come from (requireDeviceMemory).
void checkDeviceMemory(const Context& ctx, int width, int height, uint64_t bytes);

} // namespace cloudscape::vulkan
