// The cloud noise textures of GPU Pro 7 4.3.1, generated from tileable Perlin and Worley noise.
#include <cloudscape/error.h>
#include <cloudscape/noise.h>

#include "generators/tileable_noise.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace cloudscape {
namespace {

void requirePowerOfTwo(int size, int minSize, const char* what) {
    if (size < minSize || size > 1024 || (size & (size - 1)) != 0)
        throw Error(std::string(what) + " size " + std::to_string(size) +
                    " must be a power of two in [" + std::to_string(minSize) + ", 1024]");
}

// Fill level 0 of a cube texture a row at a time, one z slice per task: row(xs, y, z, texels)
// fills the `size` RGBA texels of the row at (y, z), whose texel centres' x are xs; every
// coordinate is (index + 0.5) / size, in [0, 1).
template <typename Row> Texture3D fillCubeRows(int size, const Row& row) {
    Texture3D t;
    t.size = size;
    t.mips.assign(1, std::vector<float>(static_cast<size_t>(size) * size * size * 4));
    std::vector<float> xs(size);
    for (int x = 0; x < size; ++x)
        xs[x] = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
    tbb::parallel_for(0, size, [&](int z) {
        const float pz = (static_cast<float>(z) + 0.5f) / static_cast<float>(size);
        for (int y = 0; y < size; ++y) {
            const float py = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
            row(xs.data(), py, pz, t.texel(0, 0, y, z));
        }
    });
    return t;
}

// Stretch each listed channel of level 0 linearly so that its 1st and 99th percentiles map to
// 0 and 1 (clamping the tails): the sampler's remaps need values across the whole range to make
// contrast, and a few outliers must not compress the rest.
void stretchChannels(std::vector<float>& data, int firstChannel, int lastChannel) {
    const size_t count = data.size() / 4;
    // Channels are independent: one task each (the result does not depend on the threading).
    tbb::parallel_for(firstChannel, lastChannel + 1, [&](int c) {
        std::vector<float> values(count);
        for (size_t i = 0; i < count; ++i)
            values[i] = data[i * 4 + c];
        const size_t loIndex = count / 100;
        const size_t hiIndex = count - 1 - count / 100;
        std::nth_element(values.begin(), values.begin() + loIndex, values.end());
        const float lo = values[loIndex];
        std::nth_element(values.begin(), values.begin() + hiIndex, values.end());
        const float hi = values[hiIndex];
        const float scale = hi > lo ? 1.0f / (hi - lo) : 0.0f;
        for (size_t i = 0; i < count; ++i)
            data[i * 4 + c] = std::clamp((data[i * 4 + c] - lo) * scale, 0.0f, 1.0f);
    });
}

void finish(Texture3D& t) {
    buildMipChain(t);
    quantizeToUnorm8(t);
}

} // namespace

Texture3D generateBaseNoise(uint32_t seed, int size) {
    requirePowerOfTwo(size, 8, "base noise");
    const uint32_t s = noise::hash32(seed * 3u + 0x1000u);
    // Worley FBMs with 4, 8 and 16 cells across the tile (each with two doubled octaves).
    const noise::WorleyFbm3 worleyLow(4, s + 10u), worleyMid(8, s + 20u), worleyHigh(16, s + 30u);
    // Perlin FBM with 4 cells across the tile and 5 octaves (4 .. 64 cells).
    const noise::PerlinFbm3 perlinFbm(4, 5, s);
    Texture3D t = fillCubeRows(size, [&](const float* xs, float y, float z, float* texels) {
        // The FBMs a row at a time (their row(): the same values as per point, faster).
        std::vector<float> low(size), mid(size), high(size), fbm(size), scratch(2 * size);
        worleyLow.row(xs, size, y, z, low.data(), scratch.data());
        worleyMid.row(xs, size, y, z, mid.data(), scratch.data());
        worleyHigh.row(xs, size, y, z, high.data(), scratch.data());
        perlinFbm.row(xs, size, y, z, fbm.data(), scratch.data());
        for (int x = 0; x < size; ++x) {
            // The Perlin FBM (about [-1, 1]) mapped to [0, 1].
            const float perlin = glm::clamp(fbm[x] * 0.75f + 0.5f, 0.0f, 1.0f);
            // Perlin-Worley: the Worley FBM becomes the new minimum of the Perlin range, which
            // dilates the Perlin shapes with round billows (GPU Pro 7 4.3.1).
            float* out = texels + 4 * x;
            out[0] = (perlin - (low[x] - 1.0f)) / (1.0f - (low[x] - 1.0f));
            out[1] = low[x];
            out[2] = mid[x];
            out[3] = high[x];
        }
    });
    stretchChannels(t.mips[0], 0, 3);
    finish(t);
    return t;
}

Texture3D generateDetailNoise(uint32_t seed, int size) {
    requirePowerOfTwo(size, 4, "detail noise");
    const uint32_t s = noise::hash32(seed * 3u + 0x2000u);
    const noise::WorleyFbm3 r(2, s + 10u), g(4, s + 20u), b(8, s + 30u);
    Texture3D t = fillCubeRows(size, [&](const float* xs, float y, float z, float* texels) {
        std::vector<float> red(size), green(size), blue(size), scratch(2 * size);
        r.row(xs, size, y, z, red.data(), scratch.data());
        g.row(xs, size, y, z, green.data(), scratch.data());
        b.row(xs, size, y, z, blue.data(), scratch.data());
        for (int x = 0; x < size; ++x) {
            float* out = texels + 4 * x;
            out[0] = red[x];
            out[1] = green[x];
            out[2] = blue[x];
            out[3] = 1.0f;
        }
    });
    stretchChannels(t.mips[0], 0, 2);
    finish(t);
    return t;
}

