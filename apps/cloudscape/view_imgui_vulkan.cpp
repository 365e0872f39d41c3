// Dear ImGui drawn with Vulkan through the run-time loaded dispatcher (view_imgui_vulkan.h).
#include "view_imgui_vulkan.h"

#include <cloudscape/error.h>

#include <imgui.h>

#include <array>
#include <cstring>

namespace cloudscape::cli {
namespace {

const uint32_t kImGuiVert[] = {
#include "shaders/view_imgui_vert.spv.inc"
};
const uint32_t kImGuiFrag[] = {
#include "shaders/view_imgui_frag.spv.inc"
};

struct WindowTransform {
    float scale[2];
    float translate[2];
};

} // namespace

ImGuiVulkan::ImGuiVulkan(vk::PhysicalDevice physical, vk::Device device, vk::Queue queue,
                         vk::CommandPool pool, vk::RenderPass renderPass)
    : physical_(physical), device_(device) {
    sampler_ = device_.createSamplerUnique(vk::SamplerCreateInfo(
        {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eLinear,
        vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
        vk::SamplerAddressMode::eClampToEdge));
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    setLayout_ = device_.createDescriptorSetLayoutUnique({{}, binding});
    const vk::DescriptorPoolSize size(vk::DescriptorType::eCombinedImageSampler, 1);
    descriptorPool_ = device_.createDescriptorPoolUnique({{}, 1, size});
    set_ = device_.allocateDescriptorSets({*descriptorPool_, *setLayout_})[0];
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, sizeof(WindowTransform));
    layout_ = device_.createPipelineLayoutUnique({{}, *setLayout_, push});
    createPipeline(renderPass);
    uploadFonts(queue, pool);
}

ImGuiVulkan::~ImGuiVulkan() {
    device_.waitIdle();
}

uint32_t ImGuiVulkan::memoryType(uint32_t bits, vk::MemoryPropertyFlags flags) const {
    const auto memory = physical_.getMemoryProperties();
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags)
            return i;
    throw Error("view: no suitable Vulkan memory type for the panels");
}

void ImGuiVulkan::createPipeline(vk::RenderPass renderPass) {
    const auto vert = device_.createShaderModuleUnique({{}, sizeof kImGuiVert, kImGuiVert});
    const auto frag = device_.createShaderModuleUnique({{}, sizeof kImGuiFrag, kImGuiFrag});
    const std::array stages = {
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eVertex, *vert, "main"),
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eFragment, *frag, "main")};
    const vk::VertexInputBindingDescription vertexBinding(0, sizeof(ImDrawVert));
    const std::array attributes = {
        vk::VertexInputAttributeDescription(0, 0, vk::Format::eR32G32Sfloat,
                                            offsetof(ImDrawVert, pos)),
        vk::VertexInputAttributeDescription(1, 0, vk::Format::eR32G32Sfloat,
                                            offsetof(ImDrawVert, uv)),
        vk::VertexInputAttributeDescription(2, 0, vk::Format::eR8G8B8A8Unorm,
                                            offsetof(ImDrawVert, col))};
    const vk::PipelineVertexInputStateCreateInfo vertexInput({}, vertexBinding, attributes);
    const vk::PipelineInputAssemblyStateCreateInfo assembly({},
                                                            vk::PrimitiveTopology::eTriangleList);
    const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
    vk::PipelineRasterizationStateCreateInfo raster;
    raster.lineWidth = 1.0f;
    const vk::PipelineMultisampleStateCreateInfo multisample;
    vk::PipelineColorBlendAttachmentState blend(
        true, vk::BlendFactor::eSrcAlpha, vk::BlendFactor::eOneMinusSrcAlpha, vk::BlendOp::eAdd,
        vk::BlendFactor::eOne, vk::BlendFactor::eOneMinusSrcAlpha, vk::BlendOp::eAdd,
        vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
            vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA);
    const vk::PipelineColorBlendStateCreateInfo blending({}, false, {}, blend);
    const std::array dynamic = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
    const vk::PipelineDynamicStateCreateInfo dynamicState({}, dynamic);
    const vk::GraphicsPipelineCreateInfo info({}, stages, &vertexInput, &assembly, nullptr,
                                              &viewport, &raster, &multisample, nullptr, &blending,
                                              &dynamicState, *layout_, renderPass);
    auto created = device_.createGraphicsPipelineUnique({}, info);
    if (created.result != vk::Result::eSuccess)
        throw Error("view: the panels' pipeline could not be created");
    pipeline_ = std::move(created.value);
}

