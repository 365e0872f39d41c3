// The terrain's geometry: a height field over the planet (TerrainParams), read with bilinear
// interpolation done here in full float precision (so both backends interpolate alike), and a
// per-pixel ray march of it by sphere tracing with the field's Lipschitz bound. The march gives
// the depth the cloud march stops at (pixel.glsl.h) and the point ground.glsl.h shades.
//
// Why a ray-marched height field rather than a rasterised mesh: the renderer has no raster
// pipeline, every pass is a compute pass (or its CPU twin) that already owns the view ray, and a
// march needs nothing but the field itself, identical on both backends.
#ifndef CLOUDSCAPE_MODEL_TERRAIN_GLSL_H
#define CLOUDSCAPE_MODEL_TERRAIN_GLSL_H

#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "sampling.glsl.h"
#include "shell.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// A march sample within HIT_EPSILON + HIT_RELATIVE * t metres above the surface is a hit: the
// float resolution of a position kilometres away, and well under a pixel's footprint.
CONST_FLOAT TERRAIN_HIT_EPSILON = 0.5f;
CONST_FLOAT TERRAIN_HIT_RELATIVE = 0.0005f;
// No step is shorter than this fraction of the distance travelled, so rays grazing gentle
// ground converge in bounded steps; a step that lands below the surface is refined
// (terrainCrossing).
CONST_FLOAT TERRAIN_MIN_STEP_RELATIVE = 0.003f;
CONST_INT TERRAIN_REFINE_STEPS = 8;

// One of the field's per-texel layers (the heights at `base` 0, the light's horizon after the
// cell maxima) at world xz: bilinear between texel centres, clamped at the field's edge texels;
// `outside` beyond the field's extent.
inline float terrainLayerAt(vec2 xz, IN(TerrainParams) T, int base, float outside) {
    vec2 uv = (xz - T.origin) / T.extent + vec2(0.5f);
    if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) {
        return outside;
    }
    vec2 x = uv * vec2(float(T.width), float(T.height)) - vec2(0.5f);
    x = clamp(x, vec2(0.0f), vec2(float(T.width - 1), float(T.height - 1)));
    ivec2 i0 = ivec2(floor(x));
    ivec2 i1 = min(i0 + ivec2(1), ivec2(T.width - 1, T.height - 1));
    vec2 f = x - vec2(i0);
    float a = terrainHeightTexel(base + i0.y * T.width + i0.x);
    float b = terrainHeightTexel(base + i0.y * T.width + i1.x);
    float c = terrainHeightTexel(base + i1.y * T.width + i0.x);
    float d = terrainHeightTexel(base + i1.y * T.width + i1.x);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

// Height (m above the planet's surface) at world xz; beyond the field's extent, the flat planet.
inline float terrainHeightAt(vec2 xz, IN(TerrainParams) T) {
    return terrainLayerAt(xz, T, 0, 0.0f);
}

// The altitude (m) a point above world xz must reach to see the cloud light past the field
// (HeightField's light horizon, when T.lightHorizon is set); beyond the field's extent nothing
// stands in the way.
inline float terrainLightHorizonAt(vec2 xz, IN(TerrainParams) T) {
    return terrainLayerAt(xz, T, T.lightHorizon, -1e30f);
}

// Altitude above the planet in a form that keeps its precision near the surface: the plain
// length(p - centre) - R loses about half a metre in float at Earth's radius.
inline float terrainAltitude(vec3 p, float planetRadius) {
    float horizontal = p.x * p.x + p.z * p.z;
    float fromCentreY = p.y + planetRadius;
    float squaresDifference = horizontal + p.y * (p.y + 2.0f * planetRadius);
    return squaresDifference / (sqrt(horizontal + fromCentreY * fromCentreY) + planetRadius);
}

// Height of p above the terrain below it (negative inside the terrain).
inline float terrainGap(vec3 p, IN(CloudParams) P) {
    return terrainAltitude(p, P.planetRadius) - terrainHeightAt(vec2(p.x, p.z), P.terrain);
}

