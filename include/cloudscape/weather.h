#pragma once
// The weather map: R = coverage, G = precipitation, B = cloud type (0 stratus, 1/3
// stratocumulus, 2/3 cumulus, 1 cumulonimbus) over a square, wrapping extent of the world.
#include <cloudscape/texture.h>

#include <cstdint>
#include <string>

namespace cloudscape {

struct WeatherParams {
    uint32_t seed = 1;
    int resolution = 512;            // texels along each side
    float extentM = 60000.0f;        // world size the map covers before it wraps, metres
    float coverage = 0.45f;          // mean coverage in [0, 1]
    float featureScaleM = 6000.0f;   // typical size of coverage features, metres
    float typeMean = 0.67f;          // mean cloud type in [0, 1]
    float typeVariation = 0.15f;     // amplitude of the type field's variation around the mean
    int rainCells = 0;               // number of precipitation cells
    float rainCellRadiusM = 4000.0f; // radius of a rain cell, metres
};

// Procedural generator (a "data field" in the Nubis sense): tileable FBM fields for coverage and
// type, plus Gaussian-like rain cells placed by the seed. The precipitation rule (full
// precipitation forces cumulonimbus and coverage >= 0.7) is applied to the result. The mean of
// the coverage channel equals `coverage` before that rule (rain cells only raise it); 0 and 1
// give exactly clear and overcast maps. Throws cloudscape::Error naming an out-of-range
// parameter and its range.
Texture2D generateWeatherMap(const WeatherParams& params);

// Painted override: an RGB or RGBA PNG whose R, G, B are coverage, precipitation and type in
// linear 8-bit values. Throws cloudscape::Error naming the file on an unreadable image or a
// channel count other than 3 or 4. The precipitation rule is applied; mips are built. Any width
// and height: the image is stretched over the map's extent (power-of-two sizes filter best).
Texture2D loadWeatherImage(const std::string& path);

} // namespace cloudscape
