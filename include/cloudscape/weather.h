#pragma once
// The weather map: a coverage field (16 bits: high byte in R, low byte in A), G = precipitation,
// B = cloud type (0 stratus, 1/3 stratocumulus, 2/3 cumulus, 1 cumulonimbus) over a square,
// wrapping extent of the world. Coverage itself is the field shifted by a bias that the renderer
// passes as a uniform (src/model/weather.glsl.h), chosen with CoverageField so that the map's
// mean coverage is weather.coverage: changing the coverage regenerates no texture, and works
// on a painted map as on a generated one.
#include <cloudscape/scene.h>
#include <cloudscape/texture.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape {

// The generator's inputs, the weather.* keys of a scene; defaults and ranges are the key table's.
struct WeatherParams {
    uint32_t seed = 1;
    int resolution = defaultScene().weatherResolution;      // texels along each side
    float extentM = defaultScene().weatherExtentM;          // world size before the map wraps, m
    float featureScaleM = defaultScene().featureScaleM;     // typical size of coverage features, m
    float typeMean = defaultScene().cloudType;              // mean cloud type in [0, 1]
    float typeVariation = defaultScene().typeVariation;     // amplitude of the type's variation
    int rainCells = defaultScene().rainCells;               // number of precipitation cells
    float rainCellRadiusM = defaultScene().rainCellRadiusM; // radius of a rain cell, m
};

// Procedural generator (a "data field" in the Nubis sense): tileable FBM fields for coverage and
// type, plus Gaussian-like rain cells placed by the seed. The coverage field is 0.5 + the FBM
// (about [-0.65, 0.65]; clamped to [0, 1]); with the bias for a mean coverage c the coverage is
// clamp(field + bias), which spreads the field around an offset as the seeds' generator did, so
// most of the map holds partial coverage. The precipitation rule's type part is applied to the
// map (full precipitation makes cumulonimbus); its coverage part (>= 0.7 under full
// precipitation) is applied by the model after the bias. Throws cloudscape::Error naming an
// out-of-range parameter and its range.
Texture2D generateWeatherMap(const WeatherParams& params);

// Painted override: an RGB or RGBA PNG whose R, G, B are coverage, precipitation and type in
// linear 8-bit values (the coverage is stored as the field exactly, so a bias of 0 shows it as
// painted; weather.coverage shifts it to its mean). Throws cloudscape::Error naming the file on an
// unreadable image or a channel count other than 3 or 4. The precipitation rule's type part is
// applied; mips are built. Any width and height: the image is stretched over the map's extent
// (power-of-two sizes filter best).
Texture2D loadWeatherImage(const std::string& path);

// The coverage field of a map's level 0 (what the renderer samples) as a distribution, so that
// the bias giving a mean coverage is found in microseconds, without touching the texels again:
// a coverage change on a live renderer costs this and a uniform upload.
class CoverageField {
public:
    CoverageField() = default; // empty
    explicit CoverageField(const Texture2D& map);

    bool empty() const { return texels_ == 0; }
    // The bias b for which the mean of clamp(field + b, 0, 1) over the texels is `coverage`:
    // -1 for 0 (nothing), 1 for 1 (overcast), in between by bisection.
    float biasFor(float coverage) const;
    // The mean coverage over the texels for a bias (before the precipitation rule).
    double meanCoverage(float bias) const;
    // `count` texels (RGBA, 4 floats each) changed from `before` to `after` (a painted region):
    // the distribution is what CoverageField of the edited map would be, without reading it all.
    void replaceTexels(const float* before, const float* after, size_t count);

private:
    void accumulate(); // countBelow_ and sumBelow_ from count_
    size_t texels_ = 0;
    std::vector<uint64_t> count_;      // texels with field code k, k = 0..65535
    std::vector<uint64_t> countBelow_; // texels with a field code below k, k = 0..65536
    std::vector<double> sumBelow_;     // the sum of their fields
};

// The largest raw values (coverage field, precipitation, type) a bilinear read can return in each
// cell of the real-time march's empty-space grid (model::CLOUD_TOP_GRID^2 cells over the map,
// row-major): what makeCloudParams bounds each column's cloud top with. Made once with the map
// (a 512^2 map costs about 2 ms) instead of every frame. It remembers the map it was made from
// (where its texels are, its size and a sum of 1024 of them spread over it): a maxima made from
// another map is not used.
struct WeatherCellMaxima {
    const float* map = nullptr;
    int width = 0;
    int height = 0;
    double probe = 0.0;
    std::vector<float> cells; // 3 floats a cell
    bool isFor(const Texture2D& weather) const;
};
WeatherCellMaxima weatherCellMaxima(const Texture2D& map);

// The field of one texel (4 floats), as the model decodes it (coverageField in weather.glsl.h).
float coverageFieldOf(const float* texel);

// Level 0 of a map as the renderer reads it with a coverage bias: coverage (bias and
// precipitation rule applied), precipitation and type, 3 floats per texel.
std::vector<float> weatherAsSeen(const Texture2D& map, float coverageBias);

} // namespace cloudscape
