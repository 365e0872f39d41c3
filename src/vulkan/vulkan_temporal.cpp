// The temporal reconstruction on the Vulkan backend. Per frame, one submission: the shared march
// pass (render_clouds.comp) in block mode marches one pixel of every 4x4 block into block-sized
// fresh records, then temporal_resolve.comp (the model's resolveTemporalPixel) rebuilds every
// pixel from them and the previous frame's result, which stays on the device in ping-pong
// buffers. The device, pipelines, textures and history live as long as the renderer. Both
// passes' descriptor sets are built from src/model/interface.glsl.h. Plumbing only: the physics
// is in src/model.
#include <cloudscape/error.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/temporal_impl.h"
#include "model/interface.glsl.h"
#include "model/temporal.glsl.h"
#include "vulkan/compute_pass.h"
#include "vulkan/march_pass.h"
#include "vulkan/model_textures.h"
#include "vulkan/submit.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

const uint32_t kTemporalResolveSpirv[] = {
#include "shaders/temporal_resolve.spv.inc"
};

constexpr int kWorkgroup = 8; // local_size_x/y of temporal_resolve.comp

class VulkanTemporal final : public TemporalRenderer::Impl {
public:
    VulkanTemporal(const SceneResources& resources, const BackendOptions& options);
    ~VulkanTemporal() override;
    RenderResult renderFrame(const Scene& scene, int frameIndex) override;

private:
    void allocateForSize(const Scene& scene);
    void writeDescriptors();
    RenderResult render(const Scene& scene, int frameIndex);

    // Declared first so it is destroyed last, after everything created on it.
    vulkan::Context ctx_;
    const SceneResources& resources_;
    std::unique_ptr<vulkan::MarchPass> march_;
    std::unique_ptr<vulkan::ComputePass> resolve_;
    std::unique_ptr<vulkan::ModelTextures> textures_;
    vk::UniqueDescriptorPool pool_;
    std::array<vk::DescriptorSet, 2> resolveSets_; // [p] reads history p, writes 1 - p
    vk::UniqueQueryPool queries_;

    std::unique_ptr<vulkan::ResourceSet> persistent_; // parameter blocks and counters
    vulkan::Buffer* cloudUbo_ = nullptr;
    vulkan::Buffer* frameUbo_ = nullptr;
    vulkan::Buffer* previousUbo_ = nullptr;
    vulkan::Buffer* counters_ = nullptr;

    // Per image size: reallocated when the size changes.
    std::unique_ptr<vulkan::ResourceSet> sized_;
    int width_ = 0, height_ = 0, blocksX_ = 0, blocksY_ = 0;
    vulkan::Buffer *fresh_ = nullptr, *unusedComposite_ = nullptr, *outColour_ = nullptr,
                   *sceneDepth_ = nullptr;
    std::array<vulkan::Buffer*, 2> history_{};

    int current_ = 0; // the ping-pong half holding the last frame's result
    bool haveHistory_ = false;
    int lastFrame_ = -2;
    float lastTime_ = 0.0f;
};

VulkanTemporal::VulkanTemporal(const SceneResources& resources, const BackendOptions& options)
    : ctx_(options.device, options.validation), resources_(resources) {
    vulkan::translateVulkanErrors("temporal renderer set-up", [&] {
        march_ = std::make_unique<vulkan::MarchPass>(ctx_);
        resolve_ = std::make_unique<vulkan::ComputePass>(
            ctx_, model::RESOLVE_PASS, kTemporalResolveSpirv, sizeof kTemporalResolveSpirv);
        const auto sizes = vulkan::descriptorPoolSizes({{&model::RESOLVE_PASS, 2}});
        pool_ = ctx_.device.createDescriptorPoolUnique({vk::DescriptorPoolCreateFlags{}, 2, sizes});
        const std::array<vk::DescriptorSetLayout, 2> layouts = {resolve_->setLayout(),
                                                                resolve_->setLayout()};
        const auto sets = ctx_.device.allocateDescriptorSets({*pool_, layouts});
        resolveSets_ = {sets[0], sets[1]};
        queries_ = ctx_.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, 3});
        // The textures once, for every frame.
        textures_ = std::make_unique<vulkan::ModelTextures>(ctx_, resources_);
        persistent_ = std::make_unique<vulkan::ResourceSet>(ctx_);
        const auto uniform = vk::BufferUsageFlagBits::eUniformBuffer;
        cloudUbo_ = &persistent_->hostBuffer(sizeof(model::CloudParams), uniform);
        frameUbo_ = &persistent_->hostBuffer(sizeof(model::FrameParams), uniform);
        previousUbo_ = &persistent_->hostBuffer(sizeof(model::FrameParams), uniform);
        counters_ = &persistent_->hostBuffer(sizeof(model::FrameCounters),
                                             vk::BufferUsageFlagBits::eStorageBuffer |
                                                 vk::BufferUsageFlagBits::eTransferDst);
    });
}

