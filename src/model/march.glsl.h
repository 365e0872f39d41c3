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

// Fade of cloud density toward the maximum march distance: a stand-in for aerial perspective,
// which the atmosphere will replace, so that distant clouds sink into the horizon instead of
// ending at a hard edge.
inline float distanceFade(float t, IN(CloudParams) P) {
    return 1.0f - smoothstep(P.skyHorizon.w * P.march.w, P.march.w, t);
}

// March one unit ray. jitter in [0, 1) offsets the first sample within a step so that banding
// becomes noise.
inline MarchResult marchClouds(vec3 origin, vec3 dir, float jitter, IN(CloudParams) P) {
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

    for (int span = 0; span < 2; ++span) {
        float start = span == 0 ? spans.x : spans.z;
        float len = span == 0 ? lenA : lenB;
        int count = int(ceil(len / stepLength));
        for (int i = 0; i < count; ++i) {
            float t = start + (float(i) + jitter) * stepLength;
            if (t > start + len) {
                break;
            }
            vec3 p = origin + dir * t;
            DensityContext ctx = densityContextAt(p, P);
            float base = baseCloudDensity(ctx, 0.0f, P);
            result.densitySamples += 1;
            if (base <= 0.0f) {
                continue;
            }
            float density = erodeWithDetail(base, ctx, 0.0f, P);
            float sigma = extinctionOf(density, P) * distanceFade(t, P);
            if (sigma <= 0.0f) {
                continue;
            }
            if (result.depth == NO_HIT) {
                result.depth = t;
            }
            LightSample light = sunOpticalDepth(p, ctx.weather.y, lightLod, false, P);
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
