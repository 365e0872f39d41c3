// The viewer's swapchain and the pass that draws the composite into it (view_presenter.h).
#include "view_presenter.h"

#include <cloudscape/error.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace cloudscape::cli {
namespace {

const uint32_t kPresentVert[] = {
#include "shaders/view_present_vert.spv.inc"
};
const uint32_t kPresentFrag[] = {
#include "shaders/view_present_frag.spv.inc"
};

struct Placement {
    int32_t imageWidth, imageHeight;
    float originX, originY;
    float pixelScale;
    float exposure;
    int32_t decodeSrgb;
    int32_t displayValues;
};

template <typename T> T fromHandle(uint64_t h) {
    return T(reinterpret_cast<typename T::CType>(h));
}

// A UNORM target takes the tone curve's sRGB values as they are; an sRGB one would encode them
// again, so the shader decodes first (decodeSrgb).
vk::SurfaceFormatKHR chooseFormat(vk::PhysicalDevice physical, vk::SurfaceKHR surface) {
    const auto formats = physical.getSurfaceFormatsKHR(surface);
    if (formats.empty())
        throw Error("the window's surface offers no pixel format");
    for (vk::Format wanted : {vk::Format::eB8G8R8A8Unorm, vk::Format::eR8G8B8A8Unorm})
        for (const auto& f : formats)
            if (f.format == wanted)
                return f;
    return formats.front();
}

bool isSrgb(vk::Format format) {
    return format == vk::Format::eB8G8R8A8Srgb || format == vk::Format::eR8G8B8A8Srgb;
}

vk::UniqueShaderModule moduleOf(vk::Device device, const uint32_t* words, size_t bytes) {
    return device.createShaderModuleUnique(vk::ShaderModuleCreateInfo({}, bytes, words));
}

} // namespace

ViewPresenter::ViewPresenter(const Renderer::DeviceHandles& handles, int width, int height)
    : physical_(fromHandle<vk::PhysicalDevice>(handles.physicalDevice)),
      device_(fromHandle<vk::Device>(handles.device)), queue_(fromHandle<vk::Queue>(handles.queue)),
      surface_(fromHandle<vk::SurfaceKHR>(handles.surface)), queueFamily_(handles.queueFamily) {
    if (!device_ || !surface_)
        throw Error("the viewer needs the Vulkan backend opened for a window");
    pool_ = device_.createCommandPoolUnique(vk::CommandPoolCreateInfo(
        vk::CommandPoolCreateFlagBits::eResetCommandBuffer, queueFamily_));
    commands_ = std::move(device_.allocateCommandBuffersUnique(
        vk::CommandBufferAllocateInfo(*pool_, vk::CommandBufferLevel::ePrimary, 1))[0]);
    acquired_ = device_.createSemaphoreUnique({});
    rendered_ = device_.createSemaphoreUnique({});
    done_ = device_.createFenceUnique(vk::FenceCreateInfo(vk::FenceCreateFlagBits::eSignaled));
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eStorageBuffer, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    setLayout_ = device_.createDescriptorSetLayoutUnique({{}, binding});
    const vk::DescriptorPoolSize size(vk::DescriptorType::eStorageBuffer, 1);
    descriptorPool_ = device_.createDescriptorPoolUnique({{}, 1, size});
    descriptorSet_ = device_.allocateDescriptorSets({*descriptorPool_, *setLayout_})[0];
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(Placement));
    pipelineLayout_ = device_.createPipelineLayoutUnique({{}, *setLayout_, push});

    format_ = chooseFormat(physical_, surface_);
    const vk::AttachmentDescription colour(
        {}, format_.format, vk::SampleCountFlagBits::e1, vk::AttachmentLoadOp::eClear,
        vk::AttachmentStoreOp::eStore, vk::AttachmentLoadOp::eDontCare,
        vk::AttachmentStoreOp::eDontCare, vk::ImageLayout::eUndefined,
        vk::ImageLayout::ePresentSrcKHR);
    const vk::AttachmentReference ref(0, vk::ImageLayout::eColorAttachmentOptimal);
    const vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, ref);
    // The acquire semaphore is waited at colour output; the layout change must wait for it too.
    const vk::SubpassDependency dependency(VK_SUBPASS_EXTERNAL, 0,
                                           vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                           vk::PipelineStageFlagBits::eColorAttachmentOutput, {},
                                           vk::AccessFlagBits::eColorAttachmentWrite);
    renderPass_ = device_.createRenderPassUnique({{}, colour, subpass, dependency});
    createPipeline();
    createSwapchain(width, height);
}

