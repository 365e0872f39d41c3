// The high-altitude layer (GPU Pro 7 4.5.4; the HZD notes' cirrus, cirrostratus and
// cirrocumulus): a thin shell of ice cloud at its own altitude, drawn from a 2D texture of the
// three formations blended by high_clouds.type and eroded by the inverse of its coverage, moved by
// its own wind. It is looked up once per pixel behind the volumetric clouds (it belongs to the
// background they are composited over, so opaque cumulus hides it and the temporal path evaluates
// it fresh every frame), lit by the sun through the atmosphere with an ice-crystal phase and by the
// sky's ambient light, and seen through the air in front of it. Single scattering in a thin layer:
// its optical depth is a fraction of one, so the light scattered twice is left out.
//
// A superstorm adds its cirrus to the layer (the Forbidden West talk's "cirrus formation above the
// storm, offset downwind"): the ice an anvil sheds streams downwind at the tropopause as a plume,
// so where the storm is on the layer gains a patch of streaks drawn along the wind, downwind of
// the storm and none upwind, fading with the storm's blend (stormCirrusDensity).
#ifndef CLOUDSCAPE_MODEL_HIGH_CLOUDS_GLSL_H
#define CLOUDSCAPE_MODEL_HIGH_CLOUDS_GLSL_H

#include "compat.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"
#include "sampling.glsl.h"
#include "shell.glsl.h"
#include "sky.glsl.h"
#include "storm.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Rays closer to the layer's plane than this cosine cross it as if at this slant (a shell of no
// thickness would give an infinite path at grazing incidence).
CONST_FLOAT HIGH_CLOUD_MIN_COSINE = 0.05f;
// The sun's path to the layer's middle is at most about 3 half-thicknesses long: a patch of cirrus
// is a few times wider than thick, so a low sun lights it from the side rather than through
// kilometres of it (a plane-parallel layer would darken it to nothing at sunrise, when cirrus
// glows).
CONST_FLOAT HIGH_CLOUD_MIN_SUN_COSINE = 0.35f;

// Density in [0, 1] of the layer at a world position's (x, z) and the scene's time: the type's
// blend of the texture's formations, eroded by the inverse of the coverage (coverage 1 keeps the
// texture, 0.3 only its densest 30 %). Needs coverage > 0.
inline float highCloudDensity(vec2 xz, IN(CloudParams) P) {
    vec2 uv = (xz - P.highClouds.windVelocity * P.time) / P.highClouds.period;
    vec4 formations = sampleHighClouds(uv);
    float type = P.highClouds.type;
    float value = formations.x * saturate(1.0f - abs(type)) +
                  formations.y * saturate(1.0f - abs(type - 1.0f)) +
                  formations.z * saturate(1.0f - abs(type - 2.0f));
    return saturate(remap(value, 1.0f - P.highClouds.coverage, 1.0f, 0.0f, 1.0f));
}

// The storm's cirrus patch, in storm radii R: an ellipse centred STORM_CIRRUS_SHIFT R downwind
// of the storm centre (the volumetric anvil reaches 1 R downwind, so the plume starts over it),
// STORM_CIRRUS_LENGTH R along the wind and STORM_CIRRUS_WIDTH R across, reaching from the storm
// centre to 2 R downwind and nothing upwind.
CONST_FLOAT STORM_CIRRUS_SHIFT = 1.0f;
CONST_FLOAT STORM_CIRRUS_LENGTH = 1.0f;
CONST_FLOAT STORM_CIRRUS_WIDTH = 0.6f;
// Vertical optical depth of the plume where its density is 1: anvil cirrus is optically thicker
// than the cirrus of fair weather (about 1-10 near a convective core, thinning to under 1 a few
// hundred kilometres downwind; e.g. Lilly 1988, Heymsfield and McFarquhar): the patch takes the
// thinner end, as it is the part downwind of the anvil.
CONST_FLOAT STORM_CIRRUS_OPTICAL_DEPTH = 2.0f;

inline bool stormCirrusOn(IN(CloudParams) P) {
    return P.highClouds.stormCirrus > 0.0f && stormActive(P);
}

// Density in [0, 1] of the storm's cirrus at a world (x, z): the texture's veil with its cirrus
// fibres (read in the wind's frame, so the fibres, long along the texture's v, stream along the
// wind), eroded by a coverage that is stormCirrus at the patch's centre and falls to 0 at its
// elliptical edge (as the layer's coverage erodes the layer), times the storm's blend: the plume
// thins away as the storm builds up or dissipates. 0 with no storm and outside the patch, before
// any texture read.
inline float stormCirrusDensity(vec2 xz, IN(CloudParams) P) {
    if (!stormCirrusOn(P)) {
        return 0.0f;
    }
    vec2 along = normalize(vec2(P.windDirection.x, P.windDirection.z));
    vec2 across = vec2(along.y, -along.x);
    // Offset from the patch's centre, wrapped with the weather map as the storm is.
    vec2 centre = P.stormCentre + along * (STORM_CIRRUS_SHIFT * P.stormRadius);
    vec2 d = xz - centre;
    d -= P.weatherExtent * floor(d / P.weatherExtent + vec2(0.5f, 0.5f));
    vec2 e = vec2(dot(d, across) / STORM_CIRRUS_WIDTH, dot(d, along) / STORM_CIRRUS_LENGTH) /
             P.stormRadius;
    float edge = length(e);
    if (edge >= 1.0f) {
        return 0.0f;
    }
    float coverage = P.highClouds.stormCirrus * (1.0f - smoothstep(0.3f, 1.0f, edge));
    vec2 wind = xz - P.highClouds.windVelocity * P.time;
    vec2 uv = vec2(dot(wind, across), dot(wind, along)) / P.highClouds.period;
    vec4 formations = sampleHighClouds(uv);
    float value = max(formations.x, formations.y);
    return P.stormBlend * saturate(remap(value, 1.0f - coverage, 1.0f, 0.0f, 1.0f));
}

