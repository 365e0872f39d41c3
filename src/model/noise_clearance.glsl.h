// The base noise's clearance field: for a few thresholds, how far each part of the base noise
// lies from the nearest texel whose base shape could exceed the threshold, so that the march
// passes over stretches where the weather allows cloud and the noise has none without sampling
// them (the distance field of Schneider's "Nubis cubed", GDC 2023, made exact for our sampler).
//
// Why a skip is exact: where there is no storm and no data field, a sample has cloud only where
// baseShape * profile > coverageThreshold(coverage) (density.glsl.h: coveredShape), with the
// profile at most 1; so a base shape at most t, with t at or below the threshold everywhere the
// skip reaches (cloudNoiseLevels: the column's lowest threshold), proves the sample empty.
// baseShapeAt is saturate((x + fbm - 1) / fbm) of the filtered texel (x the Perlin-Worley
// channel, fbm baseNoiseFbm of the others), and (x + fbm - 1) / fbm <= t is the linear
// x + (1 - t) fbm <= 1: a convex combination of texels that meet it meets it too. Every read the
// march makes (trilinear, and between mip levels, whose texels are box averages of level 0's) is
// such a combination of level-0 texels within readReach of the read, give or take the 8-bit
// rounding of the levels and of the filter, which NOISE_CLEARANCE_MARGIN absorbs. So a read whose
// level-0 texels all lie further than readReach from every texel that may exceed t gives a base
// shape of at most t.
//
// Layout (the host builds it, src/generators/noise_clearance.cpp): the noise's size / CELL cells
// along each side, cell (x, y, z) at texel ((z * cells + y) * cells + x) * 2 + level / 4, whose
// byte level % 4 holds the cell's Chebyshev distance, in cells, to the nearest cell holding a
// texel that may exceed level / NOISE_CLEARANCE_LEVELS (0: the cell holds one), at most 255.
#ifndef CLOUDSCAPE_MODEL_NOISE_CLEARANCE_GLSL_H
#define CLOUDSCAPE_MODEL_NOISE_CLEARANCE_GLSL_H

#include "cloud_bound.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_INT NOISE_CLEARANCE_CELL = 2;   // base-noise texels along each side of a cell
CONST_INT NOISE_CLEARANCE_LEVELS = 8; // thresholds level / LEVELS, level 0 .. LEVELS - 1
// The 8-bit rounding a read can add to x + (1 - t) fbm: a mip level's texel is rounded from the
// average of unrounded texels (1 / 255 a channel), and the filter rounds (taken as 1 / 255 a
// channel: the CPU sampler's floats do not, lavapipe's 8-bit filter does about that; Vulkan
// does not bound it); fbm's weights sum to 1, so 4 / 255 in all and 6 / 255 leaves a third to
// spare.
CONST_FLOAT NOISE_CLEARANCE_MARGIN = 6.0f / 255.0f;
// Texels of slack for the float rounding of the lookup's position. A GPU also snaps a read to
// 1/256 of a texel of its mip level (2^L / 256 level-0 texels, more than this from level 4 up);
// a texel snapped into reach that way weighs at most 1/256, which the margin's spare third covers.
CONST_FLOAT NOISE_CLEARANCE_SLACK = 0.05f;

// Metres short of the column's edge and top where a skip ends: a sample's altitude is rounded to
// about a metre at planet scale (altitudeOf) and its position to millimetres, so no passed sample
// may reach the next column or the top in the grid's eyes.
CONST_FLOAT CLEARANCE_CUT_MARGIN = 10.0f;

// The field's words for a base noise `size` texels along each side (two a cell).
inline int noiseClearanceWords(int size) {
    int cells = size / NOISE_CLEARANCE_CELL;
    return cells * cells * cells * 2;
}

// Whether a level-0 texel of the base noise may give a base shape above `threshold`.
inline bool noiseTexelMayExceed(vec4 texel, float threshold) {
    return texel.x + (1.0f - threshold) * baseNoiseFbm(texel) > 1.0f - NOISE_CLEARANCE_MARGIN;
}

#ifndef __cplusplus
// GLSL: cell `index` of CloudParams.cloudNoiseLevels, from the shader's parameter block (as
// cloudTopTexel, cloud_bound.glsl.h).
float cloudNoiseLevelTexel(int index);
#endif

