#version 450
// Thin entry point: one invocation per pixel of a tile runs the model's renderPixel and stores
// the result. All physics lives in the included headers.
#include "pixel.glsl.h"

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

// The tile this dispatch covers (long dispatches are split so no single one runs for long).
layout(push_constant) uniform Tile { ivec2 tileOrigin; };

vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return textureLod(detailNoise, uvw, lod); }
vec4 sampleCurlNoise(vec2 uv) { return textureLod(curlNoise, uv, 0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy + uvec2(tileOrigin);
    if (pixel.x >= uint(frame.size.x) || pixel.y >= uint(frame.size.y)) {
        return;
    }
    PixelResult r = renderPixel(pixel.x, pixel.y, frame, cloud);
    uint index = pixel.y * uint(frame.size.x) + pixel.x;
    cloudRadianceTransmittance[index] = vec4(r.cloudRadiance, r.transmittance);
    cloudDepth[index] = r.depth;
    composited[index] = vec4(r.composite, 1.0f);
    sampleCounts[index] = uvec2(uint(r.densitySamples), uint(r.lightSamples));
}
