#include "pathtrace/cloud_medium.h"

#include "cpu/cpu_model.h"
#include "model/cloud_bound.glsl.h"
#include "model/data_field.glsl.h"
#include "model/lightning.glsl.h"

#include <cloudscape/weather.h>

#include <algorithm>

namespace cloudscape::pathtrace {
namespace {

// Column cells of about this size: small enough to follow the coverage pattern of cumulus
// fields, large enough that a ray through the shell crosses few of them.
constexpr float kTargetCellMetres = 800.0f;

} // namespace

CloudMedium::CloudMedium(const model::CloudParams& params, glm::vec3 cameraPosition,
                         const Texture2D& weather)
    : params_(params), phase_(model::cloudPhaseFunction(params)), camera_(cameraPosition),
      texelsX_(weather.width), texelsZ_(weather.height) {
    emits_ = emitsLight(params);
    texelMetres_ = params.weatherExtent / float(std::max(texelsX_, texelsZ_));
    // The largest common divisor of both sizes whose cells stay within the target size, so
    // that the cells tile the wrapping map exactly.
    cellTexels_ = 1;
    for (int k = 1; k <= std::min(texelsX_, texelsZ_); ++k)
        if (texelsX_ % k == 0 && texelsZ_ % k == 0 && float(k) * texelMetres_ <= kTargetCellMetres)
            cellTexels_ = k;
    cellsX_ = texelsX_ / cellTexels_;
    cellsZ_ = texelsZ_ / cellTexels_;
    cells_.resize(static_cast<size_t>(cellsX_) * cellsZ_);

    for (int cz = 0; cz < cellsZ_; ++cz) {
        for (int cx = 0; cx < cellsX_; ++cx) {
            // Bilinear reads at texel coordinates in [c k, (c + 1) k] touch texels c k ..
            // (c + 1) k + 1 at most (the +1 covers the upper neighbour at the cell's far edge).
            // The largest raw values (coverage field, precipitation, type) of the texels.
            glm::vec3 maxRaw(0.0f);
            for (int j = cz * cellTexels_; j <= (cz + 1) * cellTexels_ + 1; ++j) {
                for (int i = cx * cellTexels_; i <= (cx + 1) * cellTexels_ + 1; ++i) {
                    const float* t = weather.texel(0, wrap(i, texelsX_), wrap(j, texelsZ_));
                    maxRaw = glm::max(maxRaw, glm::vec3(coverageFieldOf(t), t[1], t[2]));
                }
            }
            // The model's column bound (model/cloud_bound.glsl.h, which the real-time march's
            // empty-space grid also uses), at the cell's nearest distance to the storm.
            glm::vec2 centre, half;
            cellRectangle(cx, cz, centre, half);
            const glm::vec2 bound =
                model::columnCloudBound(maxRaw, model::dataFieldMaximum(centre, half, params),
                                        model::stormDistanceBound(centre, half, params), params);
            Cell& c = cells_[static_cast<size_t>(cz) * cellsX_ + cx];
            c.sigmaMax = bound.x * params.extinction;
            c.topAltitude = bound.y;
        }
    }
}

void CloudMedium::cellRectangle(int cx, int cz, glm::vec2& centre, glm::vec2& half) const {
    // The cell's column in world space (the copy nearest the map's origin: texel coordinate t
    // is at ((t + 0.5) / n - 0.5) extent + origin), widened by a texel for rounding; the storm's
    // offset and the data field wrap with the map, so one copy stands for all.
    const float extent = params_.weatherExtent;
    const glm::vec2 texel(extent / float(texelsX_), extent / float(texelsZ_));
    const glm::vec2 centreTexel((float(cx) + 0.5f) * float(cellTexels_) + 0.5f,
                                (float(cz) + 0.5f) * float(cellTexels_) + 0.5f);
    centre = params_.weatherOrigin + centreTexel * texel - glm::vec2(0.5f * extent);
    half = (0.5f * float(cellTexels_) + 1.0f) * texel;
}

glm::ivec2 CloudMedium::cellIndexAt(float x, float z) const {
    return {static_cast<int>(std::floor(texelX(x) / float(cellTexels_))),
            static_cast<int>(std::floor(texelZ(z) / float(cellTexels_)))};
}

bool CloudMedium::emitsLight(const model::CloudParams& params) {
    const bool glow = model::stormActive(params) && params.stormGlowRadius > 0.0f &&
                      params.stormBlend > 0.0f &&
                      glm::any(glm::greaterThan(params.stormGlow, glm::vec3(0.0f)));
    const bool flash = model::lightningOn(params) && params.lightning.flashIntensity > 0.0f &&
                       params.lightning.flashRadius > 0.0f;
    return glow || flash;
}

glm::vec3 CloudMedium::emission(glm::vec3 p) const {
    if (!emits_)
        return glm::vec3(0.0f);
    // The march's arguments: the layer's height fraction and the full (eroded) density, before
    // the horizon fade (which sigmaT carries, as the march's step weight does).
    const model::DensityContext ctx = model::densityContextAt(p, params_);
    const float density = model::cloudDensity(ctx, 0.0f, false, params_);
    if (density <= 0.0f)
        return glm::vec3(0.0f);
    return model::stormEmissionLit(p, ctx.heightFraction, density, params_);
}

float CloudMedium::sigmaT(glm::vec3 p) const {
    // The full-resolution density (mip 0, full erosion) of the shared model, with the same
    // horizon fade the real-time march applies, so both see one medium.
    const float density = model::cloudDensityAt(p, 0.0f, false, params_);
    if (density <= 0.0f)
        return 0.0f;
    return model::extinctionOf(density, params_) *
           model::distanceFade(glm::length(p - camera_), params_);
}

} // namespace cloudscape::pathtrace
