// GPU category: the clouds' shadow map (cloud_shadow.comp, the model's cloudShadowMapTexel) and
// the light shafts on the Vulkan backend against the CPU backend (the same model headers), under
// the validation layers: stills, the temporal resolve and the upsample of a reduced pass.
#include <cloudscape/backend.h>
#include <cloudscape/metrics.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>
#include <cloudscape/terrain.h>

#include "core/model_params.h"
#include "core/resources.h"
#include "core/tests/kept_shadow_map_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "vulkan/tests/vulkan_test_support.h"

using cloudscape::testing::channels;
using cloudscape::testing::vulkanWithValidation;

namespace {

// The mountains preset (which turns the map and the shafts on), small, with small textures.
cloudscape::Scene mountains() {
    cloudscape::Scene s = cloudscape::loadScene(cloudscape::resolveScenePath("mountains"));
    s.width = 64;
    s.height = 36;
    s.weatherResolution = 64;
    s.terrainResolution = 128;
    s.cloudShadowResolution = 128;
    return s;
}

cloudscape::SceneResources resourcesFor(const cloudscape::Scene& s) {
    cloudscape::SceneResources r;
    r.noise.base = cloudscape::generateBaseNoise(1, 32);
    r.noise.detail = cloudscape::generateDetailNoise(1, 16);
    r.noise.curl = cloudscape::generateCurlNoise(1, 32);
    r.weather = cloudscape::prepareWeather(s);
    r.weatherCoverage = cloudscape::CoverageField(r.weather);
    cloudscape::prepareAtmosphere(s, r);
    cloudscape::prepareTerrain(s, r);
    return r;
}

cloudscape::BackendOptions cpuBackend() {
    cloudscape::BackendOptions o;
    o.choice = cloudscape::BackendChoice::Cpu;
    return o;
}

double psnr(const std::vector<float>& a, const std::vector<float>& b) {
    return cloudscape::compareImages(channels(a, 0, 3), channels(b, 0, 3), 3).psnr;
}

// The fraction of pixels whose luminance differs by more than 2 %.
double differing(const std::vector<float>& cpu, const std::vector<float>& gpu) {
    size_t off = 0;
    for (size_t i = 0; i < cpu.size(); i += 4) {
        const double a = 0.2126 * cpu[i] + 0.7152 * cpu[i + 1] + 0.0722 * cpu[i + 2];
        const double b = 0.2126 * gpu[i] + 0.7152 * gpu[i + 1] + 0.0722 * gpu[i + 2];
        off += std::fabs(a - b) > 0.02 * std::max(a, 1e-3) ? 1 : 0;
    }
    return double(off) / double(cpu.size() / 4);
}

} // namespace

TEST(VulkanCloudShadow, StillsWithTheMapAndShaftsMatchTheCpuBackend) {
    cloudscape::Scene s = mountains();
    ASSERT_TRUE(s.cloudShadowEnabled && s.shaftsEnabled) << "the preset turns both on";
    const cloudscape::SceneResources r = resourcesFor(s);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    const cloudscape::RenderResult gpu = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    const double agree = psnr(cpu.composite, gpu.composite);
    // The map and shafts are used on the device: without them the image is another one.
    s.shaftsEnabled = false;
    s.cloudShadowEnabled = false;
    const cloudscape::RenderResult plain = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    const double changed = psnr(plain.composite, gpu.composite);
    const double off = differing(cpu.composite, gpu.composite);
    std::printf("shadow map + shafts still: CPU vs Vulkan %.1f dB, %.2f %% of pixels differ by "
                "> 2 %%; Vulkan on vs off %.1f dB\n",
                agree, 100.0 * off, changed);
    // Measured on lavapipe: 57.0 dB, and 5.5 % of the pixels differ by > 2 % (dark, shaded
    // terrain and air, where the shafts take away nearly all the single scattering, so a small
    // absolute difference at a 128-texel map's shadow edge is a large relative one; 2.7 % with
    // the preset's 512 texels). The PSNR is the figure of the agreement.
    EXPECT_GT(agree, 42.0);
    EXPECT_LT(off, 0.08);
    EXPECT_LT(changed, agree - 6.0) << "the backends agree far better than on differs from off";
    if (gpu.stats.gpuMarchMs >= 0.0) { // the shadow map's own timestamp
        std::printf("gpu shadow map %.2f ms (off: %.2f ms), march %.2f ms\n", gpu.stats.gpuShadowMs,
                    plain.stats.gpuShadowMs, gpu.stats.gpuMarchMs);
        EXPECT_GT(gpu.stats.gpuShadowMs, 0.0);
        EXPECT_LT(plain.stats.gpuShadowMs, gpu.stats.gpuShadowMs);
    }
}

