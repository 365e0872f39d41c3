#pragma once
// Vulkan instance, device and queue for compute, created through a run-time loaded loader so a
// machine without Vulkan gets a clear message instead of a binary that will not start.
#include <cloudscape/backend.h>

#include <vulkan/vulkan.hpp>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace cloudscape::vulkan {

class Context {
public:
    // deviceIndex -1 picks the best device (discrete > integrated > virtual > cpu).
    // With a presentation target the device can also draw and present to its surface.
    Context(int deviceIndex, bool validation, const PresentationTarget* presentation = nullptr);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Handles for use; the context owns them (RAII members below) and frees them in order.
    vk::Instance instance;
    vk::PhysicalDevice physicalDevice;
    vk::PhysicalDeviceProperties properties;
    vk::Device device;
    uint32_t queueFamily = 0;
    uint32_t timestampValidBits = 0;
    vk::Queue queue;
    vk::CommandPool commandPool;
    vk::SurfaceKHR surface; // the presentation target's, or null

    uint32_t memoryTypeFor(uint32_t typeBits, vk::MemoryPropertyFlags wanted,
                           vk::MemoryPropertyFlags fallback = {}) const;
    std::vector<std::string> takeValidationMessages();
    void addValidationMessage(const std::string& message);

private:
    void setUp(int deviceIndex, bool validation, const PresentationTarget* presentation);
    void destroy(); // safe after a partial set-up; hands leftover messages to the late list
    // Declared in creation order; destroy() frees them in reverse: pool, device, messenger,
    // instance (the loader last, as a member).
    std::unique_ptr<vk::DynamicLoader> loader_;
    vk::UniqueInstance ownedInstance_;
    // This instance's own entry points, for its extension functions (the messenger, the
    // surface): the process-wide dispatcher holds those of the last instance created, which may
    // not have the extension (a renderer without validation beside one with it).
    vk::DispatchLoaderDynamic instanceFunctions_;
    vk::UniqueDebugUtilsMessengerEXT messenger_;
    vk::UniqueDevice ownedDevice_;
    vk::UniqueCommandPool ownedCommandPool_;
    std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

// Loads the Vulkan loader and the global entry points once; throws cloudscape::Error naming
// what to install if there is no loader.
void ensureLoader(std::unique_ptr<vk::DynamicLoader>& loader);

std::string deviceTypeName(vk::PhysicalDeviceType type);

// Waits for the device to finish before what it may still use is freed, from destructors: a
// lost device (VK_ERROR_DEVICE_LOST) has nothing left to wait for, and the error that lost it is
// already on its way to the user, so a failed wait is not thrown (it would end the program).
void waitIdleBeforeFreeing(vk::Device device) noexcept;

// Runs f and turns Vulkan exceptions into cloudscape::Error with a useful one-line message.
template <typename F> auto translateVulkanErrors(const char* what, F&& f) -> decltype(f());

} // namespace cloudscape::vulkan

#include "vulkan/vulkan_errors.inl"
