// Ray intersection with the spherical cloud shell (GPU Pro 7 4.5.1) for a camera below, inside
// or above the layer (the three cases of Wakapon's notes). The planet's centre is at
// (0, -radius, 0) so that y is the altitude above the ground at the origin.
#ifndef CLOUDSCAPE_MODEL_SHELL_GLSL_H
#define CLOUDSCAPE_MODEL_SHELL_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_FLOAT NO_HIT = -1.0f;

inline vec3 planetCentre(float planetRadius) {
    return vec3(0.0f, -planetRadius, 0.0f);
}

// Altitude above the planet's surface.
inline float altitudeOf(vec3 p, float planetRadius) {
    return length(p - planetCentre(planetRadius)) - planetRadius;
}

// Distance along a unit ray from p, at `altitude` above a top, to where it descends to that top;
// 3e38 if it never does. Written from the altitude difference (not |p - c|^2 - r^2, which loses
// everything in float at planet scale). The cloud-top grid's empty-space skipping and the
// terrain's cell maxima both bound a ray this way.
inline float descentToAltitude(vec3 p, vec3 dir, float altitude, float top, float planetRadius) {
    vec3 oc = p - planetCentre(planetRadius);
    float b = dot(oc, dir);
    if (b >= 0.0f) {
        return 3.0e38f; // rising: never lower again
    }
    float h = altitude - top;
    float c = h * (2.0f * (planetRadius + top) + h);
    float disc = b * b - c;
    if (disc < 0.0f) {
        return 3.0e38f;
    }
    return c / (-b + sqrt(disc));
}

// Distance along a unit ray from p, at `altitude` below `top`, to where it rises to `top` (it
// leaves that sphere once: the altitude along a line is convex). The stable form of the root.
inline float ascentToAltitude(vec3 p, vec3 dir, float altitude, float top, float planetRadius) {
    vec3 oc = p - planetCentre(planetRadius);
    float b = dot(oc, dir);
    float h = altitude - top;
    float c = h * (2.0f * (planetRadius + top) + h); // |oc|^2 - (R + top)^2, negative inside
    float root = sqrt(max(b * b - c, 0.0f));
    return b > 0.0f ? -c / (b + root) : root - b;
}

// Both distances along a unit ray to a sphere; (NO_HIT, NO_HIT) if the line misses. The
// quadratic is solved in the numerically stable form because the radii (6371 km) are huge
// compared with the distances of interest.
inline vec2 raySphere(vec3 origin, vec3 dir, vec3 centre, float radius) {
    vec3 oc = origin - centre;
    float b = dot(oc, dir);
    float c = dot(oc, oc) - radius * radius;
    float disc = b * b - c;
    if (disc < 0.0f) {
        return vec2(NO_HIT, NO_HIT);
    }
    float s = sqrt(disc);
    float q = b >= 0.0f ? -b - s : -b + s;
    float t0 = q;
    float t1 = abs(q) > 1e-12f ? c / q : 0.0f;
    return vec2(min(t0, t1), max(t0, t1));
}

// The parts of a ray inside the shell between radii inner and outer, in front of the origin
// and before the ray hits the ground: up to two intervals (x, y) and (z, w); an absent interval
// has its end <= its start (both NO_HIT).
inline vec4 shellIntervals(vec3 origin, vec3 dir, float planetRadius, float bottomAltitude,
                           float topAltitude) {
    vec3 centre = planetCentre(planetRadius);
    vec2 outer = raySphere(origin, dir, centre, planetRadius + topAltitude);
    vec4 none = vec4(NO_HIT, NO_HIT, NO_HIT, NO_HIT);
    if (outer.y <= 0.0f) {
        return none;
    }
    vec2 inner = raySphere(origin, dir, centre, planetRadius + bottomAltitude);
    vec2 ground = raySphere(origin, dir, centre, planetRadius);
    float far = outer.y;
    if (ground.x > 0.0f) {
        far = min(far, ground.x); // the ground blocks everything behind it
    }
    float a0 = max(outer.x, 0.0f);
    float a1 = far;
    float b0 = NO_HIT;
    float b1 = NO_HIT;
    if (inner.y > inner.x && inner.y > 0.0f) {
        // Remove the inner ball: [a0, a1] minus [inner.x, inner.y].
        b0 = max(inner.y, a0);
        b1 = a1;
        a1 = min(a1, inner.x);
    }
    if (a1 <= a0) {
        a0 = b0;
        a1 = b1;
        b0 = NO_HIT;
        b1 = NO_HIT;
    }
    if (b1 <= b0) {
        b0 = NO_HIT;
        b1 = NO_HIT;
    }
    if (a1 <= a0) {
        return none;
    }
    return vec4(a0, a1, b0, b1);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