TEST(VulkanCloudShadow, TemporalAndUpsampledFramesMatchTheCpuBackend) {
    cloudscape::Scene s = mountains();
    s.cloudResolution = 0.5f;
    const cloudscape::SceneResources r = resourcesFor(s);
    cloudscape::TemporalRenderer cpu(r);
    cloudscape::TemporalRenderer gpu(r, vulkanWithValidation());
    for (int f = 0; f < 3; ++f) {
        s.timeS = 20.0f * float(f); // the map is remade each frame as the clouds move
        const cloudscape::RenderResult a = cpu.renderFrame(s, f);
        const cloudscape::RenderResult b = gpu.renderFrame(s, f);
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        const double agree = psnr(a.composite, b.composite);
        const double off = differing(a.composite, b.composite);
        std::printf(
            "shadow map + shafts temporal frame %d: CPU vs Vulkan %.1f dB, %.2f %% differ\n", f,
            agree, 100.0 * off);
        EXPECT_GT(agree, 42.0) << "frame " << f; // measured 58.4-61.1 dB
        EXPECT_LT(off, 0.08) << "frame " << f;   // measured 4.4-5.8 %, as the still
    }
}

TEST(VulkanCloudShadow, TemporalFramesWithTheShaftGridMatchTheCpuBackend) {
    // Full-resolution clouds, so the resolve's composite (and its shafts from a 4x4 grid,
    // shaft_grid.glsl.h: the grid dispatch, then the resolve) is what is shown; then
    // half-resolution clouds, whose upsample reads the grid the pass made over its image.
    for (float resolution : {1.0f, 0.5f}) {
        cloudscape::Scene s = mountains();
        s.cloudResolution = resolution;
        const cloudscape::SceneResources r = resourcesFor(s);
        cloudscape::TemporalRenderer cpu(r);
        cloudscape::TemporalRenderer gpu(r, vulkanWithValidation());
        cloudscape::TemporalRenderer perPixel(r, vulkanWithValidation());
        for (int f = 0; f < 3; ++f) {
            s.timeS = 20.0f * float(f);
            s.shaftsGridFactor = 4;
            const cloudscape::RenderResult a = cpu.renderFrame(s, f);
            const cloudscape::RenderResult b = gpu.renderFrame(s, f);
            s.shaftsGridFactor = 1;
            const cloudscape::RenderResult c = perPixel.renderFrame(s, f);
            EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
            const double agree = psnr(a.composite, b.composite);
            const double off = differing(a.composite, b.composite);
            const double gridVsPixel = psnr(b.composite, c.composite);
            std::printf("shafts grid 4x4 temporal frame %d, clouds at %.1f: CPU vs Vulkan %.1f dB, "
                        "%.2f %% differ; Vulkan grid vs per pixel %.1f dB\n",
                        f, resolution, agree, 100.0 * off, gridVsPixel);
            EXPECT_GT(agree, 42.0) << "frame " << f << " at " << resolution;
            EXPECT_LT(off, 0.08) << "frame " << f << " at " << resolution;
            EXPECT_NE(b.composite, c.composite) << "the device's composite reads the grid";
            // The grid dispatch has its own timestamp. Its time is reported, not compared with
            // the per-pixel renderer's: that is a timing, and at load 6 the empty span between
            // the per-pixel renderer's two stamps once measured 3.9 ms against the grid's 0.9 ms.
            if (b.stats.gpuMarchMs >= 0.0) {
                EXPECT_GT(b.stats.gpuShaftGridMs, 0.0);
            }
        }
    }
}

