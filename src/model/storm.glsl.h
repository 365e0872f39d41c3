// Superstorms (Schneider, "Nubis, evolved", GDC 2022, the Forbidden West talk): a stencil over
// the weather with a position, radius, coverage and blend factor. Within the radius coverage and
// type ramp to their maxima at the centre (the mesocyclone's cylindrical foot, up to the top of
// the layer), a bottom type relaxes the foot's bottom gradient and makes its underside wispy, a
// flipped profile combined with the normal one spreads the top into an anvil (offset downwind),
// the detail noise turns in 6 nested rings whose speed falls with radius, and the lighting gets
// the talk's three probability fields: a light-march density scale, an ambient blend and an
// internal glow. Outside the radius, or at blend 0, nothing is evaluated and nothing changes.
//
// One storm (CloudParams.storm*); it wraps with the weather map (the talk's stencil lives in the
// Nubis data field), so the path tracer's majorant cells, which tile the wrapping map, bound it.
#ifndef CLOUDSCAPE_MODEL_STORM_GLSL_H
#define CLOUDSCAPE_MODEL_STORM_GLSL_H

#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "profiles.glsl.h"
#include "sampling.glsl.h"
#include "shell.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_INT STORM_RINGS = 6;                // nested vortex rings (the talk's 6)
CONST_FLOAT STORM_RING_OVERLAP = 0.3f;    // of a ring's width, where two rings are blended
CONST_FLOAT STORM_ANVIL_SHIFT = 0.25f;    // anvil centre downwind, as a fraction of the radius
CONST_FLOAT STORM_FOOT_FRACTION = 0.5f;   // radius of the lighting fields' full strength
CONST_FLOAT STORM_FOOT_LIFT = 0.6f;       // base shape raised toward 1 over the foot
CONST_FLOAT STORM_ANVIL_LIFT = 0.5f;      // and under the anvil
CONST_FLOAT STORM_FOOT_DISTORTION = 0.3f; // the foot's edge is read up to this much nearer
CONST_FLOAT STORM_BASE_RISE = 0.1f;       // most the foot's underside rises, of the layer depth
CONST_FLOAT STORM_FOOT_WANDER = 0.25f;    // noise periods the foot's outline drifts, base to top
// The anvil's detail noise is read at offsets from the storm centre scaled by these (along the
// wind, across it): features 4x longer downwind, 2x across (density.glsl.h, stormDetailFbm).
CONST_FLOAT STORM_ANVIL_SQUEEZE_ALONG = 0.25f;
CONST_FLOAT STORM_ANVIL_SQUEEZE_ACROSS = 0.5f;
CONST_FLOAT STORM_GLOW_EXPONENT = 12.0f;  // the talk's pow(1 - d1 / radius, 12)
CONST_FLOAT STORM_MOTION_EXPONENT = 0.1f; // the talk's motion-vector mask exponent

// What a density sample needs to know about the storm at its position.
struct StormSample {
    float r;          // distance from the centre over the radius; >= 1 outside (2 with no storm)
    float footR;      // r distorted by a noise for the foot's masks (<= r)
    float bottomType; // 0 the normal bottom gradient .. 1 relaxed, wispy undersides
    float anvil;      // weight of the flipped (anvil) profile
    float lift;       // how far the foot raises the base shape toward 1 (0 .. STORM_FOOT_LIFT)
    float baseRise;   // the foot's underside raised by this fraction of the layer (0 outside)
};

inline bool stormActive(IN(CloudParams) P) {
    return stormOn(P);
}

// Offset (m) of world xz from the storm centre, wrapped into the weather map's period.
inline vec2 stormOffset(vec2 xz, IN(CloudParams) P) {
    vec2 d = xz - P.stormCentre;
    return d - P.weatherExtent * floor(d / P.weatherExtent + vec2(0.5f, 0.5f));
}

// The stencil's masks, each zero at r >= 1 and non-increasing in r (the path tracer's majorant
// evaluates them at a cell's nearest distance). Coverage and type make a steep-sided cylinder,
// the mesocyclone's foot (full to 0.3 R, gone by 0.45 R), so the anvil overhangs it.
inline float stormCoverageMask(float r, float blend) {
    return blend * (1.0f - smoothstep(0.3f, 0.45f, r));
}
inline float stormTypeMask(float r, float blend) {
    return blend * (1.0f - smoothstep(0.3f, 0.45f, r));
}
// ra: distance from the anvil's (downwind) centre over its radius, (1 - shift) R, so the anvil
// stays inside the storm radius; its edge is fairly sharp, an overhanging shelf.
inline float stormAnvilMask(float ra, float blend) {
    return blend * (1.0f - smoothstep(0.7f, 1.0f, ra));
}

inline float anvilDistanceFraction(vec2 offset, IN(CloudParams) P) {
    vec2 shift = vec2(P.windDirection.x, P.windDirection.z) * (STORM_ANVIL_SHIFT * P.stormRadius);
    return length(offset - shift) / ((1.0f - STORM_ANVIL_SHIFT) * P.stormRadius);
}

