#pragma once
// The terrain's height field (src/model/terrain.glsl.h renders it): generated from seeded ridged
// fractal noise, or loaded from a 16-bit greyscale PNG or a float EXR. Heights are metres above
// the planet's surface, row-major, row 0 at the field's smallest world z, x along a row.
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape {

struct HeightField {
    int width = 0;  // texels along x
    int height = 0; // texels along z
    // The texels the model reads: the field's width x height heights, then (after
    // measureHeightField) the maxima of its cells, level by level (terrain.glsl.h's cell maxima,
    // which let the march skip over whole cells the ray passes above).
    std::vector<float> heights;
    float maxHeightM = 0.0f; // the highest texel
    float maxSlope = 0.0f;   // bound on |grad h| of the bilinear surface (steepest texel steps)
    int cellGrid = 0;        // level 0's cells a side (a power of two; 0: no cell maxima)
    int cellLevels = 0;      // levels of cell maxima, each of cells twice as wide as the last
    // After the cell maxima (appendLightHorizon): per field texel, the altitude (m) above which a
    // point there sees the light over the field, made for lightHorizonDirection. 0: none.
    size_t lightHorizonOffset = 0;
    glm::vec3 lightHorizonDirection{0.0f};
    bool empty() const { return heights.empty(); }
    size_t texelCount() const { return size_t(width) * size_t(height); }
};

// Sets maxHeightM and maxSlope from the field's texels, for texels of the given size (m), and
// appends its cell maxima to `heights` (replacing any made before).
void measureHeightField(HeightField& field, float texelXM, float texelZM);

// Appends the light's horizon to a measured field's texels (replacing one made before): for each
// texel, the altitude a point must reach there to see past every texel toward `light` (a unit
// direction, sun or moon). One sweep from the light's side, each texel from its neighbour one
// column (or row) toward the light: H = max(h, H(neighbour) - step * tan(elevation)), the
// neighbour read between its two texels. The planet's curvature is left out (the field is
// flat), which adds up to s^2 / 2R to a shadow cast over s (8 m over 10 km).
void appendLightHorizon(HeightField& field, glm::vec3 light, float texelXM, float texelZM);

struct TerrainGenerator {
    uint32_t seed = 1;
    int resolution = 512;         // texels a side
    float extentM = 40000.0f;     // world size the field covers
    float heightM = 2500.0f;      // of the highest peak
    float featureSizeM = 8000.0f; // wavelength of the largest ridges
};
// Ridged multifractal noise (Musgrave): sharp crests, smooth valleys, fading to the flat planet
// over the outer 15 % of the extent so the field meets the ground around it without a cliff.
HeightField generateTerrain(const TerrainGenerator& params);

// The side a height map may have at most (a 8192^2 float field is 256 MiB) and at least.
constexpr int kMaxHeightMapSide = 8192;
constexpr int kMinHeightMapSide = 2;

// A 16-bit greyscale PNG (grey or grey+alpha; the first channel) mapped linearly from
// [0, 65535] to [minM, maxM], or a float EXR whose Y, R or only channel holds metres. Throws
// cloudscape::Error naming the file for a missing file, an 8-bit PNG, a side outside
// [kMinHeightMapSide, kMaxHeightMapSide], or a height that is not finite or not in [0, 20000].
HeightField loadHeightMap(const std::string& path, float minM, float maxM);

} // namespace cloudscape
