// The textures a CPU test renders with: the scene's own weather, data field and atmosphere tables,
// and small
// noise volumes (32^3 base, 16^3 detail) so a test does not spend seconds generating the 128^3
// ones. Terrain, where a test needs it, is prepared by the test (cloudscape::prepareTerrain).
#pragma once

#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/weather.h>

#include "core/atmosphere_luts.h"
#include "core/resources.h"

namespace cloudscape::test {

inline SceneResources smallResources(const Scene& s) {
    SceneResources r;
    r.noise.base = generateBaseNoise(1, 32);
    r.noise.detail = generateDetailNoise(1, 16);
    r.noise.curl = generateCurlNoise(1, 32);
    r.weather = prepareWeather(s);
    r.weatherCoverage = CoverageField(r.weather);
    prepareDataField(s, r);
    prepareAtmosphere(s, r);
    return r;
}

} // namespace cloudscape::test
