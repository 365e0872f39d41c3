#include "model/cloud_bound.glsl.h"
#include "model/profiles.glsl.h"
#include "model/shell.glsl.h"
#include "model/weather.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cm = cloudscape::model;
using glm::vec3;

TEST(Profiles, ZeroOutsideTheirHeights) {
    const float types[] = {cm::TYPE_STRATUS, cm::TYPE_STRATOCUMULUS, cm::TYPE_CUMULUS,
                           cm::TYPE_CUMULONIMBUS};
    for (float type : types) {
        const glm::vec4 p = cm::profileForType(type);
        for (int i = 0; i <= 1000; ++i) {
            const float h = -0.2f + 1.4f * i / 1000.0f;
            const float v = cm::verticalProfile(h, type);
            EXPECT_GE(v, 0.0f);
            EXPECT_LE(v, 1.0f);
            if (h <= p.x || h >= p.w) {
                EXPECT_EQ(v, 0.0f) << "type " << type << " h " << h;
            }
        }
        // And full somewhere inside.
        EXPECT_NEAR(cm::verticalProfile(0.5f * (p.y + p.z), type), 1.0f, 1e-6);
    }
}

TEST(Profiles, TallerWithType) {
    float previousTop = 0.0f;
    for (float type : {0.0f, 1.0f / 3.0f, 2.0f / 3.0f, 1.0f}) {
        const float top = cm::profileForType(type).w;
        EXPECT_GT(top, previousTop);
        previousTop = top;
    }
    EXPECT_EQ(cm::profileForType(1.0f).w, 1.0f); // cumulonimbus fill the layer
    EXPECT_EQ(cm::verticalProfile(0.3f, cm::TYPE_STRATUS), 0.0f);
    EXPECT_GT(cm::verticalProfile(0.3f, cm::TYPE_CUMULONIMBUS), 0.5f);
}

TEST(Profiles, InverseSmoothstepUndoesSmoothstep) {
    for (int i = 0; i <= 100; ++i) {
        const float u = i / 100.0f;
        EXPECT_NEAR(cm::inverseSmoothstep(glm::smoothstep(0.0f, 1.0f, u)), u, 1e-4f) << u;
    }
}

// Above profileTopAbove(type, coverage) no profile of a type up to `type`, with any bottom type,
// reaches the coverage threshold of a coverage up to `coverage`, so no base shape (at most 1)
// can make cloud there; and the bound is tighter than the profile's top where coverage is thin.
TEST(Profiles, NothingAboveTheTopAtTheCoverageThresholdReachesIt) {
    for (int ti = 0; ti <= 12; ++ti) {
        const float type = ti / 12.0f;
        for (int ci = 1; ci <= 10; ++ci) {
            const float coverage = ci / 10.0f;
            const float top = cm::profileTopAbove(type, coverage);
            EXPECT_LE(top, cm::profileForType(type).w);
            for (int k = 0; k <= ti; ++k) {
                const float lowerType = k / 12.0f;
                for (float lowerCoverage : {coverage, 0.5f * coverage}) {
                    const float threshold = cm::coverageThreshold(lowerCoverage);
                    for (float bottomType : {0.0f, 0.5f, 1.0f}) {
                        for (int i = 0; i <= 200; ++i) {
                            const float h = top + (1.0f - top) * i / 200.0f;
                            EXPECT_LE(cm::splitVerticalProfile(h, lowerType, bottomType),
                                      std::max(threshold, 0.0f))
                                << "type " << lowerType << " under " << type << ", coverage "
                                << lowerCoverage << ", h " << h << " above " << top;
                        }
                    }
                }
            }
        }
    }
    // Thin cumulus (coverage 0.3) end some 700 m below their profile's top in a 6.5 km layer.
    const float cumulusTop = cm::profileForType(cm::TYPE_CUMULUS).w;
    EXPECT_LT(cm::profileTopAbove(cm::TYPE_CUMULUS, 0.3f), cumulusTop - 0.1f);
    EXPECT_EQ(cm::profileTopAbove(cm::TYPE_CUMULUS, 1.0f), cumulusTop);
}

