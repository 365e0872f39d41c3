// The Vulkan backend's full-frame render: uploads the textures and parameter blocks, runs the
// shared march pass (render_clouds.comp, the model's renderPixel) over the image in tiles, and
// reads the results back. Plumbing only.
#include <cloudscape/backend.h>
#include <cloudscape/error.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "vulkan/march_pass.h"
#include "vulkan/model_textures.h"
#include "vulkan/submit.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <array>
#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

void checkOutputLimit(const vulkan::Context& ctx, const Scene& scene, vk::DeviceSize outputBytes) {
    const vk::PhysicalDeviceLimits& limits = ctx.properties.limits;
    if (outputBytes > limits.maxStorageBufferRange)
        throw Error("image " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                    " needs a " + std::to_string(outputBytes) +
                    "-byte storage buffer, beyond this device's limit of " +
                    std::to_string(limits.maxStorageBufferRange) + " bytes");
}

RenderResult renderOnContext(vulkan::Context& ctx, const Scene& scene,
                             const SceneResources& resources, const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    const size_t pixels = static_cast<size_t>(scene.width) * scene.height;
    checkOutputLimit(ctx, scene, pixels * sizeof(model::CloudTexel));
    vulkan::MarchPass march(ctx);
    const vulkan::ModelTextures textures(ctx, resources);
    vulkan::ResourceSet res(ctx);

    // Parameters, declared once in src/model/params.glsl.h and uploaded as they are.
    const model::CloudParams cloud = makeCloudParams(scene, resources);
    model::FrameParams frame = makeFrameParams(scene);
    // The scene depth buffer, if any, as a storage buffer (a 1-float stand-in otherwise).
    const std::vector<float> depth = sceneDepthFor(scene, resources);
    frame.hasSceneDepth = depth.empty() ? 0 : 1;
    const auto storage = vk::BufferUsageFlagBits::eStorageBuffer;
    vulkan::Buffer& depthIn =
        res.hostBuffer(std::max<size_t>(depth.size(), 1) * sizeof(float), storage);
    if (!depth.empty())
        std::memcpy(depthIn.mapped, depth.data(), depth.size() * sizeof(float));
    vulkan::Buffer& cloudUbo =
        res.hostBuffer(sizeof cloud, vk::BufferUsageFlagBits::eUniformBuffer);
    vulkan::Buffer& frameUbo =
        res.hostBuffer(sizeof frame, vk::BufferUsageFlagBits::eUniformBuffer);
    std::memcpy(cloudUbo.mapped, &cloud, sizeof cloud);
    std::memcpy(frameUbo.mapped, &frame, sizeof frame);
    vulkan::Buffer& cloudOut = res.hostBuffer(pixels * sizeof(model::CloudTexel), storage);
    vulkan::Buffer& colourOut = res.hostBuffer(pixels * 16, storage);
    vulkan::Buffer& counters = res.hostBuffer(sizeof(model::FrameCounters),
                                              storage | vk::BufferUsageFlagBits::eTransferDst);
    march.bind(ctx, textures, {&cloudUbo, &frameUbo, &depthIn, &cloudOut, &colourOut, &counters});

    // The march, one row of tiles per submission so progress can be shown and no single
    // submission runs for long.
    const bool timed = ctx.timestampValidBits > 0;
    const vk::UniqueQueryPool queries =
        ctx.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, 2});
    const int tile = vulkan::MarchPass::kTile;
    const int tileRows = (scene.height + tile - 1) / tile;
    for (int row = 0; row < tileRows; ++row) {
        vulkan::submitAndWait(ctx, [&](vk::CommandBuffer cmd) {
            if (row == 0) {
                cmd.resetQueryPool(*queries, 0, 2);
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries, 0);
                vulkan::resetCounters(cmd, counters);
            }
            march.recordRows(cmd, scene.width, row * tile,
                             std::min(scene.height, (row + 1) * tile));
            if (row + 1 == tileRows) {
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries, 1);
                vulkan::shaderWritesToHost(cmd);
            }
        });
        if (progress)
            progress(static_cast<double>(row + 1) / tileRows);
    }

    // Read back. Host memory may be non-coherent-cached: invalidate before reading.
    for (const vulkan::Buffer* b : {&cloudOut, &colourOut})
        ctx.device.invalidateMappedMemoryRanges(vk::MappedMemoryRange(b->memory, 0, VK_WHOLE_SIZE));
    RenderResult out;
    allocateResult(out, scene.width, scene.height);
    const auto* c = static_cast<const model::CloudTexel*>(cloudOut.mapped);
    const auto* k = static_cast<const float*>(colourOut.mapped);
    for (size_t i = 0; i < pixels; ++i)
        storePixel(out, i, glm::vec3(c[i].cloud), c[i].cloud.w,
                   glm::vec3(k[i * 4], k[i * 4 + 1], k[i * 4 + 2]), c[i].depth);
    const model::FrameCounters totals = vulkan::readCounters(ctx, counters);
    out.stats.densitySamples = vulkan::densitySamples(totals);
    out.stats.lightSamples = vulkan::lightSamples(totals);
    out.stats.backend = "vulkan: " + std::string(ctx.properties.deviceName.data());
    out.stats.rays = pixels * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.gpuMemoryBytes = res.deviceBytes() + textures.deviceBytes();
    out.stats.gpuTextureBytes = textures.textureBytes();
    out.stats.gpuUploadMs = textures.uploadMs();
    if (timed) {
        std::array<uint64_t, 2> ticks{};
        const vk::Result r = ctx.device.getQueryPoolResults(
            *queries, 0, 2, sizeof ticks, ticks.data(), sizeof(uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (r == vk::Result::eSuccess)
            out.stats.gpuMarchMs = static_cast<double>(ticks[1] - ticks[0]) *
                                   ctx.properties.limits.timestampPeriod * 1e-6;
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