ViewPresenter::~ViewPresenter() {
    if (device_)
        device_.waitIdle();
    destroySwapchain();
}

void ViewPresenter::createPipeline() {
    const auto vert = moduleOf(device_, kPresentVert, sizeof kPresentVert);
    const auto frag = moduleOf(device_, kPresentFrag, sizeof kPresentFrag);
    const std::array stages = {
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eVertex, *vert, "main"),
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eFragment, *frag, "main")};
    const vk::PipelineVertexInputStateCreateInfo vertexInput;
    const vk::PipelineInputAssemblyStateCreateInfo assembly({},
                                                            vk::PrimitiveTopology::eTriangleList);
    const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
    vk::PipelineRasterizationStateCreateInfo raster;
    raster.lineWidth = 1.0f;
    const vk::PipelineMultisampleStateCreateInfo multisample;
    vk::PipelineColorBlendAttachmentState blend;
    blend.colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                           vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;
    const vk::PipelineColorBlendStateCreateInfo blending({}, false, {}, blend);
    const std::array dynamic = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
    const vk::PipelineDynamicStateCreateInfo dynamicState({}, dynamic);
    const vk::GraphicsPipelineCreateInfo info({}, stages, &vertexInput, &assembly, nullptr,
                                              &viewport, &raster, &multisample, nullptr, &blending,
                                              &dynamicState, *pipelineLayout_, *renderPass_);
    auto created = device_.createGraphicsPipelineUnique({}, info);
    if (created.result != vk::Result::eSuccess)
        throw Error("the viewer's present pipeline could not be created");
    pipeline_ = std::move(created.value);
}

void ViewPresenter::createSwapchain(int width, int height) {
    const auto caps = physical_.getSurfaceCapabilitiesKHR(surface_);
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) // the surface takes the size the swapchain asks for
        extent_ = vk::Extent2D(static_cast<uint32_t>(width), static_cast<uint32_t>(height));
    extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height =
        std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    uint32_t count = caps.minImageCount + 1;
    if (caps.maxImageCount > 0)
        count = std::min(count, caps.maxImageCount);
    vk::SwapchainCreateInfoKHR info(
        {}, surface_, count, format_.format, format_.colorSpace, extent_, 1,
        vk::ImageUsageFlagBits::eColorAttachment |
            (caps.supportedUsageFlags & vk::ImageUsageFlagBits::eTransferSrc),
        vk::SharingMode::eExclusive, {}, caps.currentTransform,
        vk::CompositeAlphaFlagBitsKHR::eOpaque, vk::PresentModeKHR::eFifo, true, *swapchain_);
    if (!(caps.supportedCompositeAlpha & vk::CompositeAlphaFlagBitsKHR::eOpaque))
        info.compositeAlpha = vk::CompositeAlphaFlagBitsKHR::eInherit;
    canCapture_ = bool(caps.supportedUsageFlags & vk::ImageUsageFlagBits::eTransferSrc);
    vk::UniqueSwapchainKHR next = device_.createSwapchainKHRUnique(info);
    destroySwapchain();
    swapchain_ = std::move(next);
    images_ = device_.getSwapchainImagesKHR(*swapchain_);
    for (vk::Image image : images_) {
        views_.push_back(
            device_.createImageViewUnique({{},
                                           image,
                                           vk::ImageViewType::e2D,
                                           format_.format,
                                           {},
                                           {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}}));
        framebuffers_.push_back(device_.createFramebufferUnique(
            {{}, *renderPass_, *views_.back(), extent_.width, extent_.height, 1}));
    }
}

void ViewPresenter::destroySwapchain() {
    framebuffers_.clear();
    views_.clear();
    images_.clear();
    swapchain_.reset();
}

