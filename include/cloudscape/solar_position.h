#pragma once
// Where the sun stands for a place and a time: the elevation and heading that `sun.from_time`
// gives a scene from sun.latitude_deg, sun.day_of_year and sun.local_solar_time_h. Every
// consumer of a scene (both backends, the path tracer, the bench) takes its sun from
// sunAnglesOf, through the model's parameters, so they all see the same sun whatever order the
// keys were set in and however keyframes move them.
#include <cloudscape/scene.h>

namespace cloudscape {

struct SunAngles {
    double elevationDeg = 0.0; // above the horizon, -90 to 90
    double headingDeg = 0.0;   // clockwise from north, [0, 360)
};

// The sun's declination in degrees on a day of the year (1 = 1 January; fractions allowed).
double solarDeclinationDeg(double dayOfYear);

// The sun seen from latitude `latitudeDeg` (north positive) on `dayOfYear` at local solar time
// `localSolarTimeH` (12 = the sun due south or north, highest). Solar time, not clock time: the
// equation of time and the longitude within the time zone are the caller's.
SunAngles solarPosition(double latitudeDeg, double dayOfYear, double localSolarTimeH);

// The sun a scene renders with: sun.elevation_deg and sun.heading_deg, or, when sun.from_time
// is true, solarPosition of the scene's place and time (the two angle keys are then ignored).
SunAngles sunAnglesOf(const Scene& scene);

} // namespace cloudscape
