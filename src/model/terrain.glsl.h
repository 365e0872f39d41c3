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
// ground converge in bounded steps; a step that lands below the surface is refined by bisection.
CONST_FLOAT TERRAIN_MIN_STEP_RELATIVE = 0.003f;
CONST_INT TERRAIN_REFINE_STEPS = 8;

// Height (m above the planet's surface) at world xz: bilinear between texel centres, clamped at
// the field's edge texels; beyond the field's extent, the flat planet (0).
inline float terrainHeightAt(vec2 xz, IN(TerrainParams) T) {
    vec2 uv = (xz - T.origin) / T.extent + vec2(0.5f);
    if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) {
        return 0.0f;
    }
    vec2 x = uv * vec2(float(T.width), float(T.height)) - vec2(0.5f);
    x = clamp(x, vec2(0.0f), vec2(float(T.width - 1), float(T.height - 1)));
    ivec2 i0 = ivec2(floor(x));
    ivec2 i1 = min(i0 + ivec2(1), ivec2(T.width - 1, T.height - 1));
    vec2 f = x - vec2(i0);
    float a = terrainHeightTexel(i0.y * T.width + i0.x);
    float b = terrainHeightTexel(i0.y * T.width + i1.x);
    float c = terrainHeightTexel(i1.y * T.width + i0.x);
    float d = terrainHeightTexel(i1.y * T.width + i1.x);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
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

// Over-relaxed sphere tracing (Keinert et al. 2014, "Enhanced Sphere Tracing"): a step goes
// this many bound distances, since a ray approaching a gentle surface sees the bound shrink
// geometrically; where the bounding spheres of a relaxed step and of the point it reached no
// longer overlap, the step may have passed over terrain, so it is taken back and the march goes
// on unrelaxed from there, exactly as plain sphere tracing would.
CONST_FLOAT TERRAIN_RELAXATION = 1.6f;

// Distance along a unit ray to the terrain (NO_HIT if it misses, or with the terrain off), and
// the march's steps (terrain height reads) in `steps`; relaxation 1 is plain sphere tracing. The
// gap above the surface divided by the Lipschitz bound sqrt(1 + s^2) is a distance the ray can
// travel without reaching the surface (sphere tracing, over-relaxed as above); the march starts
// where the ray descends below the field's highest texel and ends where it leaves that ceiling, or
// analytically on the flat planet once it has left the field's extent.
inline float terrainMarch(vec3 origin, vec3 dir, IN(CloudParams) P, float relaxation,
                          OUT(int) steps) {
    steps = 0;
    if (!terrainOn(P)) {
        return NO_HIT;
    }
    vec3 centre = planetCentre(P.planetRadius);
    vec2 ceiling = raySphere(origin, dir, centre, P.planetRadius + P.terrain.maxHeight + 1.0f);
    if (ceiling.y <= 0.0f) {
        return NO_HIT;
    }
    float t = max(ceiling.x, 0.0f);
    float end = ceiling.y;
    float previous = t;
    float previousRadius = 0.0f; // the bound distance at `previous`
    float stepLength = 0.0f;
    bool relaxed = true;      // relaxation still allowed on this ray
    bool lastRelaxed = false; // the last step went further than plain sphere tracing's
    for (int i = 0; i < P.terrain.maxSteps; ++i) {
        steps = i + 1;
        vec3 p = origin + dir * t;
        float gap = terrainGap(p, P);
        float radius = gap / P.terrain.lipschitz;
        if (lastRelaxed && abs(radius) + previousRadius < stepLength) {
            // Back to the last point, and on unrelaxed: what plain tracing steps from there.
            relaxed = false;
            lastRelaxed = false;
            t = min(previous + max(previousRadius, TERRAIN_MIN_STEP_RELATIVE * previous), end);
            continue;
        }
        if (gap < TERRAIN_HIT_EPSILON + TERRAIN_HIT_RELATIVE * t) {
            if (gap >= 0.0f || i == 0) {
                return t;
            }
            // The step overshot into the surface: bisect between the last point above it and t.
            float above = previous;
            float below = t;
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
        if (t >= end) {
            return NO_HIT;
        }
        if (leavingTerrain(p, dir, P.terrain)) {
            return planetSurfaceDistance(origin, dir, P.planetRadius);
        }
        float plain = max(radius, TERRAIN_MIN_STEP_RELATIVE * t);
        stepLength = relaxed ? max(relaxation * radius, plain) : plain;
        lastRelaxed = stepLength > plain;
        previous = t;
        previousRadius = radius;
        t = min(t + stepLength, end);
    }
    return NO_HIT;
}

inline float terrainHitDistance(vec3 origin, vec3 dir, IN(CloudParams) P) {
    int steps = 0;
    return terrainMarch(origin, dir, P, TERRAIN_RELAXATION, steps);
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
