// Light shafts (issue 12; "Below clouds" in the physically based guide): the air between the
// camera and what it sees scatters the sun toward the camera only where the sun reaches it, so
// air in a cloud's shadow is darker than air in a gap, and the lit air between shadows reads as
// rays. The sky (sky-view table) and the aerial perspective already hold the air's single
// scattering as if no cloud shaded it; this takes away, step by step along the view ray, the
// single scattering of the air the clouds' shadow map (cloud_shadow.glsl.h) says is shaded. The
// medium, its phase functions and the sun's transmittance are the atmosphere's (atmosphere.glsl.h),
// so the shafts carry the air's colour and Mie forward peak; multiple scattering (the sky's
// diffuse light) is left alone, since a cloud's shadow hardly dims it.
//
// Evaluated where the composite is made (pixel.glsl.h), not in the cloud march: per pixel in full
// frames, and in the temporal resolve per pixel or on a coarser grid (shaft_grid.glsl.h).
#ifndef CLOUDSCAPE_MODEL_LIGHT_SHAFTS_GLSL_H
#define CLOUDSCAPE_MODEL_LIGHT_SHAFTS_GLSL_H

#include "atmosphere.glsl.h"
#include "cloud_shadow.glsl.h"
#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// True when shafts change the image: they are asked for, the atmosphere (whose air they are) is
// on with its aerial perspective, and the shadow map they read exists.
inline bool lightShaftsActive(IN(CloudParams) P) {
    return featureCompiled(FEATURE_SHAFTS) && shaftsWanted(P) && atmosphereOn(P.sky) &&
           P.sky.atmosphere.aerialPerspective != 0 && cloudShadowMapUsable(P);
}

// How far along a view ray shadowed air can lie: to what the ray sees (backgroundDepth: the
// geometry, or the ground of the planet), no farther than P.shafts.maxDistance, and not above the
// cloud layer's top (no cloud shades the air up there).
inline float lightShaftsEnd(vec3 origin, vec3 dir, float backgroundDepth, IN(CloudParams) P) {
    float end = min(backgroundDepth, P.shafts.maxDistance);
    vec2 top = raySphere(origin, dir, planetCentre(P.planetRadius), P.planetRadius + P.layerTop);
    if (top.y > 0.0f) {
        end = min(end, top.y);
    }
    vec2 ground = raySphere(origin, dir, planetCentre(P.planetRadius), P.planetRadius);
    if (ground.x > 0.0f) {
        end = min(end, ground.x);
    }
    return max(end, 0.0f);
}

// Where along a view ray shadowed air can begin: at the camera, or, for a camera above the cloud
// layer (an airliner's view), where the ray enters the layer's top (NO_HIT if it never does), so
// that the steps are spent on the air the clouds can shade rather than on the clear air above.
inline float lightShaftsBegin(vec3 origin, vec3 dir, IN(CloudParams) P) {
    if (altitudeOf(origin, P.planetRadius) <= P.layerTop) {
        return 0.0f;
    }
    vec2 top = raySphere(origin, dir, planetCentre(P.planetRadius), P.planetRadius + P.layerTop);
    return top.x > 0.0f ? top.x : NO_HIT; // NO_HIT < 0: no shaded air on this ray
}

// The atmosphere's transmittance between a point and one `distance` along dir from it, for a ray
// whose reverse climbs (as from a camera above the layer down to its top): the ratio of the two
// points' transmittances to the top of the atmosphere along -dir (the table's).
inline vec3 airTransmittanceAlong(vec3 origin, vec3 dir, float distance, IN(SkyParams) S) {
    vec2 far = atmospherePositionToward(origin + dir * distance, -dir, S);
    vec2 near = atmospherePositionToward(origin, -dir, S);
    vec3 toTopFar = transmittanceToTop(far.x, far.y, S.atmosphere);
    vec3 toTopNear = transmittanceToTop(near.x, near.y, S.atmosphere);
    return min(toTopFar / max(toTopNear, vec3(1e-6f)), vec3(1.0f));
}

// The light the shadowed air does not scatter toward the camera, in two parts: in front of the
// ray's first cloud (cloudDepth; NO_HIT: no cloud, all in front) and behind it, the latter not yet
// dimmed by the cloud's transmittance (so a reconstruction can apply its own pixel's).
struct ShaftLight {
    vec3 front;
    vec3 behind;
};

// The view ray is cut into P.shafts.steps equal steps from lightShaftsBegin to lightShaftsEnd, each
// sampled at `jitter` in [0, 1) of its length (one offset per pixel, fixed over frames, so a still
// view does not flicker); each adds the single scattering it would have had in full sun times the
// share of the sun the clouds above take away (1 - lightBelowClouds of the map's transmittance:
// the clouds' diffuse light reaches the air under them as it reaches the ground), through the air
// in front of it (the energy-conserving step integral of scatterAlongRay).
inline ShaftLight lightShaftsParts(vec3 origin, vec3 dir, float cloudDepth, float backgroundDepth,
                                   float jitter, IN(CloudParams) P) {
    ShaftLight r;
    r.front = vec3(0.0f);
    r.behind = vec3(0.0f);
    float begin = lightShaftsBegin(origin, dir, P);
    float end = lightShaftsEnd(origin, dir, backgroundDepth, P);
    if (begin < 0.0f || end <= begin) {
        return r;
    }
    AtmosphereParams A = P.sky.atmosphere;
    float cosTheta = dot(dir, cloudLightDirection(P.sky)); // the clouds' light
    float phaseR = rayleighPhase(cosTheta);
    float phaseM = miePhase(cosTheta, A.mieG);
    int steps = P.shafts.steps;
    float dt = (end - begin) / float(steps);
    vec3 airT = begin > 0.0f ? airTransmittanceAlong(origin, dir, begin, P.sky) : vec3(1.0f);
    for (int i = 0; i < steps; ++i) {
        float t = begin + (float(i) + jitter) * dt;
        vec3 x = origin + dir * t;
        AtmosphereSample m = atmosphereAt(altitudeOf(x, P.planetRadius), A);
        vec3 stepT = exp(-m.extinction * dt);
        vec3 integral = (vec3(1.0f) - stepT) / max(m.extinction, vec3(1e-12f));
        bool inMap = false;
        float shade = 1.0f - lightBelowClouds(cloudShadowFromMap(x, P, inMap));
        if (shade > 0.0f) {
            vec3 scattering = m.rayleighScattering * phaseR + m.mieScattering * phaseM;
            vec3 lost = airT * scattering * cloudLightIrradianceAt(x, P.sky) * (shade * integral);
            if (cloudDepth == NO_HIT || t < cloudDepth) {
                r.front += lost;
            } else {
                r.behind += lost;
            }
        }
        airT *= stepT;
    }
    return r;
}

// The change (<= 0) the shadowed air makes to a pixel's radiance: lightShaftsParts, the air
// behind the cloud's first hit seen through the cloud's transmittance.
inline vec3 lightShaftsDelta(vec3 origin, vec3 dir, float cloudDepth, float cloudTransmittance,
                             float backgroundDepth, float jitter, IN(CloudParams) P) {
    ShaftLight parts = lightShaftsParts(origin, dir, cloudDepth, backgroundDepth, jitter, P);
    float throughCloud = cloudDepth == NO_HIT ? 1.0f : cloudTransmittance;
    return -(parts.front + parts.behind * throughCloud);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
