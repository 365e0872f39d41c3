// Camera paths: frames move as documented, and a frame that would leave the scene keys' ranges
// is refused (found by fuzz_camera_path, docs/RELIABILITY.md).
#include <cloudscape/camera_path.h>
#include <cloudscape/error.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <string>
#include <vector>

namespace {

std::string errorOf(const cloudscape::Scene& base, const std::string& path, int frame, float fps) {
    try {
        cloudscape::sceneOnPath(base, path, frame, fps);
    } catch (const cloudscape::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CameraPath, FramesAdvanceTimeAndCamera) {
    const cloudscape::Scene base;
    const cloudscape::Scene pan = cloudscape::sceneOnPath(base, "slow-pan", 48, 24.0f);
    EXPECT_FLOAT_EQ(pan.timeS, base.timeS + 2.0f);
    EXPECT_FLOAT_EQ(pan.cameraHeadingDeg, base.cameraHeadingDeg + 12.0f);
    const cloudscape::Scene fly = cloudscape::sceneOnPath(base, "fly-forward", 10, 24.0f);
    EXPECT_NEAR(glm::length(fly.cameraPosition - base.cameraPosition), 400.0f, 1e-3f);
    EXPECT_FLOAT_EQ(fly.cameraPosition.y, base.cameraPosition.y) << "the flight is level";
}

TEST(CameraPath, FlyThroughClimbsFromBelowTheLayerToAboveIt) {
    cloudscape::Scene base;
    base.cloudBottomM = 1500.0f;
    base.cloudTopM = 4000.0f;
    const int last = cloudscape::kFlyThroughFrames;
    const cloudscape::Scene first = cloudscape::sceneOnPath(base, "fly-through", 0, 24.0f);
    const cloudscape::Scene middle = cloudscape::sceneOnPath(base, "fly-through", last / 2, 24.0f);
    const cloudscape::Scene end = cloudscape::sceneOnPath(base, "fly-through", last, 24.0f);
    EXPECT_FLOAT_EQ(first.cameraPosition.y, 1000.0f) << "500 m under the base";
    EXPECT_FLOAT_EQ(middle.cameraPosition.y, 2750.0f) << "inside the layer half way";
    EXPECT_FLOAT_EQ(end.cameraPosition.y, 4500.0f) << "500 m over the top";
    const float moved = std::hypot(end.cameraPosition.x - first.cameraPosition.x,
                                   end.cameraPosition.z - first.cameraPosition.z);
    EXPECT_NEAR(moved, 40.0f * last, 0.01f * last) << "40 m a frame along the heading";
    EXPECT_FLOAT_EQ(end.cameraPitchDeg, base.cameraPitchDeg);
}

// The fuzzer's input: fast-pan, frame INT_MAX at a denormal fps put the frame at t = inf.
TEST(CameraPath, AFrameOutsideTheTimeRangeIsRefused) {
    const std::string e = errorOf(cloudscape::Scene{}, "fast-pan", INT_MAX, 1.12e-38f);
    EXPECT_NE(e.find("time_s = inf"), std::string::npos) << e;
    EXPECT_NE(e.find("frame 2147483647"), std::string::npos) << e;
    EXPECT_NE(errorOf(cloudscape::Scene{}, "still", 1, 1e-40f).find("time_s"), std::string::npos);
    // Finite but beyond time_s's documented 1e8 s.
    EXPECT_NE(errorOf(cloudscape::Scene{}, "still", 1000000, 0.001f).find("outside [0, 1e+08]"),
              std::string::npos);
    EXPECT_EQ(errorOf(cloudscape::Scene{}, "still", 1000000, 1.0f), "");
}

TEST(CameraPath, AFlightOutOfThePositionRangeIsRefused) {
    const std::string e = errorOf(cloudscape::Scene{}, "fly-forward", INT_MAX, 1000.0f);
    EXPECT_NE(e.find("camera.position"), std::string::npos) << e;
    EXPECT_EQ(errorOf(cloudscape::Scene{}, "fly-forward", 200000, 1000.0f), "");
}

TEST(CameraPath, RecordedHeadingsTurnTheShortWayAcrossNorth) {
    using cloudscape::continuousHeadings;
    // Worked by hand: 350, 355, 0.5, 5 unwrap to 350, 355, 360.5, 365, past the range's 360,
    // so one turn comes off every value.
    const std::vector<float> across = continuousHeadings({350.0f, 355.0f, 0.5f, 5.0f});
    ASSERT_EQ(across.size(), 4u);
    const float expected[] = {-10.0f, -5.0f, 0.5f, 5.0f};
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(across[i], expected[i], 1e-4f) << i;
    // Inside the range the recording keeps its values: 180, 190, 200.
    const std::vector<float> kept = continuousHeadings({180.0f, 190.0f, 200.0f});
    EXPECT_EQ(kept, (std::vector<float>{180.0f, 190.0f, 200.0f}));
    // Backwards across north: 10, 355 becomes 10, -5.
    const std::vector<float> back = continuousHeadings({10.0f, 355.0f});
    EXPECT_NEAR(back[0], 10.0f, 1e-4f);
    EXPECT_NEAR(back[1], -5.0f, 1e-4f);
    // The fly camera's fmod keeps a sign: after -350, 10 is the same direction and 20 is 10
    // degrees on.
    const std::vector<float> signs = continuousHeadings({-350.0f, 10.0f, 20.0f});
    EXPECT_NEAR(signs[0], -350.0f, 1e-4f);
    EXPECT_NEAR(signs[1], -350.0f, 1e-4f);
    EXPECT_NEAR(signs[2], -340.0f, 1e-4f);
    EXPECT_TRUE(continuousHeadings({}).empty());

    // Three whole turns in 90 degree steps: every value in the key's range and the same
    // direction as recorded; every step the short way but one, where the range ends.
    std::vector<float> spin;
    for (int i = 0; i <= 12; ++i)
        spin.push_back(std::fmod(90.0f * i, 360.0f));
    const std::vector<float> turned = continuousHeadings(spin);
    int longSteps = 0;
    for (size_t i = 0; i < turned.size(); ++i) {
        EXPECT_GE(turned[i], -360.0f);
        EXPECT_LE(turned[i], 360.0f);
        EXPECT_NEAR(std::remainder(turned[i] - spin[i], 360.0f), 0.0f, 1e-3f) << i;
        if (i > 0)
            longSteps += std::abs(turned[i] - turned[i - 1]) > 180.0f;
    }
    EXPECT_EQ(longSteps, 1);
}
