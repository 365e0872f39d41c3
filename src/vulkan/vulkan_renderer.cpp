// renderVulkan: one full-frame render on a device opened for it (a persistent Renderer keeps the
// device instead, include/cloudscape/persistent_renderer.h). Plumbing only.
#include <cloudscape/backend.h>

#include "core/resources.h"
#include "vulkan/vulkan_device.h"
#include "vulkan/vulkan_still.h"

namespace cloudscape {

RenderResult renderVulkan(const Scene& scene, const SceneResources& resources,
                          const BackendOptions& options, const ProgressCallback& progress) {
    checkCameraAboveTerrain(scene, resources);
    auto device = std::make_shared<vulkan::VulkanDevice>(options, resources);
    RenderResult out = vulkan::translateVulkanErrors("rendering", [&] {
        vulkan::VulkanStill still(device);
        return still.render(scene, resources, progress, Readback::All);
    });
    out.stats.validationMessages = device->context().takeValidationMessages();
    return out;
}

} // namespace cloudscape
