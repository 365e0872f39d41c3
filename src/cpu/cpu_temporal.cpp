// CPU plumbing of the temporal reconstruction: the fresh 1/16 pass, the full-resolution resolve
// (both from src/model), and the history buffers. No cloud physics here.
#include <cloudscape/temporal.h>

#include "core/cloud_resolution.h"
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/resources.h"
#include "core/temporal_impl.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_model.h"
#include "model/temporal.glsl.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

// The buffers the model's history/fresh reads see on this thread.
struct TemporalBuffers {
    int width = 0, height = 0, blocksX = 0, blocksY = 0;
    const std::vector<float>* historyCloud = nullptr; // 4 per pixel
    const std::vector<float>* historyDepth = nullptr; // NO_HIT where none
    const std::vector<float>* historyWeight = nullptr;
    const std::vector<float>* historyFlash = nullptr; // the masked lightning flash
    const std::vector<float>* freshCloud = nullptr;   // 4 per block
    const std::vector<float>* freshDepth = nullptr;
    const std::vector<float>* freshFlash = nullptr;
    const std::vector<float>* freshDebug = nullptr; // CloudTexel.debug of each block's march
    // The ring of earlier frames' marches (sample_gather.glsl.h): gatherStride blocks a position.
    const std::vector<model::CloudTexel>* gatherRing = nullptr;
    const std::vector<model::FrameParams>* gatherFrames = nullptr;
    int gatherStride = 0;
    // The entering ring (sample_gather.glsl.h): ENTERING_MARCHES records a block a slot.
    const std::vector<model::CloudTexel>* gatherEntering = nullptr;
};
thread_local const TemporalBuffers* tlsBuffers = nullptr;

} // namespace
} // namespace cloudscape

// The model's temporal reads (temporal.glsl.h), served from this thread's buffers; the filtering
// and clamping are the model's.
namespace cloudscape::model {

CloudTexel historyTexel(ivec2 pixel) {
    const TemporalBuffers& b = *tlsBuffers;
    const size_t i = static_cast<size_t>(pixel.y) * b.width + pixel.x;
    CloudTexel t = cloudTexelOf(*b.historyCloud, (*b.historyDepth)[i], i);
    t.weight = (*b.historyWeight)[i];
    t.flash = (*b.historyFlash)[i];
    return t;
}

CloudTexel freshTexel(ivec2 block) {
    const TemporalBuffers& b = *tlsBuffers;
    const size_t i = static_cast<size_t>(block.y) * b.blocksX + block.x;
    CloudTexel t = cloudTexelOf(*b.freshCloud, (*b.freshDepth)[i], i);
    t.flash = (*b.freshFlash)[i];
    t.debug = (*b.freshDebug)[i];
    return t;
}

FrameParams gatherFrame(int position) {
    return (*tlsBuffers->gatherFrames)[static_cast<size_t>(position)];
}

CloudTexel gatherTexel(int position, int blockIndex) {
    const TemporalBuffers& b = *tlsBuffers;
    return (*b.gatherRing)[static_cast<size_t>(position) * b.gatherStride + blockIndex];
}

CloudTexel gatherEnteringTexel(int slot, int blockIndex, int k) {
    const TemporalBuffers& b = *tlsBuffers;
    const size_t block = static_cast<size_t>(slot) * b.gatherStride + blockIndex;
    return (*b.gatherEntering)[block * ENTERING_MARCHES + k];
}

} // namespace cloudscape::model