Texture2D generateCurlNoise(uint32_t seed, int size) {
    requirePowerOfTwo(size, 8, "curl noise");
    const uint32_t s = noise::hash32(seed * 3u + 0x3000u);
    // A vector potential psi(u, v) of three tileable Perlin FBMs; its curl in the plane,
    // (d psi_z / dv, -d psi_z / du, d psi_y / du - d psi_x / dv), is divergence-free in (u, v)
    // and tiles because the potential does. Derivatives are central differences on the grid.
    const int n = size;
    const noise::PerlinFbm2 psiX(4, 4, s), psiY(4, 4, s + 50u), psiZ(4, 4, s + 100u);
    std::vector<glm::vec3> psi(static_cast<size_t>(n) * n);
    tbb::parallel_for(0, n, [&](int y) {
        for (int x = 0; x < n; ++x) {
            const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(n);
            psi[static_cast<size_t>(y) * n + x] = glm::vec3(psiX(p), psiY(p), psiZ(p));
        }
    });
    auto at = [&](int x, int y) -> const glm::vec3& {
        return psi[static_cast<size_t>((y + n) % n) * n + (x + n) % n];
    };
    std::vector<glm::vec3> curl(psi.size());
    float largest = 0.0f;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::vec3 du = (at(x + 1, y) - at(x - 1, y)) * 0.5f;
            const glm::vec3 dv = (at(x, y + 1) - at(x, y - 1)) * 0.5f;
            const glm::vec3 c(dv.z, -du.z, du.y - dv.x);
            curl[static_cast<size_t>(y) * n + x] = c;
            largest = std::max({largest, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
        }
    Texture2D t;
    t.width = t.height = n;
    t.mips.assign(1, std::vector<float>(static_cast<size_t>(n) * n * 4));
    const float scale = largest > 0.0f ? 1.0f / largest : 0.0f;
    for (size_t i = 0; i < curl.size(); ++i) {
        const glm::vec3 v = curl[i] * scale;
        t.mips[0][i * 4 + 0] = 0.5f + 0.5f * v.x;
        t.mips[0][i * 4 + 1] = 0.5f + 0.5f * v.y;
        t.mips[0][i * 4 + 2] = 0.5f + 0.5f * v.z;
        t.mips[0][i * 4 + 3] = 1.0f;
    }
    buildMipChain(t);
    quantizeToUnorm8(t);
    return t;
}

Texture2D generateHighCloudTexture(uint32_t seed, int size) {
    requirePowerOfTwo(size, 16, "high cloud texture");
    const uint32_t s = noise::hash32(seed * 3u + 0x4000u);
    // Where each formation lies: broad patches, so the layer breaks up as coverage falls.
    const noise::PerlinFbm2 veil(2, 4, s), cirrusPatches(2, 3, s + 10u), warp(2, 3, s + 20u);
    const noise::PerlinFbm2 fibres(4, 4, s + 30u), puffPatches(3, 3, s + 40u);
    const noise::Worley3 puffs(48, s + 50u);
    constexpr float kStretch = 8.0f; // fibres 8 times longer (along z) than wide
    Texture2D t;
    t.width = t.height = size;
    t.mips.assign(1, std::vector<float>(static_cast<size_t>(size) * size * 4));
    tbb::parallel_for(0, size, [&](int y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(size);
            float* out = t.texel(0, x, y);
            // Cirrostratus: a smooth veil with faint streaks.
            const float streak = fibres(glm::vec2(kStretch * p.x, p.y));
            out[0] = 0.5f + 0.45f * veil(p) + 0.1f * streak;
            // Cirrus: broad streaks combed into fine ridged fibres along z, bent gently by a
            // low-frequency warp across their length (the hooks of mares' tails); integer
            // stretches keep the tile seamless.
            const float bend = 0.6f * warp(p);
            const float broad = 0.5f + 0.5f * veil(glm::vec2(2.0f * p.x + 0.25f * bend, p.y));
            const float ridge = 1.0f - std::abs(fibres(glm::vec2(kStretch * p.x + bend, p.y)));
            const float patch = glm::smoothstep(-0.3f, 0.5f, cirrusPatches(p));
            out[1] = (0.55f * broad + 0.45f * ridge * ridge) * patch;
            // Cirrocumulus: fields of small rounded puffs.
            const float puff = puffs.inverted(glm::vec3(p, 0.0f));
            out[2] = puff * std::sqrt(puff) * glm::smoothstep(-0.4f, 0.3f, puffPatches(p));
            out[3] = 1.0f;
        }
    });
    stretchChannels(t.mips[0], 0, 2);
    buildMipChain(t);
    quantizeToUnorm8(t);
    return t;
}

NoiseTextures generateNoiseTextures(uint32_t seed, bool withClearance) {
    NoiseTextures n;
    n.base = generateBaseNoise(seed, 128);
    if (withClearance)
        n.baseClearance = generateNoiseClearance(n.base);
    n.detail = generateDetailNoise(seed, 32);
    n.curl = generateCurlNoise(seed, 128);
    n.highClouds = generateHighCloudTexture(seed, 512);
    return n;
}

} // namespace cloudscape
