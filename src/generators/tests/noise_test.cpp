#include <cloudscape/error.h>
#include <cloudscape/noise.h>

#include "generators/tileable_noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using cloudscape::Texture2D;
using cloudscape::Texture3D;
namespace noise = cloudscape::noise;

namespace {

// ---- Statistics over textures ----------------------------------------------------------------

// How the wrap (texel n-1 next to texel 0) compares with ordinary neighbours along one axis.
struct SeamStats {
    double seamMean = 0.0, seamMax = 0.0;         // |t(0) - t(n-1)| over the whole face
    double interiorMean = 0.0, interiorP99 = 0.0; // |t(i+1) - t(i)| inside the texture
    double unrelatedMean = 0.0;                   // |t(n/2) - t(0)|: texels half a tile apart
};

double percentile(std::vector<double> v, double q) {
    const size_t k = static_cast<size_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

// value(a, b, c) reads the texel whose coordinate along the tested axis is a.
template <typename Value> SeamStats seamStats(int n, int layers, const Value& value) {
    SeamStats s;
    std::vector<double> interior;
    interior.reserve(static_cast<size_t>(n) * n * layers);
    size_t seamCount = 0;
    for (int c = 0; c < layers; ++c)
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a + 1 < n; ++a)
                interior.push_back(std::abs(value(a + 1, b, c) - value(a, b, c)));
            const double seam = std::abs(value(0, b, c) - value(n - 1, b, c));
            s.seamMean += seam;
            s.seamMax = std::max(s.seamMax, seam);
            s.unrelatedMean += std::abs(value(n / 2, b, c) - value(0, b, c));
            ++seamCount;
        }
    s.seamMean /= static_cast<double>(seamCount);
    s.unrelatedMean /= static_cast<double>(seamCount);
    for (double d : interior)
        s.interiorMean += d;
    s.interiorMean /= static_cast<double>(interior.size());
    s.interiorP99 = percentile(interior, 0.99);
    return s;
}

SeamStats seamStats3D(const Texture3D& t, int channel, int axis) {
    return seamStats(t.size, t.size, [&](int a, int b, int c) {
        const int x = axis == 0 ? a : b;
        const int y = axis == 0 ? b : axis == 1 ? a : c;
        const int z = axis == 2 ? a : c;
        return static_cast<double>(t.texel(0, x, y, z)[channel]);
    });
}

SeamStats seamStats2D(const Texture2D& t, int channel, int axis) {
    return seamStats(t.width, 1, [&](int a, int b, int) {
        return static_cast<double>(axis == 0 ? t.texel(0, a, b)[channel]
                                             : t.texel(0, b, a)[channel]);
    });
}

// The seam must look like any other neighbour difference: its largest value within 3x the 99th
// percentile of interior differences and its mean within 1.5x the interior mean (plus half an
// 8-bit step for quantisation). With `canFail`, also check that the test has teeth: texels half
// a tile apart differ clearly more than neighbours (false where the finest octave has a cell per
// texel, so neighbours are as unrelated as any two texels).
void expectSeamless(const SeamStats& s, const std::string& what, bool canFail = true) {
    const double step = 0.5 / 255.0;
    EXPECT_LT(s.seamMax, 3.0 * s.interiorP99 + step) << what;
    EXPECT_LT(s.seamMean, 1.5 * s.interiorMean + step) << what;
    if (canFail) {
        EXPECT_GT(s.unrelatedMean, 2.0 * s.interiorMean) << what << ": the check must be able "
                                                         << "to fail";
    }
}

void expectTiles3D(const Texture3D& t, int channels, bool canFail = true) {
    for (int c = 0; c < channels; ++c)
        for (int axis = 0; axis < 3; ++axis)
            expectSeamless(seamStats3D(t, c, axis),
                           "channel " + std::to_string(c) + " axis " + std::to_string(axis),
                           canFail);
}

// Every value of every level finite, in [0, 1] and an exact 8-bit level.
void expectUnorm8(const std::vector<std::vector<float>>& mips) {
    for (const auto& level : mips)
        for (float x : level) {
            ASSERT_TRUE(std::isfinite(x));
            ASSERT_GE(x, 0.0f);
            ASSERT_LE(x, 1.0f);
            ASSERT_EQ(std::round(x * 255.0f) / 255.0f, x);
        }
}

void expectCubeMips(const Texture3D& t, int size) {
    ASSERT_EQ(t.size, size);
    ASSERT_EQ(t.levelCount(), static_cast<int>(std::log2(size)) + 1);
    for (int l = 0; l < t.levelCount(); ++l) {
        const size_t n = static_cast<size_t>(size >> l);
        EXPECT_EQ(t.mips[l].size(), n * n * n * 4) << l;
    }
    EXPECT_EQ(t.mips.back().size(), 4u) << "the last level is one texel";
}

