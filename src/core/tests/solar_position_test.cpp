// The sun from a place and a time (sun.from_time): known positions from spherical astronomy, the
// symmetries of a day, and that every consumer's sun (the model's parameters) follows the keys
// whatever order they were set in.
#include <cloudscape/scene.h>
#include <cloudscape/solar_position.h>

#include "core/model_params.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using cloudscape::solarDeclinationDeg;
using cloudscape::solarPosition;

namespace {

constexpr double kSpringEquinox = 80.0; // 21 March (declination -0.07 deg)
constexpr double kJuneSolstice = 172.0; // 21 June (+23.45 deg)
constexpr double kDecemberSolstice = 355.0;

// Headings differ modulo 360.
double headingDifference(double a, double b) {
    return std::remainder(a - b, 360.0);
}

} // namespace

TEST(SolarPosition, DeclinationFollowsTheSeasons) {
    EXPECT_NEAR(solarDeclinationDeg(kSpringEquinox), 0.0, 0.5);
    EXPECT_NEAR(solarDeclinationDeg(266.0), 0.0, 0.5); // 23 September
    EXPECT_NEAR(solarDeclinationDeg(kJuneSolstice), 23.44, 0.05);
    EXPECT_NEAR(solarDeclinationDeg(kDecemberSolstice), -23.44, 0.05);
    // Fractional days move it smoothly between whole days.
    const double half = solarDeclinationDeg(100.5);
    EXPECT_GT(half, solarDeclinationDeg(100.0));
    EXPECT_LT(half, solarDeclinationDeg(101.0));
}

TEST(SolarPosition, NoonElevationIsNinetyMinusLatitudePlusDeclination) {
    // The equator at the equinox: the sun is overhead at noon.
    EXPECT_GT(solarPosition(0.0, kSpringEquinox, 12.0).elevationDeg, 89.5);
    // 52 N at the June solstice: 90 - 52 + 23.44.
    EXPECT_NEAR(solarPosition(52.0, kJuneSolstice, 12.0).elevationDeg, 61.44, 0.1);
    // 52 N in December: 90 - 52 - 23.44.
    EXPECT_NEAR(solarPosition(52.0, kDecemberSolstice, 12.0).elevationDeg, 14.56, 0.1);
    for (double lat : {-60.0, -34.0, 0.0, 10.0, 52.0, 66.0})
        for (double day : {1.0, 80.0, 172.0, 300.0}) {
            const double expected = 90.0 - std::abs(lat - solarDeclinationDeg(day));
            EXPECT_NEAR(solarPosition(lat, day, 12.0).elevationDeg, expected, 1e-9)
                << lat << " deg, day " << day;
        }
}

TEST(SolarPosition, NoonSunIsSouthInTheNorthAndNorthInTheSouth) {
    EXPECT_NEAR(headingDifference(solarPosition(52.0, kJuneSolstice, 12.0).headingDeg, 180.0), 0.0,
                1e-9);
    EXPECT_NEAR(headingDifference(solarPosition(-34.0, kJuneSolstice, 12.0).headingDeg, 0.0), 0.0,
                1e-9);
    EXPECT_NEAR(headingDifference(solarPosition(-34.0, kDecemberSolstice, 12.0).headingDeg, 0.0),
                0.0, 1e-9);
    // In the tropics in their summer the noon sun is on the pole's side.
    EXPECT_NEAR(headingDifference(solarPosition(10.0, kJuneSolstice, 12.0).headingDeg, 0.0), 0.0,
                1e-9);
}

TEST(SolarPosition, AtTheEquinoxTheSunRisesInTheEastAtSixAndSetsInTheWestAtSix) {
    for (double lat : {-45.0, 0.0, 30.0, 52.0}) {
        const cloudscape::SunAngles rise = solarPosition(lat, kSpringEquinox, 6.0);
        const cloudscape::SunAngles set = solarPosition(lat, kSpringEquinox, 18.0);
        EXPECT_NEAR(rise.elevationDeg, 0.0, 0.1) << lat;
        EXPECT_NEAR(set.elevationDeg, 0.0, 0.1) << lat;
        EXPECT_NEAR(headingDifference(rise.headingDeg, 90.0), 0.0, 0.2) << lat;
        EXPECT_NEAR(headingDifference(set.headingDeg, 270.0), 0.0, 0.2) << lat;
        // An hour later the sun has risen; an hour before sunset it is still up.
        EXPECT_GT(solarPosition(lat, kSpringEquinox, 7.0).elevationDeg, 5.0) << lat;
        EXPECT_GT(solarPosition(lat, kSpringEquinox, 17.0).elevationDeg, 5.0) << lat;
    }
}

