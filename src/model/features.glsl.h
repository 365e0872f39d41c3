// The optional parts of the model a pipeline is built with. Each feature has a predicate on the
// parameters ("wanted": the scene asks for it) and one that the model's code tests ("on": wanted
// and compiled in). C++ compiles everything in. A shader's MODEL_FEATURES is a specialisation
// constant (default: everything) that the Vulkan backend sets from modelFeaturesFor(P, camera) when
// it builds the pipeline, so the code of a feature the scene does not use is removed. Why: a branch
// on a parameter is uniform, but llvmpipe (Mesa 22, Debian 12's lavapipe) executes both sides of
// every `if` under a lane mask, so code that is switched off still cost its full price per pixel
// (the resolve spent 360 of its 405 ms on features the scene had off).
#ifndef CLOUDSCAPE_MODEL_FEATURES_GLSL_H
#define CLOUDSCAPE_MODEL_FEATURES_GLSL_H

#include "compat.glsl.h"
#include "params.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_INT FEATURE_TERRAIN = 1;
CONST_INT FEATURE_ATMOSPHERE = 2;
CONST_INT FEATURE_MOON = 4;
CONST_INT FEATURE_HIGH_CLOUDS = 8;
CONST_INT FEATURE_STORM = 16;
CONST_INT FEATURE_LIGHTNING = 32;
// The composite over the background: every pass displays it except the temporal renderer's
// block march, whose composite nobody reads (the resolve composites), so its pipeline drops it.
CONST_INT FEATURE_COMPOSITE = 64;
// The data field's channels (data_field.glsl.h); off, every region reads the neutral value.
CONST_INT FEATURE_DATA_FIELD = 128;
// The clouds' shadow map (cloud_shadow.glsl.h; off, the ground takes its two cheap density
// samples) and the light shafts that read it (light_shafts.glsl.h). Above the pass modes' bits.
CONST_INT FEATURE_CLOUD_SHADOW = 1024;
CONST_INT FEATURE_SHAFTS = 2048;
// The camera is above the high-altitude layer (an airliner's view), where the layer may lie in
// front of the clouds. From below it the layer lies beyond every cloud (the clouds stay under
// it and a ray leaves its sphere once), so the composites drop the layer's code ahead of the
// clouds; the background keeps the layer behind them.
CONST_INT FEATURE_ABOVE_HIGH_CLOUDS = 4096;
// The ground's two cheap density samples toward the sun where the shadow map does not reach
// (ground.glsl.h's groundCloudShadow). Every pass has it but the Vulkan background pass that
// applies the clouds to a kept light: that pass is built without it, lists the pixels that need
// it (backgroundTexelFrom says which) and a second dispatch over the list (PASS_GROUND_FALLBACK)
// makes them whole, so that the far ground's fallback is no longer paid under a SIMD mask by
// every pixel of the image.
CONST_INT FEATURE_GROUND_FALLBACK = 16384;
// The temporal resolve gathers a moving camera's earlier marches (sample_gather.glsl.h). Like the
// scene's features, a frame's: the host sets it where the frame gathers (gatherFeatureFor), since
// llvmpipe runs a branch's body under a mask even when no lane takes it, and the gather's body
// (a frame's parameters and four blocks' records, moved and weighed) took about a fifth of the
// resolve of every frame that never gathers (a still camera's, the default tier's). The block
// march takes it in the same frames for the entering edge's extra marches (enteringMarchCount).
CONST_INT FEATURE_GATHER = 131072;
// The march's skips by the base noise's clearance field (march.noise_skipping,
// noise_clearance.glsl.h): compiled in only where the scene asks for them, since the lookup's
// code under llvmpipe's mask cost the march a fifth of its time with the skips off.
CONST_INT FEATURE_NOISE_SKIPPING = 262144;
CONST_INT FEATURE_ALL = 255 | FEATURE_CLOUD_SHADOW | FEATURE_SHAFTS | FEATURE_ABOVE_HIGH_CLOUDS |
                        FEATURE_GROUND_FALLBACK | FEATURE_GATHER | FEATURE_NOISE_SKIPPING;
// Not features of the model but modes of a pass, carried by the same specialisation constant:
// the resolve and upsample shaders built with PASS_SHADE_BACKGROUND apply this frame's clouds to
// their background's light (backgroundTexelFrom per pixel), built with PASS_FILL_BACKGROUND make
// that light first (backgroundLightAt), instead of compositing; so the modes cost the composite
// nothing.
CONST_INT PASS_FILL_BACKGROUND = 256;
CONST_INT PASS_SHADE_BACKGROUND = 512;
// The resolve shader built with PASS_SHAFT_GRID fills the light shafts' grid (one invocation per
// cell: resolveShaftCell) instead of resolving. A mode of its own rather than a push constant:
// llvmpipe runs both sides of a branch on a uniform value, and the grid's side is a whole resolve
// and a shaft march (the resolve's pipeline carrying it took 1.6x as long, grid or no grid).
CONST_INT PASS_SHAFT_GRID = 8192;
// The background dispatch over the pixels the pass without FEATURE_GROUND_FALLBACK listed
// (an indirect dispatch; interface.glsl.h's ground fallback list).
CONST_INT PASS_GROUND_FALLBACK = 32768;
// The upsample shader built with PASS_UPSAMPLED_BACKGROUND composites over the background
// brought up from the pass's (upsample.glsl.h's upsampledBackground: a moving camera with
// render.moving_background_reduced) instead of the output-size background it keeps.
CONST_INT PASS_UPSAMPLED_BACKGROUND = 65536;
// The specialisation constant's id in every model shader.
CONST_INT MODEL_FEATURES_CONSTANT_ID = 0;

