// The Vulkan backend: uploads the textures and parameter blocks, runs render_clouds.comp (the
// model's renderPixel) over the image in tiles, and reads the results back. Plumbing only.
#include <cloudscape/backend.h>
#include <cloudscape/error.h>

#include <cloudscape/blue_noise.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <array>
#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

const uint32_t kRenderCloudsSpirv[] = {
#include "shaders/render_clouds.spv.inc"
};

constexpr uint32_t kTile = 256;    // pixels per side of one dispatch
constexpr uint32_t kWorkgroup = 8; // local_size_x/y of render_clouds.comp

struct Pipeline {
    vk::Device device;
    vk::DescriptorSetLayout setLayout;
    vk::PipelineLayout layout;
    vk::ShaderModule module;
    vk::Pipeline pipeline;
    vk::DescriptorPool pool;
    vk::Sampler sampler;
    vk::QueryPool queries;
    ~Pipeline() {
        if (!device)
            return;
        device.destroyQueryPool(queries);
        device.destroySampler(sampler);
        device.destroyDescriptorPool(pool);
        device.destroyPipeline(pipeline);
        device.destroyShaderModule(module);
        device.destroyPipelineLayout(layout);
        device.destroyDescriptorSetLayout(setLayout);
    }
};

void createPipeline(vulkan::Context& ctx, Pipeline& p) {
    p.device = ctx.device;
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    auto add = [&](uint32_t binding, vk::DescriptorType type) {
        bindings.emplace_back(binding, type, 1, vk::ShaderStageFlagBits::eCompute);
    };
    add(0, vk::DescriptorType::eUniformBuffer);
    add(1, vk::DescriptorType::eUniformBuffer);
    for (uint32_t b = 2; b <= 5; ++b)
        add(b, vk::DescriptorType::eCombinedImageSampler);
    for (uint32_t b = 6; b <= 9; ++b)
        add(b, vk::DescriptorType::eStorageBuffer);
    add(10, vk::DescriptorType::eCombinedImageSampler); // blue noise
    add(11, vk::DescriptorType::eStorageBuffer);        // scene depth
    // src/vulkan/vulkan_temporal.cpp (marchBindings) declares the same bindings: keep in step.
    p.setLayout = ctx.device.createDescriptorSetLayout({{}, bindings});
    // tileOrigin and temporalFrame (render_clouds.comp).
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, 3 * sizeof(int32_t));
    p.layout = ctx.device.createPipelineLayout({{}, p.setLayout, push});
    p.module = ctx.device.createShaderModule({{}, sizeof(kRenderCloudsSpirv), kRenderCloudsSpirv});
    const vk::ComputePipelineCreateInfo info(
        {},
        vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eCompute, p.module, "main"),
        p.layout);
    auto result = ctx.device.createComputePipeline(nullptr, info);
    if (result.result != vk::Result::eSuccess)
        throw Error("cannot create the cloud compute pipeline: " + vk::to_string(result.result));
    p.pipeline = result.value;
    const std::array<vk::DescriptorPoolSize, 3> sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 2),
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 5),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 5)};
    p.pool = ctx.device.createDescriptorPool({{}, 1, sizes});
    // Wrap addressing and trilinear filtering: the same sampler the CPU backend emulates.
    p.sampler = ctx.device.createSampler(vk::SamplerCreateInfo(
        {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eLinear,
        vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat,
        vk::SamplerAddressMode::eRepeat, 0.0f, VK_FALSE, 1.0f, VK_FALSE, vk::CompareOp::eNever,
        0.0f, VK_LOD_CLAMP_NONE));
    p.queries = ctx.device.createQueryPool({{}, vk::QueryType::eTimestamp, 4});
}

void checkLimits(const vulkan::Context& ctx, const Scene& scene, vk::DeviceSize outputBytes) {
    const vk::PhysicalDeviceLimits& limits = ctx.properties.limits;
    if (outputBytes > limits.maxStorageBufferRange)
        throw Error("image " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                    " needs a " + std::to_string(outputBytes) +
                    "-byte storage buffer, beyond this device's limit of " +
                    std::to_string(limits.maxStorageBufferRange) + " bytes");
    if (static_cast<uint32_t>(scene.weatherResolution) > limits.maxImageDimension2D)
        throw Error("weather.resolution " + std::to_string(scene.weatherResolution) +
                    " exceeds this device's 2D image limit of " +
                    std::to_string(limits.maxImageDimension2D));
}

