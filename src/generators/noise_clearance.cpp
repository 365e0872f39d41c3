#include <cloudscape/noise.h>

#include "model/noise_clearance.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cloudscape {
namespace {

constexpr uint8_t kFar = 255; // no seed within reach, or none at all

// One Chebyshev distance pass along an axis of an m^3 grid of distances, wrapping: each cell's
// distance becomes the least over the line's cells of max(their distance along the axis, their
// distance so far). Passes along x, y and z in turn give the Chebyshev distance to the nearest
// seed (the distance is separable: the largest of three axis distances).
void chebyshevPass(std::vector<uint8_t>& d, int m, int axis) {
    const size_t stride = axis == 0 ? 1 : axis == 1 ? static_cast<size_t>(m) : size_t(m) * m;
    tbb::parallel_for(0, m * m, [&](int line) {
        const int a = line % m, b = line / m;
        size_t start = 0;
        if (axis == 0)
            start = (size_t(b) * m + a) * m;
        else if (axis == 1)
            start = size_t(b) * m * m + a;
        else
            start = size_t(b) * m + a;
        std::vector<uint8_t> in(m), out(m);
        for (int i = 0; i < m; ++i)
            in[i] = d[start + i * stride];
        for (int i = 0; i < m; ++i) {
            int best = in[i];
            for (int r = 1; r < best && r <= m / 2; ++r) {
                const int lo = in[(i - r + m) % m], hi = in[(i + r) % m];
                best = std::min(best, std::max(r, std::min<int>(lo, hi)));
            }
            out[i] = static_cast<uint8_t>(best);
        }
        for (int i = 0; i < m; ++i)
            d[start + i * stride] = out[i];
    });
}

// The cells of side `cell` texels that hold a level-0 texel which may exceed `threshold` (0),
// every other cell kFar.
std::vector<uint8_t> seedCells(const Texture3D& base, int cell, float threshold) {
    const int n = base.size, m = n / cell;
    std::vector<uint8_t> seeds(size_t(m) * m * m, kFar);
    tbb::parallel_for(0, n, [&](int z) {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const float* t = base.texel(0, x, y, z);
                if (model::noiseTexelMayExceed(glm::vec4(t[0], t[1], t[2], t[3]), threshold))
                    seeds[(size_t(z / cell) * m + y / cell) * m + x / cell] = 0;
            }
    });
    return seeds;
}

} // namespace

std::vector<uint32_t> generateNoiseClearance(const Texture3D& base) {
    const int cell = model::NOISE_CLEARANCE_CELL;
    if (base.mips.empty() || base.size < cell || base.size % cell != 0)
        return {};
    const int m = base.size / cell;
    std::vector<uint32_t> field(size_t(model::noiseClearanceWords(base.size)), 0u);
    for (int level = 0; level < model::NOISE_CLEARANCE_LEVELS; ++level) {
        const float threshold = float(level) / float(model::NOISE_CLEARANCE_LEVELS);
        std::vector<uint8_t> d = seedCells(base, cell, threshold);
        for (int axis = 0; axis < 3; ++axis)
            chebyshevPass(d, m, axis);
        const uint32_t shift = 8u * uint32_t(level & 3);
        for (size_t i = 0; i < d.size(); ++i)
            field[i * 2 + (level >> 2)] |= uint32_t(d[i]) << shift;
    }
    return field;
}

} // namespace cloudscape
