// Lightning (Schneider, GDC 2022, "Lightning Effects"): intra-cloud flashes are the storm's
// internal glow fed a moving position, their intensity animated over the flash's life by the
// host's schedule (src/core/lightning.cpp, after Uman: strokes ~57 ms apart, each a sharp rise and
// decay); a ground discharge adds a bolt, a branching emissive polyline from the cloud base to the
// ground, and an external flash that highlights the underside of the storm.
//
// The flash mask: the radiance a flash adds is linear in its intensity, so the march integrates
// the flash at unit intensity into a channel of its own (CloudTexel.flash), which the temporal
// reconstruction accumulates over the frames before the flash like any other radiance (the flash's
// position is known ahead), and the resolve multiplies it by the intensity of this very frame.
// A flash of a few frames then keeps its full intensity through the 16-frame reconstruction.
#ifndef CLOUDSCAPE_MODEL_LIGHTNING_GLSL_H
#define CLOUDSCAPE_MODEL_LIGHTNING_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"
#include "storm.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_INT BOLT_SEGMENTS = 16;       // main channel, cloud base to ground
CONST_INT BOLT_BRANCHES = 2;        // side branches
CONST_INT BOLT_BRANCH_SEGMENTS = 6; // per branch
CONST_FLOAT BOLT_WANDER = 0.35f;    // lateral step of the random walk, per segment length
CONST_FLOAT BOLT_BRANCH_BRIGHTNESS = 0.35f;
CONST_FLOAT FLASH_EXTERNAL_REACH = 1.5f; // the external flash's radius, in flash radii

inline bool lightningOn(IN(CloudParams) P) {
    return featureCompiled(FEATURE_LIGHTNING) && lightningWanted(P);
}

// The flash at unit intensity at p (a scalar: P.lightning.flashLight gives its colour): the
// internal glow's potential about the flash's position (pow 12, brighter low in the layer, less in
// dense cloud), plus for a ground discharge the external flash, light from below catching the
// dense features of the underside near the bolt.
inline float lightningFlashUnit(vec3 p, float heightFraction, float fineDensity,
                                IN(CloudParams) P) {
    if (!lightningOn(P) || P.lightning.flashRadius <= 0.0f) {
        return 0.0f;
    }
    float internal = stormGlowAt(p, P.lightning.flashPosition, P.lightning.flashRadius,
                                 heightFraction, fineDensity);
    if (P.lightning.flashExternal <= 0.0f) {
        return internal;
    }
    vec3 d = p - P.lightning.boltTop;
    float reach = FLASH_EXTERNAL_REACH * P.lightning.flashRadius;
    float nearness = saturate(1.0f - length(d) / reach);
    float low = 1.0f - heightFraction;
    float underside =
        nearness * nearness * (low * low) * (low * low) * saturate(fineDensity * 5.0f);
    return internal + P.lightning.flashExternal * underside;
}

// The flash's radiance as the march adds it to a sample's light: all of it when the flash is not
// masked (the intensity enters the marched radiance), none when it is (the march accumulates
// lightningFlashUnit into its own channel and the composite scales it, lightningFlashRadiance).
inline vec3 lightningDirectRadiance(vec3 p, float heightFraction, float fineDensity,
                                    IN(CloudParams) P) {
    if (!lightningOn(P) || P.lightning.flashMask != 0 || P.lightning.flashIntensity <= 0.0f) {
        return vec3(0.0f, 0.0f, 0.0f);
    }
    float unit = lightningFlashUnit(p, heightFraction, fineDensity, P);
    return P.lightning.flashLight * (unit * P.lightning.flashIntensity);
}

// The masked flash's unit-intensity channel for a sample (0 when the flash is not masked).
inline float lightningMaskedUnit(vec3 p, float heightFraction, float fineDensity,
                                 IN(CloudParams) P) {
    if (!lightningOn(P) || P.lightning.flashMask == 0) {
        return 0.0f;
    }
    return lightningFlashUnit(p, heightFraction, fineDensity, P);
}

// Everything the storm emits at a lit sample (the march's one emission call): the internal glow
// and the unmasked flash.
inline vec3 stormEmission(vec3 p, float heightFraction, float fineDensity, IN(CloudParams) P) {
    return stormGlowRadiance(p, heightFraction, fineDensity, P) +
           lightningDirectRadiance(p, heightFraction, fineDensity, P);
}