TEST(SolarPosition, MorningAndAfternoonMirrorEachOtherAboutNoon) {
    for (double h : {0.5, 2.0, 5.0, 9.0}) {
        const cloudscape::SunAngles am = solarPosition(40.0, 120.0, 12.0 - h);
        const cloudscape::SunAngles pm = solarPosition(40.0, 120.0, 12.0 + h);
        EXPECT_NEAR(am.elevationDeg, pm.elevationDeg, 1e-9) << h;
        EXPECT_NEAR(headingDifference(am.headingDeg, 360.0 - pm.headingDeg), 0.0, 1e-9) << h;
        EXPECT_GE(am.headingDeg, 0.0);
        EXPECT_LT(am.headingDeg, 360.0);
    }
}

TEST(SolarPosition, NightIsFarBelowTheHorizonAndPolarDaysAreRight) {
    // Midnight at 52 N in December: 90 - 52 - 23.44 below the horizon, due north.
    const cloudscape::SunAngles midnight = solarPosition(52.0, kDecemberSolstice, 0.0);
    EXPECT_NEAR(midnight.elevationDeg, -(90.0 - 52.0 + 23.44), 0.1);
    EXPECT_NEAR(headingDifference(midnight.headingDeg, 0.0), 0.0, 1e-6);
    // The midnight sun at 80 N in June, and the polar night's noon in December.
    EXPECT_NEAR(solarPosition(80.0, kJuneSolstice, 0.0).elevationDeg, 13.44, 0.1);
    EXPECT_NEAR(solarPosition(80.0, kDecemberSolstice, 12.0).elevationDeg, -13.44, 0.1);
    // The pole and the day's ends are finite.
    for (double lat : {-90.0, 90.0})
        for (double t : {0.0, 12.0, 24.0}) {
            const cloudscape::SunAngles s = solarPosition(lat, 366.0, t);
            EXPECT_TRUE(std::isfinite(s.elevationDeg) && std::isfinite(s.headingDeg));
            EXPECT_NEAR(s.elevationDeg,
                        lat > 0 ? solarDeclinationDeg(366.0) : -solarDeclinationDeg(366.0), 1e-9);
        }
}

TEST(SolarPosition, TheSceneSunFollowsTheTimeKeysWhenAsked) {
    cloudscape::Scene s;
    // Off: the angle keys, exactly (so existing scenes render the same bits).
    const cloudscape::SunAngles keys = cloudscape::sunAnglesOf(s);
    EXPECT_EQ(static_cast<float>(keys.elevationDeg), s.sunElevationDeg);
    EXPECT_EQ(static_cast<float>(keys.headingDeg), s.sunHeadingDeg);
    const glm::vec3 byKeys = cloudscape::makeSkyParams(s).sunDirection;
    EXPECT_EQ(byKeys, cloudscape::directionFromAngles(s.sunHeadingDeg, s.sunElevationDeg));

    // On: the angle keys are ignored, in whatever order they were set.
    cloudscape::Scene a = s, b = s;
    for (const char* k : {"sun.from_time=true", "sun.latitude_deg=-34", "sun.day_of_year=172",
                          "sun.local_solar_time_h=15.5", "sun.elevation_deg=5"})
        cloudscape::applyOverride(a, k);
    for (const char* k : {"sun.elevation_deg=70", "sun.local_solar_time_h=15.5",
                          "sun.latitude_deg=-34", "sun.day_of_year=172", "sun.from_time=true"})
        cloudscape::applyOverride(b, k);
    const cloudscape::SunAngles expected = solarPosition(-34.0, 172.0, 15.5);
    const glm::vec3 direction = cloudscape::directionFromAngles(
        static_cast<float>(expected.headingDeg), static_cast<float>(expected.elevationDeg));
    EXPECT_EQ(cloudscape::makeSkyParams(a).sunDirection, direction);
    EXPECT_EQ(cloudscape::makeSkyParams(b).sunDirection, direction);
    // A winter afternoon in the south: low in the north-west.
    EXPECT_GT(expected.elevationDeg, 5.0);
    EXPECT_LT(expected.elevationDeg, 30.0);
    EXPECT_GT(expected.headingDeg, 270.0);
    EXPECT_GT(direction.y, 0.0f);
    EXPECT_LT(direction.x, 0.0f) << "west";
    EXPECT_GT(direction.z, 0.0f) << "north";
}