bool ViewPresenter::present(const Renderer::DeviceImage& image, float exposure, int width,
                            int height, const Overlay& overlay, Capture* capture) {
    if (width <= 0 || height <= 0)
        return false; // minimised: a swapchain cannot be zero-sized
    if (static_cast<uint32_t>(width) != extent_.width ||
        static_cast<uint32_t>(height) != extent_.height) {
        device_.waitIdle();
        createSwapchain(width, height);
    }
    (void)device_.waitForFences(*done_, true, UINT64_MAX);
    uint32_t index = 0;
    const VkResult acquired = VULKAN_HPP_DEFAULT_DISPATCHER.vkAcquireNextImageKHR(
        device_, *swapchain_, UINT64_MAX, *acquired_, nullptr, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        device_.waitIdle();
        createSwapchain(width, height);
        return false;
    }
    if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR)
        throw Error("the window's swapchain failed (" + vk::to_string(vk::Result(acquired)) + ")");
    device_.resetFences(*done_);
    vk::CommandBuffer cmd = *commands_;
    cmd.reset();
    vk::UniqueBuffer captureBuffer;
    vk::UniqueDeviceMemory captureMemory;
    if (capture) {
        if (!canCapture_)
            throw Error("view: this window's swapchain cannot be read back for a capture");
        const vk::DeviceSize bytes = vk::DeviceSize(extent_.width) * extent_.height * 4;
        captureBuffer =
            device_.createBufferUnique({{}, bytes, vk::BufferUsageFlagBits::eTransferDst});
        const auto needs = device_.getBufferMemoryRequirements(*captureBuffer);
        captureMemory =
            device_.allocateMemoryUnique({needs.size, hostMemoryType(needs.memoryTypeBits)});
        device_.bindBufferMemory(*captureBuffer, *captureMemory, 0);
    }
    record(cmd, index, image, exposure, overlay);
    if (capture)
        recordCapture(cmd, index, *captureBuffer);
    cmd.end();
    const vk::PipelineStageFlags waitStage = vk::PipelineStageFlagBits::eColorAttachmentOutput;
    queue_.submit(vk::SubmitInfo(*acquired_, waitStage, cmd, *rendered_), *done_);
    const vk::SwapchainKHR swapchain = *swapchain_;
    const vk::PresentInfoKHR info(*rendered_, swapchain, index);
    const VkResult presented = VULKAN_HPP_DEFAULT_DISPATCHER.vkQueuePresentKHR(
        queue_, reinterpret_cast<const VkPresentInfoKHR*>(&info));
    // The renderer writes its buffer next frame: this frame's reads must be done by then.
    (void)device_.waitForFences(*done_, true, UINT64_MAX);
    if (capture)
        readCapture(*captureMemory, *capture);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
        device_.waitIdle();
        createSwapchain(width, height);
    } else if (presented != VK_SUCCESS) {
        throw Error("presenting to the window failed (" + vk::to_string(vk::Result(presented)) +
                    ")");
    }
    return true;
}

void ViewPresenter::record(vk::CommandBuffer cmd, uint32_t imageIndex,
                           const Renderer::DeviceImage& image, float exposure,
                           const Overlay& overlay) {
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    // The renderer's compute passes, earlier on this queue, wrote the composite.
    const vk::MemoryBarrier written(vk::AccessFlagBits::eShaderWrite,
                                    vk::AccessFlagBits::eShaderRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eFragmentShader, {}, written, {}, {});
    const vk::Rect2D area({0, 0}, extent_);
    const vk::ClearValue background(vk::ClearColorValue(std::array{0.03f, 0.03f, 0.035f, 1.0f}));
    cmd.beginRenderPass(
        vk::RenderPassBeginInfo(*renderPass_, *framebuffers_[imageIndex], area, background),
        vk::SubpassContents::eInline);
    cmd.setViewport(0, vk::Viewport(0.0f, 0.0f, static_cast<float>(extent_.width),
                                    static_cast<float>(extent_.height), 0.0f, 1.0f));
    cmd.setScissor(0, area);
    if (image.buffer && image.width > 0 && image.height > 0) {
        const vk::DescriptorBufferInfo buffer(fromHandle<vk::Buffer>(image.buffer), 0, image.bytes);
        device_.updateDescriptorSets(vk::WriteDescriptorSet(descriptorSet_, 0, 0,
                                                            vk::DescriptorType::eStorageBuffer, {},
                                                            buffer),
                                     {});
        // Letterboxed: the whole image, as large as the window allows, centred.
        const float scale = std::min(static_cast<float>(extent_.width) / image.width,
                                     static_cast<float>(extent_.height) / image.height);
        const Placement place{image.width,
                              image.height,
                              0.5f * (extent_.width - scale * image.width),
                              0.5f * (extent_.height - scale * image.height),
                              1.0f / scale,
                              exposure,
                              isSrgb(format_.format) ? 1 : 0,
                              displayValues_ ? 1 : 0};
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelineLayout_, 0,
                               descriptorSet_, {});
        cmd.pushConstants(*pipelineLayout_, vk::ShaderStageFlagBits::eFragment, 0, sizeof place,
                          &place);
        cmd.draw(3, 1, 0, 0);
    }
    if (overlay)
        overlay(cmd);
    cmd.endRenderPass();
}