// Everything the storm emits at a sample once the flash is lit at this frame's intensity, masked
// or not: stormEmission plus what the composite adds for a masked flash (withFlash), per unit of
// the sample's optical depth (the march weights it as it weights the scattered light). The path
// tracer's emission (src/pathtrace/cloud_medium.h).
inline vec3 stormEmissionLit(vec3 p, float heightFraction, float fineDensity, IN(CloudParams) P) {
    vec3 glow = stormGlowRadiance(p, heightFraction, fineDensity, P);
    if (!lightningOn(P) || P.lightning.flashIntensity <= 0.0f) {
        return glow;
    }
    float unit = lightningFlashUnit(p, heightFraction, fineDensity, P);
    return glow + P.lightning.flashLight * (unit * P.lightning.flashIntensity);
}

// The weight of a march step's emission (its source per unit optical depth), with the light the
// cloud scatters on the way out. Octave 0 is the emission seen through the view ray's optical
// depth tau to the step, the march's weight for any source, T (1 - e^(-sigma dt)). A cloud of
// albedo near 1 absorbs almost nothing, so the light a flash emits deep in the storm is not lost
// as e^(-tau) says: it scatters and comes out. By reciprocity the emission's path to the eye is
// what the sun's light march is for the sun's light, so the same octave approximation of multiple
// scattering (Wrenninge 2013, lighting.glsl.h) applies to it, on the view side: octave i carries
// albedo a^i of the energy and sees the optical depth scaled by b^i, with the scene's octaves and
// factors (lighting.scattering_octaves, lighting.octave_factors). Emission is isotropic, and so
// is its scattered light, so the octaves' eccentricity does not enter. One octave (or albedo 0)
// is the emission alone; the path tracer's emission (stormEmissionLit) is not changed by this,
// it scatters the emitted light itself.
inline float emissionStepWeight(float transmittance, float stepDepth, IN(CloudParams) P) {
    bool exact = P.energyConservingSteps != 0;
    float weight = transmittance * (exact ? 1.0f - exp(-stepDepth) : stepDepth);
    int octaves = min(P.scatteringOctaves, 8);
    if (octaves <= 1 || P.albedo <= 0.0f) {
        return weight;
    }
    float viewDepth = -log(max(transmittance, 1e-30f));
    float a = P.albedo;
    float b = 1.0f;
    for (int i = 1; i < octaves; ++i) {
        a *= P.octaveFactors.x;
        b *= P.octaveFactors.y;
        // The step's integral of b sigma e^(-b sigma x), over b: the emission per unit optical
        // depth of the real medium seen through b times its depth.
        float step = exact && b > 0.0f ? (1.0f - exp(-b * stepDepth)) / b : stepDepth;
        weight += a * exp(-b * viewDepth) * step;
    }
    return weight;
}

// Premultiplied cloud radiance with the masked flash channel lit at this frame's intensity.
inline vec3 withFlash(vec3 cloudRadiance, float flash, IN(CloudParams) P) {
    if (!lightningOn(P) || flash <= 0.0f) {
        return cloudRadiance;
    }
    return cloudRadiance + P.lightning.flashLight * (flash * P.lightning.flashIntensity);
}

// ---- The bolt: a branching polyline, its vertices a deterministic random walk from boltSeed.

inline float boltRandom(int seed, int a, int b) {
    return float(hashUint(uint(seed) * 747796405u ^ uint(a) * 2891336453u ^ uint(b) * 277803737u) >>
                 8u) *
               (2.0f / 16777216.0f) -
           1.0f;
}

// Two horizontal axes at the bolt (world x and z: the bolt spans a few km, the planet's tilt there
// is negligible).
inline vec3 boltLateral(int seed, int index, int walk, float step) {
    return vec3(boltRandom(seed, index, walk), 0.0f, boltRandom(seed, index, walk + 1)) * step;
}

// Vertex i (0 .. BOLT_SEGMENTS) of the main channel: the straight line from top to bottom plus a
// random walk that starts at 0 at the cloud base.
inline vec3 boltVertex(int i, IN(CloudParams) P) {
    vec3 top = P.lightning.boltTop;
    vec3 bottom = P.lightning.boltBottom;
    float segment = length(bottom - top) / float(BOLT_SEGMENTS);
    vec3 wander = vec3(0.0f, 0.0f, 0.0f);
    for (int k = 1; k <= i; ++k) {
        wander += boltLateral(P.lightning.boltSeed, k, 0, BOLT_WANDER * segment);
    }
    return mix(top, bottom, float(i) / float(BOLT_SEGMENTS)) + wander;
}

// Distance between a ray (origin o, unit direction d, t >= 0) and the segment a-b; t receives the
// distance along the ray of the closest approach.
inline float raySegmentDistance(vec3 o, vec3 d, vec3 a, vec3 b, OUT(float) t) {
    vec3 u = b - a;
    vec3 w = a - o;
    float uu = dot(u, u);
    float ud = dot(u, d);
    float denom = uu - ud * ud;
    float s = denom > 1e-6f * uu ? clamp((ud * dot(w, d) - dot(w, u)) / denom, 0.0f, 1.0f) : 0.0f;
    vec3 q = a + u * s;
    t = max(dot(q - o, d), 0.0f);
    return length(o + d * t - q);
}

