#pragma once
// Dear ImGui's draw lists drawn with Vulkan inside the viewer's render pass. Debian's libimgui
// ships its Vulkan backend prebuilt against the loader's exported functions, while this tool
// opens the loader at run time (a machine without Vulkan must still run the CPU backend), so the
// viewer draws the lists itself: one pipeline, the font atlas, and vertex and index buffers that
// grow as needed. Plumbing only.
#include <vulkan/vulkan.hpp>

struct ImDrawData;

namespace cloudscape::cli {

class ImGuiVulkan {
public:
    // Uploads the current ImGui context's font atlas; throws cloudscape::Error.
    ImGuiVulkan(vk::PhysicalDevice physical, vk::Device device, vk::Queue queue,
                vk::CommandPool pool, vk::RenderPass renderPass);
    ~ImGuiVulkan();
    ImGuiVulkan(const ImGuiVulkan&) = delete;
    ImGuiVulkan& operator=(const ImGuiVulkan&) = delete;

    // Records the draw data into `cmd` (inside the render pass; the previous frame's commands
    // must be complete, as the presenter waits for them).
    void draw(const ImDrawData* data, vk::CommandBuffer cmd);

private:
    struct HostBuffer {
        vk::UniqueBuffer buffer;
        vk::UniqueDeviceMemory memory;
        vk::DeviceSize size = 0;
    };
    void ensure(HostBuffer& b, vk::DeviceSize bytes, vk::BufferUsageFlags usage);
    uint32_t memoryType(uint32_t bits, vk::MemoryPropertyFlags flags) const;
    void createPipeline(vk::RenderPass renderPass);
    void uploadFonts(vk::Queue queue, vk::CommandPool pool);

    vk::PhysicalDevice physical_;
    vk::Device device_;
    vk::UniqueSampler sampler_;
    vk::UniqueDescriptorSetLayout setLayout_;
    vk::UniqueDescriptorPool descriptorPool_;
    vk::DescriptorSet set_;
    vk::UniquePipelineLayout layout_;
    vk::UniquePipeline pipeline_;
    vk::UniqueImage font_;
    vk::UniqueDeviceMemory fontMemory_;
    vk::UniqueImageView fontView_;
    HostBuffer vertices_;
    HostBuffer indices_;
};

} // namespace cloudscape::cli