void ImGuiVulkan::uploadFonts(vk::Queue queue, vk::CommandPool pool) {
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    const vk::DeviceSize bytes = static_cast<vk::DeviceSize>(width) * height * 4;
    HostBuffer staging;
    ensure(staging, bytes, vk::BufferUsageFlagBits::eTransferSrc);
    void* mapped = device_.mapMemory(*staging.memory, 0, bytes);
    std::memcpy(mapped, pixels, bytes);
    device_.unmapMemory(*staging.memory);

    const vk::Extent3D extent(static_cast<uint32_t>(width), static_cast<uint32_t>(height), 1);
    font_ = device_.createImageUnique(vk::ImageCreateInfo(
        {}, vk::ImageType::e2D, vk::Format::eR8G8B8A8Unorm, extent, 1, 1,
        vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal,
        vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst));
    const auto needs = device_.getImageMemoryRequirements(*font_);
    fontMemory_ = device_.allocateMemoryUnique(
        {needs.size, memoryType(needs.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal)});
    device_.bindImageMemory(*font_, *fontMemory_, 0);
    const vk::ImageSubresourceRange whole(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
    fontView_ = device_.createImageViewUnique(
        {{}, *font_, vk::ImageViewType::e2D, vk::Format::eR8G8B8A8Unorm, {}, whole});

    auto cmds = device_.allocateCommandBuffersUnique({pool, vk::CommandBufferLevel::ePrimary, 1});
    vk::CommandBuffer cmd = *cmds[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    vk::ImageMemoryBarrier toCopy({}, vk::AccessFlagBits::eTransferWrite,
                                  vk::ImageLayout::eUndefined, vk::ImageLayout::eTransferDstOptimal,
                                  VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *font_, whole);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTopOfPipe, vk::PipelineStageFlagBits::eTransfer,
                        {}, {}, {}, toCopy);
    cmd.copyBufferToImage(*staging.buffer, *font_, vk::ImageLayout::eTransferDstOptimal,
                          vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                              {0, 0, 0}, extent));
    vk::ImageMemoryBarrier toRead(
        vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eShaderRead,
        vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
        VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *font_, whole);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eFragmentShader, {}, {}, {}, toRead);
    cmd.end();
    const vk::UniqueFence fence = device_.createFenceUnique({});
    queue.submit(vk::SubmitInfo({}, {}, cmd), *fence);
    (void)device_.waitForFences(*fence, true, UINT64_MAX);

    const vk::DescriptorImageInfo image(*sampler_, *fontView_,
                                        vk::ImageLayout::eShaderReadOnlyOptimal);
    device_.updateDescriptorSets(
        vk::WriteDescriptorSet(set_, 0, 0, vk::DescriptorType::eCombinedImageSampler, image), {});
    ImGui::GetIO().Fonts->SetTexID(
        reinterpret_cast<ImTextureID>(reinterpret_cast<uintptr_t>(static_cast<VkImage>(*font_))));
}

