// The temporal reconstruction on the Vulkan backend. Per frame, one submission: the device's
// march pass (render_clouds.comp, shared with the full-frame renderer) in block mode marches one
// pixel of every 4x4 block into block-sized CloudTexel records, then temporal_resolve.comp (the
// model's resolveAndComposite) rebuilds every pixel from them and the previous frame's result,
// which stays on the device in ping-pong buffers; with reduced-resolution clouds,
// upsample_clouds.comp (the model's upsampleCloudPass) then brings the result to the output
// size, on the device. Only what the caller asks for is read back (Readback). The device,
// pipelines and textures belong to the VulkanDevice; the history lives as long as this
// renderer. Plumbing only: the physics is in src/model.
#include "vulkan/vulkan_temporal.h"

#include <cloudscape/error.h>
#include <cloudscape/memory_estimate.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/resources.h"
#include "model/interface.glsl.h"
#include "model/temporal.glsl.h"
#include "vulkan/background_key.h"
#include "vulkan/cloud_shadow_map.h"
#include "vulkan/frame_io.h"
#include "vulkan/submit.h"
#include "vulkan/upsample_set.h"
#include "vulkan/vulkan_resources.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <optional>
#include <string>

namespace cloudscape::vulkan {
namespace {

const auto kStorage = kRecordBufferUsage; // texel-buffer bindings as well (interface.glsl.h)

// With the clouds' shadow map only the far ground needs the ground's fallback: the background
// pass that composites is built without it and lists those pixels for a dispatch of their own.
bool listsGroundFallback(int features) {
    return (features & model::FEATURE_CLOUD_SHADOW) != 0;
}
// The mask a listing pass's features take (the fallback's code left out), or ~0 with no list.
int listingFeatures(bool listFallback) {
    return listFallback ? ~model::FEATURE_GROUND_FALLBACK : ~0;
}
// Timestamps: start, after the shadow map, after the march, after the shafts' grid, after the
// resolve, after the upsample.
constexpr uint32_t kQueries = 7;

// The ground fallback's list (interface.glsl.h) emptied before the pass that fills it.
void resetGroundFallbackList(vk::CommandBuffer cmd, const Buffer& list) {
    const std::array<uint32_t, model::GROUND_FALLBACK_HEADER_WORDS> empty = {0, 1, 1, 0};
    cmd.updateBuffer(list.buffer, 0, sizeof empty, empty.data());
    const vk::MemoryBarrier barrier(vk::AccessFlagBits::eTransferWrite,
                                    vk::AccessFlagBits::eShaderRead |
                                        vk::AccessFlagBits::eShaderWrite);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eComputeShader, {}, barrier, {}, {});
}

// The list as written by a pass, read as the next dispatch's group counts and by its shader.
void listWritesToIndirectDispatch(vk::CommandBuffer cmd) {
    const vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite,
                                    vk::AccessFlagBits::eIndirectCommandRead |
                                        vk::AccessFlagBits::eShaderRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eDrawIndirect |
                            vk::PipelineStageFlagBits::eComputeShader,
                        {}, barrier, {}, {});
}

class VulkanTemporal final : public TemporalRenderer::Impl {
public:
    VulkanTemporal(std::shared_ptr<VulkanDevice> device, const SceneResources& resources);
    ~VulkanTemporal() override;
    RenderResult renderFrame(const Scene& scene, int frameIndex, Readback readback) override;
    TemporalState saveState() const override;
    void restoreState(const TemporalState& state) override;
    std::string backendName() const override {
        return "vulkan: " + std::string(ctx_.properties.deviceName.data());
    }
    std::pair<uint64_t, uint64_t> deviceComposite() const override {
        if (!lastComposite_)
            return {0, 0};
        return {reinterpret_cast<uint64_t>(static_cast<VkBuffer>(lastComposite_->buffer)),
                lastComposite_->size};
    }
    TemporalDebugImage debugImage() const override {
        if (!haveHistory_ || pendingState_)
            return {};
        const auto* texels = static_cast<const model::CloudTexel*>(history_[current_]->mapped);
        const size_t pixels = static_cast<size_t>(passWidth_) * passHeight_;
        std::vector<float> codes(pixels);
        for (size_t i = 0; i < pixels; ++i)
            codes[i] = texels[i].debug;
        return temporalDebugImageOf(codes.data(), passWidth_, passHeight_);
    }
    std::vector<glm::vec4> lastCloudShadowMap() const override {
        return shadow_ ? shadow_->texels() : std::vector<glm::vec4>{};
    }
    // The device's textures carry their own content version (ModelTextures::contentVersion).
    void texturesChanged() override {}

private:
    void allocateForSize(const Scene& full, const Scene& pass);
    void allocateShaftGrid(size_t cells);
    void allocateGatherRing(int frames);
    void keepInRing(vk::CommandBuffer cmd, const model::FrameParams& frame, glm::ivec2 blockGrid);
    void prepareGathering(int features, int resolveFeatures, bool shaftGrid);
    void prepareBackgroundFromPass(int features);
    void applyPendingState();
    void writeDescriptors();
    RenderResult render(const Scene& full, int frameIndex, Readback readback);