// The map a Renderer hands out for looking at (the viewer's shadow-map view) is the one its last
// render or frame read: read back from the device, it agrees with the CPU backend's texel by
// texel; a frame with the clouds moved on hands out its own map, not the still's; with the map
// off there is none.
TEST(VulkanCloudShadow, TheRenderersMapIsTheOneItsLastFrameRead) {
    cloudscape::Scene s = mountains();
    cloudscape::Renderer gpu(s, resourcesFor(s), vulkanWithValidation());
    cloudscape::BackendOptions onCpu;
    onCpu.choice = cloudscape::BackendChoice::Cpu;
    cloudscape::Renderer cpu(s, resourcesFor(s), onCpu);
    const size_t texels = static_cast<size_t>(s.cloudShadowResolution) * s.cloudShadowResolution;
    // Over the texels with cloud: the mean optical depth of the first map, the mean absolute
    // difference of the two maps' optical depths, and the worst difference of the sun's
    // transmittance exp(-depth) (what the ground's shadow shows).
    struct Difference {
        double mean = 0.0, meanDifference = 0.0, worstTransmittance = 0.0;
        double offTexels = 0.0; // the fraction whose transmittance differs by > 0.05
    };
    auto compare = [](const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
        Difference d;
        size_t cloudy = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            const double t = std::fabs(std::exp(-a[i].z) - std::exp(-b[i].z));
            d.worstTransmittance = std::max(d.worstTransmittance, t);
            d.offTexels += t > 0.05 ? 1.0 / double(a.size()) : 0.0;
            if (a[i].z <= 0.0f && b[i].z <= 0.0f)
                continue;
            ++cloudy;
            d.mean += a[i].z;
            d.meanDifference += std::fabs(a[i].z - b[i].z);
        }
        d.mean /= double(std::max<size_t>(cloudy, 1));
        d.meanDifference /= double(std::max<size_t>(cloudy, 1));
        return d;
    };
    gpu.render(s);
    cpu.render(s);
    const std::vector<glm::vec4> stillGpu = gpu.cloudShadowMap();
    ASSERT_EQ(stillGpu.size(), texels);
    const Difference still = compare(cpu.cloudShadowMap(), stillGpu);
    s.timeS = 600.0f; // ten minutes of wind
    gpu.renderFrame(s, 0);
    cpu.renderFrame(s, 0);
    const std::vector<glm::vec4> frameGpu = gpu.cloudShadowMap();
    ASSERT_EQ(frameGpu.size(), texels);
    const Difference frame = compare(cpu.cloudShadowMap(), frameGpu);
    const Difference moved = compare(stillGpu, frameGpu);
    std::printf("shadow map read back, CPU vs Vulkan: optical depth %.2f, mean difference %.4f "
                "(still), %.4f (frame); transmittance: worst difference %.3f, %.3f, %.3f %%, "
                "%.3f %% of texels off by > 0.05; still vs the frame 10 minutes later: mean "
                "difference %.2f\n",
                still.mean, still.meanDifference, frame.meanDifference, still.worstTransmittance,
                frame.worstTransmittance, 100.0 * still.offTexels, 100.0 * frame.offTexels,
                moved.meanDifference);
    // Measured on lavapipe: optical depth 9.35, mean differences 0.18 and 0.16 (1.9 % and
    // 2.5 %), 2.8 % and 2.1 % of the texels off by > 0.05 in transmittance (up to 0.44): one of
    // the 32 samples of a texel's ray at a cloud's edge read differently by the two backends'
    // filtering, as in the images above. A map read from the wrong place or frame is off by
    // the whole depth (the still against the frame: 8.03).
    EXPECT_GT(still.mean, 1.0) << "the map holds cloud";
    EXPECT_LT(still.meanDifference, 0.05 * still.mean);
    EXPECT_LT(frame.meanDifference, 0.05 * frame.mean);
    EXPECT_LT(still.offTexels, 0.06);
    EXPECT_LT(frame.offTexels, 0.06);
    EXPECT_GT(moved.meanDifference, 0.3 * frame.mean) << "the frame's own map, not the still's";
    s.cloudShadowEnabled = false;
    s.shaftsEnabled = false;
    gpu.render(s);
    EXPECT_TRUE(gpu.cloudShadowMap().empty());
}

// The Vulkan renderers keep their shadow map while its inputs stay, and a flying camera makes
// only the rows and columns its move brings in (src/core/tests/kept_shadow_map_checks.h, the
// checks the CPU temporal renderer passes too); the whole map for a camera is what a renderer
// coming from far away makes.
TEST(VulkanCloudShadow, TheMapIsMadeAgainOnlyWhenItsInputsChange) {
    const cloudscape::Scene s = mountains();
    cloudscape::Renderer gpu(s, resourcesFor(s), vulkanWithValidation());
    cloudscape::testing::expectTheMapMadeAgainOnlyWhenItsInputsChange(gpu, s);
}

