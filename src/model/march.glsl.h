// The view-ray march through the cloud shell (GPU Pro 7 4.5): 64 steps toward the zenith rising
// to 128 toward the horizon, full samples where the base shape is non-zero, a light march only
// where there is cloud, energy-conserving integration of each step, early exit once the ray is
// opaque. Output: premultiplied radiance, transmittance and the distance to the first cloud.
#ifndef CLOUDSCAPE_MODEL_MARCH_GLSL_H
#define CLOUDSCAPE_MODEL_MARCH_GLSL_H

#include "cloud_bound.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "lighting.glsl.h"
#include "lightning.glsl.h"
#include "noise_clearance.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

struct MarchResult {
    vec3 radiance;       // premultiplied in-scattered radiance (linear)
    float transmittance; // of the whole view ray through the clouds
    float depth;         // distance (m) to the first sample with cloud; NO_HIT if none
    int densitySamples;  // density evaluations along the view ray
    int cloudSamples;    // of those, the ones that found cloud (extinction > 0)
    int emptySkips;      // skips of provably empty space: the grid's (no texture read) and
                         // the noise's clearance field's (march.noise_skipping)
    int lightSamples;    // density evaluations along light rays
    float flash;         // the masked lightning flash at unit intensity (lightning.glsl.h)
};

// Number of view steps for a ray: GPU Pro 7 takes 64 straight up and 128 at the horizon, where
// the path through the shell is far longer.
inline int viewStepCount(vec3 origin, vec3 dir, IN(CloudParams) P) {
    vec3 up = normalize(origin - planetCentre(P.planetRadius));
    float upness = abs(dot(dir, up));
    return int(mix(float(P.horizonSteps), float(P.zenithSteps), upness) + 0.5f);
}

// The view march's near segment (march.near_step_m): this many steps of at most
// P.nearStepLength from where the ray enters the layer, when that is within their reach.
CONST_INT NEAR_STEPS = 24;

// A stretch of the view ray marched with one step length: [start, start + span).
struct MarchSegment {
    float start;
    float span;
    float stepLength;
};

// The march's three segments: the near part of the first shell interval (finer steps, when the
// camera is in or near the layer and P.nearStepLength is shorter than the layer's own step),
// the rest of it, and the second interval (a ray that leaves the shell and re-enters it).
// Lengths are already cut at the march's end; an empty segment has length 0.
inline MarchSegment marchSegment(int index, vec4 spans, float lenA, float lenB, float stepLength,
                                 IN(CloudParams) P) {
    MarchSegment s;
    s.stepLength = stepLength;
    float nearReach = float(NEAR_STEPS) * P.nearStepLength;
    bool useNear = P.nearStepLength > 0.0f && P.nearStepLength < stepLength && spans.x < nearReach;
    float nearLength = useNear ? min(lenA, nearReach - spans.x) : 0.0f;
    if (index == 0) {
        s.start = spans.x;
        s.span = nearLength;
        s.stepLength = min(P.nearStepLength, stepLength);
    } else if (index == 1) {
        s.start = spans.x + nearLength;
        s.span = lenA - nearLength;
    } else {
        s.start = spans.z;
        s.span = lenB;
    }
    return s;
}

// Consecutive empty full samples after which coarse/fine sampling returns to coarse steps.
CONST_INT ZERO_SAMPLES_TO_COARSE = 6;

// Fade of cloud density toward the maximum march distance: a stand-in for aerial perspective,
// which the atmosphere will replace, so that distant clouds sink into the horizon instead of
// ending at a hard edge.
inline float distanceFade(float t, IN(CloudParams) P) {
    return 1.0f - smoothstep(P.horizonFade * P.maxDistance, P.maxDistance, t);
}

// A view ray and what its samples need besides the position: jitter in [0, 1) offsets the first
// sample within a step so that banding becomes noise; pixelAngle (radians) is the angle one pixel
// subtends, for the noise LOD (0 for none).
struct MarchRay {
    vec3 origin;
    vec3 dir;
    float jitter;
    float pixelAngle;
};