TEST(Weather, PrecipitationRule) {
    const vec3 rain = cm::applyPrecipitationRule(vec3(0.1f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(rain.x, 0.7f);
    EXPECT_FLOAT_EQ(rain.z, 1.0f);
    const vec3 dry = cm::applyPrecipitationRule(vec3(0.3f, 0.2f, 0.4f));
    EXPECT_FLOAT_EQ(dry.x, 0.3f);
    EXPECT_FLOAT_EQ(dry.z, 0.4f);
    const vec3 again = cm::applyPrecipitationRule(rain);
    EXPECT_EQ(again, rain); // idempotent
}

namespace {
constexpr float R = 6371000.0f;
constexpr float kBottom = 1500.0f;
constexpr float kTop = 8000.0f;
glm::vec4 shell(vec3 origin, vec3 dir) {
    return cm::shellIntervals(origin, glm::normalize(dir), R, kBottom, kTop);
}
} // namespace

TEST(Shell, CameraBelowLookingUp) {
    const glm::vec4 s = shell(vec3(0, 2, 0), vec3(0, 1, 0));
    EXPECT_NEAR(s.x, kBottom - 2.0f, 1.0f);
    EXPECT_NEAR(s.y, kTop - 2.0f, 1.0f);
    EXPECT_LE(s.w, s.z); // one interval
}

TEST(Shell, CameraBelowLookingDownMisses) {
    const glm::vec4 s = shell(vec3(0, 2, 0), vec3(0.3f, -1, 0));
    EXPECT_LE(s.y, s.x);
}

TEST(Shell, CameraBelowAtTheHorizonHasALongPath) {
    const glm::vec4 s = shell(vec3(0, 2, 0), vec3(1, 0, 0));
    // Geometric horizon distances: sqrt(2 R h).
    EXPECT_NEAR(s.x, std::sqrt(2.0f * R * kBottom), 400.0f);
    EXPECT_NEAR(s.y, std::sqrt(2.0f * R * kTop), 400.0f);
}

TEST(Shell, CameraInsideStartsAtZero) {
    const glm::vec4 up = shell(vec3(0, 3000, 0), vec3(0, 1, 0));
    EXPECT_EQ(up.x, 0.0f);
    EXPECT_NEAR(up.y, 5000.0f, 1.0f);
    const glm::vec4 down = shell(vec3(0, 3000, 0), vec3(0, -1, 0));
    EXPECT_EQ(down.x, 0.0f);
    EXPECT_NEAR(down.y, 1500.0f, 1.0f); // leaves through the bottom, then the ground blocks
    EXPECT_LE(down.w, down.z);
}

TEST(Shell, CameraAboveLookingDown) {
    const glm::vec4 s = shell(vec3(0, 10000, 0), vec3(0, -1, 0));
    EXPECT_NEAR(s.x, 2000.0f, 1.0f);
    EXPECT_NEAR(s.y, 8500.0f, 1.0f);
    EXPECT_LE(s.w, s.z);
}

TEST(Shell, CameraAboveLookingUpMisses) {
    const glm::vec4 s = shell(vec3(0, 10000, 0), vec3(0.2f, 1, 0));
    EXPECT_LE(s.y, s.x);
}

TEST(Shell, CameraAboveGrazingTheInnerSphereGivesTwoIntervals) {
    // From 10 km, a ray dipping between 0.0517 rad (tangent to the 1.5 km sphere) and 0.056 rad
    // (tangent to the ground) crosses the shell, passes through the inner ball and comes out
    // into the shell again without reaching the ground.
    const float down = -0.054f;
    const glm::vec4 s = shell(vec3(0, 10000, 0), vec3(1, down, 0));
    ASSERT_GT(s.y, s.x);
    ASSERT_GT(s.w, s.z) << "expected a second interval after the inner sphere";
    EXPECT_LT(s.y, s.z);
}

TEST(Shell, RaySphereMissAndHit) {
    const glm::vec2 miss = cm::raySphere(vec3(0, 0, -10), vec3(0, 1, 0), vec3(0), 1.0f);
    EXPECT_EQ(miss.x, cm::NO_HIT);
    const glm::vec2 hit = cm::raySphere(vec3(0, 0, -10), vec3(0, 0, 1), vec3(0), 1.0f);
    EXPECT_NEAR(hit.x, 9.0f, 1e-4);
    EXPECT_NEAR(hit.y, 11.0f, 1e-4);
}