TEST(VulkanCloudShadow, AFlyingCameraMakesOnlyTheTexelsItsMoveBringsIn) {
    cloudscape::Scene s = mountains();
    s.cloudShadowResolution = 64;
    const cloudscape::SceneResources r = resourcesFor(s);
    cloudscape::Renderer flying(s, r, vulkanWithValidation());
    cloudscape::Renderer whole(s, r, vulkanWithValidation());
    const float texel = s.cloudShadowExtentM / float(s.cloudShadowResolution);
    const int64_t texels = int64_t(s.cloudShadowResolution) * s.cloudShadowResolution;
    int frame = 0;
    cloudscape::testing::expectAFlyingCameraMakesOnlyTheTexelsItsMoveBringsIn(
        flying, s, [&](const cloudscape::Scene& at) {
            cloudscape::Scene far = at;
            far.cameraPosition.x += 1000.0f * texel;
            whole.renderFrame(far, frame);
            EXPECT_EQ(whole.renderFrame(at, frame++).stats.shadowMapTexelsMade, texels);
            return whole.cloudShadowMap();
        });
}

// The Vulkan temporal renderer keeps the light of the background behind its clouds (terrain,
// ground, sky before the clouds' shadows: pixel.glsl.h's BackgroundLight) while the camera, the
// sun, the terrain and the air stay, applies each frame's clouds to it, and makes it again on
// any change of what it reads. Every frame, kept or made, matches the CPU backend (which makes it
// each frame): a change the key missed would leave the old sun's or camera's terrain behind the
// clouds (a camera left out of the key: 25.9 dB), and clouds the kept light did not follow would
// leave their old shadows. Half-resolution clouds, so both the resolve's and the upsample's
// buffers are kept; with cirrus, which is applied with the clouds.
TEST(VulkanCloudShadow, AKeptBackgroundIsTheOneTheFrameWouldMake) {
    cloudscape::Scene s = mountains();
    s.cloudResolution = 0.5f;
    s.highCloudCoverage = 0.6f;
    cloudscape::SceneResources r = resourcesFor(s);
    r.noise.highClouds = cloudscape::generateHighCloudTexture(1, 64);
    cloudscape::Renderer cpu(s, r, cpuBackend());
    cloudscape::Renderer gpu(s, r, vulkanWithValidation());
    int frame = 0;
    // made: the light is made; shaded: the clouds are applied to it (kept when nothing changed).
    auto step = [&](const char* what, bool made, bool shaded) {
        const cloudscape::RenderResult a = cpu.renderFrame(s, frame);
        const cloudscape::RenderResult b = gpu.renderFrame(s, frame);
        ++frame;
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        EXPECT_EQ(b.stats.backgroundMade, made) << what;
        EXPECT_EQ(b.stats.backgroundShaded, shaded) << what;
        const double agree = psnr(a.composite, b.composite);
        std::printf("background %s (light %s, shadows %s): CPU vs Vulkan %.1f dB\n", what,
                    made ? "made" : "kept", shaded ? "applied" : "kept", agree);
        EXPECT_GT(agree, 42.0) << what; // as the temporal frames above
    };
    auto paint = [](cloudscape::Texture2D& w) {
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                w.texel(0, x, y)[0] = 1.0f;
    };
    step("first frame", true, true);
    step("same scene", false, false);
    s.exposure *= 2.0f; // applied after the composite
    step("another exposure", false, false);
    s.timeS += 120.0f; // the clouds and their shadows move on the kept light
    step("two minutes of wind", false, true);
    s.coverage += 0.15f;
    step("more coverage", false, true);
    gpu.editWeatherMap({{0, 0, 32, 32}}, paint);
    cpu.editWeatherMap({{0, 0, 32, 32}}, paint);
    step("painted weather", false, true);
    s.cameraHeadingDeg += 4.0f;
    step("camera turned", true, true);
    step("camera still", false, false);
    s.sunElevationDeg += 8.0f;
    step("sun higher", true, true);
    s.terrainHeightM *= 0.8f;
    step("lower terrain", true, true);
    s.atmosphereGroundAlbedo = glm::vec3(0.3f);
    step("another ground albedo", true, true);
    // The high layer belongs to the clouds' part: kept light, the layer applied again.
    s.timeS += 600.0f;
    step("the cirrus drifts", false, true);
    s.highCloudCoverage = 0.4f;
    step("thinner cirrus", false, true);
    s.highCloudAltitudeM = 8000.0f;
    step("lower cirrus", false, true);
    s.highCloudPhaseG = 0.5f;
    step("another ice phase", false, true);
    step("all kept", false, false);
    // render.background_samples: the light is made of four rays a pixel, then kept again.
    s.backgroundSamples = 4;
    step("four rays a pixel", true, true);
    step("four rays kept", false, false);
}

