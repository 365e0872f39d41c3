// The viewer's debug views (apps/cloudscape/view_debug.cpp): what a pixel of each view shows, as
// display values in [0, 1] (drawn without the tone curve). Single-source like every per-pixel rule.
#ifndef CLOUDSCAPE_MODEL_DEBUG_VIEW_GLSL_H
#define CLOUDSCAPE_MODEL_DEBUG_VIEW_GLSL_H

#include "cloud_shadow.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "interface.glsl.h"
#include "terrain.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The colour where a view has no data (no cloud on the ray, the shadow map off).
inline vec3 debugNoData() {
    return vec3(0.1f, 0.2f, 0.45f);
}

// The cloud layer's transmittance: white where the sky shows through, black where the clouds
// are opaque.
inline vec3 debugTransmittance(float transmittance) {
    return vec3(saturate(transmittance));
}

// The distance to the first cloud on a log scale from 100 m (white) to `farM` (black); blue
// where the ray meets no cloud.
inline vec3 debugDepth(float metres, float farM) {
    if (!(metres < farM))
        return debugNoData();
    float t = saturate(log(max(metres, 100.0f) / 100.0f) / log(max(farM, 101.0f) / 100.0f));
    return vec3(1.0f - t);
}

// The weather map as the renderer reads it (coverage bias and precipitation rule applied):
// coverage red, precipitation green, cloud type blue.
inline vec3 debugWeather(vec4 texel, float coverageBias) {
    return weatherFromTexel(texel, coverageBias, 0.0f);
}

// A region of the data field (data_field.glsl.h): bottom type red, anvil coverage green, and
// blue the share of the layer the region's clouds may fill (maximum less minimum height; the
// neutral field is pure blue).
inline vec3 debugDataField(vec4 region) {
    return vec3(saturate(region.x), saturate(region.y), saturate(region.w - region.z));
}

// A shadow-map record (cloud_shadow.glsl.h) as the sun's transmittance through the whole
// crossing of its ray: white where the sun reaches the ground, black under thick cloud.
inline vec3 debugShadowMap(vec4 record) {
    return vec3(exp(-record.z));
}

// Where a temporal pixel's value came from (TEMPORAL_SOURCE_*): marched this frame green,
// reprojected history grey, a fallback to this frame's upsampled marches red.
inline vec3 debugTemporalSource(int source) {
    if (source == TEMPORAL_SOURCE_MARCHED)
        return vec3(0.2f, 0.8f, 0.3f);
    if (source == TEMPORAL_SOURCE_REPROJECTED)
        return vec3(0.35f, 0.35f, 0.4f);
    return vec3(0.95f, 0.25f, 0.2f);
}

// The density samples of a march on a heat ramp, linear between stops every 32 samples: black
// at 0, blue 32, green 64, yellow 96, red 128, white at 256 and beyond.
inline vec3 debugSampleHeat(float samples) {
    float x = max(samples, 0.0f) / 32.0f;
    if (x < 1.0f)
        return mix(vec3(0.0f), vec3(0.1f, 0.2f, 1.0f), x);
    if (x < 2.0f)
        return mix(vec3(0.1f, 0.2f, 1.0f), vec3(0.1f, 0.9f, 0.2f), x - 1.0f);
    if (x < 3.0f)
        return mix(vec3(0.1f, 0.9f, 0.2f), vec3(1.0f, 0.9f, 0.1f), x - 2.0f);
    if (x < 4.0f)
        return mix(vec3(1.0f, 0.9f, 0.1f), vec3(1.0f, 0.15f, 0.1f), x - 3.0f);
    return mix(vec3(1.0f, 0.15f, 0.1f), vec3(1.0f), min((x - 4.0f) / 4.0f, 1.0f));
}

// The density slice: a vertical plane through the camera along its level heading, drawn to
// scale. The world point `along` metres from the camera's xz along `heading` (unit, xz) at
// `altitude` over the planet, y written without the difference of two squares of the radius
// (as terrainAltitude), which would lose hundreds of metres in float.
inline vec3 densitySlicePoint(vec2 cameraXZ, vec2 heading, float along, float altitude,
                              float planetRadius) {
    vec2 xz = cameraXZ + heading * along;
    float horizontal = dot(xz, xz);
    float r = planetRadius + altitude;
    float y = (altitude * (2.0f * planetRadius + altitude) - horizontal) /
              (sqrt(max(r * r - horizontal, 0.0f)) + planetRadius);
    return vec3(xz.x, y, xz.y);
}

// A slice pixel at p: the terrain brown below the ground; the clouds' full density (with
// erosion, at the finest noise) white over the sky, compressed as 1 - exp(-4 density) so thin
// edges show; the cloud layer's band (clouds.bottom_m to clouds.top_m) a lighter blue than the
// air above and below it.
inline vec3 debugDensitySlice(vec3 p, IN(CloudParams) P) {
    float altitude = terrainAltitude(p, P.planetRadius);
    if (P.terrain.enabled != 0 && altitude < terrainHeightAt(vec2(p.x, p.z), P.terrain)) {
        return vec3(0.32f, 0.24f, 0.15f);
    }
    if (altitude < 0.0f) {
        return vec3(0.25f, 0.25f, 0.22f);
    }
    bool inLayer = altitude >= P.layerBottom && altitude <= P.layerTop;
    vec3 air = inLayer ? vec3(0.12f, 0.18f, 0.32f) : vec3(0.05f, 0.08f, 0.16f);
    float density = cloudDensityAt(p, 0.0f, false, P);
    return mix(air, vec3(1.0f), 1.0f - exp(-4.0f * density));
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
