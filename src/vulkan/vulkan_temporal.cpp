// The temporal reconstruction on the Vulkan backend. Per frame, one submission: render_clouds.comp
// in block mode marches one pixel of every 4x4 block into block-sized fresh buffers, then
// temporal_resolve.comp (the model's resolveTemporalPixel) rebuilds every pixel from them and the
// previous frame's result, which stays on the device in ping-pong buffers. The device, pipelines,
// textures and history live as long as the renderer. Plumbing only: the physics is in src/model.
#include <cloudscape/blue_noise.h>
#include <cloudscape/error.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/temporal_impl.h"
#include "model/temporal.glsl.h"
#include "vulkan/vulkan_context.h"
#include "vulkan/vulkan_resources.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

const uint32_t kRenderCloudsSpirv[] = {
#include "shaders/render_clouds.spv.inc"
};
const uint32_t kTemporalResolveSpirv[] = {
#include "shaders/temporal_resolve.spv.inc"
};

constexpr uint32_t kTileBlocks = 256; // blocks per side of one march dispatch
constexpr uint32_t kWorkgroup = 8;    // local_size_x/y of both shaders

struct ComputePipeline {
    vk::Device device;
    vk::DescriptorSetLayout setLayout;
    vk::PipelineLayout layout;
    vk::ShaderModule module;
    vk::Pipeline pipeline;

    void create(vulkan::Context& ctx, const uint32_t* spirv, size_t bytes,
                const std::vector<vk::DescriptorSetLayoutBinding>& bindings, uint32_t pushBytes,
                const char* name) {
        device = ctx.device;
        setLayout = device.createDescriptorSetLayout({{}, bindings});
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eCompute, 0, pushBytes);
        layout = device.createPipelineLayout({{}, setLayout, push});
        module = device.createShaderModule({{}, bytes, spirv});
        const vk::ComputePipelineCreateInfo info(
            {},
            vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eCompute, module,
                                              "main"),
            layout);
        auto result = device.createComputePipeline(nullptr, info);
        if (result.result != vk::Result::eSuccess)
            throw Error(std::string("cannot create the ") + name +
                        " pipeline: " + vk::to_string(result.result));
        pipeline = result.value;
    }
    ~ComputePipeline() {
        if (!device)
            return;
        device.destroyPipeline(pipeline);
        device.destroyShaderModule(module);
        device.destroyPipelineLayout(layout);
        device.destroyDescriptorSetLayout(setLayout);
    }
};

std::vector<vk::DescriptorSetLayoutBinding>
bindingsOf(std::initializer_list<std::pair<uint32_t, vk::DescriptorType>> list) {
    std::vector<vk::DescriptorSetLayoutBinding> out;
    for (const auto& [binding, type] : list)
        out.emplace_back(binding, type, 1, vk::ShaderStageFlagBits::eCompute);
    return out;
}

// render_clouds.comp's interface; it must stay the same as the full-frame renderer's
// (src/vulkan/vulkan_renderer.cpp), which dispatches the same shader.
std::vector<vk::DescriptorSetLayoutBinding> marchBindings() {
    using T = vk::DescriptorType;
    return bindingsOf({{0, T::eUniformBuffer},
                       {1, T::eUniformBuffer},
                       {2, T::eCombinedImageSampler},
                       {3, T::eCombinedImageSampler},
                       {4, T::eCombinedImageSampler},
                       {5, T::eCombinedImageSampler},
                       {6, T::eStorageBuffer},
                       {7, T::eStorageBuffer},
                       {8, T::eStorageBuffer},
                       {9, T::eStorageBuffer},
                       {10, T::eCombinedImageSampler}, // blue noise
                       {11, T::eStorageBuffer}});      // scene depth
}

// temporal_resolve.comp's interface: 0-2 cloud, frame and previous-frame parameters, 3-12 the
// history, fresh and output buffers, 13 the scene depth.
std::vector<vk::DescriptorSetLayoutBinding> resolveBindings() {
    std::vector<vk::DescriptorSetLayoutBinding> out =
        bindingsOf({{0, vk::DescriptorType::eUniformBuffer},
                    {1, vk::DescriptorType::eUniformBuffer},
                    {2, vk::DescriptorType::eUniformBuffer}});
    for (uint32_t b = 3; b <= 13; ++b)
        out.emplace_back(b, vk::DescriptorType::eStorageBuffer, 1,
                         vk::ShaderStageFlagBits::eCompute);
    return out;
}

