#version 450
// Thin entry point of the temporal resolve pass: one invocation per full-resolution pixel runs
// the model's resolveAndComposite; in its grid mode (the pipeline specialised with
// PASS_SHAFT_GRID), dispatched first when the light shafts come from a grid, one invocation per
// cell runs resolveShaftCell.
// Dispatched by the Vulkan temporal renderer (src/vulkan/vulkan_temporal.cpp) after
// render_clouds.comp's block mode filled the fresh records; the bindings are interface.glsl.h's
// RESOLVE_*.
#include "interface.glsl.h"
#include "pixel.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = PASS_WORKGROUP_SIDE, local_size_y = PASS_WORKGROUP_SIDE) in;

layout(std430, binding = RESOLVE_CLOUD_PARAMS) readonly buffer CloudBlock { CloudParams cloud; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
layout(std430, binding = RESOLVE_FRAME_PARAMS) readonly buffer FrameBlock { FrameParams frame; };
layout(std430, binding = RESOLVE_PREVIOUS_FRAME) readonly buffer PreviousBlock { FrameParams previous; };
layout(binding = RESOLVE_HISTORY) uniform samplerBuffer history;
layout(binding = RESOLVE_FRESH) uniform samplerBuffer fresh;
layout(binding = RESOLVE_OUT_HISTORY, rgba32f) uniform writeonly imageBuffer outHistory;
layout(binding = RESOLVE_OUT_COMPOSITE, rgba32f) uniform writeonly imageBuffer outColour;
// The scene depth buffer at the frame's size, read only when frame.hasSceneDepth is 1.
layout(std430, binding = RESOLVE_SCENE_DEPTH) readonly buffer SceneDepth { float sceneDepth[]; };
layout(std430, binding = RESOLVE_COUNTERS) buffer Counters { FrameCounters counters; };
layout(push_constant) uniform Push { ResolvePush push; };
#define ATMOSPHERE_BINDING RESOLVE_ATMOSPHERE
#define TERRAIN_BINDING RESOLVE_TERRAIN
#define CLOUD_SHADOW_BINDING RESOLVE_CLOUD_SHADOW
#include "world_buffers.glsl"
#include "texel_rows.glsl"
// The light shafts' grid (shaft_grid.glsl.h): written by the grid dispatch, read by the resolve.
layout(binding = RESOLVE_SHAFTS, rgba32f) uniform imageBuffer shafts;
int shaftCellIndex(ivec2 cell) {
    ivec2 grid = shaftGridSize(ivec2(frame.width, frame.height), cloud.shafts.gridFactor);
    return SHAFT_TEXEL_ROWS * (cell.y * grid.x + cell.x);
}
ShaftTexel shaftTexel(ivec2 cell) {
    int i = shaftCellIndex(cell);
    ShaftTexel t;
    t.front = imageLoad(shafts, i);
    t.behind = imageLoad(shafts, i + 1);
    return t;
}
// The ground's cloud shadow reads base-shape (cheap) densities: the base noise and the weather
// map. The detail and curl noise are never read on that path (the interface test would report a
// bound texture the shader does not use); their prototypes need bodies to link.
layout(binding = RESOLVE_BASE_NOISE) uniform sampler3D baseNoise;
layout(binding = RESOLVE_WEATHER_MAP) uniform sampler2D weatherMap;
vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }
layout(binding = RESOLVE_HIGH_CLOUDS) uniform sampler2D highClouds;
vec4 sampleHighClouds(vec2 uv) { return textureLod(highClouds, uv, 0.0f); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return vec4(0.0f); }
vec4 sampleCurlNoise(vec2 uv) { return vec4(0.0f); }

// The background per pixel, filled and shaded by this shader's background pipelines.
#define BACKGROUND_BINDING RESOLVE_BACKGROUND
#define BACKGROUND_SEEN_BINDING RESOLVE_BACKGROUND_SEEN
#include "background_buffers.glsl"

#include "frame_counters.glsl"
#define GROUND_FALLBACK_BINDING RESOLVE_GROUND_FALLBACK
#include "ground_fallback_list.glsl"

