#version 450
// Thin entry point of the upsample pass: one invocation per output pixel runs the model's
// upsampleCloudPass over a reduced-resolution cloud pass held on the device (a full-frame march
// or the temporal history at the pass size), so the Vulkan backend upsamples on the device. The
// bindings are interface.glsl.h's UPSAMPLE_*.
#include "interface.glsl.h"
#include "upsample.glsl.h"

layout(local_size_x = PASS_WORKGROUP_SIDE, local_size_y = PASS_WORKGROUP_SIDE) in;

layout(std430, binding = UPSAMPLE_CLOUD_PARAMS) readonly buffer CloudBlock { CloudParams cloud; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
layout(std430, binding = UPSAMPLE_FRAME_PARAMS) readonly buffer FrameBlock { FrameParams frame; };
layout(binding = UPSAMPLE_IN_CLOUD) uniform samplerBuffer pass;
layout(std430, binding = UPSAMPLE_SCENE_DEPTH) readonly buffer SceneDepth { float sceneDepth[]; };
layout(binding = UPSAMPLE_OUT_CLOUD, rgba32f) uniform writeonly imageBuffer outCloud;
layout(binding = UPSAMPLE_OUT_COMPOSITE, rgba32f) uniform writeonly imageBuffer outColour;
layout(push_constant) uniform Push { UpsamplePush push; };
#define ATMOSPHERE_BINDING UPSAMPLE_ATMOSPHERE
#define TERRAIN_BINDING UPSAMPLE_TERRAIN
#define CLOUD_SHADOW_BINDING UPSAMPLE_CLOUD_SHADOW
#include "world_buffers.glsl"
#include "texel_rows.glsl"
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

// The background per output pixel, filled and shaded by this shader's background pipelines.
#define BACKGROUND_BINDING UPSAMPLE_BACKGROUND
#define BACKGROUND_SEEN_BINDING UPSAMPLE_BACKGROUND_SEEN
#include "background_buffers.glsl"
// The light shafts' grid over the pass's image (shaft_grid.glsl.h), when push.shaftGrid is 1.
layout(binding = UPSAMPLE_SHAFTS) uniform samplerBuffer shafts;
ShaftTexel shaftTexel(ivec2 cell) {
    ivec2 grid = shaftGridSize(ivec2(push.passWidth, push.passHeight), cloud.shafts.gridFactor);
    int i = SHAFT_TEXEL_ROWS * (cell.y * grid.x + cell.x);
    ShaftTexel t;
    t.front = texelFetch(shafts, i);
    t.behind = texelFetch(shafts, i + 1);
    return t;
}

#define GROUND_FALLBACK_BINDING UPSAMPLE_GROUND_FALLBACK
#include "ground_fallback_list.glsl"
// The pass's background (the resolve's), for the pipeline built with PASS_UPSAMPLED_BACKGROUND.
layout(binding = UPSAMPLE_PASS_BACKGROUND_SEEN) uniform samplerBuffer passBackground;
BackgroundTexel passBackgroundTexel(ivec2 pixel) {
    int i = BACKGROUND_TEXEL_ROWS * (pixel.y * push.passWidth + pixel.x);
    BackgroundTexel t;
    t.beyond = texelFetch(passBackground, i);
    t.seen = texelFetch(passBackground, i + 1);
    return t;
}

CloudTexel passTexel(ivec2 pixel) {
    return fetchCloudTexel(pass, pixel.y * push.passWidth + pixel.x);
}
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
        BackgroundLight light = loadBackground(i);
        if ((MODEL_FEATURES & PASS_FILL_BACKGROUND) != 0) {
            light = backgroundLightAt(pixel, frame, cloud);
            storeBackground(i, light);
        }
        shadeBackground(light, pixel, i);
        return;
    }
    ivec2 passSize = ivec2(push.passWidth, push.passHeight);
    BackgroundTexel bg;
    if ((MODEL_FEATURES & PASS_UPSAMPLED_BACKGROUND) != 0) {
        bg = upsampledBackground(pixel, passSize, frame); // a moving camera's, from the pass
    } else {
        bg = loadSeen(i);
    }
    UpsampledPixel r =
        upsampleCloudPass(pixel, passSize, frame, cloud, bg, push.shaftGrid != 0);
    imageStore(outCloud, CLOUD_TEXEL_ROWS * i, r.cloud.cloud);
    imageStore(outCloud, CLOUD_TEXEL_ROWS * i + 1, cloudTexelSecondRow(r.cloud));
    imageStore(outColour, i, vec4(r.composite, 1.0f));
}
