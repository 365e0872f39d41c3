// The march optimisations of issue 4, each against the same render with it off: the sample
// counts must move the expected way (counts, never time) and the image must stay within a stated
// quality bound. Also the scene depth buffer: pixels behind near geometry get no cloud and no
// samples.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/metrics.h>
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include "core/model_params.h"
#include "cpu/cpu_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>

using cloudscape::RenderResult;
using cloudscape::Scene;
using cloudscape::SceneResources;
namespace cm = cloudscape::model;

namespace {

const SceneResources& smallResources() {
    static const SceneResources r = [] {
        SceneResources res;
        res.noise.base = cloudscape::generateBaseNoise(1, 32);
        res.noise.detail = cloudscape::generateDetailNoise(1, 16);
        res.noise.curl = cloudscape::generateCurlNoise(1, 32);
        Scene s;
        s.weatherResolution = 128;
        res.weather = cloudscape::prepareWeather(s);
        return res;
    }();
    return r;
}

Scene smallScene() {
    Scene s;
    s.width = 96;
    s.height = 54;
    s.cameraPitchDeg = 15.0f;
    return s;
}

struct Quality {
    double psnr; // of the display luminance, peak 1
    double ssim;
};

Quality quality(const RenderResult& reference, const RenderResult& test, float exposure = 1.0f) {
    const auto a = cloudscape::displayLuminance(cloudscape::compositeRgb(reference), 3, exposure);
    const auto b = cloudscape::displayLuminance(cloudscape::compositeRgb(test), 3, exposure);
    return {cloudscape::compareImages(a, b, 1, {}, 1.0).psnr,
            cloudscape::ssim(a, b, reference.width, reference.height)};
}

double perRay(uint64_t samples, const RenderResult& r) {
    return static_cast<double>(samples) / static_cast<double>(r.stats.rays);
}

} // namespace

TEST(MarchOptimisation, StepOptimisationTakesFewerSamplesAndKeepsTheImage) {
    Scene off = smallScene();
    Scene on = off;
    on.stepOptimisation = 2.0f;
    const RenderResult a = cloudscape::renderCpu(off, smallResources());
    const RenderResult b = cloudscape::renderCpu(on, smallResources());
    const Quality q = quality(a, b);
    std::printf("step optimisation 2: density %.1f -> %.1f per ray, PSNR %.1f dB, SSIM %.3f\n",
                perRay(a.stats.densitySamples, a), perRay(b.stats.densitySamples, b), q.psnr,
                q.ssim);
    EXPECT_LT(b.stats.densitySamples, 0.85 * a.stats.densitySamples);
    EXPECT_LE(b.stats.lightSamples, a.stats.lightSamples * 1.02);
    EXPECT_GT(q.psnr, 30.0);
    EXPECT_GT(q.ssim, 0.90);
}

TEST(MarchOptimisation, StepOptimisationOffIsThePlainCoarseFineMarch) {
    // A ray straight up through a cloud layer with no coverage: every cheap sample is empty with
    // margin 1, so the march samples the fine grid t = start + (i + jitter) * step at
    // i = 0, s, 2s, ... for i + jitter within the layer's 64 zenith steps, where s is the coarse
    // factor c with gain 0 (the plain coarse/fine march) and c + floor(c * gain) with a gain.
    cloudscape::Texture2D clear;
    clear.width = clear.height = 4;
    clear.mips.assign(1, std::vector<float>(4 * 4 * 4, 0.0f));
    cloudscape::buildMipChain(clear);
    const SceneResources& res = smallResources();
    cloudscape::cpu::TextureSet set{&res.noise.base, &res.noise.detail, &res.noise.curl, &clear};
    cloudscape::cpu::ScopedTextureBinding bind(set);
    struct Case {
        int coarse;
        float gain;
        int stride; // fine steps between samples, by hand
    };
    const Case cases[] = {{1, 0.0f, 1}, {2, 0.0f, 2}, {3, 0.0f, 3}, {6, 0.0f, 6},
                          {2, 1.0f, 4}, {2, 0.5f, 3}, {1, 2.0f, 3}, {3, 1.5f, 7}};
    for (const Case& c : cases) {
        Scene s = smallScene();
        s.coarseStepFactor = c.coarse;
        s.stepOptimisation = c.gain;
        const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
        const cm::MarchResult m = cm::marchClouds(glm::vec3(0.0f, 2.0f, 0.0f),
                                                  glm::vec3(0.0f, 1.0f, 0.0f), 0.5f, 0.0f, P);
        // i + 0.5 <= 64: the last fine index is 63.
        EXPECT_EQ(m.densitySamples, 63 / c.stride + 1)
            << "coarse " << c.coarse << " gain " << c.gain;
        EXPECT_EQ(m.lightSamples, 0);
        EXPECT_EQ(m.transmittance, 1.0f);
    }
}