// One segment's brightness (0 .. 1) seen along the ray: a core of boltWidth, spread over the
// pixel's footprint where that is wider (so its energy is kept and it never aliases away), hidden
// by geometry nearer than it. t receives the distance of the closest approach.
inline float boltSegmentLight(vec3 o, vec3 d, vec3 a, vec3 b, float pixelAngle, float geometryDepth,
                              float width, OUT(float) t) {
    float dist = raySegmentDistance(o, d, a, b, t);
    if (t <= 0.0f || t >= geometryDepth) {
        return 0.0f;
    }
    float spread = max(width, pixelAngle * t);
    float x = dist / (0.5f * spread);
    return (width / spread) * exp(-x * x);
}

// Keeps the brighter of two segment values and the distance of that one.
inline void brighterSegment(float value, float t, INOUT(float) best, INOUT(float) bestT) {
    if (value > best) {
        best = value;
        bestT = t;
    }
}

// The bolt's brightness (0 .. 1) along a ray, over its main channel and branches; bestT the
// distance of the brightest point.
inline float boltBrightness(vec3 o, vec3 d, float pixelAngle, float geometryDepth,
                            IN(CloudParams) P, OUT(float) bestT) {
    float best = 0.0f;
    bestT = NO_HIT;
    float width = P.lightning.boltWidth;
    vec3 previous = boltVertex(0, P);
    float segment = length(P.lightning.boltBottom - P.lightning.boltTop) / float(BOLT_SEGMENTS);
    vec3 down = (P.lightning.boltBottom - P.lightning.boltTop) / float(BOLT_SEGMENTS);
    for (int i = 1; i <= BOLT_SEGMENTS; ++i) {
        vec3 next = boltVertex(i, P);
        // The value first, then its distance (an argument list has no evaluation order).
        float t = 0.0f;
        float v = boltSegmentLight(o, d, previous, next, pixelAngle, geometryDepth, width, t);
        brighterSegment(v, t, best, bestT);
        // Branches leave the main channel at vertices 4, 9, ..., heading down and sideways.
        int branch = (i - 4) / 5;
        if (i >= 4 && (i - 4) % 5 == 0 && branch < BOLT_BRANCHES) {
            vec3 side = boltLateral(P.lightning.boltSeed, 100 + branch, 7, 0.6f * segment);
            vec3 a = next;
            for (int j = 1; j <= BOLT_BRANCH_SEGMENTS; ++j) {
                vec3 b = a + down * 0.7f + side +
                         boltLateral(P.lightning.boltSeed, 200 + 16 * branch + j, 3,
                                     BOLT_WANDER * segment);
                float tb = 0.0f;
                float vb =
                    boltSegmentLight(o, d, a, b, pixelAngle, geometryDepth, 0.5f * width, tb);
                brighterSegment(vb * BOLT_BRANCH_BRIGHTNESS, tb, best, bestT);
                a = b;
            }
        }
        previous = next;
    }
    return best;
}

CONST_FLOAT BOLT_CORE_GAIN = 40.0f; // the channel's radiance over the flash light's

// The radiance of the bolt's core at full brightness (boltBrightness 1) and unit intensity: a
// white-hot core tinted by the flash's colour. The path tracer draws the same bolt.
inline vec3 lightningBoltCore(IN(CloudParams) P) {
    vec3 light = P.lightning.flashLight;
    float peak = max(light.x, max(light.y, light.z));
    return mix(light, vec3(peak, peak, peak), 0.6f) * BOLT_CORE_GAIN;
}

// The bolt's radiance reaching the camera along a ray: hidden by geometry nearer than it, seen
// through the clouds' transmittance when their first cloud lies in front of it.
inline vec3 lightningBoltRadiance(vec3 o, vec3 d, float pixelAngle, float geometryDepth,
                                  float cloudDepth, float transmittance, IN(CloudParams) P) {
    if (!lightningOn(P) || P.lightning.boltIntensity <= 0.0f) {
        return vec3(0.0f, 0.0f, 0.0f);
    }
    float t = NO_HIT;
    float b = boltBrightness(o, d, pixelAngle, geometryDepth, P, t);
    if (b <= 0.0f) {
        return vec3(0.0f, 0.0f, 0.0f);
    }
    float seen = cloudDepth != NO_HIT && t > cloudDepth ? transmittance : 1.0f;
    return lightningBoltCore(P) * (b * seen * P.lightning.boltIntensity);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