// render.moving_background_reduced (the low tier): while the camera moves, the background behind
// half-resolution clouds is made for the pass's pixels (with its light, the clouds' shadows, the
// ground fallback's list, the cirrus) and brought up to the output by the upsample
// (upsampledBackground). Every frame matches the CPU backend, which brings it up by the same rule;
// moving frames differ from the full-size background only as an upsampled image does; the first
// frame and a still camera's are the full-size background's exactly, the first still frame after
// a move included (the renderer makes it again rather than keep the pass's).
TEST(VulkanCloudShadow, AMovingCamerasBackgroundComesFromTheReducedPassAndStopsWithIt) {
    cloudscape::Scene s = mountains();
    s.cloudResolution = 0.5f;
    s.highCloudCoverage = 0.6f;
    s.cloudShadowExtentM = 8000.0f; // some ground beyond the map: the fallback's list is used
    s.movingBackgroundReduced = true;
    cloudscape::SceneResources r = resourcesFor(s);
    r.noise.highClouds = cloudscape::generateHighCloudTexture(1, 64);
    cloudscape::Renderer cpu(s, r, cpuBackend());
    cloudscape::Renderer gpu(s, r, vulkanWithValidation());
    cloudscape::Renderer fullSize(s, r, vulkanWithValidation()); // the key off
    int frame = 0;
    auto step = [&](const char* what, bool moving, bool made) {
        cloudscape::Scene off = s;
        off.movingBackgroundReduced = false;
        const cloudscape::RenderResult a = cpu.renderFrame(s, frame);
        const cloudscape::RenderResult b = gpu.renderFrame(s, frame);
        const cloudscape::RenderResult c = fullSize.renderFrame(off, frame);
        ++frame;
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        const double agree = psnr(a.composite, b.composite);
        const double upsampled = psnr(c.composite, b.composite);
        std::printf("%s: CPU vs Vulkan %.1f dB; against the full-size background %.1f dB\n", what,
                    agree, upsampled);
        EXPECT_GT(agree, 42.0) << what; // as the kept backgrounds above
        EXPECT_EQ(b.stats.backgroundMade, made) << what;
        EXPECT_EQ(b.cloud, c.cloud) << what << ": the clouds do not depend on the background";
        if (moving) {
            EXPECT_LT(upsampled, 60.0) << what << ": the background came from the pass";
            EXPECT_GT(upsampled, 25.0) << what << ": as an upsampled image differs";
        } else {
            EXPECT_EQ(b.composite, c.composite) << what << ": the full-size background";
        }
    };
    step("first frame", false, true);
    s.cameraHeadingDeg += 4.0f;
    step("camera turned", true, true);
    s.cameraPosition += glm::vec3(60.0f, 0.0f, 40.0f);
    step("camera flown", true, true);
    step("camera stopped", false, true); // made again: the output's was not made while moving
    s.timeS += 60.0f; // the wind on a still camera: the kept light, the clouds applied again
    step("wind", false, false);
}

// The background pass that applies the clouds to the kept light is built without the ground's
// two-sample fallback (llvmpipe would make every pixel pay for it under a mask); it lists the
// pixels whose ground lies beyond the shadow map and a dispatch of their own shades them with
// it. With a map much smaller than the view, part of the image is such ground: the list holds
// some pixels and not all, and every frame, at full and at half resolution (the upsample's
// list), matches the CPU backend, which shades every pixel with the fallback.
TEST(VulkanCloudShadow, TheGroundBeyondTheMapIsShadedByADispatchOfItsOwn) {
    for (float resolution : {1.0f, 0.5f}) {
        cloudscape::Scene s = mountains();
        s.cloudResolution = resolution;
        s.cloudShadowExtentM = 8000.0f;
        const cloudscape::SceneResources r = resourcesFor(s);
        cloudscape::Renderer cpu(s, r, cpuBackend());
        cloudscape::Renderer gpu(s, r, vulkanWithValidation());
        for (int frame = 0; frame < 3; ++frame) {
            s.timeS += 30.0f; // the clouds move: the kept light is shaded again
            const cloudscape::RenderResult a = cpu.renderFrame(s, frame);
            const cloudscape::RenderResult b = gpu.renderFrame(s, frame);
            EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
            EXPECT_GT(b.stats.groundFallbackPixels, 0) << resolution;
            EXPECT_LT(b.stats.groundFallbackPixels, int64_t{s.width} * s.height) << resolution;
            const double agree = psnr(a.composite, b.composite);
            std::printf("resolution %.1f frame %d: %lld pixels beyond the map, CPU vs Vulkan "
                        "%.1f dB\n",
                        resolution, frame, static_cast<long long>(b.stats.groundFallbackPixels),
                        agree);
            EXPECT_GT(agree, 42.0) << resolution << " frame " << frame;
        }
    }
}
