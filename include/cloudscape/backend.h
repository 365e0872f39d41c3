#pragma once
// Choosing where a scene is rendered. Both backends run the same model code; the CPU backend is
// always available, the Vulkan backend needs a Vulkan loader and a device (any GPU, or Mesa's
// lavapipe on the CPU).
#include <cloudscape/renderer.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cloudscape {

enum class BackendChoice { Auto, Cpu, Vulkan };

// Parses "auto", "cpu" or "vulkan"; throws cloudscape::Error otherwise.
BackendChoice parseBackendChoice(const std::string& text);

// A window the Vulkan device must be able to present to (the viewer): the context enables these
// instance extensions, makes the surface as soon as the instance exists, picks a device whose
// queue does graphics, compute and presents to it, enables VK_KHR_swapchain, and destroys the
// surface before the instance.
struct PresentationTarget {
    std::vector<std::string> instanceExtensions;
    // Returns a VkSurfaceKHR for the VkInstance given (both as integers, so this header needs no
    // Vulkan); throws cloudscape::Error.
    std::function<uint64_t(uint64_t instance)> createSurface;
};

struct BackendOptions {
    BackendChoice choice = BackendChoice::Auto;
    int device = -1;         // index from listVulkanDevices(); -1 picks the best
    bool validation = false; // Vulkan validation layers; messages are collected in the stats
    std::shared_ptr<const PresentationTarget> presentation; // Vulkan only; null: compute only
    // A person is watching (the viewer): the Vulkan temporal renderer builds the pipelines of a
    // moving camera's frames (the high tier's gathering, the low tier's background from the
    // reduced pass) with its still frames instead of when the camera first moves, so that the
    // first turn does not stall on their compile (about half a second on lavapipe). Batch
    // renders leave it off and build only what their frames use.
    bool interactive = false;
};

struct VulkanDeviceInfo {
    int index = 0;
    std::string name;
    std::string type; // "discrete", "integrated", "virtual", "cpu", "other"
    uint64_t deviceLocalBytes = 0;
    std::string apiVersion;
};

// The Vulkan devices with a compute queue. Throws cloudscape::Error when there is no loader.
std::vector<VulkanDeviceInfo> listVulkanDevices();

// Render on the chosen backend. With Auto: a discrete GPU, then an integrated one, then any
// other Vulkan device (lavapipe), then the CPU backend; `notice` receives a one-line message
// when Auto falls back to the CPU because Vulkan is unavailable. stats.backend names what ran.
RenderResult renderScene(const Scene& scene, const SceneResources& resources,
                         const BackendOptions& options, const ProgressCallback& progress = {},
                         std::string* notice = nullptr);

// Validation-layer messages (BackendOptions::validation) that no RenderResult could carry: those
// raised while a Vulkan instance was destroyed, while a failed set-up was undone, or after a
// temporal renderer's last frame. Messages from instance creation on arrive in the first
// render's stats. Returns them and clears the list; tests require it to stay empty.
std::vector<std::string> takeVulkanValidationMessages();

// The Vulkan backend directly (throws cloudscape::Error with what to install or what failed).
RenderResult renderVulkan(const Scene& scene, const SceneResources& resources,
                          const BackendOptions& options, const ProgressCallback& progress = {});

} // namespace cloudscape
