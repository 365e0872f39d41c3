// The view-ray march through the cloud shell (GPU Pro 7 4.5): 64 steps toward the zenith rising
// to 128 toward the horizon, full samples where the base shape is non-zero, a light march only
// where there is cloud, energy-conserving integration of each step, early exit once the ray is
// opaque. Output: premultiplied radiance, transmittance and the distance to the first cloud.
#ifndef CLOUDSCAPE_MODEL_MARCH_GLSL_H
#define CLOUDSCAPE_MODEL_MARCH_GLSL_H

#include "compat.glsl.h"
#include "density.glsl.h"
#include "lighting.glsl.h"
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
    int lightSamples;    // density evaluations along light rays
};

// Number of view steps for a ray: GPU Pro 7 takes 64 straight up and 128 at the horizon, where
// the path through the shell is far longer.
inline int viewStepCount(vec3 origin, vec3 dir, IN(CloudParams) P) {
    vec3 up = normalize(origin - planetCentre(P.planet.x));
    float upness = abs(dot(dir, up));
    return int(mix(P.march.y, P.march.x, upness) + 0.5f);
}

// Consecutive empty full samples after which coarse/fine sampling returns to coarse steps.
CONST_INT ZERO_SAMPLES_TO_COARSE = 6;

// Fade of cloud density toward the maximum march distance: a stand-in for aerial perspective,
// which the atmosphere will replace, so that distant clouds sink into the horizon instead of
// ending at a hard edge.
inline float distanceFade(float t, IN(CloudParams) P) {
    return 1.0f - smoothstep(P.skyHorizon.w * P.march.w, P.march.w, t);
}

// Noise mip level for a view sample whose pixel covers `footprint` metres, for a texture whose
// texels are 2^log2Texel metres: far clouds read filtered noise instead of aliasing it into
// speckle (the view steps there are far longer than a detail texel).
inline float distanceLod(float footprint, float log2Texel, IN(CloudParams) P) {
    if (P.distanceLod.z == 0.0f || footprint <= 0.0f) {
        return 0.0f;
    }
    return max(log2(footprint) - log2Texel, 0.0f);
}

// March one unit ray. jitter in [0, 1) offsets the first sample within a step so that banding
// becomes noise; pixelAngle (radians) is the angle one pixel subtends, for the noise LOD (0 for
// none).
inline MarchResult marchClouds(vec3 origin, vec3 dir, float jitter, float pixelAngle,
                               IN(CloudParams) P) {
    MarchResult result;
    result.radiance = vec3(0.0f, 0.0f, 0.0f);
    result.transmittance = 1.0f;
    result.depth = NO_HIT;
    result.densitySamples = 0;
    result.lightSamples = 0;

    vec4 spans = shellIntervals(origin, dir, P.planet.x, P.planet.y, P.planet.z);
    float maxDistance = P.march.w;
    float lenA = max(min(spans.y, maxDistance) - spans.x, 0.0f);
    float lenB = max(min(spans.w, maxDistance) - spans.z, 0.0f);
    float total = lenA + lenB;
    if (total <= 0.0f) {
        return result;
    }
    int steps = viewStepCount(origin, dir, P);
    float stepLength = total / float(steps);
    vec3 sunDir = vec3(P.sunDirection.x, P.sunDirection.y, P.sunDirection.z);
    float cosTheta = dot(dir, sunDir);
    float lightLod = float(P.counts.z);

    // Coarse/fine sampling (GPU Pro 7 4.5.2): with a coarse factor c > 1, empty space is
    // crossed in steps of c fine steps using cheap (base-only) samples; the first non-zero one
    // steps back to where the last coarse step began and continues with full samples on the
    // fine grid until ZERO_SAMPLES_TO_COARSE consecutive full samples are empty. The base
    // shape bounds the full density from above, so coarse steps only miss clouds thinner than a
    // coarse step. Everything sits on one fine grid, t = start + (i + jitter) * stepLength, so
    // c = 1 is exactly the plain march.
    int coarse = max(int(P.optimisation.x), 1);
    float cheapLightAlpha = P.optimisation.y;
    for (int span = 0; span < 2; ++span) {
        float start = span == 0 ? spans.x : spans.z;
        float len = span == 0 ? lenA : lenB;
        int count = int(ceil(len / stepLength));
        bool fine = coarse == 1;
        int zeros = 0;
        int fineFloor = 0; // no fine step is ever taken twice
        int i = 0;
        while (i < count) {
            float t = start + (float(i) + jitter) * stepLength;
            if (t > start + len) {
                break;
            }
            vec3 p = origin + dir * t;
            DensityContext ctx = densityContextAt(p, P);
            float footprint = t * pixelAngle;
            float base = baseCloudDensity(ctx, distanceLod(footprint, P.distanceLod.x, P), P);
            result.densitySamples += 1;
            if (!fine) {
                if (base > 0.0f) {
                    fine = true;
                    zeros = 0;
                    i = max(i - coarse + 1, fineFloor);
                } else {
                    i += coarse;
                }
                continue;
            }
            fineFloor = i + 1;
            i += 1;
            float density =
                base > 0.0f
                    ? erodeWithDetail(base, ctx, distanceLod(footprint, P.distanceLod.y, P), P)
                    : 0.0f;
            float sigma = extinctionOf(density, P) * distanceFade(t, P);
            if (sigma <= 0.0f) {
                zeros += 1;
                if (coarse > 1 && zeros >= ZERO_SAMPLES_TO_COARSE) {
                    fine = false;
                }
                continue;
            }
            zeros = 0;
            if (result.depth == NO_HIT) {
                result.depth = t;
            }
            // Once the view ray is mostly opaque, what lies behind matters little: light it
            // with cheap samples (GPU Pro 7 4.5.3 uses alpha 0.3).
            bool cheapLight = 1.0f - result.transmittance > cheapLightAlpha;
            LightSample light = sunOpticalDepth(p, ctx.weather.y, lightLod, cheapLight, P);
            result.lightSamples += light.densitySamples;
            vec3 source =
                scatteredRadiance(light.opticalDepth, cosTheta, ctx.heightFraction, base, P);
            // Integrate a constant source over the step exactly (Hillaire 2015): the light a
            // step adds is source * (1 - its transmittance), so thick steps never add energy.
            float stepTransmittance = exp(-sigma * stepLength);
            result.radiance += source * (result.transmittance * (1.0f - stepTransmittance));
            result.transmittance *= stepTransmittance;
            if (result.transmittance < P.march.z) {
                return result;
            }
        }
    }
    return result;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