inline StormSample noStorm() {
    StormSample s;
    s.r = 2.0f;
    s.footR = 2.0f;
    s.bottomType = 0.0f;
    s.anvil = 0.0f;
    s.lift = 0.0f;
    s.baseRise = 0.0f;
    return s;
}

// The talk's varying cloud heights: distorted noises and a radial gradient raise the
// mesocyclone's underside, lowest at the centre (the wall cloud) and lumpy elsewhere, so the
// flattened bottom is "anything but flat". Only over the foot's core, falling back to the
// layer's base at the core's edge, where the ragged bottom type takes over. A fraction of the
// layer's depth (composited with the data field's minimum height); 0 with no storm.
inline float stormBaseRise(vec2 offset, float footR, IN(CloudParams) P) {
    float core = 1.0f - smoothstep(0.2f, 0.3f, footR);
    if (core <= 0.0f) {
        return 0.0f;
    }
    float wall = smoothstep(0.03f, 0.15f, footR);
    // The curl texture's channel varies by about +-0.1 about 0.5: stretched to the full range.
    float n = sampleCurlNoise(offset / (0.6f * P.stormRadius) + vec2(0.5f, 0.25f)).x;
    float lumps = saturate(0.5f + 4.0f * (n - 0.5f));
    return STORM_BASE_RISE * P.stormBlend * core * (0.35f * wall + 0.65f * lumps);
}

inline StormSample stormSampleAt(vec3 p, IN(CloudParams) P) {
    StormSample s = noStorm();
    if (!stormActive(P)) {
        return s;
    }
    vec2 offset = stormOffset(vec2(p.x, p.z), P);
    float r = length(offset) / P.stormRadius;
    if (r >= 1.0f) {
        return s;
    }
    s.r = r;
    // The talk's distorted noises and radial gradients: the foot's edge is pushed out by a
    // low-frequency noise (the curl texture's vertical channel, three storm radii to a period:
    // finer, it draws vertical streaks), so the mesocyclone is a lumpy tower, not a cylinder.
    // The noise is read further along with height, so the lumps wander up the tower (bulging
    // turrets and waists) instead of running its whole height as vertical ribs.
    float height =
        saturate((altitudeOf(p, P.planetRadius) - P.layerBottom) / (P.layerTop - P.layerBottom));
    vec2 wander = vec2(STORM_FOOT_WANDER, -0.7f * STORM_FOOT_WANDER) * height;
    float n = sampleCurlNoise(offset / (3.0f * P.stormRadius) + wander).z;
    s.footR = r * (1.0f - STORM_FOOT_DISTORTION * saturate(n));
    s.bottomType = stormTypeMask(s.footR, P.stormBlend);
    s.anvil = stormAnvilMask(anvilDistanceFraction(offset, P), P.stormBlend);
    s.lift = STORM_FOOT_LIFT * stormCoverageMask(s.footR, P.stormBlend);
    s.baseRise = stormBaseRise(offset, s.footR, P);
    return s;
}

// Weather under the storm: coverage rises to stormCoverage and type to cumulonimbus toward the
// centre. Monotonic in the weather and in each mask, as weatherFromRaw is.
inline vec3 stormWeather(vec3 weather, float r, IN(CloudParams) P) {
    if (r >= 1.0f) {
        return weather;
    }
    float c = stormCoverageMask(r, P.stormBlend);
    float t = stormTypeMask(r, P.stormBlend);
    return vec3(mix(weather.x, max(weather.x, P.stormCoverage), c), weather.y,
                mix(weather.z, TYPE_CUMULONIMBUS, t));
}

// Upper bounds of the storm's weather over a region whose nearest point lies at distance
// fraction rMin from the storm centre, for the path tracer's majorant: x coverage, y type, z the
// anvil's coverage (its flipped profile reaches the layer top). The masks are non-increasing in
// r, and the anvil's centre is STORM_ANVIL_SHIFT radii from the storm's, so its distance
// fraction is at least (rMin - shift) / (1 - shift).
inline vec3 stormWeatherBound(vec3 weather, float rMin, IN(CloudParams) P) {
    if (!stormActive(P) || rMin >= 1.0f) {
        return vec3(weather.x, weather.z, 0.0f);
    }
    vec3 w = stormWeather(weather, rMin * (1.0f - STORM_FOOT_DISTORTION), P);
    float raMin = max(rMin - STORM_ANVIL_SHIFT, 0.0f) / (1.0f - STORM_ANVIL_SHIFT);
    return vec3(w.x, w.z, stormAnvilMask(raMin, P.stormBlend) * P.stormCoverage);
}

// The anvil's flipped profile: a thin stratiform profile turned upside down, so it sits at the
// top of the layer and spreads there.
inline vec4 anvilProfile() {
    return vec4(0.0f, 0.06f, 0.12f, 0.26f);
}
inline float anvilVerticalProfile(float heightFraction) {
    return evaluateProfile(anvilProfile(), 1.0f - heightFraction);
}

