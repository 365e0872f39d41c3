// The placeholder sky behind the clouds (a gradient and a sun disc with a soft glow) and the
// final composition and tone mapping. The atmosphere model will replace skyRadiance.
#ifndef CLOUDSCAPE_MODEL_SKY_GLSL_H
#define CLOUDSCAPE_MODEL_SKY_GLSL_H

#include "compat.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The sky without the sun disc: a gradient, the ground below the horizon and a glow.
inline vec3 skyBackground(vec3 dir, IN(CloudParams) P) {
    vec3 zenith = P.sky.zenith;
    vec3 horizon = P.sky.horizon;
    vec3 ground = P.sky.ground;
    vec3 sunDir = P.sky.sunDirection;
    vec3 sun = P.sky.sunIrradiance;
    vec3 sky;
    if (dir.y >= 0.0f) {
        sky = mix(horizon, zenith, pow(dir.y, 0.45f));
    } else {
        sky = mix(horizon, ground, smoothstep(0.0f, 0.03f, -dir.y));
    }
    float cosTheta = dot(dir, sunDir);
    // A faint forward-scattering glow around the sun, as haze would give; the ground does not
    // glow.
    float aboveHorizon = smoothstep(-0.02f, 0.0f, dir.y);
    sky += sun * (0.02f * henyeyGreenstein(cosTheta, 0.8f) * aboveHorizon);
    return sky;
}

// The sun disc's radiance: the irradiance spread over its solid angle (pi r^2 for a small disc).
inline vec3 sunDiscRadiance(IN(CloudParams) P) {
    vec3 sun = P.sky.sunIrradiance;
    float radius = P.sky.sunAngularRadius;
    return sun / (PI * radius * radius);
}

// True if dir looks into the sun's disc (and the disc is above the horizon).
inline bool insideSunDisc(vec3 dir, IN(CloudParams) P) {
    vec3 sunDir = P.sky.sunDirection;
    return dot(dir, sunDir) > cos(P.sky.sunAngularRadius) && dir.y > -0.01f;
}

// The sky seen along dir, sun disc included.
inline vec3 skyRadiance(vec3 dir, IN(CloudParams) P) {
    vec3 sky = skyBackground(dir, P);
    if (insideSunDisc(dir, P)) {
        sky += sunDiscRadiance(P);
    }
    return sky;
}

// Clouds in front of the sky, premultiplied: colour = cloud + transmittance * background.
inline vec3 compositeOver(vec3 cloudRadiance, float transmittance, vec3 background) {
    return cloudRadiance + background * transmittance;
}

// ACES filmic curve (Narkowicz's fit) on exposed linear radiance, then the sRGB transfer
// function: the one place where HDR becomes display values.
inline float linearToSrgb(float x) {
    x = saturate(x);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

inline vec3 toneMap(vec3 radiance, float exposure) {
    vec3 x = radiance * exposure;
    vec3 mapped = (x * (x * 2.51f + vec3(0.03f))) / (x * (x * 2.43f + vec3(0.59f)) + vec3(0.14f));
    return vec3(linearToSrgb(mapped.x), linearToSrgb(mapped.y), linearToSrgb(mapped.z));
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
