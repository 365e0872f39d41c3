// The weather controller (the talk's "Controlling Chaos"): the blend rises 0 -> 1 over the
// build-up, holds, falls 1 -> 0 over the dissipation and stays 0 while calm; the vortex clock
// is the blend's integral; the same seed gives the same schedule, another seed another one;
// sites lie inside the map; a bad schedule is refused naming the key.
#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "core/weather_control.h"
#include "io/tests/refused_override.h"

#include <gtest/gtest.h>

#include <cmath>

using cloudscape::Scene;

namespace {

Scene cycling() {
    Scene s;
    s.stormBlend = 0.8f;
    s.stormCycle = true;
    s.stormCycleBuildS = 100.0f;
    s.stormCycleHoldS = 200.0f;
    s.stormCycleDissipateS = 50.0f;
    s.stormCycleCalmS = 150.0f;
    s.stormRadiusM = 10000.0f;
    return s;
}

} // namespace

TEST(WeatherControl, BlendBuildsHoldsAndDissipatesOnSchedule) {
    const Scene s = cycling();
    ASSERT_FLOAT_EQ(cloudscape::stormCyclePeriod(s), 500.0f);
    for (int cycle = 0; cycle < 3; ++cycle) {
        const float t0 = 500.0f * cycle;
        auto blend = [&](float t) { return cloudscape::stormStateAt(s, t0 + t).blend; };
        EXPECT_NEAR(blend(0.0f), 0.0f, 1e-6f);
        EXPECT_NEAR(blend(25.0f), 0.8f * 0.25f, 1e-4f);
        EXPECT_NEAR(blend(50.0f), 0.8f * 0.5f, 1e-4f);
        EXPECT_NEAR(blend(100.0f), 0.8f, 1e-5f);
        EXPECT_NEAR(blend(299.0f), 0.8f, 1e-5f);
        EXPECT_NEAR(blend(325.0f), 0.8f * 0.5f, 1e-4f);
        EXPECT_NEAR(blend(349.9f), 0.0f, 2e-3f);
        EXPECT_EQ(blend(360.0f), 0.0f);
        EXPECT_EQ(blend(499.0f), 0.0f);
        // The vortex clock is the blend's integral: 0.8 * (50 + 200 + 25) at the end.
        EXPECT_NEAR(cloudscape::stormStateAt(s, t0 + 400.0f).spin, 0.8f * 275.0f, 1e-2f);
        EXPECT_NEAR(cloudscape::stormStateAt(s, t0 + 200.0f).spin, 0.8f * 150.0f, 1e-2f);
        // The site holds for the whole cycle.
        const int site = cloudscape::stormStateAt(s, t0 + 1.0f).site;
        EXPECT_EQ(cloudscape::stormStateAt(s, t0 + 340.0f).site, site);
    }
    // The model's parameters follow: no storm while calm, the site's centre while on.
    Scene calm = s;
    calm.timeS = 420.0f;
    const auto off = cloudscape::makeCloudParams(calm, 0.0f);
    EXPECT_EQ(off.stormBlend, 0.0f);
    Scene on = s;
    on.timeS = 150.0f;
    const auto p = cloudscape::makeCloudParams(on, 0.0f);
    const cloudscape::StormState state = cloudscape::stormStateAt(s, 150.0f);
    EXPECT_FLOAT_EQ(p.stormBlend, 0.8f);
    EXPECT_EQ(p.stormCentre.x, state.centre.x);
    EXPECT_EQ(p.stormCentre.y, state.centre.y);
}

TEST(WeatherControl, TheSeedDecidesTheScheduleAndSitesLieInsideTheMap) {
    Scene a = cycling();
    a.stormCycleSites = 5;
    Scene b = a;
    b.seed = 2;
    int differ = 0;
    std::vector<int> visits(5, 0);
    for (int cycle = 0; cycle < 40; ++cycle) {
        const float t = 500.0f * cycle + 200.0f;
        const auto sa = cloudscape::stormStateAt(a, t);
        const auto again = cloudscape::stormStateAt(a, t);
        EXPECT_EQ(sa.site, again.site);
        EXPECT_EQ(sa.centre, again.centre);
        differ += sa.site != cloudscape::stormStateAt(b, t).site;
        visits[sa.site] += 1;
    }
    EXPECT_GT(differ, 10) << "another seed, another schedule";
    for (int v : visits)
        EXPECT_GT(v, 0) << "every site is visited in 40 cycles";
    for (int i = 0; i < 5; ++i) {
        const glm::vec2 c = cloudscape::stormSite(a, i);
        EXPECT_LE(std::abs(c.x) + a.stormRadiusM, 0.5f * a.weatherExtentM);
        EXPECT_LE(std::abs(c.y) + a.stormRadiusM, 0.5f * a.weatherExtentM);
    }
    // Without the controller the keys are the storm.
    Scene fixed;
    fixed.stormBlend = 0.6f;
    fixed.stormXM = 100.0f;
    const auto f = cloudscape::stormStateAt(fixed, 10.0f);
    EXPECT_EQ(f.blend, 0.6f);
    EXPECT_FLOAT_EQ(f.spin, 6.0f);
    EXPECT_EQ(f.centre.x, 100.0f);
}

TEST(WeatherControl, BadSchedulesAndPlacesAreRefusedNamingTheKey) {
    const auto refuses = expectOverrideRefusedNaming;
    refuses("storm.cycle_build_s=0", "storm.cycle_build_s");
    refuses("storm.cycle_dissipate_s=-3", "storm.cycle_dissipate_s");
    refuses("storm.cycle_hold_s=nan", "storm.cycle_hold_s");
    refuses("storm.cycle_sites=0", "storm.cycle_sites");
    // A storm centred outside the map.
    Scene s;
    s.stormBlend = 1.0f;
    s.stormXM = 40000.0f; // the map spans +-30 km
    try {
        cloudscape::validateScene(s, "test");
        ADD_FAILURE() << "a storm outside the map was accepted";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("storm.x_m"), std::string::npos) << e.what();
    }
}
