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
    int emptySkips;      // grid lookups that skipped provably empty space (no texture read)
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

// Noise mip level for a view sample whose pixel covers `footprint` metres, for a texture whose
// texels are 2^log2Texel metres: far clouds read filtered noise instead of aliasing it into
// speckle (the view steps there are far longer than a detail texel).
inline float distanceLod(float footprint, float log2Texel, IN(CloudParams) P) {
    if (P.distanceLod == 0 || footprint <= 0.0f) {
        return 0.0f;
    }
    return max(log2(footprint) - log2Texel, 0.0f);
}

// March one unit ray. jitter in [0, 1) offsets the first sample within a step so that banding
// becomes noise; pixelAngle (radians) is the angle one pixel subtends, for the noise LOD (0 for
// none); geometryDepth (m along the ray) is opaque scene geometry that ends the march (pass
// P.maxDistance or more for none).
inline MarchResult marchCloudsTo(vec3 origin, vec3 dir, float jitter, float pixelAngle,
                                 float geometryDepth, IN(CloudParams) P) {
    MarchResult result;
    result.radiance = vec3(0.0f, 0.0f, 0.0f);
    result.transmittance = 1.0f;
    result.depth = NO_HIT;
    result.densitySamples = 0;
    result.cloudSamples = 0;
    result.emptySkips = 0;
    result.lightSamples = 0;
    result.flash = 0.0f;

    vec4 spans = shellIntervals(origin, dir, P.planetRadius, P.layerBottom, P.layerTop);
    float maxDistance = P.maxDistance;
    float lenA = max(min(spans.y, maxDistance) - spans.x, 0.0f);
    float lenB = max(min(spans.w, maxDistance) - spans.z, 0.0f);
    float total = lenA + lenB;
    if (total <= 0.0f) {
        return result;
    }
    int steps = viewStepCount(origin, dir, P);
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
    float cosTheta = dot(dir, sunDir);
    OctavePhases phases = octavePhasesFor(cosTheta, P);
    float lightLod = float(P.lightMipBias);

    // Coarse/fine sampling (GPU Pro 7 4.5.2): with a coarse factor c > 1, empty space is
    // crossed in steps of c fine steps using cheap (base-only) samples; the first non-zero one
    // steps back to where the last coarse step began and continues with full samples on the
    // fine grid until ZERO_SAMPLES_TO_COARSE consecutive full samples are empty. The base
    // shape bounds the full density from above, so coarse steps only miss clouds thinner than a
    // coarse step. Everything sits on one fine grid, t = start + (i + jitter) * stepLength, so
    // c = 1 is exactly the plain march.
    //
    // Step optimisation (Todd, "Investigation of volumetric cloud rendering techniques", III):
    // where an empty cheap sample's profiled base shape lies far below the coverage threshold, the
    // smooth base noise cannot reach cloud within a step, so the next coarse step is longer, by
    // c * gain * margin fine steps (margin in [0, 1], see baseCloudSample). A longer step that
    // lands in cloud steps back like any coarse step, so only clouds lying wholly between two
    // samples are missed. gain 0 is off.
    int coarse = max(P.coarseStepFactor, 1);
    float cheapLightAlpha = P.cheapLightAlpha;
    float stepGain = P.stepOptimisation;
    bool skipping = coarse > 1 || stepGain > 0.0f;
    for (int segment = 0; segment < 3; ++segment) {
        MarchSegment seg = marchSegment(segment, spans, lenA, lenB, stepLength, P);
        float start = seg.start;
        float len = seg.span;
        float segStep = seg.stepLength;
        if (len <= 0.0f) {
            continue;
        }
        int count = int(ceil(len / segStep));
        bool fine = !skipping;
        int zeros = 0;
        int fineFloor = 0;   // no fine step is ever taken twice
        int lastCoarse = -1; // the previous coarse (or last fine) sample
        int i = 0;
        while (i < count) {
            float t = start + (float(i) + jitter) * segStep;
            if (t > start + len) {
                break;
            }
            vec3 p = origin + dir * t;
            // Empty-space skipping: where the weather's cloud-top grid proves the column empty
            // at this altitude, jump to the first grid sample past the empty stretch without
            // reading a texture. The skipped samples would all have had zero density, so with
            // c = 1 the result is exactly the unskipped march's; with c > 1 the coarse lattice
            // restarts where the jump lands (a thin cloud between two coarse samples may be
            // found or missed differently, as any change of the lattice's phase would).
            if (P.emptySpaceSkipping != 0) {
                float empty = provablyEmptyDistance(p, dir, altitudeOf(p, P.planetRadius), P);
                if (empty > 0.0f) {
                    result.emptySkips += 1;
                    float resume = t + empty;
                    if (resume >= start + len) {
                        break;
                    }
                    i = max(i + 1, int(ceil((resume - start) / segStep - jitter)));
                    if (skipping) {
                        fine = false;
                        lastCoarse = i - 1;
                        zeros = 0;
                    }
                    continue;
                }
            }
            DensityContext ctx = densityContextAt(p, P);
            float footprint = t * pixelAngle;
            vec2 baseSample = baseCloudSample(ctx, distanceLod(footprint, P.log2BaseTexel, P), P);
            float base = baseSample.x;
            result.densitySamples += 1;
            if (!fine) {
                if (base > 0.0f) {
                    fine = true;
                    zeros = 0;
                    i = max(lastCoarse + 1, fineFloor);
                } else {
                    lastCoarse = i;
                    i += coarse + int(float(coarse) * stepGain * baseSample.y);
                }
                continue;
            }
            fineFloor = i + 1;
            i += 1;
            float density =
                base > 0.0f
                    ? erodeWithDetail(base, ctx, distanceLod(footprint, P.log2DetailTexel, P), P)
                    : 0.0f;
            float sigma = extinctionOf(density, P) * distanceFade(t, P);
            if (sigma <= 0.0f) {
                zeros += 1;
                if (skipping && zeros >= ZERO_SAMPLES_TO_COARSE) {
                    fine = false;
                    lastCoarse = i - 1;
                }
                continue;
            }
            zeros = 0;
            result.cloudSamples += 1;
            if (result.depth == NO_HIT) {
                result.depth = t;
            }
            // Once the view ray is mostly opaque, what lies behind matters little: light it
            // with cheap samples (GPU Pro 7 4.5.3 uses alpha 0.3).
            bool cheapLight = 1.0f - result.transmittance > cheapLightAlpha;
            LightSample light = sunOpticalDepth(p, ctx.weather.y, lightLod, cheapLight, P);
            result.lightSamples += light.densitySamples;
            // Light energy = direct + ambient + the storm's internal glow and lightning (no extra
            // march); a masked flash goes to its own channel, at unit intensity.
            vec3 source = scatteredRadianceWith(p, light.opticalDepth, cosTheta, phases,
                                                ctx.heightFraction, base, P);
            vec3 emission = stormEmission(p, ctx.heightFraction, density, P);
            float maskedFlash = lightningMaskedUnit(p, ctx.heightFraction, density, P);
            // Integrate a constant source over the step exactly (Hillaire 2015): the light a
            // step adds is source * (1 - its transmittance), so thick steps never add energy.
            // The seeds' form, source * sigma * step, is kept selectable for comparison.
            float stepTransmittance = exp(-sigma * segStep);
            float stepWeight =
                P.energyConservingSteps != 0 ? 1.0f - stepTransmittance : sigma * segStep;
            result.radiance += source * (result.transmittance * stepWeight);
            if (maskedFlash > 0.0f || emission != vec3(0.0f, 0.0f, 0.0f)) {
                // The storm's emission and the light it scatters on its way out (lightning.glsl.h).
                float emissionWeight = emissionStepWeight(result.transmittance, sigma * segStep, P);
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
    }
    return result;
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
