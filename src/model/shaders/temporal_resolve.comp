#version 450
// Thin entry point of the temporal resolve pass: one invocation per full-resolution pixel runs
// the model's resolveTemporalPixel. Dispatched by the Vulkan temporal renderer
// (src/vulkan/vulkan_temporal.cpp) after render_clouds.comp's block mode filled the fresh buffers.
#include "pixel.glsl.h"
#include "sky.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CloudBlock { CloudParams cloud; };
layout(std140, binding = 1) uniform FrameBlock { FrameParams frame; };
layout(std140, binding = 2) uniform PreviousBlock { FrameParams previous; };
layout(std430, binding = 3) readonly buffer HistoryCloud { vec4 historyCloudData[]; };
layout(std430, binding = 4) readonly buffer HistoryDepth { float historyDepthData[]; };
layout(std430, binding = 5) readonly buffer FreshCloud { vec4 freshCloudData[]; };
layout(std430, binding = 6) readonly buffer FreshDepth { float freshDepthData[]; };
layout(std430, binding = 7) writeonly buffer OutCloud { vec4 outCloud[]; };
layout(std430, binding = 8) writeonly buffer OutDepth { float outDepth[]; };
layout(std430, binding = 9) writeonly buffer OutColour { vec4 outColour[]; };
layout(std430, binding = 10) readonly buffer HistoryWeight { float historyWeightData[]; };
layout(std430, binding = 11) writeonly buffer OutWeight { float outWeight[]; };
// Where each pixel came from (TemporalPixel.source), counted on the host for the breakdown.
layout(std430, binding = 12) writeonly buffer OutSource { int outSource[]; };
// The scene depth buffer at the frame's size, read only when frame.sampling.z is 1.
layout(std430, binding = 13) readonly buffer SceneDepth { float sceneDepth[]; };
layout(push_constant) uniform Step { int frameIndex; float dt; int haveHistory; };

vec4 historyAt(ivec2 p) {
    p = clamp(p, ivec2(0), ivec2(previous.size.x - 1, previous.size.y - 1));
    return historyCloudData[p.y * previous.size.x + p.x];
}
vec4 historyCloud(vec2 pixel) {
    vec2 p = clamp(pixel, vec2(0.0f), vec2(previous.size.xy - ivec2(1)));
    ivec2 p0 = ivec2(floor(p));
    vec2 a = p - vec2(p0);
    return mix(mix(historyAt(p0), historyAt(p0 + ivec2(1, 0)), a.x),
               mix(historyAt(p0 + ivec2(0, 1)), historyAt(p0 + ivec2(1, 1)), a.x), a.y);
}
float historyDepth(vec2 pixel) {
    ivec2 p = clamp(ivec2(round(pixel)), ivec2(0), ivec2(previous.size.x - 1, previous.size.y - 1));
    return historyDepthData[p.y * previous.size.x + p.x];
}
float historyWeight(vec2 pixel) {
    ivec2 p = clamp(ivec2(round(pixel)), ivec2(0), ivec2(previous.size.x - 1, previous.size.y - 1));
    return historyWeightData[p.y * previous.size.x + p.x];
}
int blocksX() { return (frame.size.x + TEMPORAL_BLOCK - 1) / TEMPORAL_BLOCK; }
vec4 freshCloud(ivec2 block) { return freshCloudData[block.y * blocksX() + block.x]; }
float freshDepth(ivec2 block) { return freshDepthData[block.y * blocksX() + block.x]; }

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= frame.size.x || pixel.y >= frame.size.y) {
        return;
    }
    TemporalPixel t = resolveTemporalPixel(pixel, frameIndex, frame, previous, cloud, dt,
                                           haveHistory != 0);
    vec3 dir = cameraRayDirection(frame, float(pixel.x), float(pixel.y));
    int i = pixel.y * frame.size.x + pixel.x;
    float geometry = frame.sampling.z != 0 ? sceneDepth[i] : cloud.march.w;
    t = hideBehindGeometry(t, geometry, cloud);
    outCloud[i] = t.cloud;
    outDepth[i] = t.depth;
    outWeight[i] = t.weight;
    outSource[i] = t.source;
    outColour[i] =
        vec4(compositeOver(t.cloud.xyz, t.cloud.w, backgroundRadiance(dir, geometry, cloud)), 1.0f);
}
