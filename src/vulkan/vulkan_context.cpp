#include "vulkan/vulkan_context.h"

#include <cloudscape/error.h>

#include <algorithm>
#include <cstring>
#include <utility>

VULKAN_HPP_DEFAULT_DISPATCH_LOADER_DYNAMIC_STORAGE

namespace cloudscape::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

int typeRank(vk::PhysicalDeviceType type) {
    switch (type) {
    case vk::PhysicalDeviceType::eDiscreteGpu:
        return 4;
    case vk::PhysicalDeviceType::eIntegratedGpu:
        return 3;
    case vk::PhysicalDeviceType::eVirtualGpu:
        return 2;
    case vk::PhysicalDeviceType::eCpu:
        return 1;
    default:
        return 0;
    }
}

// The first queue family with compute, or -1. With a surface: the first that also draws and
// presents to it, on a device with VK_KHR_swapchain.
int computeFamily(vk::PhysicalDevice device, vk::SurfaceKHR surface = {}) {
    if (surface) {
        const auto extensions = device.enumerateDeviceExtensionProperties();
        if (std::none_of(extensions.begin(), extensions.end(), [](const auto& e) {
                return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
            }))
            return -1;
    }
    const auto families = device.getQueueFamilyProperties();
    const vk::QueueFlags wanted = surface
                                      ? vk::QueueFlagBits::eCompute | vk::QueueFlagBits::eGraphics
                                      : vk::QueueFlags(vk::QueueFlagBits::eCompute);
    for (size_t i = 0; i < families.size(); ++i)
        if ((families[i].queueFlags & wanted) == wanted &&
            (!surface || device.getSurfaceSupportKHR(static_cast<uint32_t>(i), surface)))
            return static_cast<int>(i);
    return -1;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
    static_cast<Context*>(user)->addValidationMessage(data && data->pMessage ? data->pMessage
                                                                             : "(no message)");
    return VK_FALSE;
}

// Messages raised where no render can return them: when an instance is destroyed, when a
// context's set-up fails, or left over when a context ends. takeVulkanValidationMessages()
// hands them out.
std::mutex lateMessagesMutex;
std::vector<std::string> lateMessages;

void addLateMessages(std::vector<std::string> messages) {
    std::lock_guard<std::mutex> lock(lateMessagesMutex);
    for (std::string& m : messages)
        lateMessages.push_back(std::move(m));
}

vk::DebugUtilsMessengerCreateInfoEXT messengerInfo(Context* context) {
    return vk::DebugUtilsMessengerCreateInfoEXT(
        {},
        vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning |
            vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
        vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral |
            vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
            vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance,
        &onValidationMessage, context);
}