// After the pass: the presentable image copied out and handed back to presentation.
void ViewPresenter::recordCapture(vk::CommandBuffer cmd, uint32_t imageIndex, vk::Buffer target) {
    const vk::ImageSubresourceRange whole(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
    const vk::ImageMemoryBarrier toCopy(
        vk::AccessFlagBits::eColorAttachmentWrite, vk::AccessFlagBits::eTransferRead,
        vk::ImageLayout::ePresentSrcKHR, vk::ImageLayout::eTransferSrcOptimal,
        VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, images_[imageIndex], whole);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eColorAttachmentOutput,
                        vk::PipelineStageFlagBits::eTransfer, {}, {}, {}, toCopy);
    cmd.copyImageToBuffer(images_[imageIndex], vk::ImageLayout::eTransferSrcOptimal, target,
                          vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                              {0, 0, 0}, {extent_.width, extent_.height, 1}));
    const vk::ImageMemoryBarrier back(vk::AccessFlagBits::eTransferRead, {},
                                      vk::ImageLayout::eTransferSrcOptimal,
                                      vk::ImageLayout::ePresentSrcKHR, VK_QUEUE_FAMILY_IGNORED,
                                      VK_QUEUE_FAMILY_IGNORED, images_[imageIndex], whole);
    const vk::BufferMemoryBarrier toHost(vk::AccessFlagBits::eTransferWrite,
                                         vk::AccessFlagBits::eHostRead, VK_QUEUE_FAMILY_IGNORED,
                                         VK_QUEUE_FAMILY_IGNORED, target, 0, VK_WHOLE_SIZE);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eBottomOfPipe | vk::PipelineStageFlagBits::eHost,
                        {}, {}, toHost, back);
}

void ViewPresenter::readCapture(vk::DeviceMemory memory, Capture& capture) const {
    const size_t pixels = size_t(extent_.width) * extent_.height;
    const auto* bytes = static_cast<const uint8_t*>(device_.mapMemory(memory, 0, pixels * 4));
    const bool bgra =
        format_.format == vk::Format::eB8G8R8A8Unorm || format_.format == vk::Format::eB8G8R8A8Srgb;
    capture.rgba.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        capture.rgba[i * 4 + 0] = bytes[i * 4 + (bgra ? 2 : 0)];
        capture.rgba[i * 4 + 1] = bytes[i * 4 + 1];
        capture.rgba[i * 4 + 2] = bytes[i * 4 + (bgra ? 0 : 2)];
        capture.rgba[i * 4 + 3] = 255;
    }
    device_.unmapMemory(memory);
    capture.width = static_cast<int>(extent_.width);
    capture.height = static_cast<int>(extent_.height);
}

Renderer::DeviceImage ViewPresenter::hostImage(int width, int height, float** pixels) {
    const vk::DeviceSize bytes = static_cast<vk::DeviceSize>(width) * height * 4 * sizeof(float);
    if (!hostBuffer_ || hostBytes_ != bytes) {
        device_.waitIdle(); // the old buffer may still be read by the last frame
        if (hostMapped_)
            device_.unmapMemory(*hostMemory_);
        hostMapped_ = nullptr;
        hostBuffer_ =
            device_.createBufferUnique({{}, bytes, vk::BufferUsageFlagBits::eStorageBuffer});
        const auto needs = device_.getBufferMemoryRequirements(*hostBuffer_);
        hostMemory_ =
            device_.allocateMemoryUnique({needs.size, hostMemoryType(needs.memoryTypeBits)});
        device_.bindBufferMemory(*hostBuffer_, *hostMemory_, 0);
        hostMapped_ = device_.mapMemory(*hostMemory_, 0, bytes);
        hostBytes_ = bytes;
    }
    *pixels = static_cast<float*>(hostMapped_);
    Renderer::DeviceImage image;
    image.buffer = reinterpret_cast<uint64_t>(static_cast<VkBuffer>(*hostBuffer_));
    image.bytes = bytes;
    image.width = width;
    image.height = height;
    return image;
}

uint32_t ViewPresenter::hostMemoryType(uint32_t bits) const {
    const auto memory = physical_.getMemoryProperties();
    const vk::MemoryPropertyFlags wanted =
        vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    throw Error("view: no host-visible Vulkan memory for a capture");
}

} // namespace cloudscape::cli