struct ChannelStats {
    double mean = 0.0, sd = 0.0, min = 1.0, max = 0.0;
};

ChannelStats channelStats(const std::vector<float>& v, int c) {
    ChannelStats s;
    const size_t count = v.size() / 4;
    for (size_t i = c; i < v.size(); i += 4) {
        s.mean += v[i];
        s.min = std::min<double>(s.min, v[i]);
        s.max = std::max<double>(s.max, v[i]);
    }
    s.mean /= static_cast<double>(count);
    for (size_t i = c; i < v.size(); i += 4)
        s.sd += (v[i] - s.mean) * (v[i] - s.mean);
    s.sd = std::sqrt(s.sd / static_cast<double>(count));
    return s;
}

double meanAbsDifference(const std::vector<float>& a, const std::vector<float>& b, int c) {
    double sum = 0.0;
    for (size_t i = c; i < a.size(); i += 4)
        sum += std::abs(a[i] - b[i]);
    return sum / static_cast<double>(a.size() / 4);
}

// Box-filtered mips keep each channel's mean, up to 8-bit rounding of both levels.
void expectMipMeansMatch(const std::vector<std::vector<float>>& mips, int channels) {
    for (int c = 0; c < channels; ++c)
        EXPECT_NEAR(channelStats(mips[1], c).mean, channelStats(mips[0], c).mean, 1.0 / 255.0) << c;
}

std::vector<glm::vec3> randomPoints(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> points(count);
    for (auto& p : points)
        // Braces: drawn left to right (a call's arguments have no order).
        p = glm::vec3{u(rng), u(rng), u(rng)};
    return points;
}

const glm::vec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

} // namespace

// ---- The tileable noise functions ------------------------------------------------------------

TEST(TileableNoise, PerlinRepeatsWithThePeriodOnEveryAxis) {
    for (const glm::vec3& p : randomPoints(500, 1))
        for (const glm::vec3& axis : kAxes) {
            EXPECT_NEAR(noise::perlin3(p, 5, 7), noise::perlin3(p + axis, 5, 7), 1e-4);
            EXPECT_NEAR(noise::perlin3(p, 4, 7), noise::perlin3(p - 2.0f * axis, 4, 7), 1e-4);
            EXPECT_NEAR(noise::perlinFbm3(p, 4, 5, 9), noise::perlinFbm3(p + axis, 4, 5, 9), 1e-4);
            const glm::vec2 q(p.x, p.y), a2(axis.x, axis.y);
            EXPECT_NEAR(noise::perlin2(q, 3, 7), noise::perlin2(q + a2, 3, 7), 1e-4);
            EXPECT_NEAR(noise::perlinFbm2(q, 3, 4, 7), noise::perlinFbm2(q + a2, 3, 4, 7), 1e-4);
        }
}

TEST(TileableNoise, PerlinIsZeroOnTheLatticeAndBounded) {
    float largest = 0.0f;
    for (const glm::vec3& p : randomPoints(20000, 2)) {
        largest = std::max(largest, std::abs(noise::perlin3(p, 4, 3)));
        largest = std::max(largest, std::abs(noise::perlin2(glm::vec2(p), 4, 3)));
    }
    EXPECT_LE(largest, 1.5f);
    EXPECT_GT(largest, 0.4f);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(noise::perlin3(glm::vec3(i, 2 * i + 1, 3) / 4.0f, 4, 3), 0.0f);
}

TEST(TileableNoise, TabulatedPerlinFbmEqualsTheHashedOneExactly) {
    const noise::PerlinFbm3 fbm(4, 5, 123);
    for (const glm::vec3& p : randomPoints(2000, 3))
        ASSERT_EQ(fbm(p), noise::perlinFbm3(p, 4, 5, 123));
}

TEST(TileableNoise, TabulatedPerlinFbm2EqualsTheHashedOneExactly) {
    const noise::PerlinFbm2 fbm(10, 5, 77);
    for (const glm::vec3& p : randomPoints(2000, 8))
        ASSERT_EQ(fbm(glm::vec2(p)), noise::perlinFbm2(glm::vec2(p), 10, 5, 77));
}

