// The sky: a placeholder gradient with a sun disc and a soft glow, and the light the clouds take
// from it. This header and SkyParams (params.glsl.h) are the seam an atmosphere model replaces:
// the clouds ask the sky for the radiance along a direction (skyRadiance, skyBackground), the sun
// (SkyParams.sunDirection, sunIrradiance; its disc through sunSolidAngle and insideSunDisc) and
// the ambient light (skyAmbient), and for nothing else.
#ifndef CLOUDSCAPE_MODEL_SKY_GLSL_H
#define CLOUDSCAPE_MODEL_SKY_GLSL_H

#include "compat.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The sky without the sun disc: a gradient, the ground below the horizon and a glow.
inline vec3 skyBackground(vec3 dir, IN(SkyParams) S) {
    vec3 sky;
    if (dir.y >= 0.0f) {
        sky = mix(S.horizon, S.zenith, pow(dir.y, 0.45f));
    } else {
        sky = mix(S.horizon, S.ground, smoothstep(0.0f, 0.03f, -dir.y));
    }
    float cosTheta = dot(dir, S.sunDirection);
    // A faint forward-scattering glow around the sun, as haze would give; the ground does not
    // glow.
    float aboveHorizon = smoothstep(-0.02f, 0.0f, dir.y);
    sky += S.sunIrradiance * (0.02f * henyeyGreenstein(cosTheta, 0.8f) * aboveHorizon);
    return sky;
}

// The sun's disc, exactly, in one formula for the real-time renderer and the path tracer: its
// solid angle is 2 pi (1 - cos r), with 1 - cos r computed on the host in double precision
// (cos r of a sun-sized r is within a few float steps of 1, so the float form is up to 25 % off).
inline float sunSolidAngle(IN(SkyParams) S) {
    return 2.0f * PI * S.sunOneMinusCos;
}

// The disc's radiance: the irradiance spread over its solid angle.
inline vec3 sunDiscRadiance(IN(SkyParams) S) {
    return S.sunIrradiance / sunSolidAngle(S);
}

// True if dir looks into the sun's disc (and the disc is above the horizon). For unit vectors
// |dir - sun|^2 = 2 (1 - cos angle), and the difference keeps its precision where the cosine
// would round to 1.
inline bool insideSunDisc(vec3 dir, IN(SkyParams) S) {
    vec3 d = dir - S.sunDirection;
    return dot(d, d) < 2.0f * S.sunOneMinusCos && dir.y > -0.01f;
}

// The sky seen along dir, sun disc included.
inline vec3 skyRadiance(vec3 dir, IN(SkyParams) S) {
    vec3 sky = skyBackground(dir, S);
    if (insideSunDisc(dir, S)) {
        sky += sunDiscRadiance(S);
    }
    return sky;
}

// The colour of the ambient light reaching cloud at a height fraction of the layer: from below
// (ground bounce) at the base to the sky above at the top, before S.ambientStrength.
inline vec3 skyAmbient(float heightFraction, IN(SkyParams) S) {
    return mix(S.ambientBottom, S.ambientTop, heightFraction);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
