#include "generators/tileable_noise.h"

#include <algorithm>
#include <cmath>

namespace cloudscape::noise {
namespace {

// i modulo n in [0, n). Nearly every call is already in range; the division is the slow path.
inline int wrap(int i, int n) {
    if (static_cast<unsigned>(i) < static_cast<unsigned>(n))
        return i;
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Quintic fade (Perlin 2002): C2-continuous interpolation between lattice points.
inline float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// The 12 cube-edge gradients of Perlin 2002, each (+-1, +-1) on two axes and 0 on the third,
// as (first axis, its sign, second axis, its sign). Index h % 12 of a lattice hash picks one.
struct EdgeGradient {
    int axisA;
    float signA;
    int axisB;
    float signB;
};
constexpr EdgeGradient kGradients[12] = {
    {0, 1.0f, 1, 1.0f}, {0, -1.0f, 1, 1.0f}, {0, 1.0f, 1, -1.0f}, {0, -1.0f, 1, -1.0f},
    {0, 1.0f, 2, 1.0f}, {0, -1.0f, 2, 1.0f}, {0, 1.0f, 2, -1.0f}, {0, -1.0f, 2, -1.0f},
    {1, 1.0f, 2, 1.0f}, {1, -1.0f, 2, 1.0f}, {1, 1.0f, 2, -1.0f}, {1, -1.0f, 2, -1.0f},
};

// Dot product of gradient g with the offset d; multiplying by +-1 is exact, so this equals the
// textbook "d.x - d.y" etc. bit for bit, without a branch per corner.
inline float gradDot3(unsigned g, glm::vec3 d) {
    const EdgeGradient& e = kGradients[g];
    return e.signA * d[e.axisA] + e.signB * d[e.axisB];
}

// A unit gradient at one of 65536 angles, chosen by hash.
inline glm::vec2 gradient2(uint32_t h) {
    const float angle = static_cast<float>(h & 0xffffu) * (6.2831853f / 65536.0f);
    return glm::vec2(std::cos(angle), std::sin(angle));
}

inline float unitFloat(uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// Perlin noise in a lattice cell from its corners' gradients (corner i at offset (i & 1,
// (i >> 1) & 1, i >> 2)) and the point's offset d in [0, 1)^3 within the cell.
inline float perlinInCell(const unsigned (&gradients)[8], glm::vec3 d) {
    float corners[8];
    for (int i = 0; i < 8; ++i) {
        const int dx = i & 1, dy = (i >> 1) & 1, dz = (i >> 2) & 1;
        corners[i] = gradDot3(gradients[i], d - glm::vec3(dx, dy, dz));
    }
    const float u = fade(d.x), v = fade(d.y), w = fade(d.z);
    const float x00 = glm::mix(corners[0], corners[1], u);
    const float x10 = glm::mix(corners[2], corners[3], u);
    const float x01 = glm::mix(corners[4], corners[5], u);
    const float x11 = glm::mix(corners[6], corners[7], u);
    return glm::mix(glm::mix(x00, x10, v), glm::mix(x01, x11, v), w);
}

// The gradients of the 8 corners of the lattice cell whose lowest corner is (x0, y0, z0).
template <typename GradientIndex>
void cellGradients(int x0, int y0, int z0, int period, const GradientIndex& gradientIndex,
                   unsigned (&gradients)[8]) {
    const int xs[2] = {wrap(x0, period), wrap(x0 + 1, period)};
    const int ys[2] = {wrap(y0, period), wrap(y0 + 1, period)};
    const int zs[2] = {wrap(z0, period), wrap(z0 + 1, period)};
    for (int i = 0; i < 8; ++i)
        gradients[i] = gradientIndex(xs[i & 1], ys[(i >> 1) & 1], zs[(i >> 2) & 1]);
}

// Periodic 3D Perlin noise; gradientIndex(x, y, z) gives the gradient (0..11) of the lattice
// point with wrapped coordinates in [0, period).
template <typename GradientIndex>
float perlin3With(glm::vec3 p, int period, const GradientIndex& gradientIndex) {
    const glm::vec3 q = p * static_cast<float>(period);
    const glm::vec3 f = glm::floor(q);
    unsigned gradients[8];
    cellGradients(static_cast<int>(f.x), static_cast<int>(f.y), static_cast<int>(f.z), period,
                  gradientIndex, gradients);
    return perlinInCell(gradients, q - f);
}

// perlin3With at (xs[t], y, z) for t in [0, count), into out[t]: the same values, with the
// gradients looked up once for each run of the row's points in one cell.
template <typename GradientIndex>
void perlin3RowWith(const float* xs, int count, float y, float z, int period,
                    const GradientIndex& gradientIndex, float* out) {
    const float scale = static_cast<float>(period);
    const float qy = y * scale, qz = z * scale;
    const float fy = std::floor(qy), fz = std::floor(qz);
    unsigned gradients[8];
    int cellX = 0;
    for (int t = 0; t < count; ++t) {
        const float qx = xs[t] * scale;
        const float fx = std::floor(qx);
        if (t == 0 || static_cast<int>(fx) != cellX) {
            cellX = static_cast<int>(fx);
            cellGradients(cellX, static_cast<int>(fy), static_cast<int>(fz), period, gradientIndex,
                          gradients);
        }
        out[t] = perlinInCell(gradients, glm::vec3(qx - fx, qy - fy, qz - fz));
    }
}

// The third lattice coordinate of the 2D noise's hash, so that it never shares a lattice with
// a 3D noise of the same seed.
constexpr int kPerlin2Salt = 7;

// Periodic 2D Perlin noise; gradient(x, y) gives the unit gradient of the lattice point with
// wrapped coordinates. Scaled by sqrt(2) to span about [-1, 1].
template <typename Gradient> float perlin2With(glm::vec2 p, int period, const Gradient& gradient) {
    const glm::vec2 q = p * static_cast<float>(period);
    const glm::vec2 f = glm::floor(q);
    const glm::vec2 d = q - f;
    const int x0 = static_cast<int>(f.x), y0 = static_cast<int>(f.y);
    const int xs[2] = {wrap(x0, period), wrap(x0 + 1, period)};
    const int ys[2] = {wrap(y0, period), wrap(y0 + 1, period)};
    float corners[4];
    for (int i = 0; i < 4; ++i) {
        const int dx = i & 1, dy = (i >> 1) & 1;
        const glm::vec2 g = gradient(xs[dx], ys[dy]);
        const glm::vec2 e = d - glm::vec2(dx, dy);
        corners[i] = g.x * e.x + g.y * e.y;
    }
    const float u = fade(d.x), v = fade(d.y);
    return glm::mix(glm::mix(corners[0], corners[1], u), glm::mix(corners[2], corners[3], u), v) *
           1.41421356f;
}

// Octaves double the period (so each still tiles) and halve the amplitude; the sum is divided by
// the total amplitude to stay in about [-1, 1]. octave(o) evaluates octave o.
template <typename Octave> float fractalSum(int octaves, const Octave& octave) {
    float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * octave(o);
        norm += amplitude;
        amplitude *= 0.5f;
    }
    return sum / norm;
}

// Lattices with more points than this are hashed on each evaluation instead of tabulated.
constexpr int64_t kMaxTable = int64_t(1) << 22;

inline uint32_t octaveSeed(uint32_t seed, int octave) {
    return seed + static_cast<uint32_t>(octave) * 101u;
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
    return perlin3With(p, period,
                       [seed](int x, int y, int z) { return hashCombine(seed, x, y, z) % 12u; });
}

float perlin2(glm::vec2 p, int period, uint32_t seed) {
    return perlin2With(p, period, [seed](int x, int y) {
        return gradient2(hashCombine(seed, x, y, kPerlin2Salt));
    });
}

float perlinFbm3(glm::vec3 p, int period, int octaves, uint32_t seed) {
    return fractalSum(octaves, [&](int o) { return perlin3(p, period << o, octaveSeed(seed, o)); });
}

float perlinFbm2(glm::vec2 p, int period, int octaves, uint32_t seed) {
    return fractalSum(octaves, [&](int o) { return perlin2(p, period << o, octaveSeed(seed, o)); });
}

PerlinFbm3::PerlinFbm3(int period, int octaves, uint32_t seed) {
    for (int o = 0; o < octaves; ++o) {
        Octave octave{period << o, 0u, {}};
        const int n = octave.period;
        const uint32_t s = octaveSeed(seed, o);
        octave.seed = s;
        if (static_cast<int64_t>(n) * n * n > kMaxTable) {
            octaves_.push_back(std::move(octave)); // too fine to tabulate: hashed on the fly
            continue;
        }
        octave.gradient.resize(static_cast<size_t>(n) * n * n);
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    octave.gradient[(static_cast<size_t>(z) * n + y) * n + x] =
                        static_cast<uint8_t>(hashCombine(s, x, y, z) % 12u);
        octaves_.push_back(std::move(octave));
    }
}

float PerlinFbm3::operator()(glm::vec3 p) const {
    return fractalSum(static_cast<int>(octaves_.size()), [&](int o) {
        const Octave& octave = octaves_[o];
        const int n = octave.period;
        if (octave.gradient.empty())
            return perlin3(p, n, octave.seed);
        return perlin3With(p, n, [&](int x, int y, int z) -> unsigned {
            return octave.gradient[(static_cast<size_t>(z) * n + y) * n + x];
        });
    });
}

void PerlinFbm3::row(const float* xs, int count, float y, float z, float* out,
                     float* scratch) const {
    // fractalSum's operations, in its order, for each point of the row.
    std::fill(out, out + count, 0.0f);
    float amplitude = 1.0f, norm = 0.0f;
    for (const Octave& octave : octaves_) {
        const int n = octave.period;
        if (octave.gradient.empty()) {
            for (int t = 0; t < count; ++t)
                scratch[t] = perlin3(glm::vec3(xs[t], y, z), n, octave.seed);
        } else {
            perlin3RowWith(
                xs, count, y, z, n,
                [&](int x, int yy, int zz) -> unsigned {
                    return octave.gradient[(static_cast<size_t>(zz) * n + yy) * n + x];
                },
                scratch);
        }
        for (int t = 0; t < count; ++t)
            out[t] += amplitude * scratch[t];
        norm += amplitude;
        amplitude *= 0.5f;
    }
    for (int t = 0; t < count; ++t)
        out[t] /= norm;
}

PerlinFbm2::PerlinFbm2(int period, int octaves, uint32_t seed, int64_t maxTable) {
    for (int o = 0; o < octaves; ++o) {
        Octave octave{period << o, 0u, {}};
        const int n = octave.period;
        const uint32_t s = octaveSeed(seed, o);
        octave.seed = s;
        if (static_cast<int64_t>(n) * n > std::min(maxTable, kMaxTable)) {
            octaves_.push_back(std::move(octave)); // too fine to tabulate: hashed on the fly
            continue;
        }
        octave.gradient.resize(static_cast<size_t>(n) * n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                octave.gradient[static_cast<size_t>(y) * n + x] =
                    gradient2(hashCombine(s, x, y, kPerlin2Salt));
        octaves_.push_back(std::move(octave));
    }
}

float PerlinFbm2::operator()(glm::vec2 p) const {
    return fractalSum(static_cast<int>(octaves_.size()), [&](int o) { return octave(o, p); });
}

float PerlinFbm2::octave(int o, glm::vec2 p) const {
    const Octave& octave = octaves_[o];
    const int n = octave.period;
    if (octave.gradient.empty())
        return perlin2(p, n, octave.seed);
    return perlin2With(
        p, n, [&](int x, int y) { return octave.gradient[static_cast<size_t>(y) * n + x]; });
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
    float value;
    invertedRow(&p.x, 1, p.y, p.z, &value);
    return value;
}

namespace {
// The row's texels from `first` on that lie in the same cell as xs[first] (cell index `cell`).
int cellRunEnd(const float* xs, int first, int count, float scale, int cell) {
    int end = first + 1;
    while (end < count && static_cast<int>(std::floor(xs[end] * scale)) == cell)
        ++end;
    return end;
}
} // namespace

void Worley3::invertedRow(const float* xs, int count, float y, float z, float* out) const {
    const int n = cells_;
    const float scale = static_cast<float>(n);
    const float qy = y * scale, qz = z * scale;
    const int cy = static_cast<int>(std::floor(qy)), cz = static_cast<int>(std::floor(qz));
    // Wrapped indices of the cell and its two neighbours along each axis (the grid is periodic;
    // the offsets below use the unwrapped coordinates, so distances are those on the torus).
    const int wy[3] = {wrap(cy - 1, n), wrap(cy, n), wrap(cy + 1, n)};
    const int wz[3] = {wrap(cz - 1, n), wrap(cz, n), wrap(cz + 1, n)};
    // One feature point per cell means a point two cells away is always farther than 1 (where
    // F1 is clamped), so the 3x3x3 neighbourhood suffices. (Skipping cells by a distance bound
    // was tried: its mispredicted branches made it slower.)
    constexpr int kCandidates = 27;
    constexpr int kMaxRun = 64;
    for (int first = 0; first < count;) {
        const int cx = static_cast<int>(std::floor(xs[first] * scale));
        const int end = std::min(cellRunEnd(xs, first, count, scale, cx), first + kMaxRun);
        const int wx[3] = {wrap(cx - 1, n), wrap(cx, n), wrap(cx + 1, n)};
        // Each candidate's x in the row's frame and its y and z terms, which the row shares:
        // a texel's squared distance is (dx * dx + dy * dy) + dz * dz with d = (cell + point)
        // - q, the order of glm::dot, which the textures were first made with.
        float ax[kCandidates], dy2[kCandidates], dz2[kCandidates];
        for (int k = 0, c = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) {
                const size_t rowIndex = (static_cast<size_t>(wz[k]) * n + wy[j]) * n;
                for (int i = 0; i < 3; ++i, ++c) {
                    const glm::vec3 point = points_[rowIndex + wx[i]];
                    ax[c] = static_cast<float>(cx + i - 1) + point.x;
                    const float dy = (static_cast<float>(cy + j - 1) + point.y) - qy;
                    const float dz = (static_cast<float>(cz + k - 1) + point.z) - qz;
                    dy2[c] = dy * dy;
                    dz2[c] = dz * dz;
                }
            }
        float qx[kMaxRun], best[kMaxRun];
        const int run = end - first;
        for (int t = 0; t < run; ++t) {
            qx[t] = xs[first + t] * scale;
            best[t] = 1.0f;
        }
        for (int c = 0; c < kCandidates; ++c)
            for (int t = 0; t < run; ++t) { // across texels, so the compiler can vectorise
                const float dx = ax[c] - qx[t];
                best[t] = std::min(best[t], (dx * dx + dy2[c]) + dz2[c]);
            }
        for (int t = 0; t < run; ++t)
            out[first + t] = 1.0f - std::min(std::sqrt(best[t]), 1.0f);
        first = end;
    }
}

WorleyFbm3::WorleyFbm3(int cells, uint32_t seed)
    : a_(cells, seed), b_(cells * 2, seed + 1u), c_(cells * 4, seed + 2u) {}

float WorleyFbm3::operator()(glm::vec3 p) const {
    return a_.inverted(p) * 0.625f + b_.inverted(p) * 0.25f + c_.inverted(p) * 0.125f;
}

void WorleyFbm3::row(const float* xs, int count, float y, float z, float* out,
                     float* scratch) const {
    float* b = scratch;
    float* c = scratch + count;
    a_.invertedRow(xs, count, y, z, out);
    b_.invertedRow(xs, count, y, z, b);
    c_.invertedRow(xs, count, y, z, c);
    for (int t = 0; t < count; ++t)
        out[t] = out[t] * 0.625f + b[t] * 0.25f + c[t] * 0.125f;
}

} // namespace cloudscape::noise