#ifdef __cplusplus
inline bool featureCompiled(int) {
    return true;
}
#else
layout(constant_id = 0) const int MODEL_FEATURES = FEATURE_ALL;
bool featureCompiled(int feature) {
    return (MODEL_FEATURES & feature) != 0;
}
#endif

inline bool terrainWanted(IN(CloudParams) P) {
    return P.terrain.enabled != 0;
}
inline bool atmosphereWanted(IN(SkyParams) S) {
    return S.atmosphere.enabled != 0;
}
inline bool moonWanted(IN(SkyParams) S) {
    return S.moonEnabled != 0;
}
inline bool stormWanted(IN(CloudParams) P) {
    return P.stormBlend > 0.0f && P.stormRadius > 0.0f;
}
inline bool cloudShadowWanted(IN(CloudParams) P) {
    return P.cloudShadow.resolution > 0;
}
inline bool shaftsWanted(IN(CloudParams) P) {
    return P.shafts.steps > 0;
}
// The layer's own coverage, or a storm's cirrus plume (high_clouds.glsl.h).
inline bool highCloudsWanted(IN(CloudParams) P) {
    return P.highClouds.coverage > 0.0f || (P.highClouds.stormCirrus > 0.0f && stormWanted(P));
}
inline bool lightningWanted(IN(CloudParams) P) {
    return P.lightning.enabled != 0;
}
inline bool dataFieldWanted(IN(CloudParams) P) {
    return P.dataFieldEnabled != 0;
}
inline bool noiseSkippingWanted(IN(CloudParams) P) {
    return P.noiseClearanceSize > 0;
}

inline bool terrainOn(IN(CloudParams) P) {
    return featureCompiled(FEATURE_TERRAIN) && terrainWanted(P);
}
inline bool atmosphereOn(IN(SkyParams) S) {
    return featureCompiled(FEATURE_ATMOSPHERE) && atmosphereWanted(S);
}
inline bool moonOn(IN(SkyParams) S) {
    return featureCompiled(FEATURE_MOON) && moonWanted(S);
}
inline bool stormOn(IN(CloudParams) P) {
    return featureCompiled(FEATURE_STORM) && stormWanted(P);
}
inline bool highCloudsOn(IN(CloudParams) P) {
    return featureCompiled(FEATURE_HIGH_CLOUDS) && highCloudsWanted(P);
}
inline bool dataFieldOn(IN(CloudParams) P) {
    return featureCompiled(FEATURE_DATA_FIELD) && dataFieldWanted(P);
}

// Whether a camera at `camera` is outside the sphere of the high layer (high_clouds.glsl.h's
// highCloudDistance draws the same line).
inline bool cameraAboveHighClouds(IN(CloudParams) P, vec3 camera) {
    vec3 fromCentre = camera - vec3(0.0f, -P.planetRadius, 0.0f);
    return length(fromCentre) >= P.planetRadius + P.highClouds.altitude;
}

// The features a scene with these parameters, seen from `camera`, needs: what the backend
// specialises its model pipelines for. A feature left out of it is switched off in the shader
// whatever P says.
inline int modelFeaturesFor(IN(CloudParams) P, vec3 camera) {
    int features = 0;
    features |= terrainWanted(P) ? FEATURE_TERRAIN : 0;
    features |= atmosphereWanted(P.sky) ? FEATURE_ATMOSPHERE : 0;
    features |= moonWanted(P.sky) ? FEATURE_MOON : 0;
    features |= highCloudsWanted(P) ? FEATURE_HIGH_CLOUDS : 0;
    features |= stormWanted(P) ? FEATURE_STORM : 0;
    features |= lightningWanted(P) ? FEATURE_LIGHTNING : 0;
    features |= dataFieldWanted(P) ? FEATURE_DATA_FIELD : 0;
    features |= cloudShadowWanted(P) ? FEATURE_CLOUD_SHADOW : 0;
    features |= shaftsWanted(P) ? FEATURE_SHAFTS : 0;
    features |= noiseSkippingWanted(P) ? FEATURE_NOISE_SKIPPING : 0;
    bool above = highCloudsWanted(P) && cameraAboveHighClouds(P, camera);
    features |= above ? FEATURE_ABOVE_HIGH_CLOUDS : 0;
    return features | FEATURE_COMPOSITE | FEATURE_GROUND_FALLBACK;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
