// The sun's position for a place and a time.
//
// Declination: Spencer's Fourier series (J. W. Spencer, "Fourier series representation of the
// position of the sun", Search 2(5), 172, 1971; also M. Iqbal, "An Introduction to Solar
// Radiation", 1983, eq. 1.3.1), within about 0.035 deg of the ephemeris over the year, which is
// far below what a rendered sky shows. Hour angle: 15 deg an hour from local solar noon.
// Elevation and azimuth: the spherical-astronomy relations (Iqbal 1983, eqs. 1.5.1 and 1.5.2;
// J. A. Duffie and W. A. Beckman, "Solar Engineering of Thermal Processes", eqs. 1.6.5 and
// 1.6.6), written as the sun's direction in east/north/up components so the azimuth comes from
// one atan2 without quadrant cases. No refraction: the geometric sun.
#include <cloudscape/solar_position.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cloudscape {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

} // namespace

double solarDeclinationDeg(double dayOfYear) {
    const double g = 2.0 * std::numbers::pi * (dayOfYear - 1.0) / 365.0; // day angle
    const double radians = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) -
                           0.006758 * std::cos(2.0 * g) + 0.000907 * std::sin(2.0 * g) -
                           0.002697 * std::cos(3.0 * g) + 0.00148 * std::sin(3.0 * g);
    return radians / kDeg;
}

SunAngles solarPosition(double latitudeDeg, double dayOfYear, double localSolarTimeH) {
    const double lat = latitudeDeg * kDeg;
    const double dec = solarDeclinationDeg(dayOfYear) * kDeg;
    const double hour = (localSolarTimeH - 12.0) * 15.0 * kDeg; // positive in the afternoon
    // The unit vector toward the sun: the equatorial direction (declination, hour angle)
    // rotated into the observer's horizon frame.
    const double east = -std::cos(dec) * std::sin(hour);
    const double north =
        std::sin(dec) * std::cos(lat) - std::cos(dec) * std::sin(lat) * std::cos(hour);
    const double up =
        std::sin(dec) * std::sin(lat) + std::cos(dec) * std::cos(lat) * std::cos(hour);
    SunAngles sun;
    sun.elevationDeg = std::asin(std::clamp(up, -1.0, 1.0)) / kDeg;
    const double heading = std::atan2(east, north) / kDeg; // clockwise from north
    sun.headingDeg = heading < 0.0 ? heading + 360.0 : heading;
    if (sun.headingDeg >= 360.0)
        sun.headingDeg = 0.0;
    return sun;
}

SunAngles sunAnglesOf(const Scene& scene) {
    if (scene.sunFromTime)
        return solarPosition(scene.sunLatitudeDeg, scene.sunDayOfYear, scene.sunLocalSolarTimeH);
    return {scene.sunElevationDeg, scene.sunHeadingDeg};
}

} // namespace cloudscape