    std::shared_ptr<VulkanDevice> device_; // first, so it outlives what is created on it
    Context& ctx_;
    const SceneResources& resources_;
    vk::DescriptorSet marchSet_, upsampleSet_;
    std::array<vk::DescriptorSet, 2> resolveSets_; // [p] reads history p, writes 1 - p
    vk::UniqueQueryPool queries_;
    uint64_t textureGeneration_ = 0; // of the textures the march set samples

    // Parameter blocks (the pass's, that is the reconstruction's, frame; the history's frame;
    // the output's frame, for the upsample) and the frame counters.
    std::unique_ptr<FrameBlocks> blocks_;
    std::unique_ptr<CloudShadowMap> shadow_;
    BackgroundKey background_; // what the background buffers hold

    // Per image size: reallocated when the output or pass size changes.
    std::unique_ptr<ResourceSet> sized_;
    int width_ = 0, height_ = 0;         // output
    int passWidth_ = 0, passHeight_ = 0; // the reconstruction (= output at full resolution)
    Buffer *fresh_ = nullptr, *unusedComposite_ = nullptr, *passComposite_ = nullptr,
           *passDepth_ = nullptr, *outCloud_ = nullptr, *outComposite_ = nullptr,
           *outDepth_ = nullptr;
    // BackgroundLight and BackgroundTexel per pixel: at the pass's size for the resolve, at the
    // output's for the upsample (reduced only), made when background_ says they must be.
    Buffer *passBackground_ = nullptr, *outBackground_ = nullptr;
    Buffer *passSeen_ = nullptr, *outSeen_ = nullptr;
    // The pixels of the compositing background pass that need the ground's fallback (at the
    // output's size, which is the larger), shaded again by an indirect dispatch.
    Buffer* groundFallback_ = nullptr;
    std::array<Buffer*, 2> history_{};
    // The light shafts' grid (shaft_grid.glsl.h): its cells (1 when the resolve reads none).
    std::unique_ptr<ResourceSet> shaftSet_;
    Buffer* shafts_ = nullptr;
    size_t shaftCells_ = 0;
    // The moving camera's ring of earlier marches (sample_gather.glsl.h): the frames' parameters
    // by ring position and their marches, for render.moving_gather_frames frames of the pass's
    // size (one record when none).
    std::unique_ptr<ResourceSet> gatherSet_;
    Buffer *gatherFrames_ = nullptr, *gatherRing_ = nullptr;
    // The entering ring (sample_gather.glsl.h): the march writes it, the resolve reads it.
    Buffer* gatherEntering_ = nullptr;
    int gatherCapacity_ = 0;

    const Buffer* lastComposite_ = nullptr; // the displayed image of the last frame
    int current_ = 0;                       // the ping-pong half holding the last frame's result
    bool haveHistory_ = false;
    int lastFrame_ = -2;
    float lastTime_ = 0.0f;
    model::FrameParams lastFrameParams_{}; // also in blocks_->previous, for the next resolve
    // A history restored before the buffers of its size exist: copied in by the next render.
    std::optional<TemporalState> pendingState_;
};

VulkanTemporal::VulkanTemporal(std::shared_ptr<VulkanDevice> device,
                               const SceneResources& resources)
    : device_(std::move(device)), ctx_(device_->context()), resources_(resources) {
    translateVulkanErrors("temporal renderer set-up", [&] {
        marchSet_ = device_->march().allocateSet();
        upsampleSet_ = device_->upsample().allocateSet();
        resolveSets_ = {device_->resolve().allocateSet(), device_->resolve().allocateSet()};
        queries_ = ctx_.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, kQueries});
        blocks_ = std::make_unique<FrameBlocks>(ctx_);
        shadow_ = std::make_unique<CloudShadowMap>(ctx_, device_->cloudShadow());
    });
}

VulkanTemporal::~VulkanTemporal() {
    waitIdleBeforeFreeing(ctx_.device);
}

