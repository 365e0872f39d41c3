// The sky and the light the clouds take from it. Two models behind one seam: the physically based
// atmosphere (atmosphere.glsl.h, SkyParams.atmosphere.enabled) and the placeholder gradient. The
// clouds ask the sky for the radiance along a direction (skyRadiance, skyBackground), the sun's
// irradiance at a point (sunIrradianceAt; its disc through sunSolidAngle and insideSunDisc), the
// ambient light at a point (skyAmbientAt) and the air between the camera and a cloud
// (aerialPerspective), and for nothing else. At night the moon is a second source of the same
// tables (per unit irradiance: a second sky view for its direction, a second ambient lookup, a
// second aerial-perspective integral while it is on), and the clouds' direct light is the one
// source that lights them more (cloudLightDirection, cloudLightIrradianceAt).
#ifndef CLOUDSCAPE_MODEL_SKY_GLSL_H
#define CLOUDSCAPE_MODEL_SKY_GLSL_H

#include "atmosphere.glsl.h"
#include "compat.glsl.h"
#include "features.glsl.h"
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

// Where dir lies in the sky-view table's (u, v) for a source: the table is made in the frame
// whose azimuth 0 is the source's. The camera's zenith is +y. The aerial-perspective volume
// shares the mapping.
inline vec2 skyViewUvToward(vec3 dir, vec3 source, IN(SkyParams) S) {
    float r = skyViewRadius(S.atmosphere);
    float viewZenith = acos(clamp(dir.y, -1.0f, 1.0f));
    vec2 viewHorizontal = vec2(dir.x, dir.z);
    vec2 sourceHorizontal = vec2(source.x, source.z);
    float lengths = length(viewHorizontal) * length(sourceHorizontal);
    float cosAzimuth = lengths > 1e-12f ? dot(viewHorizontal, sourceHorizontal) / lengths : 1.0f;
    return skyViewLutUv(r, viewZenith, clamp(cosAzimuth, -1.0f, 1.0f), S.atmosphere);
}

// The sky-view table at `offset` (the sun's or the moon's) along dir, per unit irradiance of its
// source.
inline vec3 skyViewToward(int offset, vec3 dir, vec3 source, IN(SkyParams) S) {
    vec4 t =
        lutBilinear(offset, SKYVIEW_LUT_WIDTH, SKYVIEW_LUT_HEIGHT, skyViewUvToward(dir, source, S));
    return vec3(t.x, t.y, t.z);
}

// True if the night sky's floor (S.nightRadiance) is on.
inline bool hasNightGlow(IN(SkyParams) S) {
    return S.nightRadiance.x + S.nightRadiance.y + S.nightRadiance.z > 0.0f;
}

// The night sky's own light along dir: airglow and starlight, which come from above the air
// (airglow from about 90 km), dimmed by the air on the way. Rays that meet the ground see the
// ground, which takes this light as sky light (skyAmbientAbove).
inline vec3 nightGlow(vec3 dir, IN(SkyParams) S) {
    float r = skyViewRadius(S.atmosphere);
    if (!hasNightGlow(S) || distanceToGround(r, dir.y, S.atmosphere) >= 0.0f) {
        return vec3(0.0f);
    }
    return S.nightRadiance * transmittanceToTop(r, dir.y, S.atmosphere);
}

// The atmosphere seen from the camera along dir (the sky-view tables; below the horizon the lit
// ground through the air): the sun's light, the moon's while it is on (the same light transport
// per unit irradiance, from its own direction), and the night sky's floor.
inline vec3 atmosphereSky(vec3 dir, IN(SkyParams) S) {
    vec3 sky = skyViewToward(SKYVIEW_LUT_OFFSET, dir, S.sunDirection, S) * S.sunIrradiance;
    if (moonOn(S)) {
        sky += skyViewToward(MOON_SKYVIEW_LUT_OFFSET, dir, S.moonDirection, S) * S.moonIrradiance;
    }
    if (hasNightGlow(S)) {
        sky += nightGlow(dir, S);
    }
    return sky;
}

