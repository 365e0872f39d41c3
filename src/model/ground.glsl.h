// The planet's surface seen from the camera, with the atmosphere: a Lambertian ground at the
// atmosphere's ground albedo, lit by the sun through the air and the clouds' shadow and by the
// sky, seen through the air in front of it. (The terrain issue replaces the flat planet and the
// cheap shadow below with a height field and a shadow map.)
#ifndef CLOUDSCAPE_MODEL_GROUND_GLSL_H
#define CLOUDSCAPE_MODEL_GROUND_GLSL_H

#include "atmosphere.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Density samples of the ground's cloud shadow, and the noise mip they read (a coarse mip: the
// shadow's edge is soft, as the penumbra of a cloud kilometres up is).
CONST_INT GROUND_SHADOW_SAMPLES = 2;
CONST_FLOAT GROUND_SHADOW_LOD = 3.0f;

// Transmittance of the cloud layer from a ground point toward the sun: the optical depth of
// GROUND_SHADOW_SAMPLES cheap (base-shape) density samples across the layer. Cheap samples bound
// the full density from above, so the shadow errs dark.
inline float groundCloudShadow(vec3 p, IN(CloudParams) P) {
    vec3 sun = P.sky.sunDirection;
    vec4 spans = shellIntervals(p, sun, P.planetRadius, P.layerBottom, P.layerTop);
    float crossing = spans.y - spans.x;
    if (crossing <= 0.0f) {
        return 1.0f;
    }
    float dt = crossing / float(GROUND_SHADOW_SAMPLES);
    float depth = 0.0f;
    for (int i = 0; i < GROUND_SHADOW_SAMPLES; ++i) {
        vec3 q = p + sun * (spans.x + (float(i) + 0.5f) * dt);
        depth += extinctionOf(cloudDensityAt(q, GROUND_SHADOW_LOD, true, P), P) * dt;
    }
    return exp(-depth);
}

// Radiance leaving the ground at p toward the camera (before the air in between).
inline vec3 groundRadiance(vec3 p, IN(CloudParams) P) {
    vec2 rMuS = atmospherePosition(p, P.sky);
    vec3 sun = sunIrradianceAt(p, P.sky) * (max(rMuS.y, 0.0f) * groundCloudShadow(p, P));
    // The ambient table's upper half-space mean radiance is the sky's irradiance over pi.
    vec4 sky = lutBilinear(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE,
                           ambientLutUv(rMuS.x, rMuS.y, P.sky.atmosphere));
    vec3 skyMean = vec3(sky.x, sky.y, sky.z) * P.sky.sunIrradiance;
    return P.sky.atmosphere.groundAlbedo * (sun / PI + skyMean);
}

// The ground along a camera ray from origin, through the air; or the sky where the ray misses
// the planet (t < 0 from groundHitDistance).
inline float groundHitDistance(vec3 origin, vec3 dir, IN(CloudParams) P) {
    vec2 t = raySphere(origin, dir, planetCentre(P.planetRadius), P.planetRadius);
    return t.x > 0.0f ? t.x : NO_HIT;
}

inline vec3 groundSeen(vec3 origin, vec3 dir, float distance, IN(CloudParams) P) {
    vec3 p = origin + dir * distance;
    AirLight air = aerialPerspective(origin, dir, distance, P.sky);
    return groundRadiance(p, P) * air.transmittance + air.inScattered;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
