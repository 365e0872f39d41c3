#include "core/cloud_top_grid.h"

#include "model/cloud_bound.glsl.h"
#include "model/data_field.glsl.h"
#include "model/noise_clearance.glsl.h"

#include <cloudscape/weather.h>

#include <algorithm>
#include <cmath>

namespace cloudscape {
namespace {

int wrapIndex(int i, int n) {
    const int m = i % n;
    return m < 0 ? m + n : m;
}

// Texels a bilinear read anywhere in cell c of n (of a map `size` texels wide) can touch: texel
// coordinates in [c size / n - 0.5, (c + 1) size / n - 0.5] read floor(lo) .. floor(hi) + 1;
// one more on each side absorbs the rounding of the march's cell lookup.
void cellTexelRange(int c, int n, int size, int& first, int& last) {
    const float lo = float(c) * float(size) / float(n) - 0.5f;
    const float hi = float(c + 1) * float(size) / float(n) - 0.5f;
    first = static_cast<int>(std::floor(lo)) - 1;
    last = static_cast<int>(std::floor(hi)) + 2;
}

// A sum of 1024 texels spread over level 0, to tell one map from another at the same address.
double probeOf(const Texture2D& weather) {
    const std::vector<float>& texels = weather.mips[0];
    const size_t stride = std::max<size_t>(texels.size() / 1024, 1);
    double sum = 0.0;
    for (size_t i = 0; i < texels.size(); i += stride)
        sum += texels[i] * double(i % 7 + 1);
    return sum;
}

// The raw maxima of cell (cx, cz) of n.
glm::vec3 cellMaximum(const Texture2D& weather, int n, int cx, int cz) {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    cellTexelRange(cx, n, weather.width, i0, i1);
    cellTexelRange(cz, n, weather.height, j0, j1);
    glm::vec3 maxRaw(0.0f);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const float* t =
                weather.texel(0, wrapIndex(i, weather.width), wrapIndex(j, weather.height));
            maxRaw = glm::max(maxRaw, glm::vec3(coverageFieldOf(t), t[1], t[2]));
        }
    return maxRaw;
}

// Whether cell c of n reads any texel of [lo, hi) (wrapped) of a map `size` texels wide.
bool cellReads(int c, int n, int size, int lo, int hi) {
    int first = 0, last = 0;
    cellTexelRange(c, n, size, first, last);
    for (int i = first; i <= last; ++i) {
        const int w = wrapIndex(i, size);
        if (w >= lo && w < hi)
            return true;
    }
    return false;
}

void storeCell(WeatherCellMaxima& out, int n, int cx, int cz, glm::vec3 maxRaw) {
    const size_t c = (static_cast<size_t>(cz) * n + cx) * 3;
    out.cells[c] = maxRaw.x;
    out.cells[c + 1] = maxRaw.y;
    out.cells[c + 2] = maxRaw.z;
}

// The clearance level a column allows (noise_clearance.glsl.h): the highest level whose threshold
// is at or below the column's lowest coverage threshold (its largest coverage, `bound.x`); none
// where the storm or the data field reshape the base noise or its height fraction, or where the
// threshold is negative (full coverage: any base shape is cloud).
int clearanceLevel(glm::vec2 bound, float rMin, const model::CloudParams& p) {
    if (p.dataFieldEnabled != 0 || (model::stormActive(p) && rMin < 1.0f))
        return -1;
    const float threshold = model::coverageThreshold(bound.x);
    if (threshold < 0.0f)
        return -1;
    const int levels = model::NOISE_CLEARANCE_LEVELS;
    return std::min(static_cast<int>(std::floor(threshold * float(levels))), levels - 1);
}

} // namespace

WeatherCellMaxima weatherCellMaxima(const Texture2D& weather) {
    const int n = model::CLOUD_TOP_GRID;
    WeatherCellMaxima out;
    if (weather.mips.empty() || weather.width <= 0 || weather.height <= 0)
        return out;
    out.map = weather.mips[0].data();
    out.width = weather.width;
    out.height = weather.height;
    out.probe = probeOf(weather);
    out.cells.resize(static_cast<size_t>(n) * n * 3);
    for (int cz = 0; cz < n; ++cz)
        for (int cx = 0; cx < n; ++cx)
            storeCell(out, n, cx, cz, cellMaximum(weather, n, cx, cz));
    return out;
}

void refreshWeatherCells(WeatherCellMaxima& cells, const Texture2D& weather, int x0, int y0, int x1,
                         int y1) {
    const int n = model::CLOUD_TOP_GRID;
    const size_t size = static_cast<size_t>(n) * n * 3;
    if (weather.mips.empty() || cells.map != weather.mips[0].data() ||
        cells.width != weather.width || cells.height != weather.height ||
        cells.cells.size() != size) {
        cells = weatherCellMaxima(weather);
        return;
    }
    for (int cz = 0; cz < n; ++cz) {
        if (!cellReads(cz, n, weather.height, y0, y1))
            continue;
        for (int cx = 0; cx < n; ++cx)
            if (cellReads(cx, n, weather.width, x0, x1))
                storeCell(cells, n, cx, cz, cellMaximum(weather, n, cx, cz));
    }
    cells.probe = probeOf(weather);
}

bool WeatherCellMaxima::isFor(const Texture2D& weather) const {
    const size_t n = static_cast<size_t>(model::CLOUD_TOP_GRID);
    return !weather.mips.empty() && map == weather.mips[0].data() && width == weather.width &&
           height == weather.height && cells.size() == n * n * 3 && probe == probeOf(weather);
}

void fillCloudTopGrid(model::CloudParams& p, const Texture2D& weather,
                      const WeatherCellMaxima* cached) {
    const int n = model::CLOUD_TOP_GRID;
    WeatherCellMaxima made;
    if (!cached || !cached->isFor(weather)) {
        made = weatherCellMaxima(weather);
        cached = &made;
    }
    const std::vector<float>& cells = cached->cells;
    if (cells.empty())
        return; // no map: the grid is left as it was (makeCloudParams asks only with one)
    const float cellMetres = p.weatherExtent / float(n);
    // The storm and data-field tests widen each cell by a weather texel, as the path tracer's
    // grid does.
    const float texelMetres = p.weatherExtent / float(std::min(weather.width, weather.height));
    const glm::vec2 half(0.5f * cellMetres + texelMetres);
    float topMax = model::CLOUD_TOP_EMPTY;
    for (int cz = 0; cz < n; ++cz) {
        for (int cx = 0; cx < n; ++cx) {
            const size_t c = (static_cast<size_t>(cz) * n + cx) * 3;
            const glm::vec3 maxRaw(cells[c], cells[c + 1], cells[c + 2]);
            // The cell's column in world space: weatherUv = (xz - origin) / extent + 0.5.
            const glm::vec2 centre =
                (glm::vec2(float(cx) + 0.5f, float(cz) + 0.5f) / float(n) - glm::vec2(0.5f)) *
                    p.weatherExtent +
                p.weatherOrigin;
            const float rMin = model::stormDistanceBound(centre, half, p);
            const glm::vec4 fieldMax = model::dataFieldMaximum(centre, half, p);
            const glm::vec2 bound = model::columnCloudBound(maxRaw, fieldMax, rMin, p);
            const float top = bound.y;
            const int index = cz * n + cx;
            p.cloudTops[index >> 2][index & 3] = top;
            p.cloudNoiseLevels[index >> 2][index & 3] = float(clearanceLevel(bound, rMin, p));
            topMax = std::max(topMax, top);
        }
    }
    p.cloudTopMax = topMax;
}

} // namespace cloudscape
