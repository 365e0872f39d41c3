// The procedural terrain: ridged multifractal noise (Musgrave's "ridged multifractal", in Ebert
// et al., Texturing and Modeling) over the field, evaluated per texel on all cores.
#include <cloudscape/terrain.h>

#include "generators/tileable_noise.h"
#include "model/terrain.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cloudscape {
namespace {

// Octaves from the largest ridges down to about two texels.
int octaveCount(int resolution, int period) {
    int octaves = 1;
    while (octaves < 10 && (period << octaves) * 2 <= resolution)
        ++octaves;
    return octaves;
}

// Each octave is 1 - |noise|, squared (sharp crests where the noise crosses zero), weighted by
// the octave before it so that detail gathers on the crests and valleys stay smooth.
// The octaves are those of a Perlin FBM (period << o, seed + 101 o), its lattices tabulated.
float ridged(glm::vec2 uv, const noise::PerlinFbm2& lattices, int octaves) {
    float sum = 0.0f;
    float amplitude = 0.5f;
    float weight = 1.0f;
    for (int o = 0; o < octaves; ++o) {
        float n = 1.0f - std::fabs(lattices.octave(o, uv));
        n = n * n * weight;
        weight = std::clamp(n * 2.0f, 0.0f, 1.0f);
        sum += n * amplitude;
        amplitude *= 0.5f;
    }
    return sum;
}

float smoothstep(float a, float b, float x) {
    const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

namespace {

// The cell maxima of terrain.glsl.h: level 0's cells span TERRAIN_CELL_SPANS texel spans a
// side and hold the highest of the texels on and inside their edges (which bounds the bilinear
// surface over them); each level's cell is the highest of four of the last level's. The grid is
// padded to a square power of two (padding cells are never read) so a level's offset is closed
// form (terrainCellLevelOffset).
void appendCellMaxima(HeightField& f) {
    const int spans = model::TERRAIN_CELL_SPANS;
    const int cellsX = std::max(1, (f.width - 2) / spans + 1);
    const int cellsZ = std::max(1, (f.height - 2) / spans + 1);
    int grid = 1;
    while (grid < std::max(cellsX, cellsZ))
        grid *= 2;
    f.cellGrid = grid;
    f.cellLevels = 0;
    for (int side = grid; side >= 1; side /= 2)
        ++f.cellLevels;
    const size_t base = f.texelCount();
    f.heights.resize(base + size_t(model::terrainCellLevelOffset(f.cellLevels, grid)), 0.0f);
    float* level0 = f.heights.data() + base;
    for (int cz = 0; cz < cellsZ; ++cz)
        for (int cx = 0; cx < cellsX; ++cx) {
            float m = -std::numeric_limits<float>::max();
            for (int z = cz * spans; z <= std::min((cz + 1) * spans, f.height - 1); ++z)
                for (int x = cx * spans; x <= std::min((cx + 1) * spans, f.width - 1); ++x)
                    m = std::max(m, f.heights[size_t(z) * f.width + x]);
            level0[size_t(cz) * grid + cx] = m;
        }
    for (int level = 1; level < f.cellLevels; ++level) {
        const float* below =
            f.heights.data() + base + model::terrainCellLevelOffset(level - 1, grid);
        float* cells = f.heights.data() + base + model::terrainCellLevelOffset(level, grid);
        const int side = grid >> level, belowSide = side * 2;
        for (int cz = 0; cz < side; ++cz)
            for (int cx = 0; cx < side; ++cx) {
                const float* b = below + size_t(2 * cz) * belowSide + 2 * cx;
                cells[size_t(cz) * side + cx] =
                    std::max({b[0], b[1], b[belowSide], b[belowSide + 1]});
            }
    }
}

} // namespace

void measureHeightField(HeightField& f, float texelXM, float texelZM) {
    f.heights.resize(f.texelCount());
    f.lightHorizonOffset = 0;
    float top = 0.0f, stepX = 0.0f, stepZ = 0.0f;
    for (int z = 0; z < f.height; ++z)
        for (int x = 0; x < f.width; ++x) {
            const float h = f.heights[size_t(z) * f.width + x];
            top = std::max(top, h);
            if (x + 1 < f.width)
                stepX = std::max(stepX, std::fabs(f.heights[size_t(z) * f.width + x + 1] - h));
            if (z + 1 < f.height)
                stepZ = std::max(stepZ, std::fabs(f.heights[size_t(z + 1) * f.width + x] - h));
        }
    f.maxHeightM = top;
    // Inside a bilinear cell each partial derivative lies between its edges' texel steps.
    f.maxSlope = std::hypot(stepX / texelXM, stepZ / texelZM);
    appendCellMaxima(f);
}

namespace {

// The light's horizon over a field whose columns (x) lie along the light's dominant horizontal
// axis: read through (column, row) -> index so that the same sweep serves both axes.
struct HorizonSweep {
    int columns, rows;
    int towardLight; // +1 or -1: the next column toward the light
    float rowShift;  // rows the light's line moves per column
    float drop;      // metres the light's line rises per column (step * tan(elevation))
};

template <typename Index>
void sweepHorizon(const HorizonSweep& s, const std::vector<float>& h, std::vector<float>& out,
                  Index index) {
    const int first = s.towardLight > 0 ? s.columns - 1 : 0;
    for (int step = 0; step < s.columns; ++step) {
        const int c = first - step * s.towardLight;
        const int from = c + s.towardLight;
        for (int r = 0; r < s.rows; ++r) {
            const float own = h[index(c, r)];
            const float y = float(r) + s.rowShift;
            if (from < 0 || from >= s.columns || y < 0.0f || y > float(s.rows - 1)) {
                out[index(c, r)] = own; // the line leaves the field: nothing beyond it
                continue;
            }
            const int r0 = std::min(int(y), std::max(s.rows - 2, 0));
            const int r1 = std::min(r0 + 1, s.rows - 1);
            const float a = y - float(r0);
            const float beyond = out[index(from, r0)] * (1.0f - a) + out[index(from, r1)] * a;
            out[index(c, r)] = std::max(own, beyond - s.drop);
        }
    }
}

} // namespace

void appendLightHorizon(HeightField& f, glm::vec3 light, float texelXM, float texelZM) {
    const size_t end = f.lightHorizonOffset > 0 ? f.lightHorizonOffset : f.heights.size();
    f.heights.resize(end);
    // Where nothing stands higher toward the light, the ground itself.
    std::vector<float> horizon(f.heights.begin(), f.heights.begin() + f.texelCount());
    const float across = std::hypot(light.x, light.z);
    if (light.y > 0.0f && across > 1e-6f * light.y) {
        const float tanElevation = light.y / across;
        const float dx = light.x / across, dz = light.z / across;
        const int w = f.width, hgt = f.height;
        if (std::fabs(dx) * texelZM >= std::fabs(dz) * texelXM) {
            const float step = texelXM / std::fabs(dx); // metres along the light per column
            const HorizonSweep s{w, hgt, dx > 0.0f ? 1 : -1, dz * step / texelZM,
                                 step * tanElevation};
            sweepHorizon(s, f.heights, horizon, [w](int c, int r) { return size_t(r) * w + c; });
        } else {
            const float step = texelZM / std::fabs(dz);
            const HorizonSweep s{hgt, w, dz > 0.0f ? 1 : -1, dx * step / texelXM,
                                 step * tanElevation};
            sweepHorizon(s, f.heights, horizon, [w](int c, int r) { return size_t(c) * w + r; });
        }
    }
    f.lightHorizonOffset = f.heights.size();
    f.lightHorizonDirection = light;
    f.heights.insert(f.heights.end(), horizon.begin(), horizon.end());
}

HeightField generateTerrain(const TerrainGenerator& p) {
    HeightField f;
    f.width = f.height = p.resolution;
    f.heights.assign(size_t(p.resolution) * p.resolution, 0.0f);
    const int period = std::max(1, int(std::lround(p.extentM / p.featureSizeM)));
    const int octaves = octaveCount(p.resolution, period);
    // Tabulated only up to a lattice point a texel: a finer octave is cheaper hashed.
    const noise::PerlinFbm2 lattices(period, octaves, p.seed, int64_t(p.resolution) * p.resolution);
    tbb::parallel_for(0, p.resolution, [&](int z) {
        for (int x = 0; x < p.resolution; ++x) {
            const glm::vec2 uv((x + 0.5f) / p.resolution, (z + 0.5f) / p.resolution);
            const float edge = std::min({uv.x, 1.0f - uv.x, uv.y, 1.0f - uv.y});
            const float fade = smoothstep(0.0f, 0.15f, edge);
            f.heights[size_t(z) * p.resolution + x] = ridged(uv, lattices, octaves) * fade;
        }
    });
    // Scale so the highest texel is heightM; a power above 1 widens the valleys.
    const float top = *std::max_element(f.heights.begin(), f.heights.end());
    for (float& h : f.heights)
        h = top > 0.0f ? p.heightM * std::pow(h / top, 1.6f) : 0.0f;
    const float texel = p.extentM / p.resolution;
    measureHeightField(f, texel, texel);
    return f;
}

} // namespace cloudscape
