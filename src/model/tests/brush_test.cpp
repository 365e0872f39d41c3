// The viewer's weather brush (model/brush.glsl.h), against values worked out by hand from its
// stated rule: weight (1 - t^2)^2 with t = distance / radius, and a stroke that moves a texel
// toward 1 (or 0) by |strength| times that weight.
#include "model/brush.glsl.h"

#include <gtest/gtest.h>

namespace cm = cloudscape::model;

TEST(Brush, WeightIsOneAtTheCentreAndZeroFromTheRadiusOut) {
    EXPECT_FLOAT_EQ(cm::brushWeight(0.0f, 500.0f), 1.0f);
    EXPECT_EQ(cm::brushWeight(500.0f, 500.0f), 0.0f);
    EXPECT_EQ(cm::brushWeight(501.0f, 500.0f), 0.0f);
    EXPECT_EQ(cm::brushWeight(10.0f, 0.0f), 0.0f); // a zero radius paints nothing
}

TEST(Brush, WeightFollowsTheSmoothFalloffInBetween) {
    // t = 0.5: (1 - 0.25)^2 = 0.5625; t = 0.25: (1 - 0.0625)^2 = 0.87890625;
    // t = 0.9: (1 - 0.81)^2 = 0.0361.
    EXPECT_NEAR(cm::brushWeight(250.0f, 500.0f), 0.5625f, 1e-6f);
    EXPECT_NEAR(cm::brushWeight(125.0f, 500.0f), 0.87890625f, 1e-6f);
    EXPECT_NEAR(cm::brushWeight(450.0f, 500.0f), 0.0361f, 1e-6f);
}

TEST(Brush, StrokeMovesTowardFullOrNoneByStrengthTimesWeight) {
    EXPECT_NEAR(cm::paintedValue(0.2f, 0.5f, 1.0f), 0.6f, 1e-6f);   // 0.2 + 0.5 * (1 - 0.2)
    EXPECT_NEAR(cm::paintedValue(0.2f, 0.5f, 0.5f), 0.4f, 1e-6f);   // a quarter of the way
    EXPECT_NEAR(cm::paintedValue(0.8f, -0.25f, 1.0f), 0.6f, 1e-6f); // 0.8 - 0.25 * 0.8
    EXPECT_NEAR(cm::paintedValue(0.3f, 1.0f, 1.0f), 1.0f, 1e-6f);   // full strength: all the way
    EXPECT_NEAR(cm::paintedValue(0.3f, -1.0f, 1.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(cm::paintedValue(0.3f, 0.7f, 0.0f), 0.3f, 1e-6f); // outside: untouched
}
