#version 450
// Thin entry point of the temporal resolve pass: one invocation per full-resolution pixel runs
// the model's resolveAndComposite. Dispatched by the Vulkan temporal renderer
// (src/vulkan/vulkan_temporal.cpp) after render_clouds.comp's block mode filled the fresh
// records; the bindings are interface.glsl.h's RESOLVE_*.
#include "interface.glsl.h"
#include "pixel.glsl.h"
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

CloudTexel historyTexel(ivec2 pixel) { return history[pixel.y * previous.width + pixel.x]; }
CloudTexel freshTexel(ivec2 block) {
    return fresh[block.y * temporalBlockCount(ivec2(frame.width, frame.height)).x + block.x];
}
float sampleSceneDepth(ivec2 pixel) { return sceneDepth[pixel.y * frame.width + pixel.x]; }

void main() {
    beginCounters();
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x < frame.width && pixel.y < frame.height) {
        ResolvedPixel r = resolveAndComposite(pixel, push.frameIndex, frame, previous, cloud,
                                              push.dt, push.haveHistory != 0);
        int i = pixel.y * frame.width + pixel.x;
        outHistory[i] = r.history;
        outColour[i] = vec4(r.composite, 1.0f);
        countSource(r.source);
    }
    flushCounters();
}