// The vortex: ring n (0 innermost) turns at stormRotation / (n + 1); beyond the last ring the
// field is still. x: ring index, y: weight of the next ring outward (the overlap's blend).
inline vec2 stormRing(float r) {
    float u = r * float(STORM_RINGS);
    float ring = min(floor(u), float(STORM_RINGS - 1));
    float w = smoothstep(1.0f - STORM_RING_OVERLAP, 1.0f, u - ring);
    return vec2(ring, w);
}

inline float stormRingSpeed(int ring, IN(CloudParams) P) {
    return ring >= STORM_RINGS ? 0.0f : P.stormRotation / float(ring + 1);
}

// Angular speed (rad/s, at blend 1) at distance fraction r, blended across ring overlaps as the
// noise is: what the motion vectors use.
inline float stormAngularSpeed(float r, IN(CloudParams) P) {
    if (r >= 1.0f) {
        return 0.0f;
    }
    vec2 ring = stormRing(r);
    int n = int(ring.x);
    return mix(stormRingSpeed(n, P), stormRingSpeed(n + 1, P), ring.y);
}

// The angle a ring has turned by now, plus the ring skew: a twist growing with radius (outer
// rings twisted about the centre against the inner ones), which draws the tendrils as spirals.
// The ring beyond the last is still and untwisted, so the field is continuous at the radius.
inline float stormRingAngle(int ring, float r, IN(CloudParams) P) {
    if (ring >= STORM_RINGS) {
        return 0.0f;
    }
    return P.stormSpin * stormRingSpeed(ring, P) + P.stormRingTwist * r;
}

// p turned by angle (rad, counter-clockwise seen from above: east toward north) about the storm's
// vertical axis.
inline vec3 rotateAboutStorm(vec3 p, float angle, IN(CloudParams) P) {
    vec2 offset = stormOffset(vec2(p.x, p.z), P);
    float c = cos(angle);
    float s = sin(angle);
    vec2 turned = vec2(c * offset.x - s * offset.y, s * offset.x + c * offset.y);
    return vec3(p.x + (turned.x - offset.x), p.y, p.z + (turned.y - offset.y));
}

// The talk's light-march probability field pow(min(1 - d / radius, 0) + 1, 0.5) with radius the
// foot's (half the storm's): 1 over the foot, falling to 0 at the storm radius; times the blend.
inline float stormFootField(vec3 p, IN(CloudParams) P) {
    if (!stormActive(P)) {
        return 0.0f;
    }
    float d = length(stormOffset(vec2(p.x, p.z), P)) / (STORM_FOOT_FRACTION * P.stormRadius);
    return pow(saturate(min(1.0f - d, 0.0f) + 1.0f), 0.5f) * P.stormBlend;
}

// Scale on a light sample's density: the storm's foot is darker and more menacing.
inline float stormLightDensityScale(vec3 p, IN(CloudParams) P) {
    if (!stormActive(P)) {
        return 1.0f;
    }
    return 1.0f + (P.stormLightDensityScale - 1.0f) * stormFootField(p, P);
}

// Ambient under the storm: the cylindrical field times (d2 / h), d2 the depth below the layer top,
// blends the clouds' ambient toward the storm's (stormAmbientScale times it).
inline float stormAmbientFactor(vec3 p, float heightFraction, IN(CloudParams) P) {
    if (!stormActive(P)) {
        return 1.0f;
    }
    float blend = stormFootField(p, P) * (1.0f - heightFraction);
    return mix(1.0f, P.stormAmbientScale, blend);
}

// The internal glow without a second light march: potential energy pow(1 - d1 / radius, 12)
// about a sphere at the storm centre, a height gradient (d2 / h, brighter low in the layer) and a
// pseudo-attenuation 1 - saturate(5 fine density); the result is added to the sample's light.
inline float stormGlowAt(vec3 p, vec3 centre, float radius, float heightFraction,
                         float fineDensity) {
    float d1 = length(p - centre);
    float potential = pow(saturate(1.0f - d1 / radius), STORM_GLOW_EXPONENT);
    float pseudoAttenuation = 1.0f - saturate(fineDensity * 5.0f);
    return potential * (1.0f - heightFraction) * pseudoAttenuation;
}

// World position of the glow's centre: above the storm centre (nearest wrapped copy of p's).
inline vec3 stormGlowCentre(vec3 p, IN(CloudParams) P) {
    vec2 offset = stormOffset(vec2(p.x, p.z), P);
    vec3 foot = vec3(p.x - offset.x, p.y, p.z - offset.y);
    vec3 up = normalize(foot - planetCentre(P.planetRadius));
    float altitude = altitudeOf(foot, P.planetRadius);
    return foot + up * (P.stormGlowAltitude - altitude);
}

inline vec3 stormGlowRadiance(vec3 p, float heightFraction, float fineDensity, IN(CloudParams) P) {
    if (!stormActive(P) || P.stormGlowRadius <= 0.0f) {
        return vec3(0.0f, 0.0f, 0.0f);
    }
    vec3 centre = stormGlowCentre(p, P);
    float g = stormGlowAt(p, centre, P.stormGlowRadius, heightFraction, fineDensity);
    return P.stormGlow * (g * P.stormBlend);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
