#pragma once
// The viewer's Vulkan side: a swapchain on the renderer's own device and queue, and a pass that
// draws the renderer's composite (a storage buffer left on the device) into the window through
// the model's tone curve, with whatever the caller draws on top (the UI). No round trip through
// the host. Plumbing only.
#include <cloudscape/persistent_renderer.h>

#include <vulkan/vulkan.hpp>

#include <functional>
#include <vector>

namespace cloudscape::cli {

class ViewPresenter {
public:
    // Over the renderer's device (Renderer::deviceHandles(), opened with a presentation target);
    // the swapchain is sized to the window's framebuffer. Throws cloudscape::Error.
    ViewPresenter(const Renderer::DeviceHandles& handles, int width, int height);
    ~ViewPresenter();
    ViewPresenter(const ViewPresenter&) = delete;
    ViewPresenter& operator=(const ViewPresenter&) = delete;

    // Draws `image` letterboxed into the window, then `overlay` inside the same render pass, and
    // presents. A window whose size changed (or a swapchain the surface no longer accepts) is
    // rebuilt at `width` x `height`; returns false when nothing was presented (size 0: minimised).
    // With `capture`, also reads back what the window shows (RGBA8, top row first; sized to the
    // swapchain, captureWidth x captureHeight).
    using Overlay = std::function<void(vk::CommandBuffer)>;
    struct Capture {
        std::vector<uint8_t> rgba;
        int width = 0;
        int height = 0;
    };
    bool present(const Renderer::DeviceImage& image, float exposure, int width, int height,
                 const Overlay& overlay = {}, Capture* capture = nullptr);

    // A host-visible storage buffer of width x height vec4s (kept from call to call while its
    // size holds) for an image made on the host: a debug view. `pixels` is its mapped memory,
    // to be filled before present(); the previous frame has finished with it by then.
    Renderer::DeviceImage hostImage(int width, int height, float** pixels);
    // Whether present() draws display values in [0, 1] as they are (a debug view) instead of
    // radiance through the tone curve.
    void setDisplayValues(bool on) { displayValues_ = on; }

    vk::Device device() const { return device_; }
    vk::PhysicalDevice physicalDevice() const { return physical_; }
    vk::Queue queue() const { return queue_; }
    vk::CommandPool commandPool() const { return *pool_; }
    vk::RenderPass renderPass() const { return *renderPass_; }
    vk::Extent2D extent() const { return extent_; }

private:
    void createSwapchain(int width, int height);
    void destroySwapchain();
    void createPipeline();
    void record(vk::CommandBuffer cmd, uint32_t imageIndex, const Renderer::DeviceImage& image,
                float exposure, const Overlay& overlay);
    void recordCapture(vk::CommandBuffer cmd, uint32_t imageIndex, vk::Buffer target);
    void readCapture(vk::DeviceMemory memory, Capture& capture) const;
    uint32_t hostMemoryType(uint32_t bits) const;

    vk::PhysicalDevice physical_;
    vk::Device device_;
    vk::Queue queue_;
    vk::SurfaceKHR surface_;
    uint32_t queueFamily_ = 0;

    vk::UniqueCommandPool pool_;
    vk::UniqueCommandBuffer commands_;
    vk::UniqueSemaphore acquired_;
    vk::UniqueSemaphore rendered_;
    vk::UniqueFence done_;
    vk::UniqueDescriptorSetLayout setLayout_;
    vk::UniqueDescriptorPool descriptorPool_;
    vk::DescriptorSet descriptorSet_;
    vk::UniquePipelineLayout pipelineLayout_;

    // Rebuilt with the swapchain.
    vk::SurfaceFormatKHR format_;
    bool canCapture_ = false;
    vk::Extent2D extent_;
    vk::UniqueRenderPass renderPass_;
    vk::UniquePipeline pipeline_;
    vk::UniqueSwapchainKHR swapchain_;
    std::vector<vk::Image> images_;
    std::vector<vk::UniqueImageView> views_;
    std::vector<vk::UniqueFramebuffer> framebuffers_;

    bool displayValues_ = false;
    vk::UniqueBuffer hostBuffer_; // hostImage()
    vk::UniqueDeviceMemory hostMemory_;
    vk::DeviceSize hostBytes_ = 0;
    void* hostMapped_ = nullptr;
};

} // namespace cloudscape::cli
