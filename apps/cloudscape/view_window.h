#pragma once
// The viewer's window (GLFW): opened before the renderer, so the Vulkan device is chosen for a
// surface on it; a machine with no display or no Vulkan gets a one-line cloudscape::Error.
#include <cloudscape/backend.h>

#include <memory>
#include <string>

struct GLFWwindow;

namespace cloudscape::cli {

class ViewWindow {
public:
    ViewWindow(int width, int height, const std::string& title);
    ~ViewWindow();
    ViewWindow(const ViewWindow&) = delete;
    ViewWindow& operator=(const ViewWindow&) = delete;

    // What BackendOptions::presentation needs to make the Vulkan context draw into this window.
    std::shared_ptr<const PresentationTarget> presentationTarget() const;

    GLFWwindow* handle() const { return window_; }
    bool closeRequested() const;
    void requestClose();
    // The framebuffer's size in pixels: 0 x 0 while minimised.
    void framebufferSize(int& width, int& height) const;

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace cloudscape::cli
