#include "core/cloud_top_grid.h"

#include "model/cloud_bound.glsl.h"

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

} // namespace

void fillCloudTopGrid(model::CloudParams& p, const Texture2D& weather) {
    const int n = model::CLOUD_TOP_GRID;
    const float cellMetres = p.weatherExtent / float(n);
    // The storm test widens each cell by a weather texel, as the path tracer's grid does.
    const float texelMetres = p.weatherExtent / float(std::min(weather.width, weather.height));
    const glm::vec2 half(0.5f * cellMetres + texelMetres);
    float topMax = model::CLOUD_TOP_EMPTY;
    for (int cz = 0; cz < n; ++cz) {
        int j0 = 0, j1 = 0;
        cellTexelRange(cz, n, weather.height, j0, j1);
        for (int cx = 0; cx < n; ++cx) {
            int i0 = 0, i1 = 0;
            cellTexelRange(cx, n, weather.width, i0, i1);
            glm::vec3 maxRaw(0.0f);
            for (int j = j0; j <= j1; ++j) {
                for (int i = i0; i <= i1; ++i) {
                    const float* t =
                        weather.texel(0, wrapIndex(i, weather.width), wrapIndex(j, weather.height));
                    maxRaw = glm::max(maxRaw, glm::vec3(coverageFieldOf(t), t[1], t[2]));
                }
            }
            // The cell's column in world space: weatherUv = (xz - origin) / extent + 0.5.
            const glm::vec2 centre =
                (glm::vec2(float(cx) + 0.5f, float(cz) + 0.5f) / float(n) - glm::vec2(0.5f)) *
                    p.weatherExtent +
                p.weatherOrigin;
            const float rMin = model::stormDistanceBound(centre, half, p);
            const float top = model::columnCloudBound(maxRaw, rMin, p).y;
            const int index = cz * n + cx;
            p.cloudTops[index >> 2][index & 3] = top;
            topMax = std::max(topMax, top);
        }
    }
    p.cloudTopMax = topMax;
}

} // namespace cloudscape