TEST(TileableNoise, LatticesTooLargeToTabulateAreHashedWithTheSameValues) {
    // 1500^2 and 128^3 lattice points are tabulated; 3000^2 and 256^3 are not.
    const noise::PerlinFbm2 fbm2(1500, 2, 5);
    const noise::PerlinFbm3 fbm3(128, 2, 6);
    for (const glm::vec3& p : randomPoints(500, 9)) {
        ASSERT_EQ(fbm2(glm::vec2(p)), noise::perlinFbm2(glm::vec2(p), 1500, 2, 5));
        ASSERT_EQ(fbm3(p), noise::perlinFbm3(p, 128, 2, 6));
    }
}

TEST(TileableNoise, PerlinDependsOnTheSeed) {
    double diff = 0.0;
    const auto points = randomPoints(1000, 4);
    for (const glm::vec3& p : points)
        diff += std::abs(noise::perlinFbm3(p, 4, 3, 1) - noise::perlinFbm3(p, 4, 3, 2));
    EXPECT_GT(diff / points.size(), 0.05);
}

TEST(TileableNoise, WorleyRepeatsAndIsContinuous) {
    const noise::Worley3 worley(5, 11);
    const noise::WorleyFbm3 fbm(3, 12);
    for (const glm::vec3& p : randomPoints(500, 5))
        for (const glm::vec3& axis : kAxes) {
            EXPECT_NEAR(worley.inverted(p), worley.inverted(p + axis), 1e-4);
            EXPECT_NEAR(worley.inverted(p), worley.inverted(p - axis), 1e-4);
            EXPECT_NEAR(fbm(p), fbm(p + axis), 1e-4);
        }
    // 1 - min(F1, 1) is 1-Lipschitz in cell units; a feature point missed by the neighbourhood
    // search, or a wrong distance across the wrap, would show up as a jump.
    const float h = 1e-3f;
    for (const glm::vec3& p : randomPoints(5000, 6))
        for (const glm::vec3& axis : kAxes) {
            const glm::vec3 q = glm::fract(p + h * axis); // crosses the wrap near 1
            EXPECT_LE(std::abs(worley.inverted(q) - worley.inverted(p)), 5.0f * h * 1.001f + 1e-5f);
        }
}