// The sky without the sun disc.
inline vec3 skyBackground(vec3 dir, IN(SkyParams) S) {
    if (atmosphereOn(S)) {
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
    if (!atmosphereOn(S)) {
        return sunDiscRadiance(S);
    }
    float limb = sunLimbDarkening(dir, S);
    float r = skyViewRadius(S.atmosphere);
    return sunDiscRadiance(S) * limb * sunTransmittance(r, dir.y, 0.0f, S.atmosphere);
}

// True if dir looks into the moon's disc (the moon on and above the horizon), as insideSunDisc.
inline bool insideMoonDisc(vec3 dir, IN(SkyParams) S) {
    vec3 d = dir - S.moonDirection;
    return moonOn(S) && dot(d, d) < 2.0f * S.moonOneMinusCos && dir.y > -0.01f;
}

// The fraction of the moon's disc that is lit at phase angle alpha: (1 + cos alpha) / 2.
inline float moonIlluminatedFraction(float phaseAngle) {
    return 0.5f * (1.0f + cos(phaseAngle));
}

// The moon's disc at dir (inside it): a sphere lit from the sun at the phase angle, its bright
// limb toward S.moonBrightLimb. The lit part has the radiance that spreads the moon's
// irradiance (already at its phase) over that part; no limb darkening (the full moon is famously
// flat). Dimmed by the air toward it, as the sun's disc.
inline vec3 moonDiscSeen(vec3 dir, IN(SkyParams) S) {
    vec3 d = dir - S.moonDirection;
    float radius = sqrt(max(2.0f * S.moonOneMinusCos, 1e-20f)); // the chord, as insideMoonDisc
    vec3 across = cross(S.moonDirection, S.moonBrightLimb);
    float u = dot(d, S.moonBrightLimb) / radius;
    float v = dot(d, across) / radius;
    float towardViewer = sqrt(max(1.0f - u * u - v * v, 0.0f));
    // The sphere's normal there against the sun's direction in the moon's frame (x toward the
    // bright limb, z toward the viewer): lit where it faces the sun.
    float lit = u * sin(S.moonPhaseAngle) + towardViewer * cos(S.moonPhaseAngle);
    if (lit <= 0.0f) {
        return vec3(0.0f);
    }
    float litSolidAngle =
        2.0f * PI * S.moonOneMinusCos * max(moonIlluminatedFraction(S.moonPhaseAngle), 1e-3f);
    float r = skyViewRadius(S.atmosphere);
    return S.moonIrradiance / litSolidAngle * sunTransmittance(r, dir.y, 0.0f, S.atmosphere);
}

// The sky seen along dir, sun disc (and moon disc) included.
inline vec3 skyRadiance(vec3 dir, IN(SkyParams) S) {
    vec3 sky = skyBackground(dir, S);
    if (insideSunDisc(dir, S)) {
        sky += sunDiscSeen(dir, S);
    } else if (insideMoonDisc(dir, S)) {
        sky += moonDiscSeen(dir, S);
    }
    return sky;
}

// Radius (from the planet's centre) and the zenith cosine of `source` at a world position.
inline vec2 atmospherePositionToward(vec3 p, vec3 source, IN(SkyParams) S) {
    vec3 fromCentre = p - vec3(0.0f, -S.atmosphere.bottomRadius, 0.0f);
    float r = length(fromCentre);
    return vec2(r, dot(fromCentre / r, source));
}

// Radius and sun zenith cosine at a world position.
inline vec2 atmospherePosition(vec3 p, IN(SkyParams) S) {
    return atmospherePositionToward(p, S.sunDirection, S);
}

// The sun's irradiance on a surface facing it at a world position: through the atmosphere (which
// reddens a low sun and whose planet shadow darkens the low clouds first after sunset), or the
// placeholder's constant.
inline vec3 sunIrradianceAt(vec3 p, IN(SkyParams) S) {
    if (!atmosphereOn(S)) {
        return S.sunIrradiance;
    }
    vec2 rMuS = atmospherePosition(p, S);
    return S.sunIrradiance * sunTransmittance(rMuS.x, rMuS.y, S.sunAngularRadius, S.atmosphere);
}

// The moon's irradiance on a surface facing it at a world position, through the atmosphere and
// the planet's shadow as the sun's (the moon is on only with the atmosphere).
inline vec3 moonIrradianceAt(vec3 p, IN(SkyParams) S) {
    vec2 rMu = atmospherePositionToward(p, S.moonDirection, S);
    return S.moonIrradiance * sunTransmittance(rMu.x, rMu.y, S.moonAngularRadius, S.atmosphere);
}

// The clouds' direct light comes from one source, the one that lights the layer more
// (S.moonLightsClouds, chosen per frame by moonOutshinesSun): its direction and its irradiance at
// a point. The light cone of the march, the ground's and the high layer's direct light use these.
inline vec3 cloudLightDirection(IN(SkyParams) S) {
    return S.moonLightsClouds != 0 ? S.moonDirection : S.sunDirection;
}

inline vec3 cloudLightIrradianceAt(vec3 p, IN(SkyParams) S) {
    if (S.moonLightsClouds != 0) {
        return moonIrradianceAt(p, S);
    }
    return sunIrradianceAt(p, S);
}

// Luminance of linear Rec. 709 RGB.
inline float skyLuminance(vec3 c) {
    return dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
}

// The rule behind S.moonLightsClouds, for the host once per frame: the moon lights the clouds
// when its light on the layer's top above the camera outshines the sun's brightest light on the
// layer, which falls on its top `reach` metres from the camera toward the sun (the last of the
// layer to leave the planet's shadow). So the switch happens where the sun's light is already
// below the moon's everywhere in view and cannot pop by more than the moon's own light.
inline bool moonOutshinesSun(vec3 camera, float layerTop, float reach, IN(SkyParams) S) {
    if (!moonOn(S) || !atmosphereOn(S)) {
        return false;
    }
    float R = S.atmosphere.bottomRadius;
    vec2 toSun = vec2(S.sunDirection.x, S.sunDirection.z);
    float horizontal = length(toSun);
    toSun = horizontal > 1e-6f ? toSun / horizontal : vec2(0.0f);
    float topRadius = R + layerTop;
    // The point at the layer's top altitude, `reach` away over the curved ground.
    float y = sqrt(max(topRadius * topRadius - reach * reach, 0.0f)) - R;
    vec3 sunPoint = vec3(camera.x + toSun.x * reach, y, camera.z + toSun.y * reach);
    vec3 moonPoint = vec3(camera.x, layerTop, camera.z);
    return skyLuminance(sunIrradianceAt(sunPoint, S)) <
           skyLuminance(moonIrradianceAt(moonPoint, S));
}

// The ambient tables' mean radiance over the upper and lower half spaces at radius r for a
// source at zenith cosine mu, blended by the height fraction, per unit irradiance.
inline vec3 ambientTablesAt(float r, float mu, float heightFraction, IN(SkyParams) S) {
    vec2 uv = ambientLutUv(r, mu, S.atmosphere);
    vec4 above = lutBilinear(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE, uv);
    vec4 below = lutBilinear(AMBIENT_BELOW_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE, uv);
    vec4 ambient = mix(below, above, heightFraction);
    return vec3(ambient.x, ambient.y, ambient.z);
}

// The ambient light of cloud at a world position and a height fraction of the layer, before
// S.ambientStrength: from below (the lit ground and air) at the base to the sky above at the top.
// With the atmosphere both are its tables' mean radiance over the half spaces at that point, for
// the sun and (a second lookup at its zenith cosine) the moon, plus the night sky's floor (from
// below: the ground at its albedo); otherwise the placeholder's colours.
inline vec3 skyAmbientAt(vec3 p, float heightFraction, IN(SkyParams) S) {
    if (!atmosphereOn(S)) {
        return mix(S.ambientBottom, S.ambientTop, heightFraction);
    }
    vec2 rMuS = atmospherePosition(p, S);
    vec3 ambient = ambientTablesAt(rMuS.x, rMuS.y, heightFraction, S) * S.sunIrradiance;
    if (moonOn(S)) {
        vec2 rMuM = atmospherePositionToward(p, S.moonDirection, S);
        ambient += ambientTablesAt(rMuM.x, rMuM.y, heightFraction, S) * S.moonIrradiance;
    }
    if (hasNightGlow(S)) {
        ambient +=
            mix(S.nightRadiance * S.atmosphere.groundAlbedo, S.nightRadiance, heightFraction);
    }
    return ambient;
}

// The sky's mean radiance over the upper half space at p (its irradiance on level ground over
// pi), from the sun, the moon and the night sky's floor; atmosphere only.
inline vec3 skyAmbientAbove(vec3 p, IN(SkyParams) S) {
    vec2 rMuS = atmospherePosition(p, S);
    vec4 sky = lutBilinear(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE,
                           ambientLutUv(rMuS.x, rMuS.y, S.atmosphere));
    vec3 radiance = vec3(sky.x, sky.y, sky.z) * S.sunIrradiance;
    if (moonOn(S)) {
        vec2 rMuM = atmospherePositionToward(p, S.moonDirection, S);
        vec4 moon = lutBilinear(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE,
                                ambientLutUv(rMuM.x, rMuM.y, S.atmosphere));
        radiance += vec3(moon.x, moon.y, moon.z) * S.moonIrradiance;
    }
    if (hasNightGlow(S)) {
        radiance += S.nightRadiance;
    }
    return radiance;
}

// The air between the camera and a point `distance` away along dir: the light it scatters toward
// the camera and its transmittance. No air without the atmosphere or with
// atmosphere.aerial_perspective off.
struct AirLight {
    vec3 inScattered;
    vec3 transmittance;
};

// The air between the camera and a point `distance` away along dir, from the aerial-perspective
// volume (atmosphere.glsl.h): what every composite uses (the clouds, the high layer, the ground
// and the terrain are all seen from the camera). The integral below is its reference, and serves
// origins other than the camera.
inline AirLight cameraAerialPerspective(vec3 dir, float distance, IN(SkyParams) S) {
    AirLight air;
    air.inScattered = vec3(0.0f);
    air.transmittance = vec3(1.0f);
    if (!atmosphereOn(S) || S.atmosphere.aerialPerspective == 0 || distance <= 0.0f) {
        return air;
    }
    float slice = aerialLutSlice(distance, S.atmosphere);
    vec2 uv = skyViewUvToward(dir, S.sunDirection, S);
    vec4 light = aerialLutRead(AERIAL_SCATTER_LUT_OFFSET, uv, slice, vec4(0.0f));
    vec4 t = aerialLutRead(AERIAL_TRANSMITTANCE_LUT_OFFSET, uv, slice, vec4(1.0f));
    air.inScattered = vec3(light.x, light.y, light.z) * S.sunIrradiance;
    air.transmittance = vec3(t.x, t.y, t.z);
    if (moonOn(S)) {
        vec2 moonUv = skyViewUvToward(dir, S.moonDirection, S);
        vec4 moon = aerialLutRead(MOON_AERIAL_SCATTER_LUT_OFFSET, moonUv, slice, vec4(0.0f));
        air.inScattered += vec3(moon.x, moon.y, moon.z) * S.moonIrradiance;
    }
    return air;
}

// The same air by integration (AERIAL_PERSPECTIVE_STEPS steps through the tables) from any
// origin.
inline AirLight aerialPerspective(vec3 origin, vec3 dir, float distance, IN(SkyParams) S) {
    AirLight air;
    air.inScattered = vec3(0.0f);
    air.transmittance = vec3(1.0f);
    if (!atmosphereOn(S) || S.atmosphere.aerialPerspective == 0 || distance <= 0.0f) {
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
    if (moonOn(S)) {
        // The moon's light scattered by the same air: a second integration, only while it is on.
        vec3 localMoon =
            vec3(dot(S.moonDirection, x), dot(S.moonDirection, up), dot(S.moonDirection, z));
        ScatteredLight m =
            scatterAlongRay(r, localDir, localMoon, distance, false, AERIAL_PERSPECTIVE_STEPS,
                            false, S.moonAngularRadius, S.atmosphere);
        air.inScattered += m.radiance * S.moonIrradiance;
    }
    return air;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