// A column's clearance level (CloudParams.cloudNoiseLevels), -1 for none.
inline int cloudNoiseLevelOf(ivec2 cell, IN(CloudParams) P) {
    int x = cell.x & (CLOUD_TOP_GRID - 1);
    int z = cell.y & (CLOUD_TOP_GRID - 1);
    int index = z * CLOUD_TOP_GRID + x;
#ifdef __cplusplus
    return int(P.cloudNoiseLevels[index >> 2][index & 3]);
#else
    return int(cloudNoiseLevelTexel(index));
#endif
}

// A lower bound, in texels, of the Chebyshev distance from any point of a cell to the centre of
// a texel in a cell `cells` cells away (texel centres sit half a texel inside their cell).
inline float clearanceTexels(uint cells) {
    return cells == 0u ? 0.0f : float(cells - 1u) * float(NOISE_CLEARANCE_CELL) + 0.5f;
}

// How far (texels, Chebyshev) from a read at mip level `lod` the level-0 texels lie that its
// value mixes: a bilinear read of level L mixes its texels whose centres lie within 2^L of it,
// each the average of level-0 texels within 2^(L-1) - 0.5 of its centre; a fractional level
// mixes the next one too.
inline float readReach(float lod) {
    return 1.5f * exp2(ceil(lod)) - 0.5f;
}

// Metres along the unit ray from p (t metres from the eye, where one pixel subtends pixelAngle)
// over which every base-noise read the march makes gives a base shape at or below its column's
// clearance threshold, so every sample there is empty; 0 where nothing is proven. The skip ends
// at the column's edge, since the level is the column's. P.noiseClearanceSize is 0 unless the
// field is bound and the columns' levels are filled (makeCloudParams); a pipeline built without
// FEATURE_NOISE_SKIPPING has none of this code.
inline float noiseClearDistance(vec3 p, vec3 dir, float t, float pixelAngle, IN(CloudParams) P) {
    if (!featureCompiled(FEATURE_NOISE_SKIPPING) || !noiseSkippingWanted(P)) {
        return 0.0f;
    }
    ivec2 column = cloudTopCell(vec2(p.x, p.z), P);
    int level = cloudNoiseLevelOf(column, P);
    if (level < 0) {
        return 0.0f;
    }
    float size = float(P.noiseClearanceSize);
    int cells = P.noiseClearanceSize / NOISE_CLEARANCE_CELL;
    vec3 basePos = animatedBasePosition(p, heightFractionAt(p, P), P);
    vec3 u = fract(basePos / P.baseNoisePeriod) * size;
    ivec3 c = clamp(ivec3(floor(u / float(NOISE_CLEARANCE_CELL))), ivec3(0, 0, 0),
                    ivec3(cells - 1, cells - 1, cells - 1));
    uint word = noiseClearanceTexel(((c.z * cells + c.y) * cells + c.x) * 2 + (level >> 2));
    uint away = (word >> uint(8 * (level & 3))) & 255u;
    float clear = clearanceTexels(away) - NOISE_CLEARANCE_SLACK;
    if (clear <= 1.0f) {
        return 0.0f; // not even a read at level 0 is clear
    }
    // Texels the lookup moves a metre along the ray: the ray's own and the wind shear's, whose
    // height fraction changes by at most 1 / (the layer's depth) a metre.
    float shear = abs(P.windShear) * length(P.windDirection) / (P.layerTop - P.layerBottom);
    float speed = size / P.baseNoisePeriod * (1.0f + shear);
    // The farthest read of the skip has the coarsest level (the LOD grows with distance).
    float reach = readReach(distanceLod((t + clear / speed) * pixelAngle, P.log2BaseTexel, P));
    float span = (clear - reach) / speed;
    // The skip must not pass a sample the cloud-top grid would have skipped instead (its skip
    // moves the cursor differently): it ends at the column's edge and below the column's top.
    float altitude = altitudeOf(p, P.planetRadius);
    float belowTop = ascentToAltitude(p, dir, altitude, cloudTopOf(column, P), P.planetRadius);
    span = min(span, min(cloudTopCellExit(p, dir, column, P), belowTop) - CLEARANCE_CUT_MARGIN);
    return max(span, 0.0f);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