void VulkanTemporal::allocateForSize(const Scene& full, const Scene& pass) {
    checkImageSize(ctx_, full.width, full.height);
    // The fresh marches for the smaller block a moving camera may march (temporalBlockFor).
    const glm::ivec2 blocks =
        model::temporalBlockCount(glm::ivec2(pass.width, pass.height), model::TEMPORAL_SMALL_BLOCK);
    const size_t blockCount = static_cast<size_t>(blocks.x) * blocks.y;
    const size_t passPixels = static_cast<size_t>(pass.width) * pass.height;
    const size_t pixels = static_cast<size_t>(full.width) * full.height;
    const bool reduced = passPixels != pixels;
    // What the buffers below take: the fresh blocks, composite, depth and two histories at the
    // pass's size, and the full-size outputs when it is reduced.
    const uint64_t texel = sizeof(model::CloudTexel);
    const uint64_t background = sizeof(model::BackgroundLight) + sizeof(model::BackgroundTexel);
    checkDeviceMemory(ctx_, full.width, full.height,
                      blockCount * texel + 16 + passPixels * (16 + 4 + 2 * texel + background) +
                          (reduced ? pixels * (texel + 16 + 4 + background) : 0) +
                          (model::GROUND_FALLBACK_HEADER_WORDS + pixels) * 4 +
                          cloudShadowMapBytes(full));
    ctx_.device.waitIdle();
    sized_ = std::make_unique<ResourceSet>(ctx_);
    width_ = full.width;
    height_ = full.height;
    passWidth_ = pass.width;
    passHeight_ = pass.height;
    // Host-visible throughout: on lavapipe (or any unified-memory device) there is no faster
    // memory; on a discrete GPU the history would belong in device-local memory.
    fresh_ = &sized_->hostBuffer(blockCount * sizeof(model::CloudTexel),
                                 kStorage | vk::BufferUsageFlagBits::eTransferSrc);
    unusedComposite_ = &sized_->hostBuffer(16, kStorage); // block mode writes no composite
    passComposite_ = &sized_->hostBuffer(passPixels * 16, kStorage);
    passDepth_ = &sized_->hostBuffer(passPixels * 4, kStorage); // read with a depth buffer
    for (int p = 0; p < 2; ++p)
        history_[p] = &sized_->hostBuffer(passPixels * sizeof(model::CloudTexel), kStorage);
    passBackground_ = &sized_->hostBuffer(passPixels * sizeof(model::BackgroundLight), kStorage);
    passSeen_ = &sized_->hostBuffer(passPixels * sizeof(model::BackgroundTexel), kStorage);
    groundFallback_ = &sized_->hostBuffer((model::GROUND_FALLBACK_HEADER_WORDS + pixels) * 4,
                                          kStorage | vk::BufferUsageFlagBits::eIndirectBuffer |
                                              vk::BufferUsageFlagBits::eTransferDst);
    if (reduced) {
        outCloud_ = &sized_->hostBuffer(pixels * sizeof(model::CloudTexel), kStorage);
        outComposite_ = &sized_->hostBuffer(pixels * 16, kStorage);
        outDepth_ = &sized_->hostBuffer(pixels * 4, kStorage);
        outBackground_ = &sized_->hostBuffer(pixels * sizeof(model::BackgroundLight), kStorage);
        outSeen_ = &sized_->hostBuffer(pixels * sizeof(model::BackgroundTexel), kStorage);
    } else {
        // The resolve's own outputs.
        outCloud_ = outComposite_ = outDepth_ = outBackground_ = outSeen_ = nullptr;
    }
    background_.invalidate();
    if (!shafts_)
        allocateShaftGrid(1);
    allocateGatherRing(pass.movingGatherFrames);
    writeDescriptors();
    haveHistory_ = false;
}

// The grid's buffer, sized by its cells (the image size and shafts.grid_factor); the caller
// rewrites the descriptor sets.
void VulkanTemporal::allocateShaftGrid(size_t cells) {
    checkDeviceMemory(ctx_, width_, height_, cells * sizeof(model::ShaftTexel));
    ctx_.device.waitIdle();
    shaftSet_ = std::make_unique<ResourceSet>(ctx_);
    shafts_ = &shaftSet_->hostBuffer(cells * sizeof(model::ShaftTexel), kStorage);
    shaftCells_ = cells;
}

// The ring for `frames` frames of the pass's size (allocateForSize's, or a new
// render.moving_gather_frames); the caller rewrites the descriptor sets.
void VulkanTemporal::allocateGatherRing(int frames) {
    const size_t stride =
        static_cast<size_t>(model::gatherSlotBlocks(glm::ivec2(passWidth_, passHeight_)));
    const size_t records = frames > 0 ? static_cast<size_t>(frames) * stride : 1;
    const size_t bytes = records * sizeof(model::CloudTexel);
    const size_t entering =
        frames > 0
            ? static_cast<size_t>(model::enteringRingRecords(glm::ivec2(passWidth_, passHeight_)))
            : 1;
    const size_t enteringBytes = entering * sizeof(model::CloudTexel);
    checkDeviceMemory(ctx_, width_, height_, bytes + enteringBytes);
    ctx_.device.waitIdle();
    gatherSet_ = std::make_unique<ResourceSet>(ctx_);
    gatherFrames_ = &gatherSet_->hostBuffer(model::GATHER_MAX_FRAMES * sizeof(model::FrameParams),
                                            vk::BufferUsageFlagBits::eStorageBuffer);
    std::memset(gatherFrames_->mapped, 0, gatherFrames_->size);
    gatherRing_ = &gatherSet_->hostBuffer(bytes, kStorage | vk::BufferUsageFlagBits::eTransferDst);
    gatherEntering_ = &gatherSet_->hostBuffer(enteringBytes, kStorage);
    gatherCapacity_ = frames;
}

