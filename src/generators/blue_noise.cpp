// Void-and-cluster blue noise (Ulichney 1993). A Gaussian "energy" filter (sigma 1.5 texels,
// wrapped, as in the paper) measures how crowded each texel's neighbourhood is with set texels:
// the tightest cluster is the set texel of highest energy, the largest void the empty texel of
// lowest. Starting from a random pattern relaxed until the two coincide, texels are ranked by
// removing clusters (ranks below the initial count) and then filling voids (ranks above), so every
// threshold of the rank map is itself a well-spread pattern.
#include <cloudscape/blue_noise.h>
#include <cloudscape/error.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace cloudscape {
namespace {

constexpr float kSigma = 1.5f;

class EnergyField {
public:
    explicit EnergyField(int n) : n_(n), energy_(static_cast<size_t>(n) * n, 0.0f) {
        // Filter values by wrapped offset, computed once: each update is then a table walk.
        kernel_.resize(static_cast<size_t>(n) * n);
        for (int dy = 0; dy < n; ++dy)
            for (int dx = 0; dx < n; ++dx) {
                const float wx = static_cast<float>(std::min(dx, n - dx));
                const float wy = static_cast<float>(std::min(dy, n - dy));
                kernel_[static_cast<size_t>(dy) * n + dx] =
                    std::exp(-(wx * wx + wy * wy) / (2.0f * kSigma * kSigma));
            }
    }
    // Add (sign +1) or remove (-1) a set texel's contribution everywhere.
    void splat(int index, float sign) {
        const int px = index % n_, py = index / n_;
        for (int y = 0; y < n_; ++y) {
            const int dy = (y - py + n_) % n_;
            const float* k = &kernel_[static_cast<size_t>(dy) * n_];
            float* e = &energy_[static_cast<size_t>(y) * n_];
            for (int x = 0; x < n_; ++x)
                e[x] += sign * k[(x - px + n_) % n_];
        }
    }
    // The set texel with the highest energy (want = 1) or the empty one with the lowest (0).
    int extreme(const std::vector<uint8_t>& pattern, uint8_t want) const {
        int best = -1;
        float bestEnergy = 0.0f;
        for (size_t i = 0; i < energy_.size(); ++i) {
            if (pattern[i] != want)
                continue;
            const bool better = want ? energy_[i] > bestEnergy : energy_[i] < bestEnergy;
            if (best < 0 || better) {
                best = static_cast<int>(i);
                bestEnergy = energy_[i];
            }
        }
        return best;
    }

private:
    int n_;
    std::vector<float> energy_;
    std::vector<float> kernel_;
};

} // namespace

Texture2D generateBlueNoise(int size, uint32_t seed) {
    if (size < 8 || size > 256 || (size & (size - 1)) != 0)
        throw Error("blue noise size " + std::to_string(size) +
                    " must be a power of two in [8, 256]");
    const int count = size * size;
    std::vector<uint8_t> pattern(static_cast<size_t>(count), 0);
    std::mt19937 rng(seed);
    // 1. Initial binary pattern: a tenth of the texels at random, then relaxed by moving the
    // tightest cluster into the largest void until that move would undo itself.
    const int ones = count / 10;
    for (int placed = 0; placed < ones;) {
        const int i = static_cast<int>(rng() % static_cast<uint32_t>(count));
        if (!pattern[i]) {
            pattern[i] = 1;
            ++placed;
        }
    }
    EnergyField field(size);
    for (int i = 0; i < count; ++i)
        if (pattern[i])
            field.splat(i, 1.0f);
    for (int iteration = 0; iteration < 4 * count; ++iteration) {
        const int cluster = field.extreme(pattern, 1);
        pattern[cluster] = 0;
        field.splat(cluster, -1.0f);
        const int voidIndex = field.extreme(pattern, 0);
        pattern[voidIndex] = 1;
        field.splat(voidIndex, 1.0f);
        if (voidIndex == cluster)
            break;
    }
    std::vector<int> rank(static_cast<size_t>(count), 0);
    // 2. Ranks below the initial count: remove tightest clusters from a copy, highest rank first.
    {
        std::vector<uint8_t> p = pattern;
        EnergyField f = field;
        for (int r = ones - 1; r >= 0; --r) {
            const int cluster = f.extreme(p, 1);
            p[cluster] = 0;
            f.splat(cluster, -1.0f);
            rank[cluster] = r;
        }
    }
    // 3. Ranks from the initial count up: fill the largest void. (Ulichney's third phase, the
    // tightest cluster of empty texels once they are the minority, picks the same texel: the
    // empty texels' energy is the constant total minus the set texels'.)
    for (int r = ones; r < count; ++r) {
        const int voidIndex = field.extreme(pattern, 0);
        pattern[voidIndex] = 1;
        field.splat(voidIndex, 1.0f);
        rank[voidIndex] = r;
    }

    Texture2D t;
    t.width = size;
    t.height = size;
    t.mips.assign(1, std::vector<float>(static_cast<size_t>(count) * 4));
    for (int i = 0; i < count; ++i) {
        // 256 equally populated UNORM8 levels, so an RGBA8 upload holds the same values.
        const int level = static_cast<int>((static_cast<int64_t>(rank[i]) * 256) / count);
        const float v = static_cast<float>(level) / 255.0f;
        float* texel = &t.mips[0][static_cast<size_t>(i) * 4];
        texel[0] = texel[1] = texel[2] = v;
        texel[3] = 1.0f;
    }
    return t;
}

const Texture2D& blueNoiseTexture() {
    static const Texture2D texture = generateBlueNoise(64, 1);
    return texture;
}

} // namespace cloudscape
