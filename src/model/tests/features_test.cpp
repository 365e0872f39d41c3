// The feature set the Vulkan backend specialises its pipelines for (features.glsl.h): every
// parameter that switches a feature on must put its bit in modelFeaturesFor, or the specialised
// shader would drop that feature's code while the scene asks for it.
#include "model/features.glsl.h"
#include "model/params.glsl.h"

#include <gtest/gtest.h>

namespace cm = cloudscape::model;

TEST(ModelFeatures, EachSwitchSetsItsOwnBitAndNoOther) {
    // The composite is always wanted: only the block march's pipeline leaves it out.
    const cm::CloudParams none{};
    EXPECT_EQ(cm::modelFeaturesFor(none), cm::FEATURE_COMPOSITE);
    const auto only = [&](auto set) {
        cm::CloudParams p{};
        set(p);
        return cm::modelFeaturesFor(p) & ~cm::FEATURE_COMPOSITE;
    };
    EXPECT_EQ(only([](cm::CloudParams& p) { p.terrain.enabled = 1; }), cm::FEATURE_TERRAIN);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.sky.atmosphere.enabled = 1; }),
              cm::FEATURE_ATMOSPHERE);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.sky.moonEnabled = 1; }), cm::FEATURE_MOON);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.highClouds.coverage = 0.2f; }),
              cm::FEATURE_HIGH_CLOUDS);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.lightning.enabled = 1; }), cm::FEATURE_LIGHTNING);
    EXPECT_EQ(only([](cm::CloudParams& p) {
                  p.stormBlend = 0.5f;
                  p.stormRadius = 10000.0f;
              }),
              cm::FEATURE_STORM);
    // A storm's cirrus plume is the high layer's code: it needs that feature too.
    EXPECT_EQ(only([](cm::CloudParams& p) {
                  p.stormBlend = 0.5f;
                  p.stormRadius = 10000.0f;
                  p.highClouds.stormCirrus = 0.8f;
              }),
              cm::FEATURE_STORM | cm::FEATURE_HIGH_CLOUDS);
    // A storm of blend 0 is no storm (the scene without it, bit for bit).
    EXPECT_EQ(only([](cm::CloudParams& p) { p.stormRadius = 10000.0f; }), 0);
}

TEST(ModelFeatures, TheBitsAreDistinctAndAllCoversThem) {
    const int bits[] = {cm::FEATURE_TERRAIN,     cm::FEATURE_ATMOSPHERE, cm::FEATURE_MOON,
                        cm::FEATURE_HIGH_CLOUDS, cm::FEATURE_STORM,      cm::FEATURE_LIGHTNING,
                        cm::FEATURE_COMPOSITE,   cm::FEATURE_DATA_FIELD};
    int seen = 0;
    for (int b : bits) {
        EXPECT_EQ(b & (b - 1), 0) << b; // one bit each
        EXPECT_EQ(seen & b, 0) << b;
        seen |= b;
    }
    EXPECT_EQ(seen, cm::FEATURE_ALL);
}
