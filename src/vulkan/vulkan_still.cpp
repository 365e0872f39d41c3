// The Vulkan backend's full-frame render: the device's march pass (render_clouds.comp, the
// model's renderPixel) over the image in tiles, a row of tiles per submission so progress can be
// shown; with reduced-resolution clouds the march runs at the pass size and upsample_clouds.comp
// (the model's upsampleCloudPass) brings it to the output size on the device. Only what the
// caller asks for is read back. Plumbing only.
#include "vulkan/vulkan_still.h"

#include <cloudscape/error.h>
#include <cloudscape/memory_estimate.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "model/pixel.glsl.h"
#include "vulkan/submit.h"
#include "vulkan/upsample_set.h"

#include <array>
#include <chrono>
#include <cstring>

namespace cloudscape::vulkan {
namespace {

const auto kStorage = kRecordBufferUsage; // texel-buffer bindings as well (interface.glsl.h)

} // namespace

VulkanStill::VulkanStill(std::shared_ptr<VulkanDevice> device)
    : device_(std::move(device)), ctx_(device_->context()), blocks_(ctx_),
      shadow_(ctx_, device_->cloudShadow()) {
    marchSet_ = device_->march().allocateSet();
    upsampleSet_ = device_->upsample().allocateSet();
    queries_ = ctx_.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, 4});
}

VulkanStill::~VulkanStill() {
    waitIdleBeforeFreeing(ctx_.device);
}

void VulkanStill::allocate(const Scene& full, const Scene& pass) {
    checkImageSize(ctx_, full.width, full.height);
    const size_t pixels = static_cast<size_t>(full.width) * full.height;
    const size_t passPixels = static_cast<size_t>(pass.width) * pass.height;
    // What the buffers below take: depth, cloud texel and composite per pixel, for the pass
    // and, when it is reduced, again at full size; and the clouds' shadow map.
    const uint64_t perPixel = 4 + sizeof(model::CloudTexel) + 16;
    const bool reduced = passPixels != pixels;
    checkDeviceMemory(
        ctx_, full.width, full.height,
        perPixel * (passPixels + (reduced ? pixels : 0)) +
            (reduced ? pixels * (sizeof(model::BackgroundLight) + sizeof(model::BackgroundTexel))
                     : 32) +
            cloudShadowMapBytes(full));
    ctx_.device.waitIdle();
    sized_ = std::make_unique<ResourceSet>(ctx_);
    width_ = full.width;
    height_ = full.height;
    passWidth_ = pass.width;
    passHeight_ = pass.height;
    passDepth_ = &sized_->hostBuffer(passPixels * 4, kStorage);
    passCloud_ = &sized_->hostBuffer(passPixels * sizeof(model::CloudTexel), kStorage);
    passComposite_ = &sized_->hostBuffer(passPixels * 16, kStorage);
    if (passPixels != pixels) {
        outDepth_ = &sized_->hostBuffer(pixels * 4, kStorage);
        outCloud_ = &sized_->hostBuffer(pixels * sizeof(model::CloudTexel), kStorage);
        outComposite_ = &sized_->hostBuffer(pixels * 16, kStorage);
        outBackground_ = &sized_->hostBuffer(pixels * sizeof(model::BackgroundLight), kStorage);
        outSeen_ = &sized_->hostBuffer(pixels * sizeof(model::BackgroundTexel), kStorage);
    } else { // no upsample
        outBackground_ = &sized_->hostBuffer(16, kStorage);
        outSeen_ = &sized_->hostBuffer(16, kStorage);
        outDepth_ = passDepth_;
        outCloud_ = passCloud_;
        outComposite_ = passComposite_;
    }
    noShaftGrid_ = &sized_->hostBuffer(sizeof(model::ShaftTexel), kStorage);
    noGroundFallback_ =
        &sized_->hostBuffer((model::GROUND_FALLBACK_HEADER_WORDS + 1) * 4, kStorage);
    writeDescriptors();
}

void VulkanStill::writeDescriptors() {
    device_->march().bind(ctx_, marchSet_, device_->textures(),
                          {blocks_.cloud, blocks_.frame, passDepth_, passCloud_, passComposite_,
                           blocks_.counters, &shadow_.buffer(), blocks_.frame, passCloud_});
    shadow_.bind(*blocks_.cloud, device_->textures());
    textureGeneration_ = device_->textures().generation();
    writeUpsampleSet(ctx_, upsampleSet_, device_->textures(),
                     {.cloudParams = blocks_.cloud,
                      .frameParams = blocks_.output,
                      .inCloud = passCloud_,
                      .sceneDepth = outDepth_,
                      .outCloud = outCloud_,
                      .outComposite = outComposite_,
                      .cloudShadow = &shadow_.buffer(),
                      .background = outBackground_,
                      .backgroundSeen = outSeen_,
                      .shafts = noShaftGrid_,
                      .groundFallback = noGroundFallback_,
                      .passBackgroundSeen = outSeen_}); // read by temporal frames only
}