// Where the march stands (see marchRayTo for coarse/fine sampling).
struct MarchCursor {
    int segment;      // marchSegment's index; 3 once the ray is done
    MarchSegment seg; // the segment being marched
    int i;            // the next index on the segment's fine grid
    int count;        // fine steps in the segment
    bool fine;        // sampling every fine step (else coarse steps of base-only samples)
    int zeros;        // consecutive empty full samples
    int fineFloor;    // no fine step is ever taken twice
    int lastCoarse;   // the previous coarse (or last fine) sample
};

// The view ray's path through the shell: what marchSegment cuts into segments.
struct MarchPath {
    vec4 spans;       // shellIntervals
    float lenA;       // the first interval's length, cut at the march's end
    float lenB;       // the second's
    float stepLength; // of the layer's steps
};

// The cursor at the start of a segment (an empty one has no steps; index 3 is the ray's end).
// The segments follow one another in one cursor rather than in a loop of their own so that a
// SIMD machine (see nextFineSample) pays for the march's phases once a ray, not once a segment.
inline void startSegment(INOUT(MarchCursor) c, int segment, IN(MarchPath) path, bool skipping,
                         IN(CloudParams) P) {
    c.segment = segment;
    c.seg = marchSegment(min(segment, 2), path.spans, path.lenA, path.lenB, path.stepLength, P);
    c.i = 0;
    c.count = segment < 3 && c.seg.span > 0.0f ? int(ceil(c.seg.span / c.seg.stepLength)) : 0;
    c.fine = !skipping;
    c.zeros = 0;
    c.fineFloor = 0;
    c.lastCoarse = -1;
}

// A sample the march evaluates in full: where it is and its base shape.
struct MarchSample {
    float t;
    vec3 p;
    DensityContext ctx;
    float base;
    float footprint; // metres one pixel covers there
    float density;   // the full density, once the detail has eroded the base
    float sigma;     // its extinction (1/m), faded with distance
};

// A fine sample found empty: on to the next fine step, and back to coarse steps after
// ZERO_SAMPLES_TO_COARSE empty ones in a row.
inline void passEmptyFineSample(INOUT(MarchCursor) c, bool skipping) {
    c.fineFloor = c.i + 1;
    c.i += 1;
    c.zeros += 1;
    if (skipping && c.zeros >= ZERO_SAMPLES_TO_COARSE) {
        c.fine = false;
        c.lastCoarse = c.i - 1;
    }
}

// Where the base noise's clearance field (noise_clearance.glsl.h) proves the cursor's sample (at p,
// t along the ray) and the next ones empty, moves the cursor past them exactly as nextFineSample
// would have after sampling them: coarse samples each step on by the coarse factor (only without
// the step optimisation, whose steps depend on the samples' margins), fine samples each count as
// empty (passEmptyFineSample), up to the return to coarse steps. The march then takes the same
// samples after them, so its result is bit for bit the unskipped march's. False (cursor
// unmoved) where nothing is proven.
inline bool passClearSamples(INOUT(MarchCursor) c, vec3 p, float t, IN(MarchRay) ray, bool skipping,
                             IN(CloudParams) P) {
    if (!featureCompiled(FEATURE_NOISE_SKIPPING) || P.emptySpaceSkipping == 0 ||
        (!c.fine && P.stepOptimisation > 0.0f)) {
        return false;
    }
    float clear = noiseClearDistance(p, ray.dir, t, ray.pixelAngle, P);
    if (clear <= 0.0f) {
        return false;
    }
    if (!c.fine) {
        int coarse = max(P.coarseStepFactor, 1);
        int passed = 1 + int(clear / (float(coarse) * c.seg.stepLength));
        c.lastCoarse = c.i + (passed - 1) * coarse;
        c.i += passed * coarse;
        return true;
    }
    int passed = 1 + int(clear / c.seg.stepLength);
    if (skipping) {
        passed = min(passed, ZERO_SAMPLES_TO_COARSE - c.zeros);
    }
    c.i += passed;
    c.fineFloor = c.i;
    c.zeros += passed;
    if (skipping && c.zeros >= ZERO_SAMPLES_TO_COARSE) {
        c.fine = false;
        c.lastCoarse = c.i - 1;
    }
    return true;
}