// An interactive renderer (BackendOptions::interactive: the viewer) that can gather
// (render.moving_gather_frames) builds the pipelines of a gathering frame with the frames before
// one, not when the camera first moves: on lavapipe they take about half a second, a hitch the
// moment a person starts to turn. The features are this frame's; a moving frame of the same scene
// asks for the same ones with FEATURE_GATHER. Batch renders build them only if a frame gathers.
void VulkanTemporal::prepareGathering(int features, int resolveFeatures, bool shaftGrid) {
    device_->march().prepareBlocks(features | model::FEATURE_GATHER);
    device_->resolve().prepare(resolveFeatures | model::FEATURE_GATHER);
    if (shaftGrid)
        device_->resolve().prepare(resolveFeatures | model::FEATURE_GATHER |
                                   model::PASS_SHAFT_GRID);
}

// The same for the frames of a moving camera whose background is made at the reduced pass's size
// (backgroundFromPass: render.moving_background_reduced, the low tier): the pipelines renderFrame's
// background pass binds there, made with the still frames of an interactive renderer.
void VulkanTemporal::prepareBackgroundFromPass(int features) {
    const bool listFallback = listsGroundFallback(features);
    device_->resolve().prepare((features | model::PASS_FILL_BACKGROUND) &
                               listingFeatures(listFallback));
    if (listFallback)
        device_->resolve().prepare(features | model::PASS_GROUND_FALLBACK);
    device_->upsample().prepare(features | model::PASS_UPSAMPLED_BACKGROUND);
}

// This frame's marches into the ring (after the march pass, before the resolve reads them), and
// its parameters at their position.
void VulkanTemporal::keepInRing(vk::CommandBuffer cmd, const model::FrameParams& frame,
                                glm::ivec2 blockGrid) {
    if (gatherCapacity_ <= 0)
        return;
    const int position = model::gatherPosition(frame, 0);
    std::memcpy(static_cast<uint8_t*>(gatherFrames_->mapped) + position * sizeof frame, &frame,
                sizeof frame);
    const vk::DeviceSize record = sizeof(model::CloudTexel);
    const vk::DeviceSize stride =
        static_cast<vk::DeviceSize>(model::gatherSlotBlocks(glm::ivec2(passWidth_, passHeight_)));
    const vk::BufferCopy region(0, position * stride * record,
                                static_cast<vk::DeviceSize>(blockGrid.x) * blockGrid.y * record);
    const vk::MemoryBarrier marched(vk::AccessFlagBits::eShaderWrite,
                                    vk::AccessFlagBits::eTransferRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eTransfer, {}, marched, {}, {});
    cmd.copyBuffer(fresh_->buffer, gatherRing_->buffer, region);
    const vk::MemoryBarrier kept(vk::AccessFlagBits::eTransferWrite,
                                 vk::AccessFlagBits::eShaderRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer,
                        vk::PipelineStageFlagBits::eComputeShader, {}, kept, {}, {});
}

void VulkanTemporal::writeDescriptors() {
    device_->march().bind(ctx_, marchSet_, device_->textures(),
                          {blocks_->cloud, blocks_->frame, passDepth_, fresh_, unusedComposite_,
                           blocks_->counters, &shadow_->buffer(), blocks_->previous,
                           gatherEntering_});
    shadow_->bind(*blocks_->cloud, device_->textures());
    textureGeneration_ = device_->textures().generation();
    for (int p = 0; p < 2; ++p)
        DescriptorWriter(model::RESOLVE_PASS, resolveSets_[p])
            .buffer(model::RESOLVE_CLOUD_PARAMS, *blocks_->cloud)
            .buffer(model::RESOLVE_FRAME_PARAMS, *blocks_->frame)
            .buffer(model::RESOLVE_PREVIOUS_FRAME, *blocks_->previous)
            .buffer(model::RESOLVE_HISTORY, *history_[p])
            .buffer(model::RESOLVE_FRESH, *fresh_)
            .buffer(model::RESOLVE_OUT_HISTORY, *history_[1 - p])
            .buffer(model::RESOLVE_OUT_COMPOSITE, *passComposite_)
            .buffer(model::RESOLVE_SCENE_DEPTH, *passDepth_)
            .buffer(model::RESOLVE_COUNTERS, *blocks_->counters)
            .buffer(model::RESOLVE_ATMOSPHERE, device_->textures().atmosphere())
            .buffer(model::RESOLVE_TERRAIN, device_->textures().terrain())
            .buffer(model::RESOLVE_CLOUD_SHADOW, shadow_->buffer())
            .buffer(model::RESOLVE_SHAFTS, *shafts_)
            .buffer(model::RESOLVE_BACKGROUND, *passBackground_)
            .buffer(model::RESOLVE_BACKGROUND_SEEN, *passSeen_)
            .buffer(model::RESOLVE_GROUND_FALLBACK, *groundFallback_)
            .buffer(model::RESOLVE_GATHER_FRAMES, *gatherFrames_)
            .buffer(model::RESOLVE_GATHER_RING, *gatherRing_)
            .buffer(model::RESOLVE_GATHER_ENTERING, *gatherEntering_)
            .image(model::RESOLVE_BASE_NOISE, device_->textures().sampler(),
                   device_->textures().baseNoise())
            .image(model::RESOLVE_WEATHER_MAP, device_->textures().sampler(),
                   device_->textures().weatherMap())
            .image(model::RESOLVE_HIGH_CLOUDS, device_->textures().sampler(),
                   device_->textures().highClouds())
            .commit(ctx_.device);
    // The upsample's input (the newest history half) is rewritten every reduced frame.
}