namespace cloudscape {

namespace {

class CpuTemporal final : public TemporalRenderer::Impl {
public:
    explicit CpuTemporal(const SceneResources& r) : resources(r) {}
    RenderResult renderFrame(const Scene& scene, int frameIndex, Readback readback) override;
    // compositing false: a reduced-resolution pass, whose upsample composites at full size, so
    // no composite is made (as on Vulkan); its shadow map and shafts' grid go to passProducts.
    RenderResult renderPass(const Scene& scene, int frameIndex, Readback readback,
                            bool compositing);
    TemporalState saveState() const override;
    void restoreState(const TemporalState& state) override;
    std::string backendName() const override { return "cpu"; }
    // Whether frame frameIndex at this size continues the kept history's sequence.
    bool continuesAt(int frameIndex, int width, int height) const {
        return haveHistory && lastFrame == frameIndex - 1 && lastFrameParams.width == width &&
               lastFrameParams.height == height;
    }
    std::vector<glm::vec4> lastCloudShadowMap() const override {
        return cpu::cloudShadowMapInRows(shadow.stored(), shadow.placement());
    }
    void texturesChanged() override { ++texturesVersion; }
    TemporalDebugImage debugImage() const override {
        if (lastDebug.empty())
            return {};
        return temporalDebugImageOf(lastDebug.data(), lastFrameParams.width,
                                    lastFrameParams.height);
    }

