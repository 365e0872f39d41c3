#include "cpu/cpu_textures.h"

#include <cloudscape/blue_noise.h>

#include "model/sampling.glsl.h"

#include <cassert>
#include <cmath>

namespace cloudscape::cpu {
namespace {

thread_local const TextureSet* tlsTextures = nullptr;

// GPUs interpolate between texels with a fixed-point weight (Vulkan's subTexelPrecisionBits,
// 8 on common hardware and on lavapipe); the CPU sampler rounds its weights the same way so the
// two backends filter alike.
constexpr float kSubTexelSteps = 256.0f;
inline float subTexelWeight(float fraction) {
    return std::floor(fraction * kSubTexelSteps + 0.5f) / kSubTexelSteps;
}

inline int wrapIndex(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Texel reads of a 3D level: float RGBA, or the 8-bit copy through a table of k / 255.0f, which
// are the very floats quantizeToUnorm8 stored, so both give bit-identical results; the 8-bit
// copy moves a quarter of the bytes (the base noise is 8 MB instead of 32 MB).
struct FloatTexels {
    const float* data;
    glm::vec4 operator()(size_t index) const {
        const float* p = data + index * 4;
        return glm::vec4(p[0], p[1], p[2], p[3]);
    }
};

struct Unorm8Table {
    float value[256];
    Unorm8Table() {
        for (int k = 0; k < 256; ++k)
            value[k] = static_cast<float>(k) / 255.0f;
    }
};
const Unorm8Table kUnorm8;

struct Unorm8Texels {
    const unsigned char* data;
    glm::vec4 operator()(size_t index) const {
        const unsigned char* p = data + index * 4;
        return glm::vec4(kUnorm8.value[p[0]], kUnorm8.value[p[1]], kUnorm8.value[p[2]],
                         kUnorm8.value[p[3]]);
    }
};

template <typename Texels> glm::vec4 sampleLevelOf(const Texels& texels, int n, glm::vec3 uvw) {
    const float fx = uvw.x * n - 0.5f;
    const float fy = uvw.y * n - 0.5f;
    const float fz = uvw.z * n - 0.5f;
    const float flx = std::floor(fx);
    const float fly = std::floor(fy);
    const float flz = std::floor(fz);
    const float ax = subTexelWeight(fx - flx);
    const float ay = subTexelWeight(fy - fly);
    const float az = subTexelWeight(fz - flz);
    const int x0 = wrapIndex(static_cast<int>(flx), n);
    const int y0 = wrapIndex(static_cast<int>(fly), n);
    const int z0 = wrapIndex(static_cast<int>(flz), n);
    const int x1 = x0 + 1 == n ? 0 : x0 + 1;
    const int y1 = y0 + 1 == n ? 0 : y0 + 1;
    const int z1 = z0 + 1 == n ? 0 : z0 + 1;
    const size_t sn = static_cast<size_t>(n);
    auto at = [&](int x, int y, int z) {
        return texels((static_cast<size_t>(z) * sn + y) * sn + x);
    };
    const glm::vec4 c00 = glm::mix(at(x0, y0, z0), at(x1, y0, z0), ax);
    const glm::vec4 c10 = glm::mix(at(x0, y1, z0), at(x1, y1, z0), ax);
    const glm::vec4 c01 = glm::mix(at(x0, y0, z1), at(x1, y0, z1), ax);
    const glm::vec4 c11 = glm::mix(at(x0, y1, z1), at(x1, y1, z1), ax);
    return glm::mix(glm::mix(c00, c10, ay), glm::mix(c01, c11, ay), az);
}

glm::vec4 sampleLevel(const Texture3D& t, glm::vec3 uvw, int level) {
    const int n = t.levelSize(level);
    if (static_cast<int>(t.unorm8.size()) == t.levelCount())
        return sampleLevelOf(Unorm8Texels{t.unorm8[level].data()}, n, uvw);
    return sampleLevelOf(FloatTexels{t.mips[level].data()}, n, uvw);
}

glm::vec4 sampleLevel(const Texture2D& t, glm::vec2 uv, int level) {
    const int w = t.levelWidth(level);
    const int h = t.levelHeight(level);
    const float* data = t.mips[level].data();
    const float fx = uv.x * w - 0.5f;
    const float fy = uv.y * h - 0.5f;
    const float flx = std::floor(fx);
    const float fly = std::floor(fy);
    const float ax = subTexelWeight(fx - flx);
    const float ay = subTexelWeight(fy - fly);
    const int x0 = wrapIndex(static_cast<int>(flx), w);
    const int y0 = wrapIndex(static_cast<int>(fly), h);
    const int x1 = x0 + 1 == w ? 0 : x0 + 1;
    const int y1 = y0 + 1 == h ? 0 : y0 + 1;
    auto at = [&](int x, int y) {
        const float* p = data + (static_cast<size_t>(y) * w + x) * 4;
        return glm::vec4(p[0], p[1], p[2], p[3]);
    };
    return glm::mix(glm::mix(at(x0, y0), at(x1, y0), ax), glm::mix(at(x0, y1), at(x1, y1), ax), ay);
}

// Split a level of detail into two levels and a blend weight, clamped to the chain.
template <typename Texture, typename Coord>
glm::vec4 sampleMipmapped(const Texture& t, Coord coord, float lod) {
    const int last = t.levelCount() - 1;
    if (lod <= 0.0f)
        return sampleLevel(t, coord, 0);
    if (lod >= static_cast<float>(last))
        return sampleLevel(t, coord, last);
    const int l0 = static_cast<int>(lod);
    const float f = lod - static_cast<float>(l0);
    const glm::vec4 a = sampleLevel(t, coord, l0);
    if (f == 0.0f)
        return a;
    return glm::mix(a, sampleLevel(t, coord, l0 + 1), f);
}

} // namespace

glm::vec4 sampleTexture(const Texture3D& texture, glm::vec3 uvw, float lod) {
    return sampleMipmapped(texture, uvw, lod);
}

glm::vec4 sampleTexture(const Texture2D& texture, glm::vec2 uv, float lod) {
    return sampleMipmapped(texture, uv, lod);
}

ScopedTextureBinding::ScopedTextureBinding(const TextureSet& textures) : previous_(tlsTextures) {
    tlsTextures = &textures;
}

ScopedTextureBinding::~ScopedTextureBinding() {
    tlsTextures = previous_;
}

} // namespace cloudscape::cpu

// The model's sampling interface (src/model/sampling.glsl.h), implemented for the CPU.
namespace cloudscape::model {

vec4 sampleBaseNoise(vec3 uvw, float lod) {
    assert(cpu::tlsTextures && "no textures bound to this thread");
    return cpu::sampleTexture(*cpu::tlsTextures->baseNoise, uvw, lod);
}

vec4 sampleDetailNoise(vec3 uvw, float lod) {
    return cpu::sampleTexture(*cpu::tlsTextures->detailNoise, uvw, lod);
}

vec4 sampleCurlNoise(vec2 uv) {
    return cpu::sampleTexture(*cpu::tlsTextures->curlNoise, uv, 0.0f);
}

vec4 sampleWeatherMap(vec2 uv) {
    return cpu::sampleTexture(*cpu::tlsTextures->weatherMap, uv, 0.0f);
}

// Unfiltered, wrapping: texelFetch(blueNoise, pixel & (size - 1), 0).x on the GPU.
float sampleBlueNoise(ivec2 pixel) {
    const Texture2D& t = blueNoiseTexture();
    const int x = pixel.x & (t.width - 1);
    const int y = pixel.y & (t.height - 1);
    return t.texel(0, x, y)[0];
}

float sampleSceneDepth(ivec2 pixel) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->sceneDepth && "no scene depth bound to this thread");
    return t->sceneDepth[static_cast<size_t>(pixel.y) * t->sceneDepthWidth + pixel.x];
}

vec4 sampleHighClouds(vec2 uv) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->highClouds && "no high cloud texture bound to this thread");
    return cpu::sampleTexture(*t->highClouds, uv, 0.0f);
}

vec4 atmosphereLutTexel(int index) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->atmosphere && "no atmosphere tables bound to this thread");
    return t->atmosphere[index];
}

float terrainHeightTexel(int index) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->terrain && "no terrain height field bound to this thread");
    return t->terrain[index];
}

uint noiseClearanceTexel(int index) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->noiseClearance && "no noise clearance field bound to this thread");
    return t->noiseClearance[index];
}

vec4 cloudShadowTexel(int index) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->cloudShadow && "no cloud shadow map bound to this thread");
    return t->cloudShadow[index];
}

ShaftTexel shaftTexel(ivec2 cell) {
    const cpu::TextureSet* t = cpu::tlsTextures;
    assert(t && t->shafts && "no light shafts' grid bound to this thread");
    return t->shafts[static_cast<size_t>(cell.y) * t->shaftCellsX + cell.x];
}

} // namespace cloudscape::model