RenderResult VulkanTemporal::renderFrame(const Scene& scene, int frameIndex, Readback readback) {
    checkCameraAboveTerrain(scene, resources_);
    RenderResult out = translateVulkanErrors("temporal rendering",
                                             [&] { return render(scene, frameIndex, readback); });
    out.stats.validationMessages = ctx_.takeValidationMessages();
    return out;
}

RenderResult VulkanTemporal::render(const Scene& full, int frameIndex, Readback readback) {
    const auto start = std::chrono::steady_clock::now();
    // Reduced-resolution clouds, as on the CPU: the reconstruction and its history run at the
    // pass size; the upsample to the output size runs on the device.
    const Scene pass = full.cloudResolution < 1.0f ? cloudPassScene(full) : full;
    const bool reduced = pass.width != full.width || pass.height != full.height;
    if (full.width != width_ || full.height != height_ || pass.width != passWidth_ ||
        pass.height != passHeight_)
        allocateForSize(full, pass);
    if (pass.movingGatherFrames != gatherCapacity_) {
        allocateGatherRing(pass.movingGatherFrames);
        writeDescriptors();
    } else if (device_->textures().generation() != textureGeneration_) {
        writeDescriptors(); // new noise or weather map
    }
    applyPendingState(); // a restored history, now that the buffers have the pass size
    const bool continues = haveHistory_ && lastFrame_ == frameIndex - 1;
    const size_t pixels = static_cast<size_t>(width_) * height_;
    const size_t passPixels = static_cast<size_t>(passWidth_) * passHeight_;

    // The scene depth buffer, if any, ends the marches as in the full-frame renderer.
    model::CloudParams cloud = makeCloudParams(pass, resources_);
    device_->textures().restrictToBound(cloud);
    std::memcpy(blocks_->cloud->mapped, &cloud, sizeof cloud);
    const int features = model::modelFeaturesFor(cloud, pass.cameraPosition);
    if (shadow_->resize(CloudShadowMap::resolutionFor(cloud)) && sized_)
        writeDescriptors(); // the readers bind the new map
    // The shafts' grid over the pass's image: read by the resolve's composite, or reduced, by the
    // upsample's at full size.
    const bool shaftGrid = model::shaftGridActive(cloud);
    const glm::ivec2 shaftCells =
        shaftGrid
            ? model::shaftGridSize(glm::ivec2(passWidth_, passHeight_), cloud.shafts.gridFactor)
            : glm::ivec2(1, 1);
    if (static_cast<size_t>(shaftCells.x) * shaftCells.y != shaftCells_) {
        allocateShaftGrid(static_cast<size_t>(shaftCells.x) * shaftCells.y);
        writeDescriptors();
    }
    // As on the CPU: the block this frame marches and its jitter's cycle.
    const model::FrameParams probe = makeFrameParams(pass);
    const model::FrameMarch march = model::frameMarchFor(
        frameIndex, probe, lastFrameParams_, continues, pass.movingBlock2x2, pass.stillBlock2x2);
    const int block = march.block, cycle = march.cycle;
    const glm::ivec2 blockGrid =
        model::temporalBlockCount(glm::ivec2(passWidth_, passHeight_), block);
    const TemporalStep step = {frameIndex, continues ? pass.timeS - lastTime_ : 0.0f, block,
                               model::gatherValidFor(probe, lastFrameParams_, continues)};
    const model::FrameParams frame =
        uploadFrame(*blocks_->frame, *passDepth_, pass, resources_, cycle, step);
    if (!continues) // not read without history, but keep it defined
        std::memcpy(blocks_->previous->mapped, &frame, sizeof frame);
    const model::ResolvePush resolvePush = {continues ? 1 : 0, 0, 0, 0};
    const int p = current_, q = 1 - current_;
    model::FrameParams outputFrame = frame;
    if (reduced) {
        outputFrame = uploadFrame(*blocks_->output, *outDepth_, full, resources_, cycle);
        writeUpsampleSet(ctx_, upsampleSet_, device_->textures(),
                         {.cloudParams = blocks_->cloud,
                          .frameParams = blocks_->output,
                          .inCloud = history_[q],
                          .sceneDepth = outDepth_,
                          .outCloud = outCloud_,
                          .outComposite = outComposite_,
                          .cloudShadow = &shadow_->buffer(),
                          .background = outBackground_,
                          .backgroundSeen = outSeen_,
                          .shafts = shafts_,
                          .groundFallback = groundFallback_,
                          .passBackgroundSeen = passSeen_});
    }

    // A moving camera with render.moving_background_reduced: the background is made for the
    // pass's pixels only (with its light and clouds, as an unreduced pass makes it) and the
    // upsample brings it to the output (model::backgroundFromPass decides, as on the CPU).
    const bool fromPass = model::backgroundFromPass(frame, lastFrameParams_, continues, reduced,
                                                    full.movingBackgroundReduced);
    const bool timed = ctx_.timestampValidBits > 0;
    const uint64_t texturesVersion = device_->textures().contentVersion();
    bool shadowMade = false;
    // Reduced: nobody reads the pass's composite (the upsample composites at full size).
    const int resolveFeatures = reduced ? features & ~model::FEATURE_COMPOSITE : features;
    // The resolve's own dispatches (the shafts' grid resolves its cells' pixels too) gather only
    // in frames that do; the background's modes never gather.
    const int gatherFeature = model::gatherFeatureFor(frame, lastFrameParams_, continues);
    if (device_->interactive() && gatherCapacity_ > 0 && gatherFeature == 0)
        prepareGathering(features, resolveFeatures, shaftGrid);
    if (device_->interactive() && reduced && full.movingBackgroundReduced && !fromPass &&
        frame.hasSceneDepth == 0)
        prepareBackgroundFromPass(features);
    const BackgroundKey::Decision background =
        background_.decide(cloud, frame, outputFrame, features,
                           device_->textures().backgroundVersion(), texturesVersion);
    try {
        submitAndWait(ctx_, [&](vk::CommandBuffer cmd) {
            cmd.resetQueryPool(*queries_, 0, kQueries);
            resetCounters(cmd, *blocks_->counters);
            const auto stamp = [&](uint32_t query) {
                if (timed)
                    cmd.writeTimestamp(query == 0 ? vk::PipelineStageFlagBits::eTopOfPipe
                                                  : vk::PipelineStageFlagBits::eBottomOfPipe,
                                       *queries_, query);
            };
            stamp(0);
            // The clouds' shadow map, before the passes that read it; kept while its inputs stay.
            shadowMade = shadow_->record(cmd, cloud, features, texturesVersion);
            stamp(1);
            // The background behind the clouds: its light, kept while the camera, sun,
            // terrain and air stay, then this frame's clouds on it (after the shadow map),
            // kept while the clouds stay too.
            // With the shadow map only the far ground needs the fallback: the pass that
            // composites (the upsample's when reduced) is built without it and lists those
            // pixels, which a dispatch over the list shades whole.
            const bool listFallback = listsGroundFallback(features);
            const int listing = listingFeatures(listFallback);
            const model::UpsamplePush upsamplePush{passWidth_, passHeight_, 0, 0};
            // Which pass composites over the background it makes: the resolve's, unless the
            // upsample makes one at the output size.
            const bool outputBackground = reduced && !fromPass;
            const int passBackgroundFeatures = fromPass ? features : resolveFeatures;
            const auto backgroundPass = [&](int mode) {
                if (listFallback)
                    resetGroundFallbackList(cmd, *groundFallback_);
                device_->resolve().bind(cmd, resolveSets_[p],
                                        (passBackgroundFeatures | mode) &
                                            (outputBackground ? ~0 : listing));
                device_->resolve().push(cmd, resolvePush);
                dispatchImage(cmd, passWidth_, passHeight_);
                if (outputBackground) {
                    device_->upsample().bind(cmd, upsampleSet_, (features | mode) & listing);
                    device_->upsample().push(cmd, upsamplePush);
                    dispatchImage(cmd, width_, height_);
                }
                if (listFallback) {
                    listWritesToIndirectDispatch(cmd);
                    if (outputBackground) {
                        device_->upsample().bind(cmd, upsampleSet_,
                                                 features | model::PASS_GROUND_FALLBACK);
                        device_->upsample().push(cmd, upsamplePush);
                    } else {
                        device_->resolve().bind(cmd, resolveSets_[p],
                                                passBackgroundFeatures |
                                                    model::PASS_GROUND_FALLBACK);
                        device_->resolve().push(cmd, resolvePush);
                    }
                    cmd.dispatchIndirect(groundFallback_->buffer, 0);
                }
                shaderWritesToShader(cmd);
            };
            if (background.makeLight || fromPass) // the clouds applied in the same pass
                backgroundPass(model::PASS_FILL_BACKGROUND);
            else if (background.applyClouds)
                backgroundPass(model::PASS_SHADE_BACKGROUND);
            stamp(2);
            // 1. One pixel per block, in tiles of blocks.
            // (A gathering frame's entering blocks march their other pixels too.)
            device_->march().recordBlocks(cmd, marchSet_, blockGrid.x, blockGrid.y,
                                          features | gatherFeature);
            keepInRing(cmd, frame, blockGrid);
            stamp(3);
            // 2. The resolve reads what the march wrote (and the shafts' grid, made first from it).
            shaderWritesToShader(cmd);
            if (shaftGrid) {
                device_->resolve().bind(cmd, resolveSets_[p],
                                        resolveFeatures | gatherFeature | model::PASS_SHAFT_GRID);
                device_->resolve().push(cmd, resolvePush);
                dispatchImage(cmd, shaftCells.x, shaftCells.y);
                shaderWritesToShader(cmd);
            }
            stamp(4);
            device_->resolve().bind(cmd, resolveSets_[p], resolveFeatures | gatherFeature);
            device_->resolve().push(cmd, resolvePush);
            dispatchImage(cmd, passWidth_, passHeight_);
            stamp(5);
            // 3. Reduced resolution: the upsample reads the resolved history.
            if (reduced) {
                shaderWritesToShader(cmd);
                device_->upsample().bind(cmd, upsampleSet_,
                                         fromPass ? features | model::PASS_UPSAMPLED_BACKGROUND
                                                  : features);
                device_->upsample().push(
                    cmd, model::UpsamplePush{passWidth_, passHeight_, shaftGrid ? 1 : 0, 0});
                dispatchImage(cmd, width_, height_);
            }
            stamp(6);
            shaderWritesToHost(cmd);
        });
    } catch (...) {
        shadow_->invalidate(); // the map's and the background's passes may not have run
        background_.invalidate();
        throw;
    }
    if (fromPass) // the output's background was not made, the pass's holds its light: remake
        background_.invalidate();

    // Read back only what was asked for.
    const Buffer& cloudOut = reduced ? *outCloud_ : *history_[q];
    const Buffer& colourOut = reduced ? *outComposite_ : *passComposite_;
    lastComposite_ = &colourOut;
    RenderResult out;
    out.width = width_;
    out.height = height_;
    readBack(ctx_, colourOut, cloudOut, pixels, readback, out);
    const model::FrameCounters totals = readCounters(ctx_, *blocks_->counters);
    out.stats.densitySamples = densitySamples(totals);
    out.stats.shadowMapMade = shadowMade;
    out.stats.shadowMapTexelsMade = shadow_->texelsMade();
    out.stats.backgroundMade = background.makeLight;
    out.stats.backgroundShaded = background.applyClouds;
    if (background.applyClouds && listsGroundFallback(features))
        out.stats.groundFallbackPixels = static_cast<const uint32_t*>(
            groundFallback_->mapped)[model::GROUND_FALLBACK_HEADER_WORDS - 1];
    out.stats.lightSamples = lightSamples(totals);
    out.stats.cloudSamples = cloudSamples(totals);
    out.stats.emptySkips = emptySkips(totals);
    breakdown.reprojected = static_cast<double>(totals.reprojected) / passPixels;
    breakdown.fallback = static_cast<double>(totals.fallback) / passPixels;
    breakdown.marched = 1.0 - breakdown.reprojected - breakdown.fallback;

    out.stats.backend = "vulkan: " + device_->deviceName();
    // The blocks' marches and the entering blocks' extra ones (sample_gather.glsl.h).
    out.stats.rays = (static_cast<uint64_t>(blockGrid.x) * blockGrid.y + totals.entering) *
                     static_cast<uint64_t>(pass.samplesPerPixel);
    out.stats.gpuMemoryBytes = blocks_->set->deviceBytes() + sized_->deviceBytes() +
                               shaftSet_->deviceBytes() + gatherSet_->deviceBytes() +
                               device_->textures().deviceBytes() + shadow_->deviceBytes();
    out.stats.gpuTextureBytes = device_->textures().textureBytes();
    const std::vector<double> ms = timestampsMs(ctx_, *queries_, kQueries);
    if (!ms.empty()) {
        out.stats.gpuShadowMs = ms[1];
        out.stats.gpuBackgroundMs = ms[2] - ms[1];
        out.stats.gpuMarchMs = ms[3] - ms[2];
        out.stats.gpuShaftGridMs = ms[4] - ms[3];
        out.stats.gpuUpsampleMs = ms[6] - ms[5];
        out.stats.marchSeconds = (ms[3] - ms[2]) * 1e-3;
        out.stats.resolveSeconds = (ms[6] - ms[3]) * 1e-3; // the grid, resolve and upsample
    }

    // This frame's result (half q) is the next frame's history.
    std::memcpy(blocks_->previous->mapped, &frame, sizeof frame);
    lastFrameParams_ = frame;
    current_ = q;
    haveHistory_ = true;
    lastFrame_ = frameIndex;
    lastTime_ = pass.timeS;
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

// The history lives in host-visible, host-coherent buffers, one CloudTexel per pixel of the
// pass: saving and restoring are copies (the queue is idle between frames).
TemporalState VulkanTemporal::saveState() const {
    if (pendingState_)
        return *pendingState_; // restored and not yet rendered on
    TemporalState state;
    if (!haveHistory_)
        return state;
    const size_t pixels = static_cast<size_t>(passWidth_) * passHeight_;
    state.frameIndex = lastFrame_;
    state.timeS = lastTime_;
    state.width = passWidth_;
    state.height = passHeight_;
    const auto* params = reinterpret_cast<const uint8_t*>(&lastFrameParams_);
    state.frameParams.assign(params, params + sizeof lastFrameParams_);
    const auto* texels = static_cast<const model::CloudTexel*>(history_[current_]->mapped);
    state.cloud.resize(pixels * 4);
    state.depth.resize(pixels);
    state.weight.resize(pixels);
    state.flash.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 4; ++c)
            state.cloud[i * 4 + c] = texels[i].cloud[c];
        state.depth[i] = texels[i].depth;
        state.weight[i] = texels[i].weight;
        state.flash[i] = texels[i].flash;
    }
    if (gatherCapacity_ > 0) {
        const auto* frames = static_cast<const uint8_t*>(gatherFrames_->mapped);
        state.gatherFrames.assign(frames, frames + gatherCapacity_ * sizeof(model::FrameParams));
        // The ring's records, then the entering ring's (TemporalState::gatherRing).
        const auto* ring = static_cast<const float*>(gatherRing_->mapped);
        state.gatherRing.assign(ring, ring + gatherRing_->size / sizeof(float));
        const auto* entering = static_cast<const float*>(gatherEntering_->mapped);
        state.gatherRing.insert(state.gatherRing.end(), entering,
                                entering + gatherEntering_->size / sizeof(float));
    }
    return state;
}