CloudTexel historyTexel(ivec2 pixel) {
    return fetchCloudTexel(history, pixel.y * previous.width + pixel.x);
}
CloudTexel freshTexel(ivec2 block) {
    int blocksX = temporalBlockCount(ivec2(frame.width, frame.height), frameBlock(frame)).x;
    return fetchCloudTexel(fresh, block.y * blocksX + block.x);
}
// The ring of earlier frames' marches a moving camera gathers (sample_gather.glsl.h).
layout(std430, binding = RESOLVE_GATHER_FRAMES) readonly buffer GatherFrames {
    FrameParams gatherFrames[GATHER_MAX_FRAMES];
};
layout(binding = RESOLVE_GATHER_RING) uniform samplerBuffer gatherRing;
FrameParams gatherFrame(int position) { return gatherFrames[position]; }
CloudTexel gatherTexel(int position, int blockIndex) {
    int stride = gatherSlotBlocks(ivec2(frame.width, frame.height));
    return fetchCloudTexel(gatherRing, position * stride + blockIndex);
}
layout(binding = RESOLVE_GATHER_ENTERING) uniform samplerBuffer enteringRing;
CloudTexel gatherEnteringTexel(int slot, int blockIndex, int k) {
    int block = slot * gatherSlotBlocks(ivec2(frame.width, frame.height)) + blockIndex;
    return fetchCloudTexel(enteringRing, block * ENTERING_MARCHES + k);
}
float sampleSceneDepth(ivec2 pixel) { return sceneDepth[pixel.y * frame.width + pixel.x]; }

// The grid dispatch: one invocation per cell of the shafts' grid, before the resolve.
void fillShaftGrid() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    ivec2 grid = shaftGridSize(ivec2(frame.width, frame.height), cloud.shafts.gridFactor);
    if (cell.x < grid.x && cell.y < grid.y) {
        ShaftTexel t = resolveShaftCell(cell, frame.sequenceFrame, frame, previous, cloud,
                                        frame.secondsSincePrevious, push.haveHistory != 0);
        int index = shaftCellIndex(cell);
        imageStore(shafts, index, t.front);
        imageStore(shafts, index + 1, t.behind);
    }
}

// The background dispatches: one invocation per pixel, or per listed pixel in the dispatch over
// the ground fallback's list.
void fillBackground() {
    if ((MODEL_FEATURES & PASS_GROUND_FALLBACK) != 0) {
        shadeListedGroundFallback();
        return;
    }
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x < frame.width && pixel.y < frame.height) {
        int i = pixel.y * frame.width + pixel.x;
        // Filling makes the light and applies the clouds at once: one pass where both change.
        BackgroundLight light = loadBackground(i);
        if ((MODEL_FEATURES & PASS_FILL_BACKGROUND) != 0) {
            light = backgroundLightAt(pixel, frame, cloud);
            storeBackground(i, light);
        }
        shadeBackground(light, pixel, i);
    }
}

void main() {
    if ((MODEL_FEATURES & (PASS_FILL_BACKGROUND | PASS_SHADE_BACKGROUND | PASS_GROUND_FALLBACK)) !=
        0) {
        fillBackground();
        return;
    }
    if ((MODEL_FEATURES & PASS_SHAFT_GRID) != 0) {
        fillShaftGrid();
        return;
    }
    beginCounters();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x < frame.width && pixel.y < frame.height) {
        int i = pixel.y * frame.width + pixel.x;
        ResolvedPixel r = resolveAndComposite(
            pixel, frame.sequenceFrame, frame, previous, cloud, frame.secondsSincePrevious,
            push.haveHistory != 0, loadSeen(i));
        imageStore(outHistory, CLOUD_TEXEL_ROWS * i, r.history.cloud);
        imageStore(outHistory, CLOUD_TEXEL_ROWS * i + 1, cloudTexelSecondRow(r.history));
        imageStore(outColour, i, vec4(r.composite, 1.0f));
        countSource(r.source);
    }
    flushCounters();
}