// Share of the non-DC spectral energy of an n x n image below a quarter of Nyquist (naive DFT).
double lowFrequencyShare(const std::vector<double>& img, int n) {
    double mean = 0.0;
    for (double v : img)
        mean += v;
    mean /= static_cast<double>(img.size());
    double low = 0.0, all = 0.0;
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const int fu = std::min(u, n - u), fv = std::min(v, n - v);
            if ((fu == 0 && fv == 0) || fu * fu + fv * fv > n * n / 4)
                continue;
            std::complex<double> sum = 0.0;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    sum += (img[static_cast<size_t>(y) * n + x] - mean) *
                           std::polar(1.0, -2.0 * std::numbers::pi * (u * x + v * y) / n);
            all += std::norm(sum);
            if (fu * fu + fv * fv <= n * n / 64)
                low += std::norm(sum);
        }
    return low / all;
}

TEST(MarchOptimisation, BlueNoiseStartOffsetsAreBlueAndStratifiedOverFrames) {
    cm::CloudParams P = cloudscape::makeCloudParams(smallScene(), 0.0f); // no weather read
    const int n = 32;
    auto offsets = [&](int blue, uint32_t sample) {
        P.blueNoise = blue;
        std::vector<double> img(static_cast<size_t>(n) * n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                img[static_cast<size_t>(y) * n + x] = cm::marchStartOffset(x, y, sample, 1u, P);
        return img;
    };
    // Every frame's offsets are blue, not just the first (the golden-ratio shift keeps them so).
    for (uint32_t sample : {0u, 1u, 7u}) {
        const double blue = lowFrequencyShare(offsets(1, sample), n);
        const double white = lowFrequencyShare(offsets(0, sample), n);
        EXPECT_LT(blue, 0.35 * white) << "sample " << sample << ": " << blue << " vs " << white;
    }
    // One pixel's offsets over 16 frames leave no gap wider than 3/16 (a Weyl sequence's gaps
    // stay below 2.62/N), so temporal accumulation averages evenly spread offsets.
    P.blueNoise = 1;
    std::vector<float> o;
    for (uint32_t k = 0; k < 16; ++k)
        o.push_back(cm::marchStartOffset(5, 9, k, 1u, P));
    std::sort(o.begin(), o.end());
    float gap = o.front() + 1.0f - o.back();
    for (size_t i = 1; i < o.size(); ++i)
        gap = std::max(gap, o[i] - o[i - 1]);
    EXPECT_LT(gap, 3.0f / 16.0f);
}

TEST(MarchOptimisation, BlueNoiseCostsNothingAndKeepsTheImage) {
    // The start offset does not change how many steps a ray takes, only where they fall: the
    // image differs from the hash's by step noise alone (two hash seeds differ by ~50 dB).
    Scene hash = smallScene();
    hash.blueNoise = false;
    Scene blue = hash;
    blue.blueNoise = true;
    const RenderResult h = cloudscape::renderCpu(hash, smallResources());
    const RenderResult b = cloudscape::renderCpu(blue, smallResources());
    const Quality q = quality(h, b);
    std::printf("blue noise against hash: PSNR %.1f dB, SSIM %.4f; density %.2f vs %.2f per "
                "ray\n",
                q.psnr, q.ssim, perRay(b.stats.densitySamples, b),
                perRay(h.stats.densitySamples, h));
    EXPECT_NEAR(perRay(b.stats.densitySamples, b), perRay(h.stats.densitySamples, h),
                0.03 * perRay(h.stats.densitySamples, h));
    EXPECT_NEAR(perRay(b.stats.lightSamples, b), perRay(h.stats.lightSamples, h),
                0.03 * perRay(h.stats.lightSamples, h));
    EXPECT_GT(q.psnr, 40.0);
    EXPECT_GT(q.ssim, 0.98);
}

TEST(MarchOptimisation, HalfResolutionCloudsMarchAQuarterOfTheRays) {
    Scene full = smallScene();
    Scene half = full;
    half.cloudResolution = 0.5f;
    const RenderResult a = cloudscape::renderCpu(full, smallResources());
    const RenderResult b = cloudscape::renderCpu(half, smallResources());
    ASSERT_EQ(b.width, full.width);
    ASSERT_EQ(b.height, full.height);
    const Quality q = quality(a, b);
    std::printf("half resolution: rays %llu -> %llu, density samples ratio %.3f, PSNR %.1f dB, "
                "SSIM %.3f\n",
                static_cast<unsigned long long>(a.stats.rays),
                static_cast<unsigned long long>(b.stats.rays),
                static_cast<double>(b.stats.densitySamples) / a.stats.densitySamples, q.psnr,
                q.ssim);
    EXPECT_EQ(b.stats.rays, a.stats.rays / 4);
    EXPECT_LT(b.stats.densitySamples, 0.3 * a.stats.densitySamples);
    EXPECT_GT(q.psnr, 25.0);
    EXPECT_GT(q.ssim, 0.75);
}

TEST(SceneDepth, PixelsBehindNearGeometryHaveNoCloudAndNoSamples) {
    Scene s = smallScene();
    SceneResources res = smallResources();
    const RenderResult open = cloudscape::renderCpu(s, res);
    // Left half: a wall 50 m away (nearer than the 1500 m cloud base); right half: sky.
    res.depth.width = s.width;
    res.depth.height = s.height;
    res.depth.metres.assign(static_cast<size_t>(s.width) * s.height,
                            std::numeric_limits<float>::infinity());
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width / 2; ++x)
            res.depth.metres[static_cast<size_t>(y) * s.width + x] = 50.0f;
    const RenderResult walled = cloudscape::renderCpu(s, res);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const size_t i = static_cast<size_t>(y) * s.width + x;
            if (x < s.width / 2) {
                ASSERT_EQ(walled.cloud[i * 4 + 0], 0.0f);
                ASSERT_EQ(walled.cloud[i * 4 + 3], 1.0f);
                ASSERT_TRUE(std::isinf(walled.depth[i]));
            } else {
                // Sky pixels march exactly as without a depth buffer.
                for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(walled.cloud[i * 4 + c], open.cloud[i * 4 + c]) << x << "," << y;
            }
        }
    EXPECT_LT(walled.stats.densitySamples, open.stats.densitySamples);
    // Everything behind the wall: not a single sample.
    for (float& m : res.depth.metres)
        m = 50.0f;
    const RenderResult closed = cloudscape::renderCpu(s, res);
    EXPECT_EQ(closed.stats.densitySamples, 0u);
    EXPECT_EQ(closed.stats.lightSamples, 0u);
}