struct MarchPush {
    int32_t tileX, tileY, temporalFrame;
};
struct ResolvePush {
    int32_t frameIndex;
    float dt;
    int32_t haveHistory;
};

class VulkanTemporal final : public TemporalRenderer::Impl {
public:
    VulkanTemporal(const SceneResources& resources, const BackendOptions& options);
    ~VulkanTemporal() override;
    RenderResult renderFrame(const Scene& scene, int frameIndex) override;
    TemporalState saveState() const override;
    void restoreState(const TemporalState& state) override;
    std::string backendName() const override {
        return "vulkan: " + std::string(ctx_.properties.deviceName.data());
    }

private:
    void setUp();
    void release();
    void allocateForSize(int width, int height);
    void writeDescriptors();
    RenderResult render(const Scene& scene, int frameIndex);

    // Declared first so it is destroyed last, after everything created on it.
    vulkan::Context ctx_;
    const SceneResources& resources_;
    ComputePipeline march_, resolve_;
    vk::DescriptorPool pool_;
    vk::Sampler sampler_;
    vk::QueryPool queries_;
    vk::DescriptorSet marchSet_;
    std::array<vk::DescriptorSet, 2> resolveSets_; // [p] reads history p, writes 1 - p

    std::unique_ptr<vulkan::ResourceSet> persistent_; // textures and parameter blocks
    const vulkan::Image* textures_[5] = {};           // base, detail, curl, weather, blue noise
    vulkan::Buffer* cloudUbo_ = nullptr;
    vulkan::Buffer* frameUbo_ = nullptr;
    vulkan::Buffer* previousUbo_ = nullptr;

    // Per image size: reallocated when the size changes.
    std::unique_ptr<vulkan::ResourceSet> sized_;
    int width_ = 0, height_ = 0, blocksX_ = 0, blocksY_ = 0;
    vulkan::Buffer *freshCloud_ = nullptr, *freshDepth_ = nullptr, *freshColour_ = nullptr,
                   *freshCounts_ = nullptr, *outColour_ = nullptr, *outSource_ = nullptr,
                   *sceneDepth_ = nullptr;
    std::array<vulkan::Buffer*, 2> historyCloud_{}, historyDepth_{}, historyWeight_{};

    int current_ = 0; // the ping-pong half holding the last frame's result
    bool haveHistory_ = false;
    int lastFrame_ = -2;
    float lastTime_ = 0.0f;
    model::FrameParams lastFrameParams_{}; // also in previousUbo_, for the next resolve
};

VulkanTemporal::VulkanTemporal(const SceneResources& resources, const BackendOptions& options)
    : ctx_(options.device, options.validation), resources_(resources) {
    try {
        vulkan::translateVulkanErrors("temporal renderer set-up", [&] { setUp(); });
    } catch (...) {
        release(); // the destructor does not run for a constructor that throws
        throw;
    }
}

VulkanTemporal::~VulkanTemporal() {
    release();
}

// Destroying null handles is allowed, so this is safe after a partial set-up.
void VulkanTemporal::release() {
    ctx_.device.waitIdle();
    sized_.reset();
    persistent_.reset();
    ctx_.device.destroyQueryPool(queries_);
    ctx_.device.destroySampler(sampler_);
    ctx_.device.destroyDescriptorPool(pool_);
}

