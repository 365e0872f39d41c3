// The Nubis data field's extra channels (Schneider, "Nubis, evolved", GDC 2022): besides the
// weather map's coverage, precipitation and (top) type, each region of the map has
//   x  a bottom type: 0 the type's own bottom gradient .. 1 relaxed into a ragged, wispy underside
//   y  a superstorm (anvil) coverage: the coverage of the flipped profile that spreads the top
//   z  a minimum height: the clouds' base, as a fraction of the layer's depth (0 the layer bottom)
//   w  a maximum height: the clouds' top, as a fraction of the layer's depth (1 the layer top)
// The vertical profile is evaluated in the region's own layer [z, w] (regionHeightFraction) as
// the product of the bottom gradient (by the bottom type) and the top gradient (by the type).
//
// The field is DATA_FIELD_GRID^2 regions tiling the weather map (about 940 m each over the
// default 60 km map), read bilinearly; it lives in the parameter block (CloudParams.dataField),
// so a change of it uploads no texture. The host makes it (generateDataField: noises; or a
// painted image, loadDataFieldImage), and the model composites the storm's stencil over it per
// sample (densityContextAt): the storm's bottom type, anvil and raised base take the maximum with
// the field's. A neutral field (0, 0, 0, 1) everywhere is switched off (FEATURE_DATA_FIELD), which
// is exactly the model without it.
#ifndef CLOUDSCAPE_MODEL_DATA_FIELD_GLSL_H
#define CLOUDSCAPE_MODEL_DATA_FIELD_GLSL_H

#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The thinnest region layer (fraction of the layer's depth): a maximum height below the minimum
// plus this is raised to it, so the profile never divides by zero.
CONST_FLOAT DATA_FIELD_MIN_DEPTH = 0.05f;

inline vec4 neutralDataField() {
    return vec4(0.0f, 0.0f, 0.0f, 1.0f);
}

#ifndef __cplusplus
// GLSL: each shader reads the cells from its parameter block (as cloudTopTexel, cloud_bound.glsl.h
// says why not from the by-value P).
vec4 dataFieldTexel(int index);
#endif

// Region (i, j) of the grid, wrapped (DATA_FIELD_GRID is a power of two, so & wraps negatives).
inline vec4 dataFieldCell(int i, int j, IN(CloudParams) P) {
    int index = (j & (DATA_FIELD_GRID - 1)) * DATA_FIELD_GRID + (i & (DATA_FIELD_GRID - 1));
#ifdef __cplusplus
    return P.dataField[index];
#else
    return dataFieldTexel(index);
#endif
}

// The field at world xz: bilinear between region centres, wrapping with the weather map (whose
// uv it shares: (xz - origin) / extent + 0.5). Neutral where the field is off.
inline vec4 dataFieldAt(vec2 xz, IN(CloudParams) P) {
    if (!dataFieldOn(P)) {
        return neutralDataField();
    }
    vec2 t =
        ((xz - P.weatherOrigin) / P.weatherExtent + vec2(0.5f, 0.5f)) * float(DATA_FIELD_GRID) -
        vec2(0.5f, 0.5f);
    vec2 cell = floor(t);
    vec2 f = t - cell;
    int i = int(cell.x);
    int j = int(cell.y);
    vec4 low = mix(dataFieldCell(i, j, P), dataFieldCell(i + 1, j, P), f.x);
    vec4 high = mix(dataFieldCell(i, j + 1, P), dataFieldCell(i + 1, j + 1, P), f.x);
    return mix(low, high, f.y);
}

// The region's top, kept at least DATA_FIELD_MIN_DEPTH above its base.
inline float regionTop(float minHeight, float maxHeight) {
    return max(maxHeight, minHeight + DATA_FIELD_MIN_DEPTH);
}

// A height fraction of the layer measured in the region's own layer [minHeight, maxHeight]:
// 0 at and below its base, 1 at and above its top. Exactly the layer's at (0, 1).
inline float regionHeightFraction(float heightFraction, float minHeight, float maxHeight) {
    if (minHeight <= 0.0f && maxHeight >= 1.0f) {
        return heightFraction;
    }
    float top = regionTop(minHeight, maxHeight);
    return saturate((heightFraction - minHeight) / (top - minHeight));
}

// The largest value of each channel that dataFieldAt can return anywhere in an axis-aligned
// world rectangle (centre and half size in xz, m), for the column bounds (cloud_bound.glsl.h):
// the maximum over every region a bilinear read there can touch, plus one on each side for the
// rounding of the lookup. The rectangle must be small against the map.
inline vec4 dataFieldMaximum(vec2 centre, vec2 halfSize, IN(CloudParams) P) {
    if (!dataFieldOn(P)) {
        return neutralDataField();
    }
    vec2 scale = vec2(float(DATA_FIELD_GRID), float(DATA_FIELD_GRID)) / P.weatherExtent;
    vec2 lo = (centre - halfSize - P.weatherOrigin) * scale +
              vec2(0.5f, 0.5f) * float(DATA_FIELD_GRID) - vec2(0.5f, 0.5f);
    vec2 hi = (centre + halfSize - P.weatherOrigin) * scale +
              vec2(0.5f, 0.5f) * float(DATA_FIELD_GRID) - vec2(0.5f, 0.5f);
    int i0 = int(floor(lo.x)) - 1;
    int j0 = int(floor(lo.y)) - 1;
    int i1 = min(int(floor(hi.x)) + 2, i0 + DATA_FIELD_GRID - 1);
    int j1 = min(int(floor(hi.y)) + 2, j0 + DATA_FIELD_GRID - 1);
    vec4 m = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            m = max(m, dataFieldCell(i, j, P));
        }
    }
    return m;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