TEST(SceneDepth, GeometryInsideTheLayerShortensTheMarch) {
    Scene s = smallScene();
    SceneResources res = smallResources();
    const RenderResult open = cloudscape::renderCpu(s, res);
    res.depth.width = s.width;
    res.depth.height = s.height;
    res.depth.metres.assign(static_cast<size_t>(s.width) * s.height, 8000.0f);
    const RenderResult cut = cloudscape::renderCpu(s, res);
    EXPECT_LT(cut.stats.densitySamples, open.stats.densitySamples);
    double tOpen = 0.0, tCut = 0.0;
    for (size_t i = 0; i < open.depth.size(); ++i) {
        tOpen += open.cloud[i * 4 + 3];
        tCut += cut.cloud[i * 4 + 3];
        // No cloud is seen beyond the geometry.
        if (std::isfinite(cut.depth[i])) {
            EXPECT_LE(cut.depth[i], 8000.0f);
        }
    }
    EXPECT_GT(tCut, tOpen); // less cloud in front of the geometry than in the open sky
}

TEST(SceneDepth, HalfResolutionRespectsFullResolutionGeometry) {
    Scene s = smallScene();
    s.cloudResolution = 0.5f;
    SceneResources res = smallResources();
    res.depth.width = s.width;
    res.depth.height = s.height;
    res.depth.metres.assign(static_cast<size_t>(s.width) * s.height,
                            std::numeric_limits<float>::infinity());
    // A one-pixel-wide pole at an odd column: thinner than a half-resolution pixel.
    for (int y = 0; y < s.height; ++y)
        res.depth.metres[static_cast<size_t>(y) * s.width + 31] = 20.0f;
    const RenderResult r = cloudscape::renderCpu(s, res);
    for (int y = 0; y < s.height; ++y) {
        const size_t i = static_cast<size_t>(y) * s.width + 31;
        EXPECT_EQ(r.cloud[i * 4 + 3], 1.0f) << "row " << y;
        EXPECT_EQ(r.cloud[i * 4 + 0], 0.0f) << "row " << y;
    }
}

