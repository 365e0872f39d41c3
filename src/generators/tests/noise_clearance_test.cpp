// The base noise's clearance field (model/noise_clearance.glsl.h): every cell's stored distance
// must be the exact Chebyshev distance, in cells and wrapping, to the nearest cell holding a
// texel that may exceed the level's threshold; and a read the field calls clear must give a
// base shape at most that threshold, at every mip level the march uses.
#include <cloudscape/noise.h>
#include <cloudscape/texture.h>

#include "cpu/cpu_textures.h"
#include "model/noise_clearance.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace cm = cloudscape::model;

namespace {

const cloudscape::Texture3D& base32() {
    static const cloudscape::Texture3D t = cloudscape::generateBaseNoise(1, 32);
    return t;
}

int storedDistance(const std::vector<uint32_t>& field, int cells, int x, int y, int z, int level) {
    const uint32_t word = field[(size_t(z * cells + y) * cells + x) * 2 + size_t(level >> 2)];
    return int((word >> (8 * (level & 3))) & 255u);
}

int wrapped(int d, int m) {
    d = std::abs(d) % m;
    return std::min(d, m - d);
}

} // namespace

TEST(NoiseClearance, EveryCellHoldsTheExactDistanceToTheNearestSeed) {
    const cloudscape::Texture3D& base = base32();
    const std::vector<uint32_t> field = cloudscape::generateNoiseClearance(base);
    const int m = base.size / cm::NOISE_CLEARANCE_CELL;
    ASSERT_EQ(field.size(), size_t(m) * m * m * 2) << "two words a cell";
    ASSERT_EQ(field.size(), size_t(cm::noiseClearanceWords(base.size)));
    int far = 0;
    for (int level = 0; level < cm::NOISE_CLEARANCE_LEVELS; ++level) {
        const float threshold = float(level) / float(cm::NOISE_CLEARANCE_LEVELS);
        std::vector<glm::ivec3> seeds;
        for (int z = 0; z < base.size; ++z)
            for (int y = 0; y < base.size; ++y)
                for (int x = 0; x < base.size; ++x) {
                    const float* t = base.texel(0, x, y, z);
                    if (cm::noiseTexelMayExceed(glm::vec4(t[0], t[1], t[2], t[3]), threshold))
                        seeds.push_back(glm::ivec3(x, y, z) / cm::NOISE_CLEARANCE_CELL);
                }
        std::sort(seeds.begin(), seeds.end(), [](glm::ivec3 a, glm::ivec3 b) {
            return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
        });
        seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
        ASSERT_FALSE(seeds.empty()) << "level " << level;
        for (int z = 0; z < m; ++z)
            for (int y = 0; y < m; ++y)
                for (int x = 0; x < m; ++x) {
                    int best = 255;
                    for (const glm::ivec3& s : seeds)
                        best = std::min(best, std::max({wrapped(x - s.x, m), wrapped(y - s.y, m),
                                                        wrapped(z - s.z, m)}));
                    const int stored = storedDistance(field, m, x, y, z, level);
                    ASSERT_EQ(stored, best)
                        << "cell " << x << "," << y << "," << z << " level " << level;
                    if (level > 0) {
                        ASSERT_GE(stored, storedDistance(field, m, x, y, z, level - 1))
                            << "a higher threshold has fewer seeds";
                    }
                    far += stored >= 2 ? 1 : 0;
                }
    }
    std::printf("cells at least 2 cells from a seed, over all levels: %d of %d\n", far,
                m * m * m * cm::NOISE_CLEARANCE_LEVELS);
    EXPECT_GT(far, m * m * m / 4) << "a field with nothing to skip proves nothing";
}

TEST(NoiseClearance, ReadsTheFieldCallsClearHaveNoBaseShapeAboveTheLevel) {
    // Random reads at every level of detail the march uses, and reads displaced from them by up
    // to the clearance the model allows (clear minus the read's reach): each filtered texel's
    // base shape must be at most the level's threshold.
    const cloudscape::Texture3D& base = base32();
    const std::vector<uint32_t> field = cloudscape::generateNoiseClearance(base);
    const int n = base.size, m = n / cm::NOISE_CLEARANCE_CELL;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int checked = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 u(unit(rng) * n, unit(rng) * n, unit(rng) * n);
        const int level = int(unit(rng) * cm::NOISE_CLEARANCE_LEVELS) % cm::NOISE_CLEARANCE_LEVELS;
        const float lod = std::vector<float>{0.0f, 0.0f, 0.4f, 1.0f, 1.7f}[i % 5];
        const glm::ivec3 c = glm::ivec3(glm::floor(u / float(cm::NOISE_CLEARANCE_CELL)));
        const int away = storedDistance(field, m, c.x, c.y, c.z, level);
        const float clear = cm::clearanceTexels(uint32_t(away)) - cm::NOISE_CLEARANCE_SLACK;
        const float room = clear - cm::readReach(lod);
        if (room <= 0.0f)
            continue;
        const glm::vec3 d(unit(rng) * 2.0f - 1.0f, unit(rng) * 2.0f - 1.0f,
                          unit(rng) * 2.0f - 1.0f);
        const glm::vec3 q = u + d * room;
        const glm::vec4 v = cloudscape::cpu::sampleTexture(base, q / float(n), lod);
        const float fbm = cm::baseNoiseFbm(v);
        const float shape = cm::saturate(cm::remap(v.x, 1.0f - fbm, 1.0f, 0.0f, 1.0f));
        ASSERT_LE(shape, float(level) / float(cm::NOISE_CLEARANCE_LEVELS))
            << "read at " << q.x << "," << q.y << "," << q.z << " lod " << lod;
        ++checked;
    }
    std::printf("%d clear reads checked\n", checked);
    EXPECT_GT(checked, 4000);
}

TEST(NoiseClearance, AReadMixesNoTexelBeyondItsReach) {
    // One bright texel in a dark 16^3 texture, with its box-filtered mip chain: a read sees it
    // only within readReach of its centre (Chebyshev, wrapping), at every level of detail, and
    // the reach is tight (reads nearly that far do see it), so a smaller one would be wrong.
    cloudscape::Texture3D t;
    t.size = 16;
    t.mips.assign(1, std::vector<float>(size_t(16) * 16 * 16 * 4, 0.0f));
    const glm::vec3 centre(5.5f, 9.5f, 12.5f);
    float* bright = t.texel(0, 5, 9, 12);
    std::fill(bright, bright + 4, 1.0f);
    cloudscape::buildMipChain(t);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float lod : {0.0f, 0.3f, 1.0f, 1.5f, 2.0f}) {
        const float reach = cm::readReach(lod);
        float farthest = 0.0f;
        for (int i = 0; i < 200000; ++i) {
            const glm::vec3 q(unit(rng) * 16.0f, unit(rng) * 16.0f, unit(rng) * 16.0f);
            const glm::vec3 d = glm::abs(q - centre);
            const glm::vec3 wrapped = glm::min(d, glm::vec3(16.0f) - d);
            const float distance = std::max({wrapped.x, wrapped.y, wrapped.z});
            if (cloudscape::cpu::sampleTexture(t, q / 16.0f, lod).x <= 0.0f)
                continue;
            ASSERT_LT(distance, reach)
                << "lod " << lod << " at " << q.x << "," << q.y << "," << q.z;
            farthest = std::max(farthest, distance);
        }
        std::printf("lod %.1f: reach %.2f, farthest read seeing the texel %.3f\n", lod, reach,
                    farthest);
        EXPECT_GT(farthest, reach - 0.25f) << "lod " << lod;
    }
}
