// Backend choice: parsing, device listing and the Auto fallback order, for single renders and for
// the temporal renderer.
#include <cloudscape/backend.h>
#include <cloudscape/error.h>
#include <cloudscape/temporal.h>

#include "core/renderer_backend.h"
#include "core/temporal_impl.h"
#include "vulkan/vulkan_context.h"

namespace cloudscape {

// Auto: any Vulkan device beats the CPU backend; only a missing loader or device falls back, and
// `notice` says which.
bool autoChoosesVulkan(std::string* notice) {
    bool haveDevice = false;
    try {
        haveDevice = !listVulkanDevices().empty();
    } catch (const Error& e) {
        if (notice)
            *notice = std::string("Vulkan unavailable (") + e.what() + "); using the CPU backend";
    }
    if (!haveDevice && notice && notice->empty())
        *notice = "no Vulkan device; using the CPU backend";
    return haveDevice;
}

BackendChoice parseBackendChoice(const std::string& text) {
    if (text == "auto")
        return BackendChoice::Auto;
    if (text == "cpu")
        return BackendChoice::Cpu;
    if (text == "vulkan")
        return BackendChoice::Vulkan;
    throw Error("--backend '" + text + "': expected auto, cpu or vulkan");
}

std::vector<VulkanDeviceInfo> listVulkanDevices() {
    std::unique_ptr<vk::DynamicLoader> loader;
    vulkan::ensureLoader(loader);
    return vulkan::translateVulkanErrors("device listing", [&] {
        vk::ApplicationInfo app("cloudscape", 1, "cloudscape", 1, VK_API_VERSION_1_2);
        const vk::UniqueInstance owned = vk::createInstanceUnique(vk::InstanceCreateInfo({}, &app));
        const vk::Instance instance = *owned;
        VULKAN_HPP_DEFAULT_DISPATCHER.init(instance);
        std::vector<VulkanDeviceInfo> out;
        for (vk::PhysicalDevice d : instance.enumeratePhysicalDevices()) {
            bool compute = false;
            for (const auto& f : d.getQueueFamilyProperties())
                compute = compute || static_cast<bool>(f.queueFlags & vk::QueueFlagBits::eCompute);
            if (!compute)
                continue;
            const auto props = d.getProperties();
            VulkanDeviceInfo info;
            info.index = static_cast<int>(out.size());
            info.name = props.deviceName.data();
            info.type = vulkan::deviceTypeName(props.deviceType);
            const auto memory = d.getMemoryProperties();
            for (uint32_t h = 0; h < memory.memoryHeapCount; ++h)
                if (memory.memoryHeaps[h].flags & vk::MemoryHeapFlagBits::eDeviceLocal)
                    info.deviceLocalBytes += memory.memoryHeaps[h].size;
            info.apiVersion = std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_PATCH(props.apiVersion));
            out.push_back(info);
        }
        return out;
    });
}

RenderResult renderScene(const Scene& scene, const SceneResources& resources,
                         const BackendOptions& options, const ProgressCallback& progress,
                         std::string* notice) {
    if (options.choice == BackendChoice::Cpu)
        return renderCpu(scene, resources, progress);
    if (options.choice == BackendChoice::Vulkan)
        return renderVulkan(scene, resources, options, progress);
    if (!autoChoosesVulkan(notice))
        return renderCpu(scene, resources, progress);
    return renderVulkan(scene, resources, options, progress);
}

TemporalRenderer::TemporalRenderer(const SceneResources& resources)
    : impl_(makeCpuTemporal(resources)) {}

TemporalRenderer::TemporalRenderer(const SceneResources& resources, const BackendOptions& options,
                                   std::string* notice) {
    const bool vulkan = options.choice == BackendChoice::Vulkan ||
                        (options.choice == BackendChoice::Auto && autoChoosesVulkan(notice));
    impl_ = vulkan ? makeVulkanTemporal(resources, options) : makeCpuTemporal(resources);
}

TemporalRenderer::~TemporalRenderer() = default;

RenderResult TemporalRenderer::renderFrame(const Scene& scene, int frameIndex, Readback readback) {
    return impl_->renderFrame(scene, frameIndex, readback);
}

TemporalRenderer::Breakdown TemporalRenderer::lastBreakdown() const {
    return impl_->breakdown;
}

TemporalState TemporalRenderer::saveState() const {
    return impl_->saveState();
}

void TemporalRenderer::restoreState(const TemporalState& state) {
    checkTemporalState(state);
    impl_->restoreState(state);
}

std::string TemporalRenderer::backendName() const {
    return impl_->backendName();
}

} // namespace cloudscape
