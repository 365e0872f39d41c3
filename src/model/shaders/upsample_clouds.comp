#version 450
// Thin entry point of the upsample pass: one invocation per output pixel runs the model's
// upsampleCloudPass over a reduced-resolution cloud pass held on the device (a full-frame march
// or the temporal history at the pass size), so the Vulkan backend upsamples on the device. The
// bindings are interface.glsl.h's UPSAMPLE_*.
#include "interface.glsl.h"
#include "upsample.glsl.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = UPSAMPLE_CLOUD_PARAMS) readonly buffer CloudBlock { CloudParams cloud; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
layout(std430, binding = UPSAMPLE_FRAME_PARAMS) readonly buffer FrameBlock { FrameParams frame; };
layout(std430, binding = UPSAMPLE_IN_CLOUD) readonly buffer Pass { CloudTexel pass[]; };
layout(std430, binding = UPSAMPLE_SCENE_DEPTH) readonly buffer SceneDepth { float sceneDepth[]; };
layout(std430, binding = UPSAMPLE_OUT_CLOUD) writeonly buffer OutCloud { CloudTexel outCloud[]; };
layout(std430, binding = UPSAMPLE_OUT_COMPOSITE) writeonly buffer OutColour {
    vec4 outColour[];
};
layout(push_constant) uniform Push { UpsamplePush push; };
// The atmosphere's lookup tables, one vec4 per texel (atmosphere.glsl.h's layout).
layout(std430, binding = UPSAMPLE_ATMOSPHERE) readonly buffer Atmosphere { vec4 atmosphereLut[]; };
vec4 atmosphereLutTexel(int index) { return atmosphereLut[index]; }
// The terrain's height field, one float per texel (terrain.glsl.h).
layout(std430, binding = UPSAMPLE_TERRAIN) readonly buffer Terrain { float terrainHeights[]; };
float terrainHeightTexel(int index) { return terrainHeights[index]; }
// The clouds' shadow map of this frame (cloud_shadow.glsl.h), written by cloud_shadow.comp.
layout(std430, binding = UPSAMPLE_CLOUD_SHADOW) readonly buffer CloudShadow { vec4 cloudShadowMap[]; };
vec4 cloudShadowTexel(int index) { return cloudShadowMap[index]; }
// The ground's cloud shadow reads base-shape (cheap) densities: the base noise and the weather
// map. The detail and curl noise are never read on that path (the interface test would report a
// bound texture the shader does not use); their prototypes need bodies to link.
layout(binding = UPSAMPLE_BASE_NOISE) uniform sampler3D baseNoise;
layout(binding = UPSAMPLE_WEATHER_MAP) uniform sampler2D weatherMap;
vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }
layout(binding = UPSAMPLE_HIGH_CLOUDS) uniform sampler2D highClouds;
vec4 sampleHighClouds(vec2 uv) { return textureLod(highClouds, uv, 0.0f); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return vec4(0.0f); }
vec4 sampleCurlNoise(vec2 uv) { return vec4(0.0f); }

// The background's light per output pixel (pixel.glsl.h's BackgroundLight): filled by this
// shader's PASS_FILL_BACKGROUND pipeline when the renderer's background changed, read by the
// upsample.
layout(std430, binding = UPSAMPLE_BACKGROUND) buffer Background { BackgroundLight background[]; };
// The background under this frame's clouds (BackgroundTexel), made from that light by the
// PASS_SHADE_BACKGROUND pipeline when the light or the clouds changed.
layout(std430, binding = UPSAMPLE_BACKGROUND_SEEN) buffer Seen { BackgroundTexel seen[]; };
// The light shafts' grid over the pass's image (shaft_grid.glsl.h), when push.shaftGrid is 1.
layout(std430, binding = UPSAMPLE_SHAFTS) readonly buffer Shafts { ShaftTexel shafts[]; };
ShaftTexel shaftTexel(ivec2 cell) {
    ivec2 grid = shaftGridSize(ivec2(push.passWidth, push.passHeight), cloud.shafts.gridFactor);
    return shafts[cell.y * grid.x + cell.x];
}

#define GROUND_FALLBACK_BINDING UPSAMPLE_GROUND_FALLBACK
#include "ground_fallback_list.glsl"

CloudTexel passTexel(ivec2 pixel) { return pass[pixel.y * push.passWidth + pixel.x]; }
float sampleSceneDepth(ivec2 pixel) { return sceneDepth[pixel.y * frame.width + pixel.x]; }

void main() {
    if ((MODEL_FEATURES & PASS_GROUND_FALLBACK) != 0) {
        shadeListedGroundFallback(); // the dispatch over the ground fallback's list
        return;
    }
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= frame.width || pixel.y >= frame.height) {
        return;
    }
    int i = pixel.y * frame.width + pixel.x;
    if ((MODEL_FEATURES & (PASS_FILL_BACKGROUND | PASS_SHADE_BACKGROUND)) != 0) {
        // Filling makes the light and applies the clouds at once: one pass where both change.
        BackgroundLight light = background[i];
        if ((MODEL_FEATURES & PASS_FILL_BACKGROUND) != 0) {
            light = backgroundLightAt(pixel, frame, cloud);
            background[i] = light;
        }
        shadeBackground(light, pixel, i);
        return;
    }
    UpsampledPixel r = upsampleCloudPass(pixel, ivec2(push.passWidth, push.passHeight), frame,
                                         cloud, seen[i], push.shaftGrid != 0);
    outCloud[i] = r.cloud;
    outColour[i] = vec4(r.composite, 1.0f);
}