TEST(TileableNoise, WorleyIsOneAtFeaturePointsAndCoversTheRange) {
    const noise::Worley3 worley(4, 21);
    float lo = 1.0f, hi = 0.0f;
    for (const glm::vec3& p : randomPoints(20000, 7)) {
        const float v = worley.inverted(p);
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    EXPECT_GT(hi, 0.9f);
    EXPECT_LT(lo, 0.4f);
}

// The generators fill their textures a row at a time; each row function must give the point
// evaluation's value bit for bit (the textures, and every image since, depend on it). The rows
// here are texel rows of several sizes, including rows whose cells hold one texel or several
// dozen, and rows of arbitrary points (out of order, outside [0, 1), repeated).
TEST(TileableNoise, RowsEqualThePointEvaluationsBitForBit) {
    std::vector<std::vector<float>> rows;
    for (int size : {8, 32, 128, 200, 1024}) {
        std::vector<float> xs(size);
        for (int x = 0; x < size; ++x)
            xs[x] = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
        rows.push_back(xs);
    }
    std::vector<float> arbitrary;
    for (const glm::vec3& p : randomPoints(300, 8))
        arbitrary.push_back(p.x * 3.0f - 1.0f);
    arbitrary.push_back(arbitrary.back());
    rows.push_back(arbitrary);
    const noise::Worley3 worley(3, 31); // 341 texels a cell at size 1024: past a run's cap
    const noise::WorleyFbm3 worleyFbm(5, 32);
    const noise::PerlinFbm3 perlinFbm(4, 5, 33);
    int compared = 0;
    for (const std::vector<float>& xs : rows)
        for (const glm::vec3& p : randomPoints(6, 9)) {
            const int n = static_cast<int>(xs.size());
            std::vector<float> a(n), b(n), c(n), scratch(2 * n);
            worley.invertedRow(xs.data(), n, p.y, p.z, a.data());
            worleyFbm.row(xs.data(), n, p.y, p.z, b.data(), scratch.data());
            perlinFbm.row(xs.data(), n, p.y, p.z, c.data(), scratch.data());
            for (int t = 0; t < n; ++t) {
                const glm::vec3 q(xs[t], p.y, p.z);
                ASSERT_EQ(a[t], worley.inverted(q)) << "Worley3 at " << t << " of " << n;
                ASSERT_EQ(b[t], worleyFbm(q)) << "WorleyFbm3 at " << t << " of " << n;
                ASSERT_EQ(c[t], perlinFbm(q)) << "PerlinFbm3 at " << t << " of " << n;
                ++compared;
            }
        }
    EXPECT_EQ(compared, 6 * (8 + 32 + 128 + 200 + 1024 + 301));
}

// The terrain takes the octaves of a tabulated 2D FBM one at a time; each must be the hashed
// octave's value bit for bit.
TEST(TileableNoise, TabulatedOctavesEqualTheHashedOnes) {
    const noise::PerlinFbm2 fbm(5, 7, 41);
    for (const glm::vec3& p : randomPoints(400, 10))
        for (int o = 0; o < 7; ++o) {
            const glm::vec2 uv(p.x, p.y);
            ASSERT_EQ(fbm.octave(o, uv), noise::perlin2(uv, 5 << o, 41u + 101u * o)) << o;
        }
}

// ---- Base noise ------------------------------------------------------------------------------

TEST(BaseNoise, DefaultSizeTilesStaysInRangeAndHasMips) {
    // Through the bundle, which must equal the single generators (checked for the cheap two;
    // generating the 128^3 base twice would double the test's time).
    const cloudscape::NoiseTextures bundle = cloudscape::generateNoiseTextures(1);
    EXPECT_EQ(bundle.detail.mips, cloudscape::generateDetailNoise(1, 32).mips);
    EXPECT_EQ(bundle.curl.mips, cloudscape::generateCurlNoise(1, 128).mips);
    const Texture3D& t = bundle.base;
    expectCubeMips(t, 128);
    expectUnorm8(t.mips);
    expectTiles3D(t, 4);
    expectMipMeansMatch(t.mips, 4);
    // Every channel uses the range: the sampler's remaps need contrast.
    for (int c = 0; c < 4; ++c) {
        const ChannelStats s = channelStats(t.mips[0], c);
        EXPECT_LT(s.min, 0.05) << c;
        EXPECT_GT(s.max, 0.95) << c;
        EXPECT_GT(s.sd, 0.15) << c;
        EXPECT_GT(s.mean, 0.35) << c;
        EXPECT_LT(s.mean, 0.65) << c;
    }
    // The Perlin-Worley channel in particular is centred.
    const ChannelStats pw = channelStats(t.mips[0], 0);
    EXPECT_GT(pw.mean, 0.4);
    EXPECT_LT(pw.mean, 0.6);
}

TEST(BaseNoise, DeterministicAndSeedDependent) {
    const Texture3D a = cloudscape::generateBaseNoise(5, 32);
    const Texture3D b = cloudscape::generateBaseNoise(5, 32);
    const Texture3D c = cloudscape::generateBaseNoise(6, 32);
    expectCubeMips(a, 32);
    EXPECT_EQ(a.mips, b.mips);
    for (int ch = 0; ch < 4; ++ch)
        EXPECT_GT(meanAbsDifference(a.mips[0], c.mips[0], ch), 0.08) << ch;
}

TEST(BaseNoise, ChannelsAreDistinctFields) {
    // G, B and A are Worley FBMs of different frequencies and seeds; R adds the Perlin FBM.
    const Texture3D t = cloudscape::generateBaseNoise(2, 32);
    for (int c = 0; c < 4; ++c)
        for (int d = c + 1; d < 4; ++d) {
            double sum = 0.0;
            for (size_t i = 0; i < t.mips[0].size(); i += 4)
                sum += std::abs(t.mips[0][i + c] - t.mips[0][i + d]);
            EXPECT_GT(sum / (t.mips[0].size() / 4), 0.08) << c << " vs " << d;
        }
}

TEST(BaseNoise, LowerFrequencyChannelsAreSmoother) {
    // Mean neighbour difference rises with the channel's frequency (G 4, B 8, A 16 cells).
    const Texture3D t = cloudscape::generateBaseNoise(3, 64);
    double previous = 0.0;
    for (int c = 1; c < 4; ++c) {
        const double roughness = seamStats3D(t, c, 0).interiorMean;
        EXPECT_GT(roughness, 1.3 * previous) << c;
        previous = roughness;
    }
}

// ---- Detail noise ----------------------------------------------------------------------------

TEST(DetailNoise, DefaultSizeStaysInRangeTilesAndHasMips) {
    const Texture3D t = cloudscape::generateDetailNoise(1, 32);
    expectCubeMips(t, 32);
    expectUnorm8(t.mips);
    expectMipMeansMatch(t.mips, 4);
    for (int c = 0; c < 3; ++c) {
        const ChannelStats s = channelStats(t.mips[0], c);
        EXPECT_LT(s.min, 0.05) << c;
        EXPECT_GT(s.max, 0.95) << c;
        EXPECT_GT(s.sd, 0.15) << c;
    }
    for (size_t i = 3; i < t.mips[0].size(); i += 4)
        ASSERT_EQ(t.mips[0][i], 1.0f);
    // At 32^3 the finest octave of B has a cell per texel, so neighbours are as unrelated as any
    // two texels: the seam is checked but the check cannot show teeth at this size.
    expectTiles3D(t, 3, false);
    // At 64^3 every octave spans at least two texels per cell, so the check can fail there.
    expectTiles3D(cloudscape::generateDetailNoise(1, 64), 3);
}

TEST(DetailNoise, DeterministicAndSeedDependent) {
    const Texture3D t = cloudscape::generateDetailNoise(1, 32);
    EXPECT_EQ(t.mips, cloudscape::generateDetailNoise(1, 32).mips);
    const Texture3D other = cloudscape::generateDetailNoise(2, 32);
    for (int c = 0; c < 3; ++c)
        EXPECT_GT(meanAbsDifference(t.mips[0], other.mips[0], c), 0.08) << c;
}

// ---- Curl noise ------------------------------------------------------------------------------

TEST(CurlNoise, TilesIsCentredAndBounded) {
    const Texture2D t = cloudscape::generateCurlNoise(1, 128);
    ASSERT_EQ(t.width, 128);
    ASSERT_EQ(t.height, 128);
    ASSERT_EQ(t.levelCount(), 8);
    EXPECT_EQ(t.mips.back().size(), 4u);
    expectUnorm8(t.mips);
    expectMipMeansMatch(t.mips, 4);
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 2; ++axis)
            expectSeamless(seamStats2D(t, c, axis),
                           "channel " + std::to_string(c) + " axis " + std::to_string(axis));
        const ChannelStats s = channelStats(t.mips[0], c);
        // A curl field encoded around 0.5 has mean near 0.5 and spreads both ways.
        EXPECT_NEAR(s.mean, 0.5, 0.05) << c;
        EXPECT_GT(s.sd, 0.05) << c;
        largest = std::max({largest, std::abs(s.min - 0.5), std::abs(s.max - 0.5)});
    }
    // Scaled so the largest component reaches |v| = 1.
    EXPECT_NEAR(largest, 0.5, 1.0 / 255.0);
    for (size_t i = 3; i < t.mips[0].size(); i += 4)
        ASSERT_EQ(t.mips[0][i], 1.0f);
}