void ImGuiVulkan::ensure(HostBuffer& b, vk::DeviceSize bytes, vk::BufferUsageFlags usage) {
    if (b.buffer && b.size >= bytes)
        return;
    const vk::DeviceSize size = std::max<vk::DeviceSize>(bytes * 3 / 2, 4096);
    b.memory.reset();
    b.buffer = device_.createBufferUnique({{}, size, usage});
    const auto needs = device_.getBufferMemoryRequirements(*b.buffer);
    b.memory = device_.allocateMemoryUnique(
        {needs.size,
         memoryType(needs.memoryTypeBits, vk::MemoryPropertyFlagBits::eHostVisible |
                                              vk::MemoryPropertyFlagBits::eHostCoherent)});
    device_.bindBufferMemory(*b.buffer, *b.memory, 0);
    b.size = size;
}

void ImGuiVulkan::draw(const ImDrawData* data, vk::CommandBuffer cmd) {
    if (!data || data->TotalVtxCount == 0 || data->DisplaySize.x <= 0.0f)
        return;
    const vk::DeviceSize vertexBytes = data->TotalVtxCount * sizeof(ImDrawVert);
    const vk::DeviceSize indexBytes = data->TotalIdxCount * sizeof(ImDrawIdx);
    ensure(vertices_, vertexBytes, vk::BufferUsageFlagBits::eVertexBuffer);
    ensure(indices_, indexBytes, vk::BufferUsageFlagBits::eIndexBuffer);
    auto* v = static_cast<ImDrawVert*>(device_.mapMemory(*vertices_.memory, 0, vertexBytes));
    auto* i = static_cast<ImDrawIdx*>(device_.mapMemory(*indices_.memory, 0, indexBytes));
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        std::memcpy(v, list->VtxBuffer.Data, list->VtxBuffer.Size * sizeof(ImDrawVert));
        std::memcpy(i, list->IdxBuffer.Data, list->IdxBuffer.Size * sizeof(ImDrawIdx));
        v += list->VtxBuffer.Size;
        i += list->IdxBuffer.Size;
    }
    device_.unmapMemory(*vertices_.memory);
    device_.unmapMemory(*indices_.memory);

    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, set_, {});
    cmd.bindVertexBuffers(0, *vertices_.buffer, vk::DeviceSize(0));
    cmd.bindIndexBuffer(*indices_.buffer, 0,
                        sizeof(ImDrawIdx) == 2 ? vk::IndexType::eUint16 : vk::IndexType::eUint32);
    const ImVec2 origin = data->DisplayPos, size = data->DisplaySize;
    const ImVec2 scale = data->FramebufferScale;
    const WindowTransform transform{
        {2.0f / size.x, 2.0f / size.y},
        {-1.0f - origin.x * 2.0f / size.x, -1.0f - origin.y * 2.0f / size.y}};
    cmd.pushConstants(*layout_, vk::ShaderStageFlagBits::eVertex, 0, sizeof transform, &transform);
    cmd.setViewport(0, vk::Viewport(0.0f, 0.0f, size.x * scale.x, size.y * scale.y, 0.0f, 1.0f));
    uint32_t vertexBase = 0, indexBase = 0;
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        for (const ImDrawCmd& c : list->CmdBuffer) {
            if (c.UserCallback) // the viewer adds none
                continue;
            const float x0 = std::max((c.ClipRect.x - origin.x) * scale.x, 0.0f);
            const float y0 = std::max((c.ClipRect.y - origin.y) * scale.y, 0.0f);
            const float x1 = (c.ClipRect.z - origin.x) * scale.x;
            const float y1 = (c.ClipRect.w - origin.y) * scale.y;
            if (x1 <= x0 || y1 <= y0)
                continue;
            cmd.setScissor(
                0, vk::Rect2D({static_cast<int32_t>(x0), static_cast<int32_t>(y0)},
                              {static_cast<uint32_t>(x1 - x0), static_cast<uint32_t>(y1 - y0)}));
            cmd.drawIndexed(c.ElemCount, 1, indexBase + c.IdxOffset,
                            static_cast<int32_t>(vertexBase + c.VtxOffset), 0);
        }
        vertexBase += static_cast<uint32_t>(list->VtxBuffer.Size);
        indexBase += static_cast<uint32_t>(list->IdxBuffer.Size);
    }
}

} // namespace cloudscape::cli
