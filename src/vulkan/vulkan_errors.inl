// Implementation of translateVulkanErrors (included by vulkan_context.h).
#include <cloudscape/error.h>

namespace cloudscape::vulkan {

template <typename F> auto translateVulkanErrors(const char* what, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const vk::IncompatibleDriverError&) {
        throw Error("no Vulkan driver found: install mesa-vulkan-drivers (lavapipe runs on the "
                    "CPU) or your GPU's driver, or use --backend cpu");
    } catch (const vk::DeviceLostError&) {
        throw Error(std::string("Vulkan device lost during ") + what +
                    " (driver crash or timeout); try a smaller --width/--height or --backend cpu");
    } catch (const vk::OutOfDeviceMemoryError&) {
        throw Error(std::string("out of device memory during ") + what +
                    "; try a smaller image or --backend cpu");
    } catch (const vk::OutOfHostMemoryError&) {
        throw Error(std::string("out of host memory during ") + what);
    } catch (const vk::SystemError& e) {
        throw Error(std::string("Vulkan error during ") + what + ": " + e.what());
    }
}

} // namespace cloudscape::vulkan
