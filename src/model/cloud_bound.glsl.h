// Where cloud can exist: an upper bound on the density of a column of the cloud layer from the
// weather alone, shared by the path tracer's majorant grid (src/pathtrace/cloud_medium.cpp) and
// the real-time march's empty-space skipping (march.glsl.h, over P.cloudTops).
//
// Why the bound holds: the density is coverage * shaped * (erosion), where shaped and the
// erosion remap are in [0, 1] and the erosion never raises a value, so density <= coverage; and
// density is zero above where the height profile of the cloud type falls to the coverage
// threshold (profileTopAbove), which rises with the type and the coverage. The weather map is read
// bilinearly (a convex combination of four texels; the coverage field's decoding is linear) at the
// point itself (no distortion), and the model's mapping (weatherFromRaw: coverage bias, type
// offset, precipitation rule) is monotonic in the map's values; so are the storm's masks in the
// distance to its centre (stormWeatherBound). So over a region, the largest raw values of the
// texels its bilinear footprint touches, pushed through that mapping at the region's nearest
// distance to the storm, bound the density everywhere in the region's column. The horizon fade only
// lowers it. The high-altitude layer and the terrain add no density to the layer (the one is a 2D
// shell drawn apart, the other only ends rays).
#ifndef CLOUDSCAPE_MODEL_CLOUD_BOUND_GLSL_H
#define CLOUDSCAPE_MODEL_CLOUD_BOUND_GLSL_H

#include "compat.glsl.h"
#include "data_field.glsl.h"
#include "density.glsl.h"
#include "params.glsl.h"
#include "profiles.glsl.h"
#include "shell.glsl.h"
#include "storm.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Margin on a column's cloud top, for the float rounding of altitudes at planet scale.
CONST_FLOAT CLOUD_TOP_MARGIN = 20.0f;
// The top of a column that holds no cloud at all (below every altitude a sample can have).
CONST_FLOAT CLOUD_TOP_EMPTY = -1.0e9f;

// The inverse of smoothstep(0, 1, u) = s for s in [0, 1] (the cubic's root in [0, 1]).
inline float inverseSmoothstep(float s) {
    return 0.5f - sin(asin(1.0f - 2.0f * saturate(s)) / 3.0f);
}

// Height fraction above which a column of cloud type at most `type` and coverage at most
// `coverage` holds no cloud: the base shape is at most 1, so density needs the profile above
// coverageThreshold (density.glsl.h). The profile (the split profile too) is its rise, at most 1,
// times its fall, 1 - smoothstep(z, w, h), which grows with the type (both z and w rise with
// it); so the column is empty where the largest type's fall is at or below the threshold.
// 0.002 of the layer (13 m at the default depth) of margin covers the inverse's rounding.
inline float profileTopAbove(float type, float coverage) {
    vec4 profile = profileForType(type);
    float threshold = coverageThreshold(coverage);
    if (threshold <= 0.0f) {
        return profile.w;
    }
    float fallen = profile.z + (profile.w - profile.z) * inverseSmoothstep(1.0f - threshold);
    return min(fallen + 0.002f, profile.w);
}

// Bound on a column whose weather texels' largest raw values (coverage field, precipitation,
// type) are maxRaw, whose data field's largest values are fieldMax (dataFieldMaximum) and whose
// nearest point lies rMin storm radii from the storm's centre (2 or more: outside the storm):
// x the largest density (coverage), y the altitude (m) above which the column is empty
// (CLOUD_TOP_EMPTY where x is 0).
inline vec2 columnCloudBound(vec3 maxRaw, vec4 fieldMax, float rMin, IN(CloudParams) P) {
    vec3 weather = weatherFromRaw(maxRaw, P.coverageBias, P.typeOffset);
    // A storm raises coverage and type toward its centre and adds the anvil's flipped profile,
    // which reaches the top of the region's layer; so does the data field's anvil coverage.
    vec3 stormed = stormWeatherBound(weather, rMin, P);
    float anvil = max(stormed.z, fieldMax.y);
    float coverage = min(max(stormed.x, anvil), 1.0f);
    if (coverage <= 0.0f) {
        return vec2(0.0f, CLOUD_TOP_EMPTY);
    }
    float topFraction = anvil > 0.0f ? 1.0f : profileTopAbove(stormed.y, stormed.x);
    // The region's layer [lo, hi] puts the profile's top t at lo (1 - t) + hi t, which grows
    // with both, so the largest base (the field's, or the storm's raised base) and top bound it.
    float lo = max(fieldMax.z, rMin < 1.0f ? STORM_BASE_RISE * P.stormBlend : 0.0f);
    float hi = regionTop(lo, fieldMax.w);
    float top = lo * (1.0f - topFraction) + hi * topFraction;
    return vec2(coverage, P.layerBottom + top * (P.layerTop - P.layerBottom) + CLOUD_TOP_MARGIN);
}

