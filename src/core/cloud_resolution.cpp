#include "core/cloud_resolution.h"

#include <cloudscape/error.h>

#include "core/model_params.h"
#include "core/pixel_store.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_textures.h"
#include "model/upsample.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cloudscape {

Scene cloudPassScene(const Scene& full) {
    Scene s = full;
    s.width = std::max(1, static_cast<int>(std::ceil(full.width * full.cloudResolution)));
    s.height = std::max(1, static_cast<int>(std::ceil(full.height * full.cloudResolution)));
    s.cloudResolution = 1.0f;
    // The upsample carries the cloud layer alone (the CPU's from a RenderResult): the pass marches
    // the flash into it rather than into a mask channel.
    s.stormLightningFlashMask = false;
    return s;
}

std::vector<float> sceneDepthFor(const Scene& scene, const SceneResources& resources) {
    const DepthBuffer& d = resources.depth;
    if (d.empty())
        return {};
    if (d.width == scene.width && d.height == scene.height)
        return d.metres;
    if (d.width < scene.width || d.height < scene.height)
        throw Error("render.depth_file is " + std::to_string(d.width) + "x" +
                    std::to_string(d.height) + " but the render is " + std::to_string(scene.width) +
                    "x" + std::to_string(scene.height));
    std::vector<float> out(static_cast<size_t>(scene.width) * scene.height);
    for (int y = 0; y < scene.height; ++y) {
        const int y0 = y * d.height / scene.height;
        const int y1 = std::max(y0 + 1, (y + 1) * d.height / scene.height);
        for (int x = 0; x < scene.width; ++x) {
            const int x0 = x * d.width / scene.width;
            const int x1 = std::max(x0 + 1, (x + 1) * d.width / scene.width);
            float farthest = 0.0f;
            for (int yy = y0; yy < y1; ++yy)
                for (int xx = x0; xx < x1; ++xx)
                    farthest = std::max(farthest, d.metres[static_cast<size_t>(yy) * d.width + xx]);
            out[static_cast<size_t>(y) * scene.width + x] = farthest;
        }
    }
    return out;
}

namespace {
thread_local const RenderResult* tlsPass = nullptr; // what the model's passTexel reads
// What the model's passBackgroundTexel reads: the pass's background, one texel per pass pixel.
thread_local const std::vector<model::BackgroundTexel>* tlsPassBackground = nullptr;

// The background of every pass pixel (the model's backgroundTexelAt with the pass's frame and
// parameters, as the Vulkan pass's background dispatch makes it), for upsampledBackground.
std::vector<model::BackgroundTexel> passBackground(const Scene& full,
                                                   const SceneResources& resources,
                                                   const cpu::TextureSet& textures) {
    const Scene passScene = cloudPassScene(full);
    const model::CloudParams cloud = makeCloudParams(passScene, resources);
    const model::FrameParams frame = makeFrameParams(passScene);
    std::vector<model::BackgroundTexel> out(static_cast<size_t>(passScene.width) *
                                            passScene.height);
    tbb::parallel_for(0, passScene.height, [&](int y) {
        cpu::ScopedTextureBinding bind(textures);
        for (int x = 0; x < passScene.width; ++x)
            out[static_cast<size_t>(y) * passScene.width + x] =
                model::backgroundTexelAt(glm::ivec2(x, y), frame, cloud);
    });
    return out;
}
} // namespace

RenderResult upsampleCloudPass(const RenderResult& pass, const Scene& full,
                               const SceneResources& resources, const PassProducts* products,
                               bool backgroundFromPass) {
    const auto start = std::chrono::steady_clock::now();
    const model::CloudParams cloud = makeCloudParams(full, resources);
    model::FrameParams frame = makeFrameParams(full);
    const std::vector<float> depth = sceneDepthFor(full, resources);
    frame.hasSceneDepth = depth.empty() ? 0 : 1;
    cpu::TextureSet textures{&resources.noise.base, &resources.noise.detail, &resources.noise.curl,
                             &resources.weather};
    textures.sceneDepth = depth.empty() ? nullptr : depth.data();
    textures.sceneDepthWidth = full.width;
    textures.atmosphere = resources.atmosphere.empty() ? nullptr : resources.atmosphere.data();
    textures.highClouds =
        resources.noise.highClouds.mips.empty() ? nullptr : &resources.noise.highClouds;
    textures.terrain =
        resources.terrain.heights.empty() ? nullptr : resources.terrain.heights.data();
    std::vector<glm::vec4> made;
    const std::vector<glm::vec4>* shadowMap =
        products && !products->shadowMap.empty() ? &products->shadowMap : nullptr;
    if (!shadowMap) {
        made = cpu::computeCloudShadowMap(cloud, textures);
        shadowMap = &made;
    }
    cpu::bindCloudShadowMap(textures, *shadowMap);
    RenderResult out;
    allocateResult(out, full.width, full.height);
    const glm::ivec2 passSize(pass.width, pass.height);
    const bool shaftGrid = products && !products->shafts.empty();
    if (shaftGrid) {
        textures.shafts = products->shafts.data();
        textures.shaftCellsX = model::shaftGridSize(passSize, cloud.shafts.gridFactor).x;
    }
    const std::vector<model::BackgroundTexel> passBg =
        backgroundFromPass && depth.empty() ? passBackground(full, resources, textures)
                                            : std::vector<model::BackgroundTexel>{};
    // The per-pixel rule is the model's (upsample.glsl.h); this is scheduling and storage.
    tbb::parallel_for(0, full.height, [&](int y) {
        cpu::ScopedTextureBinding bind(textures);
        tlsPass = &pass;
        tlsPassBackground = &passBg;
        for (int x = 0; x < full.width; ++x) {
            const glm::ivec2 pixel(x, y);
            const model::UpsampledPixel p = model::upsampleCloudPass(
                pixel, passSize, frame, cloud,
                passBg.empty() ? model::backgroundTexelAt(pixel, frame, cloud)
                               : model::upsampledBackground(pixel, passSize, frame),
                shaftGrid);
            storePixel(out, static_cast<size_t>(y) * full.width + x, glm::vec3(p.cloud.cloud),
                       p.cloud.cloud.w, p.composite, p.cloud.depth);
        }
        tlsPass = nullptr;
        tlsPassBackground = nullptr;
    });
    out.stats = pass.stats;
    out.stats.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

RenderResult renderAtCloudResolution(const Scene& full, const SceneResources& resources,
                                     const CloudPass& pass, bool backgroundFromPass) {
    PassProducts products;
    const RenderResult reduced = pass(cloudPassScene(full), products);
    return upsampleCloudPass(reduced, full, resources, &products, backgroundFromPass);
}

} // namespace cloudscape

// The model's read of the pass (upsample.glsl.h), from this thread's RenderResult.
namespace cloudscape::model {

CloudTexel passTexel(ivec2 pixel) {
    const RenderResult& pass = *tlsPass;
    const size_t i = static_cast<size_t>(pixel.y) * pass.width + pixel.x;
    return cloudTexelOf(pass.cloud, std::isinf(pass.depth[i]) ? NO_HIT : pass.depth[i], i);
}

BackgroundTexel passBackgroundTexel(ivec2 pixel) {
    return (*tlsPassBackground)[static_cast<size_t>(pixel.y) * tlsPass->width + pixel.x];
}

} // namespace cloudscape::model
