#include <cloudscape/texture.h>

#include <gtest/gtest.h>

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
