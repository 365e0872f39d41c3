// The sky and the light the clouds take from it. Two models behind one seam: the physically based
// atmosphere (atmosphere.glsl.h, SkyParams.atmosphere.enabled) and the placeholder gradient. The
// clouds ask the sky for the radiance along a direction (skyRadiance, skyBackground), the sun's
// irradiance at a point (sunIrradianceAt; its disc through sunSolidAngle and insideSunDisc), the
// ambient light at a point (skyAmbientAt) and the air between the camera and a cloud
// (aerialPerspective), and for nothing else.
#ifndef CLOUDSCAPE_MODEL_SKY_GLSL_H
#define CLOUDSCAPE_MODEL_SKY_GLSL_H

#include "atmosphere.glsl.h"
#include "compat.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The placeholder sky without the sun disc: a gradient, the ground below the horizon and a glow.
inline vec3 gradientSky(vec3 dir, IN(SkyParams) S) {
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

// The atmosphere seen from the camera along dir (the sky-view table; below the horizon the lit
// ground through the air). The camera's zenith is +y.
inline vec3 atmosphereSky(vec3 dir, IN(SkyParams) S) {
    float r = skyViewRadius(S.atmosphere);
    float viewZenith = acos(clamp(dir.y, -1.0f, 1.0f));
    vec2 viewHorizontal = vec2(dir.x, dir.z);
    vec2 sunHorizontal = vec2(S.sunDirection.x, S.sunDirection.z);
    float lengths = length(viewHorizontal) * length(sunHorizontal);
    float cosAzimuth = lengths > 1e-12f ? dot(viewHorizontal, sunHorizontal) / lengths : 1.0f;
    vec4 t = lutBilinear(SKYVIEW_LUT_OFFSET, SKYVIEW_LUT_WIDTH, SKYVIEW_LUT_HEIGHT,
                         skyViewLutUv(r, viewZenith, clamp(cosAzimuth, -1.0f, 1.0f), S.atmosphere));
    return vec3(t.x, t.y, t.z) * S.sunIrradiance;
}

// The sky without the sun disc.
inline vec3 skyBackground(vec3 dir, IN(SkyParams) S) {
    if (S.atmosphere.enabled != 0) {
        return atmosphereSky(dir, S);
    }
    return gradientSky(dir, S);
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

// The disc's limb darkening at dir (inside it): I = 1 - u (1 - mu), normalised so the disc still
// delivers sunIrradiance.
inline float sunLimbDarkening(vec3 dir, IN(SkyParams) S) {
    vec3 d = dir - S.sunDirection;
    float fromCentre2 = dot(d, d) / max(2.0f * S.sunOneMinusCos, 1e-20f); // (angle / radius)^2
    float mu = sqrt(max(1.0f - fromCentre2, 0.0f));
    float u = S.atmosphere.limbDarkening;
    return (1.0f - u * (1.0f - mu)) / (1.0f - u / 3.0f);
}

// The sun disc's radiance at dir (inside it): with the atmosphere, dimmed and reddened by the air
// toward the sun and darkened toward the limb.
inline vec3 sunDiscSeen(vec3 dir, IN(SkyParams) S) {
    if (S.atmosphere.enabled == 0) {
        return sunDiscRadiance(S);
    }
    float limb = sunLimbDarkening(dir, S);
    float r = skyViewRadius(S.atmosphere);
    return sunDiscRadiance(S) * limb * sunTransmittance(r, dir.y, 0.0f, S.atmosphere);
}

// The sky seen along dir, sun disc included.
inline vec3 skyRadiance(vec3 dir, IN(SkyParams) S) {
    vec3 sky = skyBackground(dir, S);
    if (insideSunDisc(dir, S)) {
        sky += sunDiscSeen(dir, S);
    }
    return sky;
}

// Radius (from the planet's centre) and sun zenith cosine at a world position.
inline vec2 atmospherePosition(vec3 p, IN(SkyParams) S) {
    vec3 fromCentre = p - vec3(0.0f, -S.atmosphere.bottomRadius, 0.0f);
    float r = length(fromCentre);
    return vec2(r, dot(fromCentre / r, S.sunDirection));
}

// The sun's irradiance on a surface facing it at a world position: through the atmosphere (which
// reddens a low sun and whose planet shadow darkens the low clouds first after sunset), or the
// placeholder's constant.
inline vec3 sunIrradianceAt(vec3 p, IN(SkyParams) S) {
    if (S.atmosphere.enabled == 0) {
        return S.sunIrradiance;
    }
    vec2 rMuS = atmospherePosition(p, S);
    return S.sunIrradiance * sunTransmittance(rMuS.x, rMuS.y, S.sunAngularRadius, S.atmosphere);
}

// The ambient light of cloud at a world position and a height fraction of the layer, before
// S.ambientStrength: from below (the lit ground and air) at the base to the sky above at the top.
// With the atmosphere both are its tables' mean radiance over the half spaces at that point;
// otherwise the placeholder's colours.
inline vec3 skyAmbientAt(vec3 p, float heightFraction, IN(SkyParams) S) {
    if (S.atmosphere.enabled == 0) {
        return mix(S.ambientBottom, S.ambientTop, heightFraction);
    }
    vec2 rMuS = atmospherePosition(p, S);
    vec2 uv = ambientLutUv(rMuS.x, rMuS.y, S.atmosphere);
    vec4 above = lutBilinear(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE, uv);
    vec4 below = lutBilinear(AMBIENT_BELOW_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE, uv);
    vec4 ambient = mix(below, above, heightFraction);
    return vec3(ambient.x, ambient.y, ambient.z) * S.sunIrradiance;
}

// The air between the camera and a point `distance` away along dir: the light it scatters toward
// the camera and its transmittance (per pixel, AERIAL_PERSPECTIVE_STEPS steps through the
// tables). No air without the atmosphere or with atmosphere.aerial_perspective off.
struct AirLight {
    vec3 inScattered;
    vec3 transmittance;
};

inline AirLight aerialPerspective(vec3 origin, vec3 dir, float distance, IN(SkyParams) S) {
    AirLight air;
    air.inScattered = vec3(0.0f);
    air.transmittance = vec3(1.0f);
    if (S.atmosphere.enabled == 0 || S.atmosphere.aerialPerspective == 0 || distance <= 0.0f) {
        return air;
    }
    vec2 rMu = atmospherePosition(origin, S);
    float r = min(rMu.x, S.atmosphere.topRadius - 1.0f);
    // The ray in the frame atmosphere.glsl.h integrates in: the origin on the y axis.
    vec3 fromCentre = origin - vec3(0.0f, -S.atmosphere.bottomRadius, 0.0f);
    vec3 up = fromCentre / rMu.x;
    float mu = dot(dir, up);
    vec3 side = dir - up * mu;
    float sideLength = length(side);
    vec3 x = sideLength > 1e-6f ? side / sideLength : vec3(1.0f, 0.0f, 0.0f);
    vec3 z = cross(up, x);
    vec3 localDir = vec3(sideLength, mu, 0.0f);
    vec3 localSun = vec3(dot(S.sunDirection, x), dot(S.sunDirection, up), dot(S.sunDirection, z));
    ScatteredLight s =
        scatterAlongRay(r, localDir, localSun, distance, false, AERIAL_PERSPECTIVE_STEPS, false,
                        S.sunAngularRadius, S.atmosphere);
    air.inScattered = s.radiance * S.sunIrradiance;
    air.transmittance = s.transmittance;
    return air;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