vk::CommandBuffer beginCommands(vulkan::Context& ctx) {
    vk::CommandBuffer cmd = ctx.device.allocateCommandBuffers(
        {ctx.commandPool, vk::CommandBufferLevel::ePrimary, 1})[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    return cmd;
}

void submitAndWait(vulkan::Context& ctx, vk::CommandBuffer cmd) {
    cmd.end();
    vk::Fence fence = ctx.device.createFence({});
    ctx.queue.submit(vk::SubmitInfo({}, {}, cmd), fence);
    const vk::Result waited = ctx.device.waitForFences(fence, VK_TRUE, UINT64_MAX);
    ctx.device.destroyFence(fence);
    ctx.device.freeCommandBuffers(ctx.commandPool, cmd);
    if (waited != vk::Result::eSuccess)
        throw Error("waiting for the GPU failed: " + vk::to_string(waited));
}

RenderResult renderOnContext(vulkan::Context& ctx, const Scene& scene,
                             const SceneResources& resources, const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    const size_t pixels = static_cast<size_t>(scene.width) * scene.height;
    checkLimits(ctx, scene, pixels * 16);
    Pipeline pipe;
    createPipeline(ctx, pipe);
    vulkan::ResourceSet res(ctx);
    const bool timed = ctx.timestampValidBits > 0;

    // Parameters, declared once in src/model/params.glsl.h and uploaded as they are.
    const model::CloudParams cloud = makeCloudParams(scene);
    model::FrameParams frame = makeFrameParams(scene);
    // The scene depth buffer, if any, as a storage buffer (a 1-float stand-in otherwise).
    const std::vector<float> depth = sceneDepthFor(scene, resources);
    frame.sampling.z = depth.empty() ? 0 : 1;
    vulkan::Buffer& depthIn = res.hostBuffer(std::max<size_t>(depth.size(), 1) * sizeof(float),
                                             vk::BufferUsageFlagBits::eStorageBuffer);
    if (!depth.empty())
        std::memcpy(depthIn.mapped, depth.data(), depth.size() * sizeof(float));
    vulkan::Buffer& cloudUbo =
        res.hostBuffer(sizeof cloud, vk::BufferUsageFlagBits::eUniformBuffer);
    vulkan::Buffer& frameUbo =
        res.hostBuffer(sizeof frame, vk::BufferUsageFlagBits::eUniformBuffer);
    std::memcpy(cloudUbo.mapped, &cloud, sizeof cloud);
    std::memcpy(frameUbo.mapped, &frame, sizeof frame);
    const auto storage = vk::BufferUsageFlagBits::eStorageBuffer;
    vulkan::Buffer& cloudOut = res.hostBuffer(pixels * 16, storage);
    vulkan::Buffer& depthOut = res.hostBuffer(pixels * 4, storage);
    vulkan::Buffer& colourOut = res.hostBuffer(pixels * 16, storage);
    vulkan::Buffer& countsOut = res.hostBuffer(pixels * 8, storage);

    // Textures, uploaded with timestamps around the copies.
    vk::CommandBuffer upload = beginCommands(ctx);
    upload.resetQueryPool(pipe.queries, 0, 4);
    if (timed)
        upload.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, pipe.queries, 0);
    const vulkan::Image& base = res.texture(resources.noise.base, upload);
    const vulkan::Image& detail = res.texture(resources.noise.detail, upload);
    const vulkan::Image& curl = res.texture(resources.noise.curl, upload);
    const vulkan::Image& weather = res.texture(resources.weather, upload);
    const vulkan::Image& blue = res.texture(blueNoiseTexture(), upload);
    if (timed)
        upload.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, pipe.queries, 1);
    submitAndWait(ctx, upload);

    vk::DescriptorSet set = ctx.device.allocateDescriptorSets({pipe.pool, pipe.setLayout})[0];
    const std::array<vk::DescriptorBufferInfo, 6> bufferInfos = {
        vk::DescriptorBufferInfo(cloudUbo.buffer, 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(frameUbo.buffer, 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(cloudOut.buffer, 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(depthOut.buffer, 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(colourOut.buffer, 0, VK_WHOLE_SIZE),
        vk::DescriptorBufferInfo(countsOut.buffer, 0, VK_WHOLE_SIZE)};
    const vk::ImageLayout readOnly = vk::ImageLayout::eShaderReadOnlyOptimal;
    const std::array<vk::DescriptorImageInfo, 4> imageInfos = {
        vk::DescriptorImageInfo(pipe.sampler, base.view, readOnly),
        vk::DescriptorImageInfo(pipe.sampler, detail.view, readOnly),
        vk::DescriptorImageInfo(pipe.sampler, curl.view, readOnly),
        vk::DescriptorImageInfo(pipe.sampler, weather.view, readOnly)};
    std::vector<vk::WriteDescriptorSet> writes;
    for (uint32_t b = 0; b < 2; ++b)
        writes.emplace_back(set, b, 0, 1, vk::DescriptorType::eUniformBuffer, nullptr,
                            &bufferInfos[b]);
    for (uint32_t b = 0; b < 4; ++b)
        writes.emplace_back(set, 2 + b, 0, 1, vk::DescriptorType::eCombinedImageSampler,
                            &imageInfos[b]);
    for (uint32_t b = 0; b < 4; ++b)
        writes.emplace_back(set, 6 + b, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr,
                            &bufferInfos[2 + b]);
    // Blue noise is read with texelFetch, so the trilinear sampler never filters it.
    const vk::DescriptorImageInfo blueInfo(pipe.sampler, blue.view, readOnly);
    const vk::DescriptorBufferInfo depthInfo(depthIn.buffer, 0, VK_WHOLE_SIZE);
    writes.emplace_back(set, 10, 0, 1, vk::DescriptorType::eCombinedImageSampler, &blueInfo);
    writes.emplace_back(set, 11, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr, &depthInfo);
    ctx.device.updateDescriptorSets(writes, {});

    // The march, one row of tiles per submission so progress can be shown and no single
    // submission runs for long.
    const auto width = static_cast<uint32_t>(scene.width);
    const auto height = static_cast<uint32_t>(scene.height);
    const uint32_t tileRows = (height + kTile - 1) / kTile;
    for (uint32_t row = 0; row < tileRows; ++row) {
        vk::CommandBuffer cmd = beginCommands(ctx);
        if (timed && row == 0)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, pipe.queries, 2);
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, pipe.pipeline);
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, pipe.layout, 0, set, {});
        const uint32_t y0 = row * kTile;
        const uint32_t tileHeight = std::min(kTile, height - y0);
        for (uint32_t x0 = 0; x0 < width; x0 += kTile) {
            // temporalFrame -1: every pixel (block mode is src/vulkan/vulkan_temporal.cpp's).
            const std::array<int32_t, 3> origin = {static_cast<int32_t>(x0),
                                                   static_cast<int32_t>(y0), -1};
            cmd.pushConstants(pipe.layout, vk::ShaderStageFlagBits::eCompute, 0, sizeof origin,
                              origin.data());
            const uint32_t tileWidth = std::min(kTile, width - x0);
            cmd.dispatch((tileWidth + kWorkgroup - 1) / kWorkgroup,
                         (tileHeight + kWorkgroup - 1) / kWorkgroup, 1);
        }
        if (timed && row + 1 == tileRows)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, pipe.queries, 3);
        if (row + 1 == tileRows) {
            // Make the shader's writes visible to the host reads below.
            vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite,
                                     vk::AccessFlagBits::eHostRead);
            cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                                vk::PipelineStageFlagBits::eHost, {}, toHost, {}, {});
        }
        submitAndWait(ctx, cmd);
        if (progress)
            progress(static_cast<double>(row + 1) / tileRows);
    }

    // Read back. Host memory may be non-coherent-cached: invalidate before reading.
    for (const vulkan::Buffer* b : {&cloudOut, &depthOut, &colourOut, &countsOut})
        ctx.device.invalidateMappedMemoryRanges(vk::MappedMemoryRange(b->memory, 0, VK_WHOLE_SIZE));
    RenderResult out;
    allocateResult(out, scene.width, scene.height);
    const auto* c = static_cast<const float*>(cloudOut.mapped);
    const auto* d = static_cast<const float*>(depthOut.mapped);
    const auto* k = static_cast<const float*>(colourOut.mapped);
    const auto* n = static_cast<const uint32_t*>(countsOut.mapped);
    for (size_t i = 0; i < pixels; ++i) {
        storePixel(out, i, glm::vec3(c[i * 4], c[i * 4 + 1], c[i * 4 + 2]), c[i * 4 + 3],
                   glm::vec3(k[i * 4], k[i * 4 + 1], k[i * 4 + 2]), d[i]);
        out.stats.densitySamples += n[i * 2];
        out.stats.lightSamples += n[i * 2 + 1];
    }
    out.stats.backend = "vulkan: " + std::string(ctx.properties.deviceName.data());
    out.stats.rays = pixels * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.gpuMemoryBytes = res.deviceBytes();
    out.stats.gpuTextureBytes = res.textureBytes();
    if (timed) {
        std::array<uint64_t, 4> ticks{};
        const vk::Result r = ctx.device.getQueryPoolResults(
            pipe.queries, 0, 4, sizeof ticks, ticks.data(), sizeof(uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (r == vk::Result::eSuccess) {
            const double ns = ctx.properties.limits.timestampPeriod;
            out.stats.gpuUploadMs = static_cast<double>(ticks[1] - ticks[0]) * ns * 1e-6;
            out.stats.gpuMarchMs = static_cast<double>(ticks[3] - ticks[2]) * ns * 1e-6;
        }
    }
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace

RenderResult renderVulkan(const Scene& scene, const SceneResources& resources,
                          const BackendOptions& options, const ProgressCallback& progress) {
    if (scene.cloudResolution < 1.0f)
        return renderAtCloudResolution(scene, resources, [&](const Scene& pass) {
            return renderVulkan(pass, resources, options, progress);
        });
    vulkan::Context ctx(options.device, options.validation);
    RenderResult out = vulkan::translateVulkanErrors(
        "rendering", [&] { return renderOnContext(ctx, scene, resources, progress); });
    out.stats.validationMessages = ctx.takeValidationMessages();
    return out;
}

} // namespace cloudscape
