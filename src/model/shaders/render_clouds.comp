#version 450
// Thin entry point: one invocation per pixel of a tile (full frames) or per 4x4 block (the
// temporal renderer's block mode) runs the model's renderPixel and stores the result. All physics
// lives in the included headers; the bindings are interface.glsl.h's MARCH_*.
#include "interface.glsl.h"
#include "pixel.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = PASS_WORKGROUP_SIDE, local_size_y = PASS_WORKGROUP_SIDE) in;

layout(std430, binding = MARCH_CLOUD_PARAMS) readonly buffer CloudBlock { CloudParams cloud; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
float cloudNoiseLevelTexel(int index) { return cloud.cloudNoiseLevels[index >> 2][index & 3]; }
layout(std430, binding = MARCH_FRAME_PARAMS) readonly buffer FrameBlock { FrameParams frame; };
layout(std430, binding = MARCH_PREVIOUS_FRAME) readonly buffer PreviousBlock {
    FrameParams previous;
};
layout(binding = MARCH_BASE_NOISE) uniform sampler3D baseNoise;
layout(binding = MARCH_DETAIL_NOISE) uniform sampler3D detailNoise;
layout(binding = MARCH_CURL_NOISE) uniform sampler2D curlNoise;
layout(binding = MARCH_WEATHER_MAP) uniform sampler2D weatherMap;
layout(binding = MARCH_BLUE_NOISE) uniform sampler2D blueNoise;
layout(std430, binding = MARCH_SCENE_DEPTH) readonly buffer SceneDepth { float sceneDepth[]; };
layout(binding = MARCH_OUT_CLOUD, rgba32f) uniform writeonly imageBuffer cloudOut;
layout(binding = MARCH_OUT_COMPOSITE, rgba32f) uniform writeonly imageBuffer compositeOut;
layout(binding = MARCH_OUT_ENTERING, rgba32f) uniform writeonly imageBuffer enteringOut;
layout(std430, binding = MARCH_COUNTERS) buffer Counters { FrameCounters counters; };
layout(push_constant) uniform Push { MarchPush push; };
#define ATMOSPHERE_BINDING MARCH_ATMOSPHERE
#define TERRAIN_BINDING MARCH_TERRAIN
#define CLOUD_SHADOW_BINDING MARCH_CLOUD_SHADOW
#include "world_buffers.glsl"
layout(binding = MARCH_NOISE_CLEARANCE) uniform usamplerBuffer noiseClearance;
uint noiseClearanceTexel(int index) { return texelFetch(noiseClearance, index).x; }
#include "texel_rows.glsl"
#include "frame_counters.glsl"
#include "dispatch_order.glsl"

vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return textureLod(detailNoise, uvw, lod); }
vec4 sampleCurlNoise(vec2 uv) { return textureLod(curlNoise, uv, 0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }
layout(binding = MARCH_HIGH_CLOUDS) uniform sampler2D highClouds;
vec4 sampleHighClouds(vec2 uv) { return textureLod(highClouds, uv, 0.0f); }
float sampleBlueNoise(ivec2 pixel) {
    ivec2 n = textureSize(blueNoise, 0);
    return texelFetch(blueNoise, ivec2(pixel.x & (n.x - 1), pixel.y & (n.y - 1)), 0).x;
}
float sampleSceneDepth(ivec2 pixel) { return sceneDepth[pixel.y * frame.width + pixel.x]; }

// A gathering frame's entering block marches its other pixels into the entering ring
// (sample_gather.glsl.h); the pipeline of every other frame is built without the loop.
int marchEntering(ivec2 block, int index) {
    if (!featureCompiled(FEATURE_GATHER)) {
        return 0;
    }
    int extra = enteringMarchCount(block, frame, previous, cloud, frame.secondsSincePrevious, true);
    int slot = enteringSlot(frame, 0);
    int first = (slot * gatherSlotBlocks(ivec2(frame.width, frame.height)) + index) *
                ENTERING_MARCHES;
    countEntering(uint(extra));
    for (int k = 0; k < extra; ++k) {
        ivec2 pixel = enteringPixel(block, k, frame);
        PixelResult r = renderPixel(uint(pixel.x), uint(pixel.y), frame, cloud);
        CloudTexel t = marchRecord(r, 0.0f, 0.0f);
        imageStore(enteringOut, CLOUD_TEXEL_ROWS * (first + k), t.cloud);
        imageStore(enteringOut, CLOUD_TEXEL_ROWS * (first + k) + 1, cloudTexelSecondRow(t));
        countSamples(uint(r.densitySamples), uint(r.lightSamples), uint(r.cloudSamples),
                     uint(r.emptySkips));
    }
    return extra;
}

void main() {
    beginCounters();
    ivec2 size = ivec2(frame.width, frame.height);
    bool blockMode = push.blockMode != 0;
    ivec2 extent = blockMode ? temporalBlockCount(size, frameBlock(frame)) : size;
    // The full frame's tiles visit their rows interleaved (dispatch_order.glsl); the block march
    // measured slower so. Both include the tile's base workgroup.
    ivec2 id = blockMode ? ivec2(gl_GlobalInvocationID.xy) : balancedTileInvocation();
    if (id.x < extent.x && id.y < extent.y) {
        ivec2 pixel = blockMode ? marchedPixel(id, frame.sequenceFrame, frame) : id;
        PixelResult r = renderPixel(uint(pixel.x), uint(pixel.y), frame, cloud);
        int index = id.y * extent.x + id.x;
        int entering = blockMode ? marchEntering(id, index) : 0;
        CloudTexel t = marchRecord(r, float(entering),
                                   texelDebugCode(TEMPORAL_SOURCE_MARCHED, float(r.densitySamples)));
        imageStore(cloudOut, CLOUD_TEXEL_ROWS * index, t.cloud);
        imageStore(cloudOut, CLOUD_TEXEL_ROWS * index + 1, cloudTexelSecondRow(t));
        if (!blockMode) {
            imageStore(compositeOut, index, vec4(r.composite, 1.0f));
        }
        countSamples(uint(r.densitySamples), uint(r.lightSamples), uint(r.cloudSamples),
                     uint(r.emptySkips));
    }
    flushCounters();
}