    const SceneResources& resources;
    bool haveHistory = false;
    int lastFrame = -2;
    float lastTime = 0.0f;
    model::FrameParams lastFrameParams{};
    std::vector<float> historyCloud, historyDepth, historyWeight;
    // The clouds' shadow map, kept while its inputs stay; the version of the resources'
    // textures (texturesChanged).
    cpu::KeptCloudShadowMap shadow;
    uint64_t texturesVersion = 0;
    // The clouds' shadow map and shafts' grid the last reduced-resolution pass made, for its
    // upsample.
    PassProducts passProducts;
    // The masked lightning flash channel (CloudTexel.flash).
    std::vector<float> historyFlash;
    // The last frame's CloudTexel.debug per pixel (the viewer's debug views); not history.
    std::vector<float> lastDebug;
    // The moving camera's ring of earlier marches (render.moving_gather_frames): the frames'
    // parameters by ring position, and their marches, gatherSlotBlocks a position.
    std::vector<model::FrameParams> gatherFrames;
    std::vector<model::CloudTexel> gatherRing;
    // The entering blocks' extra marches of the last ENTERING_FRAMES frames, enteringSlot's
    // slots of gatherSlotBlocks blocks (empty without a ring).
    std::vector<model::CloudTexel> gatherEntering;
    // Keeps this frame's marches in the ring (renderPass, after the march); entering: each
    // block's entering marches, which the march wrote into gatherEntering.
    void keepInRing(const model::FrameParams& frame, const std::vector<float>& cloud,
                    const std::vector<float>& depth, const std::vector<float>& flash,
                    const std::vector<float>& debug, const std::vector<float>& entering);
    // Makes room for this frame's entering marches: the entering ring, sized for the frame.
    void prepareEnteringRing(const model::FrameParams& frame);
};

} // namespace

// The history is kept as exactly these arrays, so saving and restoring are copies.
TemporalState CpuTemporal::saveState() const {
    TemporalState state;
    if (!haveHistory)
        return state;
    state.frameIndex = lastFrame;
    state.timeS = lastTime;
    state.width = lastFrameParams.width;
    state.height = lastFrameParams.height;
    const auto* params = reinterpret_cast<const uint8_t*>(&lastFrameParams);
    state.frameParams.assign(params, params + sizeof lastFrameParams);
    state.cloud = historyCloud;
    state.depth = historyDepth;
    state.weight = historyWeight;
    state.flash = historyFlash;
    const auto* frames = reinterpret_cast<const uint8_t*>(gatherFrames.data());
    state.gatherFrames.assign(frames, frames + gatherFrames.size() * sizeof(model::FrameParams));
    // The ring's records, then the entering ring's (TemporalState::gatherRing).
    const size_t floatsPerRecord = sizeof(model::CloudTexel) / 4;
    const auto* ring = reinterpret_cast<const float*>(gatherRing.data());
    state.gatherRing.assign(ring, ring + gatherRing.size() * floatsPerRecord);
    const auto* entering = reinterpret_cast<const float*>(gatherEntering.data());
    state.gatherRing.insert(state.gatherRing.end(), entering,
                            entering + gatherEntering.size() * floatsPerRecord);
    return state;
}

void CpuTemporal::restoreState(const TemporalState& state) {
    std::memcpy(&lastFrameParams, state.frameParams.data(), sizeof lastFrameParams);
    lastFrame = state.frameIndex;
    lastTime = state.timeS;
    historyCloud = state.cloud;
    historyDepth = state.depth;
    historyWeight = state.weight;
    historyFlash = state.flash;
    if (historyFlash.empty()) // a state saved without the channel: no flash in the history
        historyFlash.assign(historyWeight.size(), 0.0f);
    gatherFrames.resize(state.gatherFrames.size() / sizeof(model::FrameParams));
    const glm::ivec2 size(state.width, state.height);
    const size_t records = gatherFrames.size() * model::gatherSlotBlocks(size);
    gatherRing.resize(records);
    gatherEntering.resize(gatherFrames.empty() ? 0 : model::enteringRingRecords(size));
    if (gatherFrames.empty()) { // no ring kept: the next frame's starts over
        lastFrameParams.gatherValid = 0;
    } else { // (memcpy is not given the empty vectors' null pointers; the sizes were checked
             // by checkTemporalState)
        const size_t ringFloats = records * (sizeof(model::CloudTexel) / 4);
        std::memcpy(gatherFrames.data(), state.gatherFrames.data(), state.gatherFrames.size());
        std::memcpy(gatherRing.data(), state.gatherRing.data(), ringFloats * 4);
        std::memcpy(gatherEntering.data(), state.gatherRing.data() + ringFloats,
                    (state.gatherRing.size() - ringFloats) * 4);
    }
    haveHistory = true;
}

std::unique_ptr<TemporalRenderer::Impl> makeCpuTemporal(const SceneResources& resources) {
    return std::make_unique<CpuTemporal>(resources);
}

RenderResult CpuTemporal::renderFrame(const Scene& scene, int frameIndex, Readback readback) {
    checkCameraAboveTerrain(scene, resources);
    // Reduced-resolution clouds: the whole reconstruction runs at the pass size (its history
    // too), and each resolved frame is upsampled.
    if (scene.cloudResolution < 1.0f) {
        // While the camera moves the background may come from the pass too (decided before the
        // pass replaces the last frame's parameters).
        const Scene passScene = cloudPassScene(scene);
        model::FrameParams passFrame = makeFrameParams(passScene);
        passFrame.hasSceneDepth = resources.depth.empty() ? 0 : 1;
        const bool backgroundFromPass = model::backgroundFromPass(
            passFrame, lastFrameParams, continuesAt(frameIndex, passScene.width, passScene.height),
            true, scene.movingBackgroundReduced);
        RenderResult r = renderAtCloudResolution(
            scene, resources,
            [&](const Scene& pass, PassProducts& products) {
                RenderResult p = renderPass(pass, frameIndex, Readback::All, false);
                products = std::move(passProducts);
                return p;
            },
            backgroundFromPass);
        keepReadback(r, readback);
        return r;
    }
    return renderPass(scene, frameIndex, readback, true);
}

void CpuTemporal::prepareEnteringRing(const model::FrameParams& frame) {
    const size_t records =
        frame.gatherFrames > 0
            ? static_cast<size_t>(model::enteringRingRecords(glm::ivec2(frame.width, frame.height)))
            : 0;
    gatherEntering.resize(records);
}

void CpuTemporal::keepInRing(const model::FrameParams& frame, const std::vector<float>& cloud,
                             const std::vector<float>& depth, const std::vector<float>& flash,
                             const std::vector<float>& debug, const std::vector<float>& entering) {
    if (frame.gatherFrames <= 0) {
        gatherFrames.clear();
        gatherRing.clear();
        return;
    }
    const size_t stride =
        static_cast<size_t>(model::gatherSlotBlocks(glm::ivec2(frame.width, frame.height)));
    gatherFrames.resize(static_cast<size_t>(frame.gatherFrames));
    gatherRing.resize(gatherFrames.size() * stride);
    const size_t position = static_cast<size_t>(model::gatherPosition(frame, 0));
    gatherFrames[position] = frame;
    for (size_t b = 0; b < depth.size(); ++b) {
        model::CloudTexel& t = gatherRing[position * stride + b];
        t = cloudTexelOf(cloud, depth[b], b);
        t.weight = entering[b]; // the block's entering marches, as the device's march writes it
        t.flash = flash[b];
        t.debug = debug[b];
    }
}

RenderResult CpuTemporal::renderPass(const Scene& scene, int frameIndex, Readback readback,
                                     bool compositing) {
    const auto start = std::chrono::steady_clock::now();
    CpuTemporal& s = *this;
    const int width = scene.width, height = scene.height;
    const size_t pixels = static_cast<size_t>(width) * height;
    const bool continues = continuesAt(frameIndex, width, height);
    const model::CloudParams cloud = makeCloudParams(scene, s.resources);
    model::FrameParams frame = makeFrameParams(scene);
    const model::FrameMarch march = model::frameMarchFor(
        frameIndex, frame, s.lastFrameParams, continues, scene.movingBlock2x2, scene.stillBlock2x2);
    frame.temporalBlock = march.block;
    frame.frameIndex = march.cycle;
    frame.sequenceFrame = frameIndex;
    frame.gatherValid = model::gatherValidFor(frame, s.lastFrameParams, continues);
    const float dt = continues ? scene.timeS - s.lastTime : 0.0f;

    TemporalBuffers buffers;
    buffers.width = width;
    buffers.height = height;
    const glm::ivec2 blockCount =
        model::temporalBlockCount(glm::ivec2(width, height), frame.temporalBlock);
    buffers.blocksX = blockCount.x;
    buffers.blocksY = blockCount.y;
    const size_t blocks = static_cast<size_t>(buffers.blocksX) * buffers.blocksY;
    std::vector<float> freshCloud(blocks * 4), freshDepth(blocks), freshFlash(blocks),
        freshDebug(blocks), freshEntering(blocks);
    buffers.freshCloud = &freshCloud;
    buffers.freshDepth = &freshDepth;
    buffers.freshFlash = &freshFlash;
    buffers.freshDebug = &freshDebug;
    if (s.historyFlash.size() != s.historyWeight.size())
        s.historyFlash.assign(s.historyWeight.size(), 0.0f);
    buffers.historyCloud = &s.historyCloud;
    buffers.historyDepth = &s.historyDepth;
    buffers.historyWeight = &s.historyWeight;
    buffers.historyFlash = &s.historyFlash;

    cpu::TextureSet textures{&s.resources.noise.base, &s.resources.noise.detail,
                             &s.resources.noise.curl, &s.resources.weather};
    const std::vector<float> sceneDepth = sceneDepthFor(scene, s.resources);
    frame.hasSceneDepth = sceneDepth.empty() ? 0 : 1;
    textures.sceneDepth = sceneDepth.empty() ? nullptr : sceneDepth.data();
    textures.sceneDepthWidth = width;
    textures.noiseClearance =
        s.resources.noise.baseClearance.empty() ? nullptr : s.resources.noise.baseClearance.data();
    textures.atmosphere = s.resources.atmosphere.empty() ? nullptr : s.resources.atmosphere.data();
    textures.highClouds =
        s.resources.noise.highClouds.mips.empty() ? nullptr : &s.resources.noise.highClouds;
    textures.terrain =
        s.resources.terrain.heights.empty() ? nullptr : s.resources.terrain.heights.data();
    const std::vector<glm::vec4>& shadowMap = s.shadow.update(cloud, textures, s.texturesVersion);
    cpu::bindCloudShadowMap(textures, shadowMap);
    struct Counters {
        uint64_t density = 0, light = 0, cloud = 0, skips = 0, reprojected = 0, fallback = 0,
                 entering = 0;
        void addMarch(const model::PixelResult& p) {
            density += static_cast<uint64_t>(p.densitySamples);
            light += static_cast<uint64_t>(p.lightSamples);
            cloud += static_cast<uint64_t>(p.cloudSamples);
            skips += static_cast<uint64_t>(p.emptySkips);
        }
    };
    tbb::enumerable_thread_specific<Counters> counters;
    // A gathering frame's entering blocks march their other pixels too (sample_gather.glsl.h).
    const bool gathering = model::gatherActive(frame, s.lastFrameParams, continues);
    s.prepareEnteringRing(frame);
    const size_t enteringSlot = static_cast<size_t>(model::enteringSlot(frame, 0));
    const size_t slotBlocks =
        static_cast<size_t>(model::gatherSlotBlocks(glm::ivec2(width, height)));
    // 1. March one pixel per block.
    tbb::parallel_for(0, buffers.blocksY, [&](int by) {
        cpu::ScopedTextureBinding bind(textures);
        Counters& c = counters.local();
        for (int bx = 0; bx < buffers.blocksX; ++bx) {
            const glm::ivec2 pixel = model::marchedPixel(glm::ivec2(bx, by), frameIndex, frame);
            const model::PixelResult p = model::renderPixel(
                static_cast<uint32_t>(pixel.x), static_cast<uint32_t>(pixel.y), frame, cloud);
            c.addMarch(p);
            const size_t b = static_cast<size_t>(by) * buffers.blocksX + bx;
            freshCloud[b * 4 + 0] = p.cloudRadiance.x;
            freshCloud[b * 4 + 1] = p.cloudRadiance.y;
            freshCloud[b * 4 + 2] = p.cloudRadiance.z;
            freshCloud[b * 4 + 3] = p.transmittance;
            freshDepth[b] = p.depth;
            freshFlash[b] = p.flash;
            freshDebug[b] = model::texelDebugCode(model::TEMPORAL_SOURCE_MARCHED,
                                                  static_cast<float>(p.densitySamples));
            const int extra = model::enteringMarchCount(glm::ivec2(bx, by), frame,
                                                        s.lastFrameParams, cloud, dt, gathering);
            freshEntering[b] = static_cast<float>(extra);
            c.entering += static_cast<uint64_t>(extra);
            for (int k = 0; k < extra; ++k) {
                const glm::ivec2 m = model::enteringPixel(glm::ivec2(bx, by), k, frame);
                const model::PixelResult e = model::renderPixel(
                    static_cast<uint32_t>(m.x), static_cast<uint32_t>(m.y), frame, cloud);
                c.addMarch(e);
                const size_t record = (enteringSlot * slotBlocks + b) * model::ENTERING_MARCHES + k;
                s.gatherEntering[record] = model::marchRecord(e, 0.0f, 0.0f);
            }
        }
    });

    const auto marched = std::chrono::steady_clock::now();
    s.keepInRing(frame, freshCloud, freshDepth, freshFlash, freshDebug, freshEntering);
    buffers.gatherRing = &s.gatherRing;
    buffers.gatherFrames = &s.gatherFrames;
    buffers.gatherStride = model::gatherSlotBlocks(glm::ivec2(width, height));
    buffers.gatherEntering = &s.gatherEntering;

    // 2. The light shafts' grid, when the resolve's composite or the upsample's reads one.
    std::vector<model::ShaftTexel> shafts;
    if (model::shaftGridActive(cloud)) {
        const glm::ivec2 cells =
            model::shaftGridSize(glm::ivec2(width, height), cloud.shafts.gridFactor);
        shafts.resize(static_cast<size_t>(cells.x) * cells.y);
        tbb::parallel_for(0, cells.y, [&](int cy) {
            cpu::ScopedTextureBinding bind(textures);
            tlsBuffers = &buffers;
            for (int cx = 0; cx < cells.x; ++cx)
                shafts[static_cast<size_t>(cy) * cells.x + cx] = model::resolveShaftCell(
                    glm::ivec2(cx, cy), frameIndex, frame, s.lastFrameParams, cloud, dt, continues);
            tlsBuffers = nullptr;
        });
        textures.shafts = shafts.data();
        textures.shaftCellsX = cells.x;
    }

    // 3. Resolve every pixel from the fresh pixels and the reprojected history.
    RenderResult out;
    allocateResult(out, width, height);
    std::vector<float> newDepth(pixels), newWeight(pixels), newFlash(pixels), newDebug(pixels);
    tbb::parallel_for(0, height, [&](int y) {
        cpu::ScopedTextureBinding bind(textures); // the scene depth buffer
        tlsBuffers = &buffers;
        Counters& c = counters.local();
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            const glm::ivec2 pixel(x, y);
            const model::ResolvedPixel r =
                compositing
                    ? model::resolveAndComposite(pixel, frameIndex, frame, s.lastFrameParams, cloud,
                                                 dt, continues,
                                                 model::backgroundTexelAt(pixel, frame, cloud))
                    : model::resolveTemporal(pixel, frameIndex, frame, s.lastFrameParams, cloud, dt,
                                             continues,
                                             model::sceneGeometryDepth(pixel, frame, cloud));
            c.reprojected += r.source == model::TEMPORAL_SOURCE_REPROJECTED;
            c.fallback += r.source == model::TEMPORAL_SOURCE_FALLBACK;
            storePixel(out, i, glm::vec3(r.history.cloud), r.history.cloud.w, r.composite,
                       r.history.depth);
            newDepth[i] = r.history.depth;
            newWeight[i] = r.history.weight;
            newFlash[i] = r.history.flash;
            newDebug[i] = r.history.debug;
        }
        tlsBuffers = nullptr;
    });