// Vertical optical depth of the layer at a world (x, z): the layer's own, and where a storm
// sheds its cirrus the plume's, whichever is thicker (the plume is the same ice layer, thickened).
inline float highCloudOpticalDepthAt(vec2 xz, IN(CloudParams) P) {
    float depth = 0.0f;
    if (P.highClouds.coverage > 0.0f) {
        depth = P.highClouds.opticalDepth * highCloudDensity(xz, P);
    }
    return max(depth, STORM_CIRRUS_OPTICAL_DEPTH * stormCirrusDensity(xz, P));
}

struct HighCloudLayer {
    vec3 radiance;       // scattered toward the camera, before the air in front of the layer
    float transmittance; // of the layer along the ray
    float distance;      // m to the layer; NO_HIT where the ray does not see it
};

// Distance along a ray to the layer's sphere: from below, where the ray leaves it overhead; from
// above (a camera over the layer: an airliner's view), where the ray first meets it on its way
// down. NO_HIT with coverage 0 (and no storm cirrus) or where the ray misses it.
inline float highCloudDistance(vec3 origin, vec3 dir, IN(CloudParams) P) {
    if (!highCloudsOn(P)) {
        return NO_HIT;
    }
    vec3 centre = planetCentre(P.planetRadius);
    float radius = P.planetRadius + P.highClouds.altitude;
    vec2 roots = raySphere(origin, dir, centre, radius);
    if (length(origin - centre) < radius) {
        // From inside the sphere the far root is the one crossing ahead.
        return roots.y;
    }
    return roots.x > 0.0f ? roots.x : NO_HIT;
}

// The layer along a ray, from below it or above it. No layer: coverage 0 and no storm cirrus, a
// ray that misses it, or no cloud where the ray crosses it.
inline HighCloudLayer highCloudLayerAlong(vec3 origin, vec3 dir, IN(CloudParams) P) {
    HighCloudLayer layer;
    layer.radiance = vec3(0.0f);
    layer.transmittance = 1.0f;
    layer.distance = NO_HIT;
    float distance = highCloudDistance(origin, dir, P);
    if (distance == NO_HIT) {
        return layer;
    }
    vec3 p = origin + dir * distance;
    float verticalDepth = highCloudOpticalDepthAt(vec2(p.x, p.z), P);
    if (verticalDepth <= 0.0f) {
        return layer;
    }
    vec3 up = normalize(p - planetCentre(P.planetRadius));
    // Downward from above or upward from below, the slant through the layer is the same.
    float viewDepth = verticalDepth / max(abs(dot(dir, up)), HIGH_CLOUD_MIN_COSINE);
    // The sun (or the moon at night: the clouds' light) reaches the layer's middle through half
    // of it.
    vec3 light = cloudLightDirection(P.sky);
    float sunDepth = 0.5f * verticalDepth / max(dot(light, up), HIGH_CLOUD_MIN_SUN_COSINE);
    float phase = henyeyGreenstein(dot(dir, light), P.highClouds.phaseG);
    vec3 sun = cloudLightIrradianceAt(p, P.sky) * (phase * exp(-sunDepth));
    // Ice scatters nearly all it intercepts (albedo 1): ambient from the sky above and below.
    vec3 ambient = skyAmbientAt(p, 0.5f, P.sky) * P.sky.ambientStrength;
    layer.transmittance = exp(-viewDepth);
    layer.radiance = (sun + ambient) * (1.0f - layer.transmittance);
    layer.distance = distance;
    return layer;
}

// True when the layer lies along the ray nearer than `distance` (NO_HIT: the sky, infinitely
// far): from below only the sky lies beyond it; from above the ground, the terrain and the
// volumetric clouds below it do too.
inline bool highCloudsBefore(float distance, vec3 origin, vec3 dir, IN(CloudParams) P) {
    float layer = highCloudDistance(origin, dir, P);
    return layer != NO_HIT && (distance == NO_HIT || layer < distance);
}

// What lies `distance` away (NO_HIT: the sky) seen through the layer where the layer is nearer:
// the air in front of the layer scatters its own light and dims the layer's; the layer dims what
// lies beyond it (its radiance less the air in front of the layer, which it already holds).
// Elsewhere `behind` is returned unchanged.
inline vec3 highCloudsOver(vec3 behind, float distance, vec3 origin, vec3 dir, IN(CloudParams) P) {
    if (!highCloudsBefore(distance, origin, dir, P)) {
        return behind;
    }
    HighCloudLayer layer = highCloudLayerAlong(origin, dir, P);
    if (layer.distance == NO_HIT) {
        return behind;
    }
    AirLight air = cameraAerialPerspective(dir, layer.distance, P.sky);
    vec3 beyond = max(behind - air.inScattered, vec3(0.0f));
    return air.inScattered + air.transmittance * layer.radiance + beyond * layer.transmittance;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