// Distance along a unit ray to the planet's surface (NO_HIT if it does not descend to it), in
// the cancellation-free form: with C = |o - centre|^2 - R^2 (from terrainAltitude's squares) and
// b = dot(o - centre, dir) < 0, the near root -b - sqrt(b^2 - C) is C / (-b + sqrt(b^2 - C)).
inline float planetSurfaceDistance(vec3 o, vec3 dir, float planetRadius) {
    float fromCentreY = o.y + planetRadius;
    float c = o.x * o.x + o.z * o.z + o.y * (o.y + 2.0f * planetRadius);
    float b = o.x * dir.x + fromCentreY * dir.y + o.z * dir.z;
    float disc = b * b - c;
    if (b >= 0.0f || c <= 0.0f || disc < 0.0f) {
        return NO_HIT;
    }
    return c / (-b + sqrt(disc));
}

// True when a ray at p has left the field's extent and moves away from it: from there on the
// ground is the flat planet.
inline bool leavingTerrain(vec3 p, vec3 dir, IN(TerrainParams) T) {
    vec2 d = vec2(p.x, p.z) - T.origin;
    vec2 halfExtent = 0.5f * T.extent;
    return (d.x > halfExtent.x && dir.x >= 0.0f) || (d.x < -halfExtent.x && dir.x <= 0.0f) ||
           (d.y > halfExtent.y && dir.z >= 0.0f) || (d.y < -halfExtent.y && dir.z <= 0.0f);
}

// ---- Cell maxima: the highest texel over square cells of the field, in levels (built on the
// host by measureHeightField, stored after the field's texels). Level 0's cells span
// TERRAIN_CELL_SPANS texel spans a side (texel-centre coordinates [i s, (i + 1) s], the edge
// cells reaching out to the field's edge), each level's cells twice as wide as the last; the grid
// is padded to a square of T.cellGrid (a power of two) cells at level 0, so level k starts
// terrainCellLevelOffset(k) values after the field. A ray above a cell's maximum cannot meet the
// surface until it leaves the cell or descends to that height: the march skips that far, which
// over gentle ground and beside peaks is much further than the slope's bound allows.
CONST_INT TERRAIN_CELL_SPANS = 4;
// The level a march starts at (it adapts from there).
CONST_INT TERRAIN_CELL_START_LEVEL = 2;

inline int terrainCellLevelOffset(int level, int grid) {
    // sum over j < level of (grid >> j)^2 = ((2 grid)^2 - ((2 grid) >> level)^2) / 3, exact in
    // integers for every level up to one past the top (where grid >> level is already 0).
    int twice = 2 * grid;
    int below = twice >> level;
    return (twice * twice - below * below) / 3;
}

// How far the ray from p (`altitude` above the planet, inside the field's extent) certainly stays
// above the terrain within p's cell at `level`: to where it leaves the cell across its sides or
// descends to the cell's maximum, whichever comes first; 0 when p is not above that maximum.
inline float terrainCellSkip(vec3 p, vec3 dir, float altitude, int level, IN(CloudParams) P) {
    TerrainParams T = P.terrain;
    vec2 size = vec2(float(T.width), float(T.height));
    vec2 x = ((vec2(p.x, p.z) - T.origin) / T.extent + vec2(0.5f)) * size - vec2(0.5f);
    x = clamp(x, vec2(0.0f), size - vec2(1.0f));
    int spans = TERRAIN_CELL_SPANS << level;
    ivec2 last = max(ivec2(T.width - 2, T.height - 2), ivec2(0)) / spans;
    ivec2 cell = min(ivec2(floor(x / float(spans))), last);
    int side = T.cellGrid >> level;
    int index =
        T.width * T.height + terrainCellLevelOffset(level, T.cellGrid) + cell.y * side + cell.x;
    float highest = terrainHeightTexel(index);
    if (altitude <= highest) {
        return 0.0f;
    }
    // The cell's sides in texel-centre coordinates (the edge cells out to the field's edge), then
    // in world metres.
    vec2 lo = vec2(cell * spans);
    vec2 hi = vec2((cell + ivec2(1)) * spans);
    lo.x = cell.x == 0 ? -0.5f : lo.x;
    lo.y = cell.y == 0 ? -0.5f : lo.y;
    hi.x = cell.x == last.x ? size.x - 0.5f : hi.x;
    hi.y = cell.y == last.y ? size.y - 0.5f : hi.y;
    vec2 worldLo = T.origin + ((lo + vec2(0.5f)) / size - vec2(0.5f)) * T.extent;
    vec2 worldHi = T.origin + ((hi + vec2(0.5f)) / size - vec2(0.5f)) * T.extent;
    float exitX = dir.x > 0.0f ? (worldHi.x - p.x) / dir.x
                               : (dir.x < 0.0f ? (worldLo.x - p.x) / dir.x : 3.0e38f);
    float exitZ = dir.z > 0.0f ? (worldHi.y - p.z) / dir.z
                               : (dir.z < 0.0f ? (worldLo.y - p.z) / dir.z : 3.0e38f);
    float exit = max(min(exitX, exitZ), 0.0f);
    return min(exit, descentToAltitude(p, dir, altitude, highest, P.planetRadius));
}