// Moves the cursor to the next position the march must sample, s.t and s.p: past the ends of
// segments and over what the weather's cloud-top grid proves empty, without reading a texture.
// False when the ray's march ends first.
//
// A loop of its own, inside nextFineSample's: a SIMD machine that marches several rays in
// lockstep (a GPU's warp, llvmpipe's vector) runs a loop body whole for all of them, so a ray
// that only moves its cursor here (a segment's end, a skip) would otherwise make the others wait
// through one whole sample (the weather and base-noise reads) each time.
inline bool nextSamplePosition(INOUT(MarchCursor) c, IN(MarchPath) path, IN(MarchRay) ray,
                               INOUT(MarchResult) result, INOUT(MarchSample) s, bool skipping,
                               IN(CloudParams) P) {
    bool found = false;
    while (c.segment < 3) {
        s.t = c.seg.start + (float(c.i) + ray.jitter) * c.seg.stepLength;
        if (c.i >= c.count || s.t > c.seg.start + c.seg.span) {
            startSegment(c, c.segment + 1, path, skipping, P);
            continue;
        }
        s.p = ray.origin + ray.dir * s.t;
        // Empty-space skipping: where the weather's cloud-top grid proves the column empty
        // at this altitude, jump to the first grid sample past the empty stretch without
        // reading a texture. The skipped samples would all have had zero density, so with
        // c = 1 the result is exactly the unskipped march's; with c > 1 the coarse lattice
        // restarts where the jump lands (a thin cloud between two coarse samples may be
        // found or missed differently, as any change of the lattice's phase would).
        float empty = skippableDistance(s.p, ray.dir, P);
        if (empty <= 0.0f) {
            if (passClearSamples(c, s.p, s.t, ray, skipping, P)) {
                result.emptySkips += 1;
                continue;
            }
            found = true;
            break;
        }
        result.emptySkips += 1;
        float resume = s.t + empty;
        if (resume >= c.seg.start + c.seg.span) {
            startSegment(c, c.segment + 1, path, skipping, P);
            continue;
        }
        c.i = max(c.i + 1, int(ceil((resume - c.seg.start) / c.seg.stepLength - ray.jitter)));
        if (skipping) {
            c.fine = false;
            c.lastCoarse = c.i - 1;
            c.zeros = 0;
        }
    }
    return found;
}

// The march's cheap part: from the cursor on (nextSamplePosition's skips), take base-only coarse
// steps through empty space and pass fine samples whose base shape is zero (no detail can add
// cloud there), up to the next fine sample with a base shape, which s receives; from one segment
// to the next. False when the ray's march ends first.
//
// Each phase of the march is a loop of its own (this one, the detail's in nextCloudySample, the
// light's in marchRayTo) rather than branches of one loop body: a SIMD machine that marches
// several rays in lockstep (a GPU's warp, llvmpipe's vector) runs every branch of a loop body for
// all of them, so one loop would make every empty-sky step pay for the detail noise and the light
// march. Per ray the samples, their order and the result are exactly those of a single loop.
inline bool nextFineSample(INOUT(MarchCursor) c, IN(MarchPath) path, IN(MarchRay) ray,
                           INOUT(MarchResult) result, INOUT(MarchSample) s, IN(CloudParams) P) {
    int coarse = max(P.coarseStepFactor, 1);
    bool skipping = coarse > 1 || P.stepOptimisation > 0.0f;
    bool found = false;
    while (nextSamplePosition(c, path, ray, result, s, skipping, P)) {
        s.ctx = densityContextAt(s.p, P);
        s.footprint = s.t * ray.pixelAngle;
        vec2 baseSample = baseCloudSample(s.ctx, distanceLod(s.footprint, P.log2BaseTexel, P), P);
        s.base = baseSample.x;
        result.densitySamples += 1;
        if (c.fine) {
            if (s.base > 0.0f) {
                found = true;
                break;
            }
            passEmptyFineSample(c, skipping); // no base shape: no detail can make cloud
            continue;
        }
        if (s.base > 0.0f) {
            c.fine = true;
            c.zeros = 0;
            c.i = max(c.lastCoarse + 1, c.fineFloor);
        } else {
            c.lastCoarse = c.i;
            c.i += coarse + int(float(coarse) * P.stepOptimisation * baseSample.y);
        }
    }
    return found;
}

