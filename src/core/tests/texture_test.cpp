#include <cloudscape/texture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

double levelMean(const std::vector<float>& level, int channel) {
    double sum = 0.0;
    for (size_t i = channel; i < level.size(); i += 4)
        sum += level[i];
    return sum / static_cast<double>(level.size() / 4);
}

std::vector<float> randomValues(size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> v(count);
    for (float& x : v)
        x = u(rng);
    return v;
}

} // namespace

TEST(Texture, MipChainOf3DTextureAveragesAndEndsAtOneTexel) {
    cloudscape::Texture3D t;
    t.size = 4;
    t.mips.assign(1, std::vector<float>(4 * 4 * 4 * 4, 0.0f));
    // One bright 2x2x2 block in the corner.
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                t.texel(0, x, y, z)[0] = 1.0f;
    cloudscape::buildMipChain(t);
    ASSERT_EQ(t.levelCount(), 3);
    EXPECT_FLOAT_EQ(t.texel(1, 0, 0, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(t.texel(1, 1, 0, 0)[0], 0.0f);
    EXPECT_FLOAT_EQ(t.texel(2, 0, 0, 0)[0], 1.0f / 8.0f);
}

TEST(Texture, MipChainOf2DTextureHandlesNonSquare) {
    cloudscape::Texture2D t;
    t.width = 4;
    t.height = 2;
    t.mips.assign(1, std::vector<float>(4 * 2 * 4, 0.0f));
    t.texel(0, 3, 1)[1] = 4.0f;
    cloudscape::buildMipChain(t);
    ASSERT_EQ(t.levelCount(), 3); // 4x2, 2x1, 1x1
    EXPECT_FLOAT_EQ(t.texel(1, 1, 0)[1], 1.0f);
    EXPECT_FLOAT_EQ(t.texel(2, 0, 0)[1], 0.5f);
}

TEST(Texture, QuantisationRoundsToUnorm8Levels) {
    cloudscape::Texture2D t;
    t.width = t.height = 1;
    t.mips = {{0.5f, -1.0f, 2.0f, 0.1f}};
    cloudscape::quantizeToUnorm8(t);
    EXPECT_FLOAT_EQ(t.mips[0][0], 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(t.mips[0][1], 0.0f);
    EXPECT_FLOAT_EQ(t.mips[0][2], 1.0f);
    EXPECT_FLOAT_EQ(t.mips[0][3], 26.0f / 255.0f);
}

TEST(Texture, MipChainOf3DTextureHasEveryLevelAndKeepsTheMean) {
    cloudscape::Texture3D t;
    t.size = 8;
    t.mips.assign(1, randomValues(8 * 8 * 8 * 4, 1));
    cloudscape::buildMipChain(t);
    ASSERT_EQ(t.levelCount(), 4); // 8, 4, 2, 1
    for (int l = 0; l < t.levelCount(); ++l) {
        const size_t n = static_cast<size_t>(8 >> l);
        ASSERT_EQ(t.levelSize(l), static_cast<int>(n));
        ASSERT_EQ(t.mips[l].size(), n * n * n * 4);
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(levelMean(t.mips[l], c), levelMean(t.mips[0], c), 1e-5) << l << " " << c;
    }
    // A texel of level 1 is the average of its 2x2x2 parents.
    float sum = 0.0f;
    for (int z = 2; z < 4; ++z)
        for (int y = 4; y < 6; ++y)
            for (int x = 6; x < 8; ++x)
                sum += t.texel(0, x, y, z)[2];
    EXPECT_FLOAT_EQ(t.texel(1, 3, 2, 1)[2], sum / 8.0f);
}

TEST(Texture, MipChainOfOneTexelIsJustLevelZero) {
    cloudscape::Texture3D t;
    t.size = 1;
    t.mips.assign(1, {0.1f, 0.2f, 0.3f, 0.4f});
    cloudscape::buildMipChain(t);
    EXPECT_EQ(t.levelCount(), 1);
    cloudscape::Texture2D u;
    u.width = u.height = 1;
    u.mips.assign(1, {0.1f, 0.2f, 0.3f, 0.4f});
    cloudscape::buildMipChain(u);
    EXPECT_EQ(u.levelCount(), 1);
}

TEST(Texture, MipChainOf2DTextureKeepsTheMean) {
    cloudscape::Texture2D t;
    t.width = t.height = 16;
    t.mips.assign(1, randomValues(16 * 16 * 4, 2));
    cloudscape::buildMipChain(t);
    ASSERT_EQ(t.levelCount(), 5); // 16 .. 1
    EXPECT_EQ(t.mips.back().size(), 4u);
    for (int l = 0; l < t.levelCount(); ++l)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(levelMean(t.mips[l], c), levelMean(t.mips[0], c), 1e-5) << l << " " << c;
}

TEST(Texture, QuantisationCoversEveryLevelAndIsIdempotent) {
    cloudscape::Texture3D t;
    t.size = 4;
    t.mips.assign(1, randomValues(4 * 4 * 4 * 4, 3));
    cloudscape::buildMipChain(t);
    cloudscape::quantizeToUnorm8(t);
    const auto once = t.mips;
    for (const auto& level : t.mips)
        for (float x : level)
            ASSERT_EQ(std::round(x * 255.0f) / 255.0f, x);
    cloudscape::quantizeToUnorm8(t);
    EXPECT_EQ(t.mips, once);
}