// Over-relaxed sphere tracing (Keinert et al. 2014, "Enhanced Sphere Tracing"): a step goes
// this many bound distances, since a ray approaching a gentle surface sees the bound shrink
// geometrically; where the bounding spheres of a relaxed step and of the point it reached no
// longer overlap, the step may have passed over terrain, so it is taken back and the march goes
// on unrelaxed from there, exactly as plain sphere tracing would.
CONST_FLOAT TERRAIN_RELAXATION = 1.6f;

// Where a terrain march ended: `hit` the distance along the ray (NO_HIT for a miss); where the
// last step went below the surface (`overshot`), the crossing lies between `above`, the last
// point over it, and `hit`.
struct TerrainMarchEnd {
    float hit;
    bool overshot;
    float above;
};

// The march proper: the distance along a unit ray to the terrain (NO_HIT if it misses, or with
// the terrain off), unrefined, and its steps in `steps`; relaxation 1 is plain sphere tracing.
// The gap above the surface divided by the Lipschitz bound sqrt(1 + s^2) is a distance the ray
// can travel without reaching the surface (sphere tracing, over-relaxed as above); with `cells`,
// a step goes at least as far as terrainCellSkip allows at the march's current level of cells,
// which climbs after a skip and falls after a cell the ray is not above (as in Tevs et al. 2008,
// "Maximum Mipmaps for Fast, Accurate, and Scalable Dynamic Height Field Rendering"). The march
// starts where the ray descends below the field's highest texel and ends where it leaves that
// ceiling, or analytically on the flat planet once it has left the field's extent. The loop only
// finds where the march ends; refining an overshot crossing comes after it (terrainMarch), so a
// SIMD device that runs every side of a branch (lavapipe) does not pay for it each step, and a
// shadow ray, which only asks whether there is a crossing, not at all.
inline TerrainMarchEnd terrainMarchCoarse(vec3 origin, vec3 dir, IN(CloudParams) P,
                                          float relaxation, bool cells, OUT(int) steps) {
    steps = 0;
    TerrainMarchEnd e;
    e.hit = NO_HIT;
    e.overshot = false;
    e.above = 0.0f;
    if (!terrainOn(P)) {
        return e;
    }
    vec3 centre = planetCentre(P.planetRadius);
    vec2 ceiling = raySphere(origin, dir, centre, P.planetRadius + P.terrain.maxHeight + 1.0f);
    if (ceiling.y <= 0.0f) {
        return e;
    }
    float t = max(ceiling.x, 0.0f);
    float end = ceiling.y;
    float previous = t;
    float previousRadius = 0.0f; // the bound distance at `previous`
    float stepLength = 0.0f;
    bool relaxed = true;      // relaxation still allowed on this ray
    bool lastRelaxed = false; // the last step went further than plain sphere tracing's
    int topLevel = cells ? P.terrain.cellLevels - 1 : -1;
    int level = min(TERRAIN_CELL_START_LEVEL, topLevel);
    for (int i = 0; i < P.terrain.maxSteps; ++i) {
        steps = i + 1;
        vec3 p = origin + dir * t;
        float altitude = terrainAltitude(p, P.planetRadius);
        float gap = altitude - terrainHeightAt(vec2(p.x, p.z), P.terrain);
        float radius = gap / P.terrain.lipschitz;
        if (lastRelaxed && abs(radius) + previousRadius < stepLength) {
            // Back to the last point, and on unrelaxed: what plain tracing steps from there.
            relaxed = false;
            lastRelaxed = false;
            t = min(previous + max(previousRadius, TERRAIN_MIN_STEP_RELATIVE * previous), end);
            continue;
        }
        if (gap < TERRAIN_HIT_EPSILON + TERRAIN_HIT_RELATIVE * t) {
            e.hit = t;
            // A step that went below the surface: the crossing lies between the last point
            // above it and t.
            e.overshot = gap < 0.0f && i > 0;
            e.above = previous;
            break;
        }
        if (t >= end) {
            break;
        }
        if (leavingTerrain(p, dir, P.terrain)) {
            e.hit = planetSurfaceDistance(origin, dir, P.planetRadius);
            break;
        }
        float plain = max(radius, TERRAIN_MIN_STEP_RELATIVE * t);
        stepLength = relaxed ? max(relaxation * radius, plain) : plain;
        lastRelaxed = stepLength > plain;
        if (level >= 0) {
            float skip = terrainCellSkip(p, dir, altitude, level, P);
            if (skip > stepLength) {
                // A safe step: past the cell's side by the hit tolerance (a landing below the
                // surface there is refined back like any other).
                stepLength = skip + TERRAIN_HIT_EPSILON + TERRAIN_HIT_RELATIVE * t;
                lastRelaxed = false;
            }
            level = skip > 0.0f ? min(level + 1, topLevel) : max(level - 1, 0);
        }
        previous = t;
        previousRadius = radius;
        t = min(t + stepLength, end);
    }
    return e;
}

