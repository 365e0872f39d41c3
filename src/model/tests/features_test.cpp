// The feature set the Vulkan backend specialises its pipelines for (features.glsl.h): every
// parameter that switches a feature on must put its bit in modelFeaturesFor, or the specialised
// shader would drop that feature's code while the scene asks for it.
#include "model/features.glsl.h"
#include "model/params.glsl.h"

#include <gtest/gtest.h>

namespace cm = cloudscape::model;

TEST(ModelFeatures, EachSwitchSetsItsOwnBitAndNoOther) {
    // The composite is always wanted: only the block march's pipeline leaves it out. So is the
    // ground's fallback shadow: only the background pass that lists its pixels leaves it out.
    const cm::CloudParams none{};
    const glm::vec3 ground(0.0f, 2.0f, 0.0f);
    const int always = cm::FEATURE_COMPOSITE | cm::FEATURE_GROUND_FALLBACK;
    EXPECT_EQ(cm::modelFeaturesFor(none, ground), always);
    const auto only = [&](auto set) {
        cm::CloudParams p{};
        p.planetRadius = 6360e3f; // the camera on the ground, under the high layer
        p.highClouds.altitude = 10000.0f;
        set(p);
        return cm::modelFeaturesFor(p, ground) & ~always;
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
    EXPECT_EQ(only([](cm::CloudParams& p) { p.cloudShadow.resolution = 256; }),
              cm::FEATURE_CLOUD_SHADOW);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.shafts.steps = 32; }), cm::FEATURE_SHAFTS);
    EXPECT_EQ(only([](cm::CloudParams& p) { p.noiseClearanceSize = 128; }),
              cm::FEATURE_NOISE_SKIPPING);
    // The high layer in front of the clouds: only with the layer on and the camera above it.
    const auto seenFrom = [](float altitude, float coverage) {
        cm::CloudParams p{};
        p.planetRadius = 6360e3f;
        p.highClouds.altitude = 10000.0f;
        p.highClouds.coverage = coverage;
        return cm::modelFeaturesFor(p, glm::vec3(3000.0f, altitude, -2000.0f)) &
               cm::FEATURE_ABOVE_HIGH_CLOUDS;
    };
    EXPECT_EQ(seenFrom(9990.0f, 0.3f), 0);
    EXPECT_EQ(seenFrom(10010.0f, 0.3f), cm::FEATURE_ABOVE_HIGH_CLOUDS);
    EXPECT_EQ(seenFrom(10010.0f, 0.0f), 0);
    // A storm of blend 0 is no storm (the scene without it, bit for bit).
    EXPECT_EQ(only([](cm::CloudParams& p) { p.stormRadius = 10000.0f; }), 0);
}

TEST(ModelFeatures, TheBitsAreDistinctAndAllCoversThem) {
    const int bits[] = {cm::FEATURE_TERRAIN,
                        cm::FEATURE_ATMOSPHERE,
                        cm::FEATURE_MOON,
                        cm::FEATURE_HIGH_CLOUDS,
                        cm::FEATURE_STORM,
                        cm::FEATURE_LIGHTNING,
                        cm::FEATURE_COMPOSITE,
                        cm::FEATURE_DATA_FIELD,
                        cm::FEATURE_CLOUD_SHADOW,
                        cm::FEATURE_SHAFTS,
                        cm::FEATURE_ABOVE_HIGH_CLOUDS,
                        cm::FEATURE_GROUND_FALLBACK,
                        cm::FEATURE_GATHER,
                        cm::FEATURE_NOISE_SKIPPING};
    int seen = 0;
    for (int b : bits) {
        EXPECT_EQ(b & (b - 1), 0) << b; // one bit each
        EXPECT_EQ(seen & b, 0) << b;
        seen |= b;
    }
    EXPECT_EQ(seen, cm::FEATURE_ALL);
    // The pass modes share the specialisation constant but are no features.
    const int modes[] = {cm::PASS_FILL_BACKGROUND, cm::PASS_SHADE_BACKGROUND, cm::PASS_SHAFT_GRID,
                         cm::PASS_GROUND_FALLBACK, cm::PASS_UPSAMPLED_BACKGROUND};
    for (int m : modes) {
        EXPECT_EQ(m & (m - 1), 0) << m;
        EXPECT_EQ(seen & m, 0) << m;
        seen |= m;
    }
}
