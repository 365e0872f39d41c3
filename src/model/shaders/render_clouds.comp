#version 450
// Thin entry point: one invocation per pixel of a tile runs the model's renderPixel and stores
// the result. All physics lives in the included headers.
#include "pixel.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CloudBlock { CloudParams cloud; };
layout(std140, binding = 1) uniform FrameBlock { FrameParams frame; };
layout(binding = 2) uniform sampler3D baseNoise;
layout(binding = 3) uniform sampler3D detailNoise;
layout(binding = 4) uniform sampler2D curlNoise;
layout(binding = 5) uniform sampler2D weatherMap;
layout(std430, binding = 6) buffer CloudOut { vec4 cloudRadianceTransmittance[]; };
layout(std430, binding = 7) buffer DepthOut { float cloudDepth[]; };
layout(std430, binding = 8) buffer ColourOut { vec4 composited[]; };
layout(std430, binding = 9) buffer CounterOut { uvec2 sampleCounts[]; };
// The march's start offsets (src/generators/blue_noise.cpp) and the scene depth buffer at the
// frame's size (a 1-float stand-in when frame.sampling.z is 0).
layout(binding = 10) uniform sampler2D blueNoise;
layout(std430, binding = 11) readonly buffer SceneDepth { float sceneDepth[]; };

// The tile this dispatch covers (long dispatches are split so no single one runs for long), and
// the mode: temporalFrame -1 marches every pixel; temporalFrame >= 0 is the temporal renderer's
// block mode, marching the one pixel per 4x4 block of that frame (tileOrigin then counts blocks)
// into block-sized outputs.
layout(push_constant) uniform Tile {
    ivec2 tileOrigin;
    int temporalFrame;
};

vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return textureLod(detailNoise, uvw, lod); }
vec4 sampleCurlNoise(vec2 uv) { return textureLod(curlNoise, uv, 0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }
float sampleBlueNoise(ivec2 pixel) {
    ivec2 n = textureSize(blueNoise, 0);
    return texelFetch(blueNoise, ivec2(pixel.x & (n.x - 1), pixel.y & (n.y - 1)), 0).x;
}
float sampleSceneDepth(ivec2 pixel) { return sceneDepth[pixel.y * frame.size.x + pixel.x]; }

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy + uvec2(tileOrigin);
    uint index;
    if (temporalFrame >= 0) {
        ivec2 block = ivec2(pixel);
        int blocksX = (frame.size.x + TEMPORAL_BLOCK - 1) / TEMPORAL_BLOCK;
        int blocksY = (frame.size.y + TEMPORAL_BLOCK - 1) / TEMPORAL_BLOCK;
        if (block.x >= blocksX || block.y >= blocksY) {
            return;
        }
        pixel = uvec2(marchedPixel(block, temporalFrame, frame));
        index = uint(block.y * blocksX + block.x);
    } else {
        if (pixel.x >= uint(frame.size.x) || pixel.y >= uint(frame.size.y)) {
            return;
        }
        index = pixel.y * uint(frame.size.x) + pixel.x;
    }
    PixelResult r = renderPixel(pixel.x, pixel.y, frame, cloud);
    cloudRadianceTransmittance[index] = vec4(r.cloudRadiance, r.transmittance);
    cloudDepth[index] = r.depth;
    composited[index] = vec4(r.composite, 1.0f);
    sampleCounts[index] = uvec2(uint(r.densitySamples), uint(r.lightSamples));
}