// The crossing inside an overshot march's bracket, by bisection: the point below the surface
// when the bracket is TERRAIN_REFINE_STEPS halvings narrow. (False position took fewer steps on
// smooth ground but stalled beside cliffs, ten times outside the hit tolerance.)
inline float terrainCrossing(vec3 origin, vec3 dir, IN(TerrainMarchEnd) e, IN(CloudParams) P) {
    float above = e.above;
    float below = e.hit;
    for (int k = 0; k < TERRAIN_REFINE_STEPS; ++k) {
        float mid = 0.5f * (above + below);
        if (terrainGap(origin + dir * mid, P) < 0.0f) {
            below = mid;
        } else {
            above = mid;
        }
    }
    return below;
}

// Distance along a unit ray to the terrain (NO_HIT if it misses, or with the terrain off), and
// the march's steps in `steps`: terrainMarchCoarse, its overshoot refined.
inline float terrainMarch(vec3 origin, vec3 dir, IN(CloudParams) P, float relaxation, bool cells,
                          OUT(int) steps) {
    TerrainMarchEnd e = terrainMarchCoarse(origin, dir, P, relaxation, cells, steps);
    return e.overshot ? terrainCrossing(origin, dir, e, P) : e.hit;
}

inline float terrainHitDistance(vec3 origin, vec3 dir, IN(CloudParams) P) {
    int steps = 0;
    return terrainMarch(origin, dir, P, TERRAIN_RELAXATION, true, steps);
}

// Whether a unit ray from origin meets the terrain at all (a shadow ray: no crossing refined).
inline bool terrainBlocks(vec3 origin, vec3 dir, IN(CloudParams) P) {
    int steps = 0;
    return terrainMarchCoarse(origin, dir, P, TERRAIN_RELAXATION, true, steps).hit != NO_HIT;
}

// The surface normal at world xz, from central differences one texel apart, tilted with the
// planet's local vertical `up`.
inline vec3 terrainNormal(vec2 xz, vec3 up, IN(TerrainParams) T) {
    float dx = T.extent.x / float(T.width);
    float dz = T.extent.y / float(T.height);
    float sx = (terrainHeightAt(xz + vec2(dx, 0.0f), T) - terrainHeightAt(xz - vec2(dx, 0.0f), T)) /
               (2.0f * dx);
    float sz = (terrainHeightAt(xz + vec2(0.0f, dz), T) - terrainHeightAt(xz - vec2(0.0f, dz), T)) /
               (2.0f * dz);
    return normalize(up + vec3(-sx, 0.0f, -sz));
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