// The next fine sample with cloud in it: nextFineSample's samples eroded by the detail noise
// until one has extinction. False when the ray's march ends first.
inline bool nextCloudySample(INOUT(MarchCursor) c, IN(MarchPath) path, IN(MarchRay) ray,
                             INOUT(MarchResult) result, INOUT(MarchSample) s, IN(CloudParams) P) {
    bool skipping = max(P.coarseStepFactor, 1) > 1 || P.stepOptimisation > 0.0f;
    bool found = false;
    while (nextFineSample(c, path, ray, result, s, P)) {
        float lod = distanceLod(s.footprint, P.log2DetailTexel, P);
        s.density = erodeWithDetail(s.base, s.ctx, lod, P);
        s.sigma = extinctionOf(s.density, P) * distanceFade(s.t, P);
        if (s.sigma > 0.0f) {
            c.fineFloor = c.i + 1;
            c.i += 1;
            c.zeros = 0;
            found = true;
            break;
        }
        passEmptyFineSample(c, skipping);
    }
    return found;
}

// March one unit ray (MarchRay); geometryDepth (m along the ray) is opaque scene geometry that
// ends the march (pass P.maxDistance or more for none).
//
// Coarse/fine sampling (GPU Pro 7 4.5.2): with a coarse factor c > 1, empty space is crossed in
// steps of c fine steps using cheap (base-only) samples; the first non-zero one steps back to
// where the last coarse step began and continues with full samples on the fine grid until
// ZERO_SAMPLES_TO_COARSE consecutive full samples are empty. The base shape bounds the full
// density from above, so coarse steps only miss clouds thinner than a coarse step. Everything
// sits on one fine grid, t = start + (i + jitter) * stepLength, so c = 1 is exactly the plain
// march.
//
// Step optimisation (Todd, "Investigation of volumetric cloud rendering techniques", III): where
// an empty cheap sample's profiled base shape lies far below the coverage threshold, the smooth
// base noise cannot reach cloud within a step, so the next coarse step is longer, by
// c * gain * margin fine steps (margin in [0, 1], see baseCloudSample). A longer step that lands
// in cloud steps back like any coarse step, so only clouds lying wholly between two samples are
// missed. gain 0 is off.
inline MarchResult marchRayTo(IN(MarchRay) ray, float geometryDepth, IN(CloudParams) P) {
    MarchResult result;
    result.radiance = vec3(0.0f, 0.0f, 0.0f);
    result.transmittance = 1.0f;
    result.depth = NO_HIT;
    result.densitySamples = 0;
    result.cloudSamples = 0;
    result.emptySkips = 0;
    result.lightSamples = 0;
    result.flash = 0.0f;

    vec4 spans = shellIntervals(ray.origin, ray.dir, P.planetRadius, P.layerBottom, P.layerTop);
    float maxDistance = P.maxDistance;
    float lenA = max(min(spans.y, maxDistance) - spans.x, 0.0f);
    float lenB = max(min(spans.w, maxDistance) - spans.z, 0.0f);
    float total = lenA + lenB;
    if (total <= 0.0f) {
        return result;
    }
    int steps = viewStepCount(ray.origin, ray.dir, P);
    // The step length follows the whole path through the shell, so geometry that cuts the ray
    // short saves steps rather than refining them; a ray that meets geometry before the shell is
    // not marched at all.
    float stepLength = total / float(steps);
    float end = min(maxDistance, geometryDepth);
    lenA = max(min(spans.y, end) - spans.x, 0.0f);
    lenB = max(min(spans.w, end) - spans.z, 0.0f);
    if (lenA + lenB <= 0.0f) {
        return result;
    }
    vec3 sunDir = cloudLightDirection(P.sky); // the sun, or the moon when it lights more
    float cosTheta = dot(ray.dir, sunDir);
    OctavePhases phases = octavePhasesFor(cosTheta, P);
    float lightLod = float(P.lightMipBias);
    bool skipping = max(P.coarseStepFactor, 1) > 1 || P.stepOptimisation > 0.0f;
    MarchPath path;
    path.spans = spans;
    path.lenA = lenA;
    path.lenB = lenB;
    path.stepLength = stepLength;
    MarchCursor c;
    startSegment(c, 0, path, skipping, P);
    MarchSample s;
    while (nextCloudySample(c, path, ray, result, s, P)) {
        result.cloudSamples += 1;
        if (result.depth == NO_HIT) {
            result.depth = s.t;
        }
        // Once the view ray is mostly opaque, what lies behind matters little: light it
        // with cheap samples (GPU Pro 7 4.5.3 uses alpha 0.3).
        bool cheapLight = 1.0f - result.transmittance > P.cheapLightAlpha;
        LightSample light = sunOpticalDepth(s.p, s.ctx.weather.y, lightLod, cheapLight, P);
        result.lightSamples += light.densitySamples;
        // Light energy = direct + ambient + the storm's internal glow and lightning (no extra
        // march); a masked flash goes to its own channel, at unit intensity.
        vec3 source = scatteredRadianceWith(s.p, light.opticalDepth, cosTheta, phases,
                                            s.ctx.heightFraction, s.base, P);
        vec3 emission = stormEmission(s.p, s.ctx.heightFraction, s.density, P);
        float maskedFlash = lightningMaskedUnit(s.p, s.ctx.heightFraction, s.density, P);
        // Integrate a constant source over the step exactly (Hillaire 2015): the light a
        // step adds is source * (1 - its transmittance), so thick steps never add energy.
        // The seeds' form, source * sigma * step, is kept selectable for comparison.
        float stepTransmittance = exp(-s.sigma * c.seg.stepLength);
        float stepWeight =
            P.energyConservingSteps != 0 ? 1.0f - stepTransmittance : s.sigma * c.seg.stepLength;
        result.radiance += source * (result.transmittance * stepWeight);
        if (maskedFlash > 0.0f || emission != vec3(0.0f, 0.0f, 0.0f)) {
            // The storm's emission and the light it scatters on its way out (lightning.glsl.h).
            float emissionWeight =
                emissionStepWeight(result.transmittance, s.sigma * c.seg.stepLength, P);
            result.radiance += emission * emissionWeight;
            result.flash += maskedFlash * emissionWeight;
        }
        result.transmittance *= stepTransmittance;
        if (result.transmittance < P.minTransmittance) {
            // Stopped: the rest of the ray is taken as opaque. Keeping the residue as the
            // cloud's transmittance would let the background through it, and the sun's disc
            // (some 10^4 times the sky's radiance) would shine through an overcast deck.
            result.transmittance = 0.0f;
            return result;
        }
    }
    return result;
}

inline MarchResult marchCloudsTo(vec3 origin, vec3 dir, float jitter, float pixelAngle,
                                 float geometryDepth, IN(CloudParams) P) {
    MarchRay ray;
    ray.origin = origin;
    ray.dir = dir;
    ray.jitter = jitter;
    ray.pixelAngle = pixelAngle;
    return marchRayTo(ray, geometryDepth, P);
}

// The march with no scene geometry.
inline MarchResult marchClouds(vec3 origin, vec3 dir, float jitter, float pixelAngle,
                               IN(CloudParams) P) {
    return marchCloudsTo(origin, dir, jitter, pixelAngle, P.maxDistance, P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