// Lower bound of the distance, in storm radii, from an axis-aligned world rectangle (centre and
// half size in xz, metres) to the storm's centre; 2 with no storm. The storm wraps with the
// weather map, so the rectangle must be small against the map.
inline float stormDistanceBound(vec2 centre, vec2 halfSize, IN(CloudParams) P) {
    if (!stormActive(P)) {
        return 2.0f;
    }
    vec2 gap = max(abs(stormOffset(centre, P)) - halfSize, vec2(0.0f, 0.0f));
    return length(gap) / P.stormRadius;
}

// The march's grid of column tops (P.cloudTops, CLOUD_TOP_GRID^2 cells tiling the weather map,
// four to a vec4): the cell holding world xz, in unwrapped integer coordinates.
inline ivec2 cloudTopCell(vec2 xz, IN(CloudParams) P) {
    vec2 cell = floor(weatherUv(xz, P) * float(CLOUD_TOP_GRID));
    return ivec2(int(cell.x), int(cell.y));
}

// A cell's top altitude (m). CLOUD_TOP_GRID is a power of two, so & wraps negative indices too.
// GLSL reads the cell from the parameter block itself (cloudTopTexel, sampling.glsl.h), not from
// P: P is a by-value copy there, and a dynamically indexed array in a copy is a 4 KB local array
// per invocation, which llvmpipe keeps in scratch memory (the lavapipe march took 7x longer).
inline float cloudTopOf(ivec2 cell, IN(CloudParams) P) {
    int x = cell.x & (CLOUD_TOP_GRID - 1);
    int z = cell.y & (CLOUD_TOP_GRID - 1);
    int index = z * CLOUD_TOP_GRID + x;
#ifdef __cplusplus
    return P.cloudTops[index >> 2][index & 3];
#else
    return cloudTopTexel(index);
#endif
}

// Distance along a unit ray from p to where it leaves cell's column (>= 0).
inline float cloudTopCellExit(vec3 p, vec3 dir, ivec2 cell, IN(CloudParams) P) {
    float size = P.weatherExtent / float(CLOUD_TOP_GRID);
    vec2 low = (vec2(float(cell.x), float(cell.y)) / float(CLOUD_TOP_GRID) - vec2(0.5f, 0.5f)) *
                   P.weatherExtent +
               P.weatherOrigin;
    float exitX = 3.0e38f;
    float exitZ = 3.0e38f;
    if (dir.x != 0.0f) {
        exitX = ((dir.x > 0.0f ? low.x + size : low.x) - p.x) / dir.x;
    }
    if (dir.z != 0.0f) {
        exitZ = ((dir.z > 0.0f ? low.y + size : low.y) - p.z) / dir.z;
    }
    return max(min(exitX, exitZ), 0.0f);
}

// Empty-space skipping: the distance along a unit ray from a sample at p (altitude `altitude`)
// over which the cloud-top grid proves the density zero; 0 where p's column may hold cloud at
// p's altitude. A ray that rises above the highest top (P.cloudTopMax) never meets cloud again
// (3e38). Reads no texture.
inline float provablyEmptyDistance(vec3 p, vec3 dir, float altitude, IN(CloudParams) P) {
    if (altitude >= P.cloudTopMax) {
        if (P.cloudTopMax <= CLOUD_TOP_EMPTY ||
            dot(p - planetCentre(P.planetRadius), dir) >= 0.0f) {
            return 3.0e38f;
        }
        return descentToAltitude(p, dir, altitude, P.cloudTopMax, P.planetRadius);
    }
    ivec2 cell = cloudTopCell(vec2(p.x, p.z), P);
    float top = cloudTopOf(cell, P);
    if (altitude < top) {
        return 0.0f;
    }
    float exit = cloudTopCellExit(p, dir, cell, P);
    if (top > CLOUD_TOP_EMPTY) {
        exit = min(exit, descentToAltitude(p, dir, altitude, top, P.planetRadius));
    }
    return exit;
}

// provablyEmptyDistance where the scene skips empty space (march.empty_space_skipping), else 0:
// what a march along dir from p may skip without reading a texture.
inline float skippableDistance(vec3 p, vec3 dir, IN(CloudParams) P) {
    if (P.emptySpaceSkipping == 0) {
        return 0.0f;
    }
    return provablyEmptyDistance(p, dir, altitudeOf(p, P.planetRadius), P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