RenderResult VulkanStill::render(const Scene& full, const SceneResources& resources,
                                 const ProgressCallback& progress, Readback readback) {
    const auto start = std::chrono::steady_clock::now();
    const Scene pass = full.cloudResolution < 1.0f ? cloudPassScene(full) : full;
    const bool reduced = pass.width != full.width || pass.height != full.height;
    if (full.width != width_ || full.height != height_ || pass.width != passWidth_ ||
        pass.height != passHeight_)
        allocate(full, pass);
    if (device_->textures().generation() != textureGeneration_)
        writeDescriptors();

    // Parameters, declared once in src/model/params.glsl.h and uploaded as they are.
    model::CloudParams cloud = makeCloudParams(pass, resources);
    device_->textures().restrictToBound(cloud);
    std::memcpy(blocks_.cloud->mapped, &cloud, sizeof cloud);
    const int features = model::modelFeaturesFor(cloud, pass.cameraPosition);
    if (shadow_.resize(CloudShadowMap::resolutionFor(cloud)) && sized_)
        writeDescriptors(); // the readers bind the new map
    uploadFrame(*blocks_.frame, *passDepth_, pass, resources, 0);
    if (reduced)
        uploadFrame(*blocks_.output, *outDepth_, full, resources, 0);

    const bool timed = ctx_.timestampValidBits > 0;
    const int tile = MarchPass::kTile;
    const int tileRows = (passHeight_ + tile - 1) / tile;
    bool shadowMade = false;
    for (int row = 0; row < tileRows; ++row) {
        const auto submit = [&](const std::function<void(vk::CommandBuffer)>& record) {
            try {
                submitAndWait(ctx_, record);
            } catch (...) {
                shadow_.invalidate(); // the map's pass may not have run
                throw;
            }
        };
        submit([&](vk::CommandBuffer cmd) {
            if (row == 0) {
                // Timestamps: start, after the shadow map, after the march, after the upsample.
                cmd.resetQueryPool(*queries_, 0, 4);
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries_, 0);
                resetCounters(cmd, *blocks_.counters);
                // The clouds' shadow map, before the passes that read it; kept while its
                // inputs stay (a still re-rendered, samples per pixel).
                shadowMade =
                    shadow_.record(cmd, cloud, features, device_->textures().contentVersion());
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries_, 1);
            }
            device_->march().recordRows(cmd, marchSet_, passWidth_, row * tile,
                                        std::min(passHeight_, (row + 1) * tile), features);
            if (row + 1 == tileRows) {
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries_, 2);
                if (reduced) {
                    // The background behind the clouds at the output size, then the upsample
                    // over it.
                    const model::UpsamplePush push{passWidth_, passHeight_, 0, 0};
                    device_->upsample().bind(cmd, upsampleSet_,
                                             features | model::PASS_FILL_BACKGROUND);
                    device_->upsample().push(cmd, push);
                    dispatchImage(cmd, width_, height_);
                    shaderWritesToShader(cmd);
                    device_->upsample().bind(cmd, upsampleSet_, features);
                    device_->upsample().push(cmd, push);
                    dispatchImage(cmd, width_, height_);
                }
                if (timed)
                    cmd.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *queries_, 3);
                shaderWritesToHost(cmd);
            }
        });
        if (progress)
            progress(static_cast<double>(row + 1) / tileRows);
    }

    // Read back only what was asked for.
    const size_t pixels = static_cast<size_t>(width_) * height_;
    RenderResult out;
    out.width = width_;
    out.height = height_;
    readBack(ctx_, *outComposite_, *outCloud_, pixels, readback, out);
    const model::FrameCounters totals = readCounters(ctx_, *blocks_.counters);
    out.stats.densitySamples = densitySamples(totals);
    out.stats.lightSamples = lightSamples(totals);
    out.stats.cloudSamples = cloudSamples(totals);
    out.stats.emptySkips = emptySkips(totals);
    out.stats.shadowMapMade = shadowMade;
    out.stats.shadowMapTexelsMade = shadow_.texelsMade();
    out.stats.backend = "vulkan: " + device_->deviceName();
    out.stats.rays = static_cast<uint64_t>(passWidth_) * passHeight_ *
                     static_cast<uint64_t>(pass.samplesPerPixel);
    out.stats.gpuMemoryBytes = blocks_.set->deviceBytes() + sized_->deviceBytes() +
                               device_->textures().deviceBytes() + shadow_.deviceBytes();
    out.stats.gpuTextureBytes = device_->textures().textureBytes();
    out.stats.gpuUploadMs = device_->textures().uploadMs();
    const std::vector<double> ms = timestampsMs(ctx_, *queries_, 4);
    if (!ms.empty()) {
        out.stats.gpuShadowMs = ms[1];
        out.stats.gpuMarchMs = ms[2] - ms[1];
        out.stats.marchSeconds = (ms[2] - ms[1]) * 1e-3;
        out.stats.resolveSeconds = (ms[3] - ms[2]) * 1e-3;
    }
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace cloudscape::vulkan
