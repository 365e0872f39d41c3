// The planet's surface seen from the camera: with the atmosphere, a Lambertian ground at the
// atmosphere's ground albedo, lit by the sun through the air and the clouds' shadow and by the
// sky, seen through the air in front of it; with the terrain (terrain.glsl.h), the height field's
// surface, lit the same way plus its own shadows, at albedos by slope and altitude.
#ifndef CLOUDSCAPE_MODEL_GROUND_GLSL_H
#define CLOUDSCAPE_MODEL_GROUND_GLSL_H

#include "atmosphere.glsl.h"
#include "camera.glsl.h"
#include "cloud_shadow.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"
#include "sky.glsl.h"
#include "terrain.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Density samples of the ground's cloud shadow, and the noise mip they read (a coarse mip: the
// shadow's edge is soft, as the penumbra of a cloud kilometres up is).
CONST_INT GROUND_SHADOW_SAMPLES = 2;
CONST_FLOAT GROUND_SHADOW_LOD = 3.0f;

// Transmittance of the cloud layer from a ground point toward the clouds' light (the sun, or the
// moon at night: cloudLightDirection): the optical depth of
// GROUND_SHADOW_SAMPLES cheap (base-shape) density samples across the layer. Cheap samples bound
// the full density from above, so the shadow errs dark.
inline float groundCloudShadow(vec3 p, IN(CloudParams) P) {
    vec3 sun = cloudLightDirection(P.sky);
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

// The sun's light through the clouds at a point on the ground or terrain, as shares of the open
// sky's: the beam (the clouds' transmittance toward the sun) and the clouds' diffuse light.
// Where the map covers the point (cloud_shadow.glsl.h), its beam and cloudDiffuseShare of it;
// elsewhere groundCloudShadow's two cheap samples and no diffuse light: those bound the density
// from above, so their optical depth is no estimate of the cloud's, and the diffuse share, which
// still falls with optical depth where the beam is already nothing, would turn their error into
// light (CPU and Vulkan, whose coarse mips differ a little, disagreed by 10 % in deep shadow).
struct SunThroughClouds {
    float beam;
    float diffuse;
    bool beyondMap; // the beam is groundCloudShadow's (or, compiled without it, a placeholder)
};

inline SunThroughClouds sunThroughCloudsAt(vec3 p, IN(CloudParams) P) {
    bool inMap = false;
    float mapped = cloudShadowFromMap(p, P, inMap);
    SunThroughClouds r;
    // Without FEATURE_GROUND_FALLBACK (the Vulkan background pass that lists these points for a
    // pass of their own) the beam outside the map is a placeholder, made whole by that pass.
    bool fallback = featureCompiled(FEATURE_GROUND_FALLBACK);
    r.beam = inMap ? mapped : (fallback ? groundCloudShadow(p, P) : 1.0f);
    r.diffuse = inMap ? cloudDiffuseShare(mapped) : 0.0f;
    r.beyondMap = !inMap;
    return r;
}

// The clouds' transmittance toward the sun at a point on the ground or terrain (the beam alone).
inline float cloudShadowAt(vec3 p, IN(CloudParams) P) {
    return sunThroughCloudsAt(p, P).beam;
}

// The sky's mean radiance over the upper half-space at p (its irradiance on level ground over
// pi): the atmosphere's ambient table, or the placeholder sky's ambient colour.
inline vec3 skyMeanRadianceAt(vec3 p, IN(CloudParams) P) {
    if (!atmosphereOn(P.sky)) {
        return P.sky.ambientTop * P.sky.ambientStrength;
    }
    return skyAmbientAbove(p, P.sky);
}

// The light a surface point sends toward the camera, split by what the clouds do to it:
// base + beam * (the clouds' beam share there) + diffuse * (their diffuse share), the shares of
// sunThroughCloudsAt. The clouds move every frame; the rest changes only with the camera, the
// sun, the terrain or the air, so a renderer may keep the split (pixel.glsl.h's
// BackgroundLight) and apply each frame's shares.
struct SurfaceLight {
    vec3 base;
    vec3 beam;
    vec3 diffuse;
};

inline vec3 litByClouds(IN(SurfaceLight) l, IN(SunThroughClouds) clouds) {
    return l.base + l.beam * clouds.beam + l.diffuse * clouds.diffuse;
}

// The ground at p, lit directly by the clouds' light (the sun, or the moon at night): both shares
// reach it alike.
inline SurfaceLight groundLight(vec3 p, IN(CloudParams) P) {
    vec2 rMuS = atmospherePositionToward(p, cloudLightDirection(P.sky), P.sky);
    vec3 albedo = P.sky.atmosphere.groundAlbedo;
    SurfaceLight l;
    l.base = albedo * skyMeanRadianceAt(p, P);
    l.beam = albedo * cloudLightIrradianceAt(p, P.sky) * (max(rMuS.y, 0.0f) / PI);
    l.diffuse = l.beam;
    return l;
}

// Radiance leaving the ground at p toward the camera (before the air in between).
inline vec3 groundRadiance(vec3 p, IN(CloudParams) P) {
    return litByClouds(groundLight(p, P), sunThroughCloudsAt(p, P));
}

// ---- The terrain's surface.

CONST_FLOAT TERRAIN_SNOW_ALBEDO = 0.8f;

// The fields' grid is turned this far off the world axes (rad), so that its rows are not
// parallel to a camera looking north, east, south or west.
CONST_FLOAT TERRAIN_FIELD_ANGLE = 0.55f;

// A uniform number in [0, 1) from an integer cell coordinate and a channel.
inline float fieldRandom(int cell, int row, uint channel) {
    uint h = hashUint(uint(cell) + hashUint(uint(row) + hashUint(channel)));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

// Fields: farmland is a patchwork (meadows, crops, stubble), each field's albedo a little brighter
// or darker, greener or yellower, than the next. The plain albedo is scaled per cell of a grid of
// T.fieldSize, turned off the axes and with each row shifted by a random fraction of a cell (so
// fields do not line up in columns), by two independent factors of mean 1 (uniform in
// 1 +- fieldVariation): one on all channels, one on red. Where a pixel's footprint on the ground
// (footprint, m) spans several fields the variation fades out over a factor of 2: the mean over
// many fields is the plain albedo, so distant land shows its mean instead of aliasing.
inline vec3 fieldAlbedoFactor(vec2 xz, float footprint, IN(TerrainParams) T) {
    float v = T.fieldVariation * (1.0f - smoothstep(0.5f, 1.0f, footprint / T.fieldSize));
    if (v <= 0.0f) {
        return vec3(1.0f);
    }
    float c = cos(TERRAIN_FIELD_ANGLE);
    float s = sin(TERRAIN_FIELD_ANGLE);
    vec2 uv = vec2(c * xz.x - s * xz.y, s * xz.x + c * xz.y) / T.fieldSize;
    int row = int(floor(uv.y));
    int cell = int(floor(uv.x + fieldRandom(0, row, 2u)));
    float brightness = 1.0f + v * (2.0f * fieldRandom(cell, row, 0u) - 1.0f);
    float red = 1.0f + v * (2.0f * fieldRandom(cell, row, 1u) - 1.0f);
    return vec3(brightness * red, brightness, brightness);
}

// Albedo by slope and altitude: rock where the surface is steeper than about 35 degrees, snow on
// gentler slopes above the snow line (a 300 m band), the plain albedo elsewhere, varied from field
// to field (fieldAlbedoFactor; footprint in m).
inline vec3 terrainAlbedo(vec2 xz, float height, float flatness, float footprint,
                          IN(TerrainParams) T) {
    vec3 plain = T.albedo;
    if (T.fieldVariation > 0.0f) {
        plain = min(plain * fieldAlbedoFactor(xz, footprint, T), vec3(1.0f));
    }
    vec3 a = mix(T.rockAlbedo, plain, smoothstep(0.72f, 0.88f, flatness));
    float snow = smoothstep(T.snowLine - 150.0f, T.snowLine + 150.0f, height) *
                 smoothstep(0.6f, 0.8f, flatness);
    return mix(a, vec3(TERRAIN_SNOW_ALBEDO), snow);
}

// The fraction of the sun's direct light reaching terrain point p: zero where the terrain itself
// stands between p and the sun, else the clouds' transmittance (`clouds`, cloudShadowAt's).
// `lift` (m) raises the shadow ray's start clear of the view march's hit tolerance. With the
// light's horizon made for this light (TerrainParams.lightHorizon) one read replaces the shadow
// ray's march, which took 1-2.5 times the view march's steps (fly-through, mountains).
inline float terrainSunVisibility(vec3 p, vec3 up, float lift, float clouds, IN(CloudParams) P) {
    if (P.terrain.lightHorizon > 0) {
        float altitude = terrainAltitude(p, P.planetRadius) + lift;
        return altitude >= terrainLightHorizonAt(vec2(p.x, p.z), P.terrain) ? clouds : 0.0f;
    }
    vec3 sun = cloudLightDirection(P.sky);
    if (terrainBlocks(p + up * lift, sun, P)) {
        return 0.0f;
    }
    return clouds;
}

// How far (m) above a terrain hit found at distance t a ray leaving the surface starts: clear of
// the march's hit tolerance (TERRAIN_HIT_EPSILON + TERRAIN_HIT_RELATIVE * t) on either side.
inline float terrainLeaveLift(float t) {
    return 1.0f + 2.0f * (TERRAIN_HIT_EPSILON + TERRAIN_HIT_RELATIVE * t);
}

// The terrain's surface at p as a Lambertian reflector: the planet's vertical there, the normal
// and the albedo, its fields averaged over the footprint of a camera pixel that sees p at
// distance t along dir (its width there, stretched along the view by the grazing angle, bounded
// where the march's own tolerance is coarser). t = 0 for a point: the path tracer, whose paths
// average the fields themselves. The real-time shading below and the path tracer (src/pathtrace)
// both read it.
struct TerrainSurface {
    vec3 up;
    vec3 normal;
    vec3 albedo;
};

inline TerrainSurface terrainSurfaceAt(vec3 p, vec3 dir, float t, IN(CloudParams) P) {
    TerrainSurface s;
    s.up = normalize(p - planetCentre(P.planetRadius));
    s.normal = terrainNormal(vec2(p.x, p.z), s.up, P.terrain);
    float flatness = dot(s.normal, s.up);
    float footprint = t * P.terrain.pixelAngle / max(abs(dot(s.normal, dir)), 0.02f);
    s.albedo = terrainAlbedo(vec2(p.x, p.z), terrainAltitude(p, P.planetRadius), flatness,
                             footprint, P.terrain);
    return s;
}

// Terrain point p (found at distance t from the camera along dir) as a Lambertian surface: the
// sun through the air, the clouds and the terrain's own shadow, plus the sky's light in
// proportion to the sky the surface faces.
inline SurfaceLight terrainLight(vec3 p, vec3 dir, float t, IN(CloudParams) P) {
    TerrainSurface s = terrainSurfaceAt(p, dir, t, P);
    vec3 sunDir = cloudLightDirection(P.sky); // the sun, or the moon at night
    float cosSun = dot(s.normal, sunDir);
    float sunUp = dot(s.up, sunDir);
    float skyView = 0.5f + 0.5f * dot(s.normal, s.up);
    SurfaceLight l;
    l.base = s.albedo * skyMeanRadianceAt(p, P) * skyView;
    l.beam = vec3(0.0f);
    l.diffuse = vec3(0.0f);
    if (sunUp > 0.0f) {
        vec3 sun = s.albedo * cloudLightIrradianceAt(p, P.sky) / PI;
        if (cosSun > 0.0f) {
            l.beam = sun * (cosSun * terrainSunVisibility(p, s.up, terrainLeaveLift(t), 1.0f, P));
        }
        // The clouds' diffuse light comes from their base above: the sky the surface faces.
        l.diffuse = sun * (sunUp * skyView);
    }
    return l;
}

// Radiance leaving terrain point p toward the camera (before the air in between).
inline vec3 terrainRadiance(vec3 p, vec3 dir, float t, IN(CloudParams) P) {
    return litByClouds(terrainLight(p, dir, t, P), sunThroughCloudsAt(p, P));
}

// A surface's light seen through the air in front of it (at distance t along dir): the air dims
// every part and adds its own light to the base.
inline SurfaceLight seenThroughAir(IN(SurfaceLight) l, vec3 dir, float t, IN(CloudParams) P) {
    AirLight air = cameraAerialPerspective(dir, t, P.sky);
    SurfaceLight seen;
    seen.base = l.base * air.transmittance + air.inScattered;
    seen.beam = l.beam * air.transmittance;
    seen.diffuse = l.diffuse * air.transmittance;
    return seen;
}

// The terrain at distance t along a camera ray, through the air in front of it.
inline SurfaceLight terrainSeenLight(vec3 origin, vec3 dir, float t, IN(CloudParams) P) {
    return seenThroughAir(terrainLight(origin + dir * t, dir, t, P), dir, t, P);
}

// The ground along a camera ray from origin, through the air; or the sky where the ray misses
// the planet (t < 0 from groundHitDistance).
inline float groundHitDistance(vec3 origin, vec3 dir, IN(CloudParams) P) {
    vec2 t = raySphere(origin, dir, planetCentre(P.planetRadius), P.planetRadius);
    return t.x > 0.0f ? t.x : NO_HIT;
}

inline SurfaceLight groundSeenLight(vec3 origin, vec3 dir, float distance, IN(CloudParams) P) {
    return seenThroughAir(groundLight(origin + dir * distance, P), dir, distance, P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