// The buffers are sized by the next frame's scene (output and pass size), which the state does
// not know: the copy waits for that render, and the frame counters say it continues.
void VulkanTemporal::restoreState(const TemporalState& state) {
    pendingState_ = state;
    std::memcpy(&lastFrameParams_, state.frameParams.data(), sizeof lastFrameParams_);
    if (state.gatherFrames.empty()) // no ring kept: the next frame's starts over
        lastFrameParams_.gatherValid = 0;
    haveHistory_ = true;
    lastFrame_ = state.frameIndex;
    lastTime_ = state.timeS;
}

void VulkanTemporal::applyPendingState() {
    if (!pendingState_)
        return;
    const TemporalState state = std::move(*pendingState_);
    pendingState_.reset();
    if (state.width != passWidth_ || state.height != passHeight_)
        throw Error("temporal state of " + std::to_string(state.width) + "x" +
                    std::to_string(state.height) + " does not match the cloud pass of " +
                    std::to_string(passWidth_) + "x" + std::to_string(passHeight_));
    auto* texels = static_cast<model::CloudTexel*>(history_[current_]->mapped);
    const size_t pixels = static_cast<size_t>(passWidth_) * passHeight_;
    for (size_t i = 0; i < pixels; ++i) {
        texels[i] = model::CloudTexel{};
        for (int c = 0; c < 4; ++c)
            texels[i].cloud[c] = state.cloud[i * 4 + c];
        texels[i].depth = state.depth[i];
        texels[i].weight = state.weight[i];
        texels[i].flash = state.flash.empty() ? 0.0f : state.flash[i];
    }
    // The ring, when the scene keeps the one the state holds (else the next frame starts it).
    const size_t ringFrames = state.gatherFrames.size() / sizeof(model::FrameParams);
    if (ringFrames > 0 && static_cast<int>(ringFrames) == gatherCapacity_ &&
        state.gatherRing.size() * sizeof(float) == gatherRing_->size + gatherEntering_->size) {
        std::memcpy(gatherFrames_->mapped, state.gatherFrames.data(), state.gatherFrames.size());
        std::memcpy(gatherRing_->mapped, state.gatherRing.data(), gatherRing_->size);
        std::memcpy(gatherEntering_->mapped,
                    reinterpret_cast<const uint8_t*>(state.gatherRing.data()) + gatherRing_->size,
                    gatherEntering_->size);
    } else {
        lastFrameParams_.gatherValid = 0;
    }
    std::memcpy(blocks_->previous->mapped, &lastFrameParams_, sizeof lastFrameParams_);
    haveHistory_ = true;
    lastFrame_ = state.frameIndex;
    lastTime_ = state.timeS;
}

} // namespace

std::unique_ptr<TemporalRenderer::Impl> makeTemporalOn(std::shared_ptr<VulkanDevice> device,
                                                       const SceneResources& resources) {
    return std::make_unique<VulkanTemporal>(std::move(device), resources);
}

} // namespace cloudscape::vulkan

namespace cloudscape {

std::unique_ptr<TemporalRenderer::Impl> makeVulkanTemporal(const SceneResources& resources,
                                                           const BackendOptions& options) {
    return vulkan::makeTemporalOn(std::make_shared<vulkan::VulkanDevice>(options, resources),
                                  resources);
}

} // namespace cloudscape