VulkanTemporal::~VulkanTemporal() {
    ctx_.device.waitIdle();
}

void VulkanTemporal::allocateForSize(const Scene& scene) {
    const size_t pixels = static_cast<size_t>(scene.width) * scene.height;
    if (pixels * sizeof(model::CloudTexel) > ctx_.properties.limits.maxStorageBufferRange)
        throw Error("image " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                    " needs a " + std::to_string(pixels * sizeof(model::CloudTexel)) +
                    "-byte storage buffer, beyond this device's limit of " +
                    std::to_string(ctx_.properties.limits.maxStorageBufferRange) + " bytes");
    ctx_.device.waitIdle();
    sized_ = std::make_unique<vulkan::ResourceSet>(ctx_);
    width_ = scene.width;
    height_ = scene.height;
    const glm::ivec2 blocks = model::temporalBlockCount(glm::ivec2(width_, height_));
    blocksX_ = blocks.x;
    blocksY_ = blocks.y;
    const size_t blockCount = static_cast<size_t>(blocksX_) * blocksY_;
    const auto storage = vk::BufferUsageFlagBits::eStorageBuffer;
    // Host-visible throughout: the result is read back every frame, and on lavapipe (or any
    // unified-memory device) there is no faster memory to keep the history in.
    fresh_ = &sized_->hostBuffer(blockCount * sizeof(model::CloudTexel), storage);
    unusedComposite_ = &sized_->hostBuffer(16, storage); // block mode writes no composite
    outColour_ = &sized_->hostBuffer(pixels * 16, storage);
    sceneDepth_ = &sized_->hostBuffer(pixels * 4, storage); // read only with a depth buffer
    for (int p = 0; p < 2; ++p)
        history_[p] = &sized_->hostBuffer(pixels * sizeof(model::CloudTexel), storage);
    writeDescriptors();
    haveHistory_ = false;
}

void VulkanTemporal::writeDescriptors() {
    march_->bind(ctx_, *textures_,
                 {cloudUbo_, frameUbo_, sceneDepth_, fresh_, unusedComposite_, counters_});
    for (int p = 0; p < 2; ++p)
        vulkan::DescriptorWriter(model::RESOLVE_PASS, resolveSets_[p])
            .buffer(model::RESOLVE_CLOUD_PARAMS, *cloudUbo_)
            .buffer(model::RESOLVE_FRAME_PARAMS, *frameUbo_)
            .buffer(model::RESOLVE_PREVIOUS_FRAME, *previousUbo_)
            .buffer(model::RESOLVE_HISTORY, *history_[p])
            .buffer(model::RESOLVE_FRESH, *fresh_)
            .buffer(model::RESOLVE_OUT_HISTORY, *history_[1 - p])
            .buffer(model::RESOLVE_OUT_COMPOSITE, *outColour_)
            .buffer(model::RESOLVE_SCENE_DEPTH, *sceneDepth_)
            .buffer(model::RESOLVE_COUNTERS, *counters_)
            .commit(ctx_.device);
}

RenderResult VulkanTemporal::renderFrame(const Scene& scene, int frameIndex) {
    // Reduced-resolution clouds, as on the CPU: the reconstruction and its history run at the
    // pass size, and each resolved frame is upsampled.
    if (scene.cloudResolution < 1.0f)
        return renderAtCloudResolution(
            scene, resources_, [&](const Scene& pass) { return renderFrame(pass, frameIndex); });
    RenderResult out = vulkan::translateVulkanErrors("temporal rendering",
                                                     [&] { return render(scene, frameIndex); });
    out.stats.validationMessages = ctx_.takeValidationMessages();
    return out;
}

