// The viewer's GLFW window (view_window.h).
#include "view_window.h"

#include <cloudscape/error.h>

#include <vulkan/vulkan.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdint>

namespace cloudscape::cli {
namespace {

// GLFW reports why it failed through a callback; the last message is kept for the one line.
std::string lastGlfwError;

void onGlfwError(int, const char* description) {
    lastGlfwError = description ? description : "unknown GLFW error";
}

} // namespace

ViewWindow::ViewWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw Error("view: no display to open a window on (" + lastGlfwError +
                    "); run it on a desktop, or under xvfb-run");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("view: no Vulkan loader or driver usable for a window: install libvulkan1 "
                    "and a driver (mesa-vulkan-drivers for lavapipe)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw Error("view: the window could not be opened (" + lastGlfwError + ")");
    }
}

ViewWindow::~ViewWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::shared_ptr<const PresentationTarget> ViewWindow::presentationTarget() const {
    auto target = std::make_shared<PresentationTarget>();
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    for (uint32_t i = 0; names && i < count; ++i)
        target->instanceExtensions.emplace_back(names[i]);
    GLFWwindow* window = window_;
    target->createSurface = [window](uint64_t instance) {
        VkSurfaceKHR surface = VK_NULL_HANDLE;
        const VkResult result = glfwCreateWindowSurface(reinterpret_cast<VkInstance>(instance),
                                                        window, nullptr, &surface);
        if (result != VK_SUCCESS)
            throw Error("view: no Vulkan surface for the window (" + lastGlfwError + ")");
        return reinterpret_cast<uint64_t>(surface);
    };
    return target;
}

bool ViewWindow::closeRequested() const {
    return glfwWindowShouldClose(window_);
}

void ViewWindow::requestClose() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void ViewWindow::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

} // namespace cloudscape::cli