// With validation, a messenger is chained into the instance's create info, so the layer reports
// what it finds during vkCreateInstance and vkDestroyInstance too (the messenger created after
// the instance covers only the time between).
vk::Instance createInstance(bool validation, Context* context,
                            const PresentationTarget* presentation) {
    vk::ApplicationInfo app("cloudscape", 1, "cloudscape", 1, VK_API_VERSION_1_2);
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (presentation)
        for (const std::string& e : presentation->instanceExtensions)
            extensions.push_back(e.c_str());
    if (validation) {
        const auto available = vk::enumerateInstanceLayerProperties();
        const bool found = std::any_of(available.begin(), available.end(), [](const auto& l) {
            return std::strcmp(l.layerName, kValidationLayer) == 0;
        });
        if (!found)
            throw Error(std::string("Vulkan validation requested but ") + kValidationLayer +
                        " is not installed (Debian package vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    vk::InstanceCreateInfo info({}, &app, layers, extensions);
    const vk::DebugUtilsMessengerCreateInfoEXT lifetimeMessenger = messengerInfo(context);
    if (validation)
        info.pNext = &lifetimeMessenger;
    return vk::createInstance(info);
}

} // namespace

void ensureLoader(std::unique_ptr<vk::DynamicLoader>& loader) {
    try {
        loader = std::make_unique<vk::DynamicLoader>();
    } catch (const std::exception&) {
        throw Error("no Vulkan loader (libvulkan.so.1) found: install libvulkan1 and a driver, "
                    "e.g. mesa-vulkan-drivers for the lavapipe CPU device, or use --backend cpu");
    }
    auto getInstanceProcAddr =
        loader->getProcAddress<PFN_vkGetInstanceProcAddr>("vkGetInstanceProcAddr");
    if (!getInstanceProcAddr)
        throw Error("the Vulkan loader has no vkGetInstanceProcAddr; reinstall libvulkan1");
    VULKAN_HPP_DEFAULT_DISPATCHER.init(getInstanceProcAddr);
}

std::string deviceTypeName(vk::PhysicalDeviceType type) {
    switch (type) {
    case vk::PhysicalDeviceType::eDiscreteGpu:
        return "discrete";
    case vk::PhysicalDeviceType::eIntegratedGpu:
        return "integrated";
    case vk::PhysicalDeviceType::eVirtualGpu:
        return "virtual";
    case vk::PhysicalDeviceType::eCpu:
        return "cpu";
    default:
        return "other";
    }
}

Context::Context(int deviceIndex, bool validation, const PresentationTarget* presentation) {
    ensureLoader(loader_);
    try {
        setUp(deviceIndex, validation, presentation);
    } catch (...) {
        destroy(); // the destructor does not run for a constructor that throws
        throw;
    }
}

void Context::setUp(int deviceIndex, bool validation, const PresentationTarget* presentation) {
    translateVulkanErrors("device setup", [&] {
        // Owned from here on; the deleter is given the dispatcher explicitly (a defaulted one
        // has none).
        ownedInstance_ =
            vk::UniqueInstance(createInstance(validation, this, presentation),
                               vk::ObjectDestroy<vk::NoParent, VULKAN_HPP_DEFAULT_DISPATCHER_TYPE>(
                                   nullptr, VULKAN_HPP_DEFAULT_DISPATCHER));
        instance = *ownedInstance_;
        VULKAN_HPP_DEFAULT_DISPATCHER.init(instance);
        instanceFunctions_.init(instance, VULKAN_HPP_DEFAULT_DISPATCHER.vkGetInstanceProcAddr);
        if (validation)
            messenger_ = instance.createDebugUtilsMessengerEXTUnique(messengerInfo(this), nullptr,
                                                                     instanceFunctions_);
        if (presentation)
            surface = vk::SurfaceKHR(
                static_cast<VkSurfaceKHR>(reinterpret_cast<void*>(presentation->createSurface(
                    reinterpret_cast<uint64_t>(static_cast<VkInstance>(instance))))));
        std::vector<vk::PhysicalDevice> usable;
        for (vk::PhysicalDevice d : instance.enumeratePhysicalDevices())
            if (computeFamily(d, surface) >= 0)
                usable.push_back(d);
        if (usable.empty())
            throw Error(surface ? "no Vulkan device can present to this window (a queue with "
                                  "graphics, compute and present, and VK_KHR_swapchain)"
                                : "no Vulkan device with a compute queue: install a driver (e.g. "
                                  "mesa-vulkan-drivers for lavapipe) or use --backend cpu");
        if (deviceIndex >= static_cast<int>(usable.size()))
            throw Error("--device " + std::to_string(deviceIndex) + " does not exist: there " +
                        (usable.size() == 1
                             ? "is 1 Vulkan device"
                             : "are " + std::to_string(usable.size()) + " Vulkan devices") +
                        " (see `cloudscape devices`)");
        if (deviceIndex >= 0) {
            physicalDevice = usable[static_cast<size_t>(deviceIndex)];
        } else {
            // Stable: the first of the best type wins, so the choice is repeatable.
            physicalDevice = *std::max_element(usable.begin(), usable.end(), [](auto a, auto b) {
                return typeRank(a.getProperties().deviceType) <
                       typeRank(b.getProperties().deviceType);
            });
        }
        properties = physicalDevice.getProperties();
        queueFamily = static_cast<uint32_t>(computeFamily(physicalDevice, surface));
        timestampValidBits =
            physicalDevice.getQueueFamilyProperties()[queueFamily].timestampValidBits;
        const float priority = 1.0f;
        vk::DeviceQueueCreateInfo queueInfo({}, queueFamily, 1, &priority);
        std::vector<const char*> deviceExtensions;
        if (surface)
            deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        ownedDevice_ = physicalDevice.createDeviceUnique(
            vk::DeviceCreateInfo({}, queueInfo, {}, deviceExtensions));
        device = *ownedDevice_;
        // The dispatcher is one per process: device functions stay the loader's trampolines
        // (loaded with the instance), which find each device's own chain. Loading this device's
        // entry points into it would send every other device's calls down this one's chain (a
        // renderer with the validation layers beside one without crashed in lavapipe).
        queue = device.getQueue(queueFamily, 0);
        ownedCommandPool_ = device.createCommandPoolUnique(vk::CommandPoolCreateInfo(
            vk::CommandPoolCreateFlagBits::eResetCommandBuffer, queueFamily));
        commandPool = *ownedCommandPool_;
    });
}

Context::~Context() {
    destroy();
}

// Frees in reverse creation order, explicitly rather than by member destruction, so that what
// the chained messenger reports while the instance is destroyed still reaches this context and
// is handed on to the late list. Safe after a partial set-up.
void Context::destroy() {
    if (device)
        waitIdleBeforeFreeing(device);
    ownedCommandPool_.reset();
    commandPool = nullptr;
    ownedDevice_.reset();
    device = nullptr;
    if (surface)
        instance.destroySurfaceKHR(surface, nullptr, instanceFunctions_);
    surface = nullptr;
    messenger_.reset();
    ownedInstance_.reset(); // the chained messenger still reports into this context
    instance = nullptr;
    addLateMessages(takeValidationMessages());
}

uint32_t Context::memoryTypeFor(uint32_t typeBits, vk::MemoryPropertyFlags wanted,
                                vk::MemoryPropertyFlags fallback) const {
    const auto memory = physicalDevice.getMemoryProperties();
    for (vk::MemoryPropertyFlags flags : {wanted, fallback}) {
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags)
                return i;
        if (!fallback)
            break;
    }
    throw Error("no suitable Vulkan memory type on " + std::string(properties.deviceName.data()));
}

void Context::addValidationMessage(const std::string& message) {
    std::lock_guard<std::mutex> lock(messagesMutex_);
    messages_.push_back(message);
}

std::vector<std::string> Context::takeValidationMessages() {
    std::lock_guard<std::mutex> lock(messagesMutex_);
    return std::exchange(messages_, {});
}

void waitIdleBeforeFreeing(vk::Device device) noexcept {
    try {
        device.waitIdle();
    } catch (const vk::SystemError&) {
    }
}

} // namespace cloudscape::vulkan

namespace cloudscape {

std::vector<std::string> takeVulkanValidationMessages() {
    std::lock_guard<std::mutex> lock(vulkan::lateMessagesMutex);
    return std::exchange(vulkan::lateMessages, {});
}

} // namespace cloudscape