void VulkanTemporal::setUp() {
    march_.create(ctx_, kRenderCloudsSpirv, sizeof kRenderCloudsSpirv, marchBindings(),
                  sizeof(MarchPush), "cloud march");
    resolve_.create(ctx_, kTemporalResolveSpirv, sizeof kTemporalResolveSpirv, resolveBindings(),
                    sizeof(ResolvePush), "temporal resolve");
    const std::array<vk::DescriptorPoolSize, 3> sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 2 + 2 * 3),
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 5),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 5 + 2 * 11)};
    pool_ = ctx_.device.createDescriptorPool({{}, 3, sizes});
    marchSet_ = ctx_.device.allocateDescriptorSets({pool_, march_.setLayout})[0];
    const std::array<vk::DescriptorSetLayout, 2> resolveLayouts = {resolve_.setLayout,
                                                                   resolve_.setLayout};
    const auto sets = ctx_.device.allocateDescriptorSets({pool_, resolveLayouts});
    resolveSets_ = {sets[0], sets[1]};
    // Wrap addressing and trilinear filtering: the same sampler the CPU backend emulates.
    sampler_ = ctx_.device.createSampler(vk::SamplerCreateInfo(
        {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eLinear,
        vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat,
        vk::SamplerAddressMode::eRepeat, 0.0f, VK_FALSE, 1.0f, VK_FALSE, vk::CompareOp::eNever,
        0.0f, VK_LOD_CLAMP_NONE));
    queries_ = ctx_.device.createQueryPool({{}, vk::QueryType::eTimestamp, 3});

    // The textures once, for every frame.
    if (static_cast<uint32_t>(resources_.weather.width) >
            ctx_.properties.limits.maxImageDimension2D ||
        static_cast<uint32_t>(resources_.weather.height) >
            ctx_.properties.limits.maxImageDimension2D)
        throw Error("the weather map exceeds this device's 2D image limit of " +
                    std::to_string(ctx_.properties.limits.maxImageDimension2D));
    persistent_ = std::make_unique<vulkan::ResourceSet>(ctx_);
    const auto uniform = vk::BufferUsageFlagBits::eUniformBuffer;
    cloudUbo_ = &persistent_->hostBuffer(sizeof(model::CloudParams), uniform);
    frameUbo_ = &persistent_->hostBuffer(sizeof(model::FrameParams), uniform);
    previousUbo_ = &persistent_->hostBuffer(sizeof(model::FrameParams), uniform);
    vk::CommandBuffer cmd = ctx_.device.allocateCommandBuffers(
        {ctx_.commandPool, vk::CommandBufferLevel::ePrimary, 1})[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    textures_[0] = &persistent_->texture(resources_.noise.base, cmd);
    textures_[1] = &persistent_->texture(resources_.noise.detail, cmd);
    textures_[2] = &persistent_->texture(resources_.noise.curl, cmd);
    textures_[3] = &persistent_->texture(resources_.weather, cmd);
    textures_[4] = &persistent_->texture(blueNoiseTexture(), cmd);
    cmd.end();
    ctx_.queue.submit(vk::SubmitInfo({}, {}, cmd), nullptr);
    ctx_.queue.waitIdle();
    ctx_.device.freeCommandBuffers(ctx_.commandPool, cmd);
    persistent_->releaseStaging(); // 10.7 MB that would otherwise live as long as the renderer
}

void VulkanTemporal::allocateForSize(int width, int height) {
    const size_t pixels = static_cast<size_t>(width) * height;
    if (pixels * 16 > ctx_.properties.limits.maxStorageBufferRange)
        throw Error("image " + std::to_string(width) + "x" + std::to_string(height) + " needs a " +
                    std::to_string(pixels * 16) +
                    "-byte storage buffer, beyond this device's limit of " +
                    std::to_string(ctx_.properties.limits.maxStorageBufferRange) + " bytes");
    ctx_.device.waitIdle();
    sized_ = std::make_unique<vulkan::ResourceSet>(ctx_);
    width_ = width;
    height_ = height;
    blocksX_ = (width_ + model::TEMPORAL_BLOCK - 1) / model::TEMPORAL_BLOCK;
    blocksY_ = (height_ + model::TEMPORAL_BLOCK - 1) / model::TEMPORAL_BLOCK;
    const size_t blocks = static_cast<size_t>(blocksX_) * blocksY_;
    const auto storage = vk::BufferUsageFlagBits::eStorageBuffer;
    // Host-visible throughout: the result is read back every frame, and on lavapipe (or any
    // unified-memory device) there is no faster memory to keep the history in.
    freshCloud_ = &sized_->hostBuffer(blocks * 16, storage);
    freshDepth_ = &sized_->hostBuffer(blocks * 4, storage);
    freshColour_ = &sized_->hostBuffer(blocks * 16, storage); // written by the shader, unused
    freshCounts_ = &sized_->hostBuffer(blocks * 8, storage);
    outColour_ = &sized_->hostBuffer(pixels * 16, storage);
    outSource_ = &sized_->hostBuffer(pixels * 4, storage);
    sceneDepth_ = &sized_->hostBuffer(pixels * 4, storage); // read only with a depth buffer
    for (int p = 0; p < 2; ++p) {
        historyCloud_[p] = &sized_->hostBuffer(pixels * 16, storage);
        historyDepth_[p] = &sized_->hostBuffer(pixels * 4, storage);
        historyWeight_[p] = &sized_->hostBuffer(pixels * 4, storage);
    }
    writeDescriptors();
    haveHistory_ = false;
}

void VulkanTemporal::writeDescriptors() {
    auto info = [](const vulkan::Buffer* b) {
        return vk::DescriptorBufferInfo(b->buffer, 0, VK_WHOLE_SIZE);
    };
    // Kept alive until updateDescriptorSets below: the writes point into these arrays.
    std::vector<vk::DescriptorBufferInfo> buffers;
    buffers.reserve(64);
    std::vector<vk::DescriptorImageInfo> images;
    std::vector<vk::WriteDescriptorSet> writes;
    auto buffer = [&](vk::DescriptorSet set, uint32_t binding, vk::DescriptorType type,
                      const vulkan::Buffer* b) {
        buffers.push_back(info(b));
        writes.emplace_back(set, binding, 0, 1, type, nullptr, &buffers.back());
    };
    const auto ubo = vk::DescriptorType::eUniformBuffer;
    const auto ssbo = vk::DescriptorType::eStorageBuffer;

    buffer(marchSet_, 0, ubo, cloudUbo_);
    buffer(marchSet_, 1, ubo, frameUbo_);
    images.reserve(5);
    for (uint32_t t = 0; t < 4; ++t) {
        images.emplace_back(sampler_, textures_[t]->view, vk::ImageLayout::eShaderReadOnlyOptimal);
        writes.emplace_back(marchSet_, 2 + t, 0, 1, vk::DescriptorType::eCombinedImageSampler,
                            &images.back());
    }
    buffer(marchSet_, 6, ssbo, freshCloud_);
    buffer(marchSet_, 7, ssbo, freshDepth_);
    buffer(marchSet_, 8, ssbo, freshColour_);
    buffer(marchSet_, 9, ssbo, freshCounts_);
    // Blue noise is read with texelFetch, so the trilinear sampler never filters it.
    images.emplace_back(sampler_, textures_[4]->view, vk::ImageLayout::eShaderReadOnlyOptimal);
    writes.emplace_back(marchSet_, 10, 0, 1, vk::DescriptorType::eCombinedImageSampler,
                        &images.back());
    buffer(marchSet_, 11, ssbo, sceneDepth_);

    for (int p = 0; p < 2; ++p) {
        const vk::DescriptorSet set = resolveSets_[p];
        const int q = 1 - p;
        buffer(set, 0, ubo, cloudUbo_);
        buffer(set, 1, ubo, frameUbo_);
        buffer(set, 2, ubo, previousUbo_);
        buffer(set, 3, ssbo, historyCloud_[p]);
        buffer(set, 4, ssbo, historyDepth_[p]);
        buffer(set, 5, ssbo, freshCloud_);
        buffer(set, 6, ssbo, freshDepth_);
        buffer(set, 7, ssbo, historyCloud_[q]);
        buffer(set, 8, ssbo, historyDepth_[q]);
        buffer(set, 9, ssbo, outColour_);
        buffer(set, 10, ssbo, historyWeight_[p]);
        buffer(set, 11, ssbo, historyWeight_[q]);
        buffer(set, 12, ssbo, outSource_);
        buffer(set, 13, ssbo, sceneDepth_);
    }
    ctx_.device.updateDescriptorSets(writes, {});
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
        allocateForSize(scene.width, scene.height);
    const bool continues = haveHistory_ && lastFrame_ == frameIndex - 1;
    const size_t pixels = static_cast<size_t>(width_) * height_;
    const size_t blocks = static_cast<size_t>(blocksX_) * blocksY_;

    // As on the CPU: the march's jitter changes once per 16-frame cycle.
    const model::CloudParams cloud = makeCloudParams(scene);
    model::FrameParams frame = makeFrameParams(scene, frameIndex / model::TEMPORAL_CYCLE);
    // The scene depth buffer, if any, ends the marches as in the full-frame renderer.
    const std::vector<float> depth = sceneDepthFor(scene, resources_);
    frame.sampling.z = depth.empty() ? 0 : 1;
    if (!depth.empty())
        std::memcpy(sceneDepth_->mapped, depth.data(), depth.size() * sizeof(float));
    std::memcpy(cloudUbo_->mapped, &cloud, sizeof cloud);
    std::memcpy(frameUbo_->mapped, &frame, sizeof frame);
    if (!continues) // not read without history, but keep it defined
        std::memcpy(previousUbo_->mapped, &frame, sizeof frame);
    const ResolvePush resolvePush = {frameIndex, continues ? scene.timeS - lastTime_ : 0.0f,
                                     continues ? 1 : 0};
    const int p = current_, q = 1 - current_;

    vk::CommandBuffer cmd = ctx_.device.allocateCommandBuffers(
        {ctx_.commandPool, vk::CommandBufferLevel::ePrimary, 1})[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    const bool timed = ctx_.timestampValidBits > 0;
    cmd.resetQueryPool(queries_, 0, 3);
    if (timed)
        cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, queries_, 0);
    // 1. One pixel per block, in tiles of blocks.
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, march_.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, march_.layout, 0, marchSet_, {});
    const auto bx = static_cast<uint32_t>(blocksX_), by = static_cast<uint32_t>(blocksY_);
    for (uint32_t y0 = 0; y0 < by; y0 += kTileBlocks)
        for (uint32_t x0 = 0; x0 < bx; x0 += kTileBlocks) {
            const MarchPush push = {static_cast<int32_t>(x0), static_cast<int32_t>(y0), frameIndex};
            cmd.pushConstants(march_.layout, vk::ShaderStageFlagBits::eCompute, 0, sizeof push,
                              &push);
            cmd.dispatch((std::min(kTileBlocks, bx - x0) + kWorkgroup - 1) / kWorkgroup,
                         (std::min(kTileBlocks, by - y0) + kWorkgroup - 1) / kWorkgroup, 1);
        }
    if (timed)
        cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, queries_, 1);
    // 2. The resolve reads what the march wrote.
    const vk::MemoryBarrier marched(vk::AccessFlagBits::eShaderWrite,
                                    vk::AccessFlagBits::eShaderRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eComputeShader, {}, marched, {}, {});
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, resolve_.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, resolve_.layout, 0, resolveSets_[p],
                           {});
    cmd.pushConstants(resolve_.layout, vk::ShaderStageFlagBits::eCompute, 0, sizeof resolvePush,
                      &resolvePush);
    cmd.dispatch((static_cast<uint32_t>(width_) + kWorkgroup - 1) / kWorkgroup,
                 (static_cast<uint32_t>(height_) + kWorkgroup - 1) / kWorkgroup, 1);
    if (timed)
        cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, queries_, 2);
    const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost,
                        {}, toHost, {}, {});
    cmd.end();
    vk::Fence fence = ctx_.device.createFence({});
    ctx_.queue.submit(vk::SubmitInfo({}, {}, cmd), fence);
    const vk::Result waited = ctx_.device.waitForFences(fence, VK_TRUE, UINT64_MAX);
    ctx_.device.destroyFence(fence);
    ctx_.device.freeCommandBuffers(ctx_.commandPool, cmd);
    if (waited != vk::Result::eSuccess)
        throw Error("waiting for the GPU failed: " + vk::to_string(waited));

    // Read back. Host memory may be non-coherent-cached: invalidate before reading.
    for (const vulkan::Buffer* b :
         {historyCloud_[q], historyDepth_[q], outColour_, outSource_, freshCounts_})
        ctx_.device.invalidateMappedMemoryRanges(
            vk::MappedMemoryRange(b->memory, 0, VK_WHOLE_SIZE));
    RenderResult out;
    allocateResult(out, width_, height_);
    const auto* c = static_cast<const float*>(historyCloud_[q]->mapped);
    const auto* d = static_cast<const float*>(historyDepth_[q]->mapped);
    const auto* k = static_cast<const float*>(outColour_->mapped);
    const auto* source = static_cast<const int32_t*>(outSource_->mapped);
    uint64_t reprojected = 0, fallback = 0;
    for (size_t i = 0; i < pixels; ++i) {
        storePixel(out, i, glm::vec3(c[i * 4], c[i * 4 + 1], c[i * 4 + 2]), c[i * 4 + 3],
                   glm::vec3(k[i * 4], k[i * 4 + 1], k[i * 4 + 2]), d[i]);
        reprojected += source[i] == 1;
        fallback += source[i] == 2;
    }
    const auto* n = static_cast<const uint32_t*>(freshCounts_->mapped);
    for (size_t b = 0; b < blocks; ++b) {
        out.stats.densitySamples += n[b * 2];
        out.stats.lightSamples += n[b * 2 + 1];
    }
    breakdown.reprojected = static_cast<double>(reprojected) / pixels;
    breakdown.fallback = static_cast<double>(fallback) / pixels;
    breakdown.marched = 1.0 - breakdown.reprojected - breakdown.fallback;

    out.stats.backend = "vulkan: " + std::string(ctx_.properties.deviceName.data());
    out.stats.rays = blocks * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.gpuMemoryBytes = persistent_->deviceBytes() + sized_->deviceBytes();
    out.stats.gpuTextureBytes = persistent_->textureBytes();
    if (timed) {
        std::array<uint64_t, 3> ticks{};
        const vk::Result r = ctx_.device.getQueryPoolResults(
            queries_, 0, 3, sizeof ticks, ticks.data(), sizeof(uint64_t),
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
    lastFrameParams_ = frame;
    current_ = q;
    haveHistory_ = true;
    lastFrame_ = frameIndex;
    lastTime_ = scene.timeS;
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

// The history lives in host-visible, host-coherent buffers: saving and restoring are copies
// (the queue is idle between frames).
TemporalState VulkanTemporal::saveState() const {
    TemporalState state;
    if (!haveHistory_)
        return state;
    const size_t pixels = static_cast<size_t>(width_) * height_;
    state.frameIndex = lastFrame_;
    state.timeS = lastTime_;
    state.width = width_;
    state.height = height_;
    const auto* params = reinterpret_cast<const uint8_t*>(&lastFrameParams_);
    state.frameParams.assign(params, params + sizeof lastFrameParams_);
    auto copy = [](const vulkan::Buffer* b, size_t floats) {
        const auto* f = static_cast<const float*>(b->mapped);
        return std::vector<float>(f, f + floats);
    };
    state.cloud = copy(historyCloud_[current_], pixels * 4);
    state.depth = copy(historyDepth_[current_], pixels);
    state.weight = copy(historyWeight_[current_], pixels);
    return state;
}

void VulkanTemporal::restoreState(const TemporalState& state) {
    vulkan::translateVulkanErrors("restoring the temporal history", [&] {
        if (state.width != width_ || state.height != height_)
            allocateForSize(state.width, state.height);
        std::memcpy(historyCloud_[current_]->mapped, state.cloud.data(),
                    state.cloud.size() * sizeof(float));
        std::memcpy(historyDepth_[current_]->mapped, state.depth.data(),
                    state.depth.size() * sizeof(float));
        std::memcpy(historyWeight_[current_]->mapped, state.weight.data(),
                    state.weight.size() * sizeof(float));
        std::memcpy(&lastFrameParams_, state.frameParams.data(), sizeof lastFrameParams_);
        std::memcpy(previousUbo_->mapped, &lastFrameParams_, sizeof lastFrameParams_);
    });
    haveHistory_ = true;
    lastFrame_ = state.frameIndex;
    lastTime_ = state.timeS;
}

} // namespace

std::unique_ptr<TemporalRenderer::Impl> makeVulkanTemporal(const SceneResources& resources,
                                                           const BackendOptions& options) {
    return std::make_unique<VulkanTemporal>(resources, options);
}

} // namespace cloudscape
