#include "generators/tileable_noise.h"

#include <algorithm>
#include <cmath>

namespace cloudscape::noise {
namespace {

inline int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Quintic fade (Perlin 2002): C2-continuous interpolation between lattice points.
inline float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// One of 12 cube-edge gradients (Perlin 2002), chosen by hash.
inline float gradDot3(uint32_t h, glm::vec3 d) {
    switch (h % 12u) {
    case 0:
        return d.x + d.y;
    case 1:
        return -d.x + d.y;
    case 2:
        return d.x - d.y;
    case 3:
        return -d.x - d.y;
    case 4:
        return d.x + d.z;
    case 5:
        return -d.x + d.z;
    case 6:
        return d.x - d.z;
    case 7:
        return -d.x - d.z;
    case 8:
        return d.y + d.z;
    case 9:
        return -d.y + d.z;
    case 10:
        return d.y - d.z;
    default:
        return -d.y - d.z;
    }
}

inline float gradDot2(uint32_t h, glm::vec2 d) {
    const float angle = static_cast<float>(h & 0xffffu) * (6.2831853f / 65536.0f);
    return std::cos(angle) * d.x + std::sin(angle) * d.y;
}

inline float unitFloat(uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

} // namespace

uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

uint32_t hashCombine(uint32_t seed, int a, int b, int c) {
    uint32_t h = hash32(seed ^ 0x9e3779b9u);
    h = hash32(h ^ static_cast<uint32_t>(a));
    h = hash32(h ^ (static_cast<uint32_t>(b) * 0x85ebca6bu));
    h = hash32(h ^ (static_cast<uint32_t>(c) * 0xc2b2ae35u));
    return h;
}

float perlin3(glm::vec3 p, int period, uint32_t seed) {
    const glm::vec3 q = p * static_cast<float>(period);
    const glm::vec3 f = glm::floor(q);
    const glm::vec3 d = q - f;
    const int x0 = static_cast<int>(f.x), y0 = static_cast<int>(f.y), z0 = static_cast<int>(f.z);
    float corners[8];
    for (int i = 0; i < 8; ++i) {
        const int dx = i & 1, dy = (i >> 1) & 1, dz = (i >> 2) & 1;
        const uint32_t h =
            hashCombine(seed, wrap(x0 + dx, period), wrap(y0 + dy, period), wrap(z0 + dz, period));
        corners[i] = gradDot3(h, d - glm::vec3(dx, dy, dz));
    }
    const float u = fade(d.x), v = fade(d.y), w = fade(d.z);
    const float x00 = glm::mix(corners[0], corners[1], u);
    const float x10 = glm::mix(corners[2], corners[3], u);
    const float x01 = glm::mix(corners[4], corners[5], u);
    const float x11 = glm::mix(corners[6], corners[7], u);
    return glm::mix(glm::mix(x00, x10, v), glm::mix(x01, x11, v), w);
}

float perlin2(glm::vec2 p, int period, uint32_t seed) {
    const glm::vec2 q = p * static_cast<float>(period);
    const glm::vec2 f = glm::floor(q);
    const glm::vec2 d = q - f;
    const int x0 = static_cast<int>(f.x), y0 = static_cast<int>(f.y);
    float corners[4];
    for (int i = 0; i < 4; ++i) {
        const int dx = i & 1, dy = (i >> 1) & 1;
        const uint32_t h = hashCombine(seed, wrap(x0 + dx, period), wrap(y0 + dy, period), 7);
        corners[i] = gradDot2(h, d - glm::vec2(dx, dy));
    }
    const float u = fade(d.x), v = fade(d.y);
    return glm::mix(glm::mix(corners[0], corners[1], u), glm::mix(corners[2], corners[3], u), v) *
           1.41421356f;
}

namespace {

// Octaves double the period (so each still tiles) and halve the amplitude; the sum is divided by
// the total amplitude to stay in about [-1, 1].
template <typename Vec, typename Noise>
float fractalSum(Vec p, int period, int octaves, uint32_t seed, Noise noise) {
    float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * noise(p, period << o, seed + static_cast<uint32_t>(o) * 101u);
        norm += amplitude;
        amplitude *= 0.5f;
    }
    return sum / norm;
}

} // namespace

float perlinFbm3(glm::vec3 p, int period, int octaves, uint32_t seed) {
    return fractalSum(p, period, octaves, seed, perlin3);
}

float perlinFbm2(glm::vec2 p, int period, int octaves, uint32_t seed) {
    return fractalSum(p, period, octaves, seed, perlin2);
}

Worley3::Worley3(int cells, uint32_t seed) : cells_(cells) {
    points_.resize(static_cast<size_t>(cells) * cells * cells);
    for (int z = 0; z < cells; ++z)
        for (int y = 0; y < cells; ++y)
            for (int x = 0; x < cells; ++x) {
                const uint32_t h = hashCombine(seed, x, y, z);
                points_[(static_cast<size_t>(z) * cells + y) * cells + x] =
                    glm::vec3(unitFloat(h), unitFloat(hash32(h + 1u)), unitFloat(hash32(h + 2u)));
            }
}

float Worley3::inverted(glm::vec3 p) const {
    const glm::vec3 q = p * static_cast<float>(cells_);
    const glm::vec3 f = glm::floor(q);
    const int cx = static_cast<int>(f.x), cy = static_cast<int>(f.y), cz = static_cast<int>(f.z);
    float best = 1e9f;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = cx + dx, y = cy + dy, z = cz + dz;
                const glm::vec3& fp =
                    points_[(static_cast<size_t>(wrap(z, cells_)) * cells_ + wrap(y, cells_)) *
                                cells_ +
                            wrap(x, cells_)];
                const glm::vec3 d = glm::vec3(x, y, z) + fp - q;
                best = std::min(best, glm::dot(d, d));
            }
    return 1.0f - std::min(std::sqrt(best), 1.0f);
}

WorleyFbm3::WorleyFbm3(int cells, uint32_t seed)
    : a_(cells, seed), b_(cells * 2, seed + 1u), c_(cells * 4, seed + 2u) {}

float WorleyFbm3::operator()(glm::vec3 p) const {
    return a_.inverted(p) * 0.625f + b_.inverted(p) * 0.25f + c_.inverted(p) * 0.125f;
}

} // namespace cloudscape::noise