    const auto resolved = std::chrono::steady_clock::now();
    out.stats.marchSeconds = std::chrono::duration<double>(marched - start).count();
    out.stats.resolveSeconds = std::chrono::duration<double>(resolved - marched).count();
    Counters total;
    for (const Counters& c : counters) {
        total.density += c.density;
        total.light += c.light;
        total.cloud += c.cloud;
        total.skips += c.skips;
        total.reprojected += c.reprojected;
        total.fallback += c.fallback;
        total.entering += c.entering;
    }
    // The blocks' marches and the entering blocks' extra ones (sample_gather.glsl.h).
    out.stats.rays = (blocks + total.entering) * static_cast<uint64_t>(scene.samplesPerPixel);
    out.stats.densitySamples = total.density;
    out.stats.shadowMapMade = s.shadow.texelsMade() > 0;
    out.stats.shadowMapTexelsMade = s.shadow.texelsMade();
    out.stats.lightSamples = total.light;
    out.stats.cloudSamples = total.cloud;
    out.stats.emptySkips = total.skips;
    s.breakdown.reprojected = static_cast<double>(total.reprojected) / pixels;
    s.breakdown.fallback = static_cast<double>(total.fallback) / pixels;
    s.breakdown.marched = 1.0 - s.breakdown.reprojected - s.breakdown.fallback;

    s.historyCloud = out.cloud;
    s.historyDepth = std::move(newDepth);
    s.historyWeight = std::move(newWeight);
    s.historyFlash = std::move(newFlash);
    s.lastDebug = std::move(newDebug);
    s.haveHistory = true;
    s.lastFrame = frameIndex;
    s.lastTime = scene.timeS;
    s.lastFrameParams = frame;
    // A reduced pass hands its map and shafts' grid to the upsample (renderFrame).
    s.passProducts.shadowMap = compositing ? std::vector<glm::vec4>{} : shadowMap;
    s.passProducts.shafts = compositing ? std::vector<model::ShaftTexel>{} : std::move(shafts);
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    keepReadback(out, readback);
    return out;
}

} // namespace cloudscape