RenderResult VulkanTemporal::render(const Scene& scene, int frameIndex) {
    const auto start = std::chrono::steady_clock::now();
    if (scene.width != width_ || scene.height != height_)
        allocateForSize(scene);
    const bool continues = haveHistory_ && lastFrame_ == frameIndex - 1;
    const size_t pixels = static_cast<size_t>(width_) * height_;
    const size_t blocks = static_cast<size_t>(blocksX_) * blocksY_;

    // As on the CPU: the march's jitter changes once per 16-frame cycle.
    const model::CloudParams cloud = makeCloudParams(scene, resources_);
    model::FrameParams frame = makeFrameParams(scene, frameIndex / model::TEMPORAL_CYCLE);
    // The scene depth buffer, if any, ends the marches as in the full-frame renderer.
    const std::vector<float> depth = sceneDepthFor(scene, resources_);
    frame.hasSceneDepth = depth.empty() ? 0 : 1;
    if (!depth.empty())
        std::memcpy(sceneDepth_->mapped, depth.data(), depth.size() * sizeof(float));
    std::memcpy(cloudUbo_->mapped, &cloud, sizeof cloud);
    std::memcpy(frameUbo_->mapped, &frame, sizeof frame);
    if (!continues) // not read without history, but keep it defined
        std::memcpy(previousUbo_->mapped, &frame, sizeof frame);
    const model::ResolvePush resolvePush = {frameIndex, continues ? scene.timeS - lastTime_ : 0.0f,
                                            continues ? 1 : 0, 0};
    const int p = current_, q = 1 - current_;

    const bool timed = ctx_.timestampValidBits > 0;
    vulkan::submitAndWait(ctx_, [&](vk::CommandBuffer cmd) {
        cmd.resetQueryPool(*queries_, 0, 3);
        vulkan::resetCounters(cmd, *counters_);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries_, 0);
        // 1. One pixel per block, in tiles of blocks.
        march_->recordBlocks(cmd, blocksX_, blocksY_, frameIndex);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries_, 1);
        // 2. The resolve reads what the march wrote.
        vulkan::shaderWritesToShader(cmd);
        resolve_->bind(cmd, resolveSets_[p]);
        resolve_->push(cmd, resolvePush);
        cmd.dispatch(static_cast<uint32_t>((width_ + kWorkgroup - 1) / kWorkgroup),
                     static_cast<uint32_t>((height_ + kWorkgroup - 1) / kWorkgroup), 1);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries_, 2);
        vulkan::shaderWritesToHost(cmd);
    });

    // Read back. Host memory may be non-coherent-cached: invalidate before reading.
    for (const vulkan::Buffer* b : {history_[q], outColour_})
        ctx_.device.invalidateMappedMemoryRanges(
            vk::MappedMemoryRange(b->memory, 0, VK_WHOLE_SIZE));
    RenderResult out;
    allocateResult(out, width_, height_);
    const auto* c = static_cast<const model::CloudTexel*>(history_[q]->mapped);
    const auto* k = static_cast<const float*>(outColour_->mapped);
    for (size_t i = 0; i < pixels; ++i)
        storePixel(out, i, glm::vec3(c[i].cloud), c[i].cloud.w,
                   glm::vec3(k[i * 4], k[i * 4 + 1], k[i * 4 + 2]), c[i].depth);
    const model::FrameCounters totals = vulkan::readCounters(ctx_, *counters_);
    out.stats.densitySamples = vulkan::densitySamples(totals);
    out.stats.lightSamples = vulkan::lightSamples(totals);
    breakdown.reprojected = static_cast<double>(totals.reprojected) / pixels;
    breakdown.fallback = static_cast<double>(totals.fallback) / pixels;
    breakdown.marched = 1.0 - breakdown.reprojected - breakdown.fallback;

    out.stats.backend = "vulkan: " + std::string(ctx_.properties.deviceName.data());
    out.stats.rays = blocks * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.gpuMemoryBytes =
        persistent_->deviceBytes() + sized_->deviceBytes() + textures_->deviceBytes();
    out.stats.gpuTextureBytes = textures_->textureBytes();
    if (timed) {
        std::array<uint64_t, 3> ticks{};
        const vk::Result r = ctx_.device.getQueryPoolResults(
            *queries_, 0, 3, sizeof ticks, ticks.data(), sizeof(uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        if (r == vk::Result::eSuccess) {
            const double ns = ctx_.properties.limits.timestampPeriod;
            out.stats.gpuMarchMs = static_cast<double>(ticks[1] - ticks[0]) * ns * 1e-6;
            out.stats.marchSeconds = out.stats.gpuMarchMs * 1e-3;
            out.stats.resolveSeconds = static_cast<double>(ticks[2] - ticks[1]) * ns * 1e-9;
        }
    }

    // This frame's result (half q) is the next frame's history.
    std::memcpy(previousUbo_->mapped, &frame, sizeof frame);
    current_ = q;
    haveHistory_ = true;
    lastFrame_ = frameIndex;
    lastTime_ = scene.timeS;
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace

std::unique_ptr<TemporalRenderer::Impl> makeVulkanTemporal(const SceneResources& resources,
                                                           const BackendOptions& options) {
    return std::make_unique<VulkanTemporal>(resources, options);
}

} // namespace cloudscape