TEST(CurlNoise, InPlaneFieldIsDivergenceFree) {
    // (R, G) = (d psi / dy, -d psi / dx) by central differences, whose central-difference
    // divergence vanishes exactly; only the 8-bit rounding remains.
    const Texture2D t = cloudscape::generateCurlNoise(4, 64);
    const int n = t.width;
    auto v = [&](int x, int y, int c) {
        return 2.0 * t.texel(0, (x + n) % n, (y + n) % n)[c] - 1.0;
    };
    double divergence = 0.0, twisted = 0.0, gradient = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dxR = 0.5 * (v(x + 1, y, 0) - v(x - 1, y, 0));
            const double dyG = 0.5 * (v(x, y + 1, 1) - v(x, y - 1, 1));
            divergence += (dxR + dyG) * (dxR + dyG);
            twisted += (dxR - dyG) * (dxR - dyG); // 2 d2psi/dxdy: not zero
            gradient += dxR * dxR + dyG * dyG;
        }
    EXPECT_LT(std::sqrt(divergence / gradient), 0.2);
    EXPECT_GT(std::sqrt(twisted / gradient), 0.5) << "the check must be able to fail";
}

TEST(CurlNoise, DeterministicAndSeedDependent) {
    const Texture2D t = cloudscape::generateCurlNoise(1, 64);
    EXPECT_EQ(t.mips, cloudscape::generateCurlNoise(1, 64).mips);
    const Texture2D other = cloudscape::generateCurlNoise(2, 64);
    for (int c = 0; c < 3; ++c)
        EXPECT_GT(meanAbsDifference(t.mips[0], other.mips[0], c), 0.04) << c;
}

TEST(Noise, RejectsBadSizes) {
    EXPECT_THROW(cloudscape::generateBaseNoise(1, 100), cloudscape::Error);
    EXPECT_THROW(cloudscape::generateBaseNoise(1, 0), cloudscape::Error);
    EXPECT_THROW(cloudscape::generateDetailNoise(1, 2), cloudscape::Error);
    EXPECT_THROW(cloudscape::generateCurlNoise(1, 4096), cloudscape::Error);
    try {
        cloudscape::generateBaseNoise(1, 96);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("96"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("power of two"), std::string::npos);
    }
}
