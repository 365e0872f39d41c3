#version 450
// Thin entry point of the temporal resolve pass: one invocation per full-resolution pixel runs
// the model's resolveTemporalPixel. Dispatched by the Vulkan temporal renderer
// (src/vulkan/vulkan_temporal.cpp) after render_clouds.comp's block mode filled the fresh
// records; the bindings are interface.glsl.h's RESOLVE_*.
#include "interface.glsl.h"
#include "pixel.glsl.h"
#include "sky.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = RESOLVE_CLOUD_PARAMS) uniform CloudBlock { CloudParams cloud; };
layout(std140, binding = RESOLVE_FRAME_PARAMS) uniform FrameBlock { FrameParams frame; };
layout(std140, binding = RESOLVE_PREVIOUS_FRAME) uniform PreviousBlock { FrameParams previous; };
layout(std430, binding = RESOLVE_HISTORY) readonly buffer History { CloudTexel history[]; };
layout(std430, binding = RESOLVE_FRESH) readonly buffer Fresh { CloudTexel fresh[]; };
layout(std430, binding = RESOLVE_OUT_HISTORY) writeonly buffer OutHistory {
    CloudTexel outHistory[];
};
layout(std430, binding = RESOLVE_OUT_COMPOSITE) writeonly buffer OutColour { vec4 outColour[]; };
// The scene depth buffer at the frame's size, read only when frame.hasSceneDepth is 1.
layout(std430, binding = RESOLVE_SCENE_DEPTH) readonly buffer SceneDepth { float sceneDepth[]; };
layout(std430, binding = RESOLVE_COUNTERS) buffer Counters { FrameCounters counters; };
layout(push_constant) uniform Push { ResolvePush push; };

#include "frame_counters.glsl"

vec4 historyAt(ivec2 p) {
    p = clamp(p, ivec2(0), ivec2(previous.width - 1, previous.height - 1));
    return history[p.y * previous.width + p.x].cloud;
}
vec4 historyCloud(vec2 pixel) {
    vec2 p = clamp(pixel, vec2(0.0f), vec2(previous.width - 1, previous.height - 1));
    ivec2 p0 = ivec2(floor(p));
    vec2 a = p - vec2(p0);
    return mix(mix(historyAt(p0), historyAt(p0 + ivec2(1, 0)), a.x),
               mix(historyAt(p0 + ivec2(0, 1)), historyAt(p0 + ivec2(1, 1)), a.x), a.y);
}
CloudTexel historyNearest(vec2 pixel) {
    ivec2 p = clamp(ivec2(round(pixel)), ivec2(0), ivec2(previous.width - 1, previous.height - 1));
    return history[p.y * previous.width + p.x];
}
float historyDepth(vec2 pixel) { return historyNearest(pixel).depth; }
float historyWeight(vec2 pixel) { return historyNearest(pixel).weight; }
int blocksX() { return temporalBlockCount(ivec2(frame.width, frame.height)).x; }
vec4 freshCloud(ivec2 block) { return fresh[block.y * blocksX() + block.x].cloud; }
float freshDepth(ivec2 block) { return fresh[block.y * blocksX() + block.x].depth; }

void main() {
    beginCounters();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x < frame.width && pixel.y < frame.height) {
        TemporalPixel t = resolveTemporalPixel(pixel, push.frameIndex, frame, previous, cloud,
                                               push.dt, push.haveHistory != 0);
        vec3 dir = cameraRayDirection(frame, float(pixel.x), float(pixel.y));
        int i = pixel.y * frame.width + pixel.x;
        float geometry = frame.hasSceneDepth != 0 ? sceneDepth[i] : cloud.maxDistance;
        t = hideBehindGeometry(t, geometry, cloud);
        CloudTexel out_;
        out_.cloud = t.cloud;
        out_.depth = t.depth;
        out_.weight = t.weight;
        out_.unused0 = 0.0f;
        out_.unused1 = 0.0f;
        outHistory[i] = out_;
        outColour[i] = vec4(
            compositeOver(t.cloud.xyz, t.cloud.w, backgroundRadiance(dir, geometry, cloud)), 1.0f);
        countSource(t.source);
    }
    flushCounters();
}
