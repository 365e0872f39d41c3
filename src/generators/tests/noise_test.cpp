#include <cloudscape/error.h>
#include <cloudscape/noise.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using cloudscape::Texture2D;
using cloudscape::Texture3D;

namespace {

// Seam check along x (the generators are symmetric in their axes; y and z are checked by
// swapping roles): the difference across the wrap (x = n-1 -> 0) must look like any other
// neighbour difference, not like the difference between unrelated texels.
struct SeamStats {
    double seamMean = 0.0, interiorMean = 0.0, unrelatedMean = 0.0;
};

SeamStats seamStats3D(const Texture3D& t, int channel, int axis) {
    const int n = t.size;
    SeamStats s;
    size_t seamCount = 0, interiorCount = 0;
    auto value = [&](int a, int b, int c) {
        // a runs along `axis`
        int x = a, y = b, z = c;
        if (axis == 1) {
            x = b;
            y = a;
            z = c;
        }
        if (axis == 2) {
            x = b;
            y = c;
            z = a;
        }
        return t.texel(0, x, y, z)[channel];
    };
    for (int c = 0; c < n; ++c)
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a + 1 < n; ++a) {
                s.interiorMean += std::abs(value(a + 1, b, c) - value(a, b, c));
                ++interiorCount;
            }
            s.seamMean += std::abs(value(0, b, c) - value(n - 1, b, c));
            s.unrelatedMean += std::abs(value(n / 2, b, c) - value(0, b, c));
            ++seamCount;
        }
    s.seamMean /= seamCount;
    s.interiorMean /= interiorCount;
    s.unrelatedMean /= seamCount;
    return s;
}

void expectTiles3D(const Texture3D& t, int channels) {
    for (int c = 0; c < channels; ++c)
        for (int axis = 0; axis < 3; ++axis) {
            const SeamStats s = seamStats3D(t, c, axis);
            EXPECT_LT(s.seamMean, 1.5 * s.interiorMean + 1.0 / 255.0)
                << "channel " << c << " axis " << axis;
            EXPECT_GT(s.unrelatedMean, 2.0 * s.interiorMean) << "the check must be able to fail";
        }
}

void expectInUnitRange(const std::vector<float>& v) {
    for (float x : v) {
        ASSERT_TRUE(std::isfinite(x));
        ASSERT_GE(x, 0.0f);
        ASSERT_LE(x, 1.0f);
    }
}

double channelMean(const std::vector<float>& v, int c) {
    double sum = 0.0;
    for (size_t i = c; i < v.size(); i += 4)
        sum += v[i];
    return sum / (v.size() / 4);
}

} // namespace

TEST(BaseNoise, DefaultSizeTilesStaysInRangeAndHasMips) {
    const Texture3D t = cloudscape::generateBaseNoise(1, 128);
    ASSERT_EQ(t.size, 128);
    ASSERT_EQ(t.levelCount(), 8); // 128 .. 1
    EXPECT_EQ(t.mips.back().size(), 4u);
    for (const auto& level : t.mips)
        expectInUnitRange(level);
    expectTiles3D(t, 4);
    // Every channel uses the range: the sampler's remaps need contrast.
    for (int c = 0; c < 4; ++c) {
        float lo = 1, hi = 0;
        for (size_t i = c; i < t.mips[0].size(); i += 4) {
            lo = std::min(lo, t.mips[0][i]);
            hi = std::max(hi, t.mips[0][i]);
        }
        EXPECT_LT(lo, 0.05f) << c;
        EXPECT_GT(hi, 0.95f) << c;
        // Box-filtered mips keep the mean (up to 8-bit quantisation).
        EXPECT_NEAR(channelMean(t.mips[1], c), channelMean(t.mips[0], c), 2.0 / 255.0);
    }
    // Values are 8-bit levels.
    for (size_t i = 0; i < 1000; ++i)
        EXPECT_FLOAT_EQ(std::round(t.mips[0][i] * 255.0f) / 255.0f, t.mips[0][i]);
}

TEST(BaseNoise, DeterministicAndSeedDependent) {
    const Texture3D a = cloudscape::generateBaseNoise(5, 32);
    const Texture3D b = cloudscape::generateBaseNoise(5, 32);
    const Texture3D c = cloudscape::generateBaseNoise(6, 32);
    EXPECT_EQ(a.mips, b.mips);
    double diff = 0.0;
    for (size_t i = 0; i < a.mips[0].size(); ++i)
        diff += std::abs(a.mips[0][i] - c.mips[0][i]);
    EXPECT_GT(diff / a.mips[0].size(), 0.05);
}

TEST(DetailNoise, TilesAndIsDeterministic) {
    const Texture3D t = cloudscape::generateDetailNoise(1, 32);
    ASSERT_EQ(t.levelCount(), 6);
    for (const auto& level : t.mips)
        expectInUnitRange(level);
    // At 32^3 the finest octave has a cell per texel, so neighbours are as unrelated as any two
    // texels; the same generator at 128^3 resolves its cells and shows whether it tiles.
    expectTiles3D(cloudscape::generateDetailNoise(1, 128), 3);
    EXPECT_EQ(t.mips, cloudscape::generateDetailNoise(1, 32).mips);
    EXPECT_NE(t.mips, cloudscape::generateDetailNoise(2, 32).mips);
}

TEST(CurlNoise, TilesAndIsCentred) {
    const Texture2D t = cloudscape::generateCurlNoise(1, 128);
    ASSERT_EQ(t.levelCount(), 8);
    expectInUnitRange(t.mips[0]);
    const int n = t.width;
    for (int c = 0; c < 3; ++c) {
        double seam = 0, interior = 0;
        for (int y = 0; y < n; ++y) {
            seam += std::abs(t.texel(0, 0, y)[c] - t.texel(0, n - 1, y)[c]);
            seam += std::abs(t.texel(0, y, 0)[c] - t.texel(0, y, n - 1)[c]);
            for (int x = 0; x + 1 < n; ++x)
                interior += std::abs(t.texel(0, x + 1, y)[c] - t.texel(0, x, y)[c]);
        }
        EXPECT_LT(seam / (2 * n), 1.5 * interior / (n * (n - 1)) + 1.0 / 255.0) << c;
        // A curl field encoded around 0.5 has mean near 0.5.
        EXPECT_NEAR(channelMean(t.mips[0], c), 0.5, 0.05) << c;
    }
    EXPECT_EQ(t.mips, cloudscape::generateCurlNoise(1, 128).mips);
}

TEST(Noise, RejectsBadSizes) {
    EXPECT_THROW(cloudscape::generateBaseNoise(1, 100), cloudscape::Error);
    EXPECT_THROW(cloudscape::generateDetailNoise(1, 2), cloudscape::Error);
    EXPECT_THROW(cloudscape::generateCurlNoise(1, 4096), cloudscape::Error);
}