TEST(SceneDepth, FileErrorsAreOneLine) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "cloudscape_depth_test";
    fs::create_directories(dir);
    const std::string missing = (dir / "missing.exr").string();
    try {
        cloudscape::loadDepthBuffer(missing, 16, 16);
        FAIL() << "no error for a missing file";
    } catch (const cloudscape::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("no such file"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
    const std::string path = (dir / "depth.exr").string();
    std::vector<float> metres(20 * 10, 100.0f);
    fs::remove(path);
    cloudscape::writeExr(path, 20, 10, {{"R", metres.data()}});
    const cloudscape::DepthBuffer d = cloudscape::loadDepthBuffer(path, 20, 10);
    EXPECT_EQ(d.metres, metres);
    try {
        cloudscape::loadDepthBuffer(path, 16, 16);
        FAIL() << "no error for a wrong size";
    } catch (const cloudscape::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("20x10 pixels, but the render is 16x16"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
    fs::remove_all(dir);
}

TEST(SceneDepth, TemporalReconstructionKeepsCloudOffNearGeometry) {
    // Reprojected history and upsampled marches come from neighbouring pixels; none may paint
    // cloud over the wall (the right half), at full or half cloud resolution.
    for (float resolution : {1.0f, 0.5f}) {
        Scene s = smallScene();
        s.cloudResolution = resolution;
        s.windSpeedMps = 150.0f; // the clouds move, so history is reprojected across the wall
        SceneResources res = smallResources();
        res.depth.width = s.width;
        res.depth.height = s.height;
        res.depth.metres.assign(static_cast<size_t>(s.width) * s.height,
                                std::numeric_limits<float>::infinity());
        for (int y = 0; y < s.height; ++y)
            for (int x = s.width / 2; x < s.width; ++x)
                res.depth.metres[static_cast<size_t>(y) * s.width + x] = 50.0f;
        cloudscape::TemporalRenderer temporal(res);
        RenderResult r;
        for (int f = 0; f < 24; ++f) {
            s.timeS = static_cast<float>(f) / 24.0f;
            r = temporal.renderFrame(s, f);
        }
        double sky = 0.0;
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const size_t i = static_cast<size_t>(y) * s.width + x;
                if (x >= s.width / 2) {
                    ASSERT_EQ(r.cloud[i * 4 + 3], 1.0f) << resolution << ": " << x << "," << y;
                    ASSERT_EQ(r.cloud[i * 4 + 0], 0.0f) << resolution << ": " << x << "," << y;
                } else {
                    sky += 1.0 - r.cloud[i * 4 + 3];
                }
            }
        EXPECT_GT(sky, 1.0) << resolution << ": the open half has cloud";
    }
}

TEST(MarchOptimisation, TiersSetTheNewKeys) {
    // The low tier is the PS4 column: half-resolution clouds, step optimisation on. The
    // reference (what `bench` measures against) and high tiers take no such shortcut, whatever
    // the scene says.
    Scene s;
    cloudscape::applyTier(s, "low");
    EXPECT_EQ(s.cloudResolution, 0.5f);
    EXPECT_EQ(s.stepOptimisation, 1.0f);
    for (const char* tier : {"reference", "high"}) {
        Scene t = s;
        cloudscape::applyTier(t, tier);
        EXPECT_EQ(t.cloudResolution, 1.0f) << tier;
        EXPECT_EQ(t.stepOptimisation, 0.0f) << tier;
    }
}
