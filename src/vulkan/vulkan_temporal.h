#pragma once
// The temporal reconstruction on a VulkanDevice shared with the rest of a renderer: history and
// per-size buffers live here, the pipelines and textures in the device.
#include <cloudscape/temporal.h>

#include "core/temporal_impl.h"
#include "vulkan/vulkan_device.h"

#include <memory>

namespace cloudscape::vulkan {

// A temporal renderer on `device`, reading `resources` (which must outlive it).
std::unique_ptr<TemporalRenderer::Impl> makeTemporalOn(std::shared_ptr<VulkanDevice> device,
                                                       const SceneResources& resources);

} // namespace cloudscape::vulkan
