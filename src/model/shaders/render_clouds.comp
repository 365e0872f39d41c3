#version 450
// Thin entry point: one invocation per pixel marches the clouds with the shared model and writes
// premultiplied radiance + transmittance, depth, and the composited colour. All physics lives in
// the included headers.
#include "camera.glsl.h"
#include "march.glsl.h"
#include "sky.glsl.h"

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

vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return textureLod(detailNoise, uvw, lod); }
vec4 sampleCurlNoise(vec2 uv) { return textureLod(curlNoise, uv, 0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= uint(frame.size.x) || pixel.y >= uint(frame.size.y)) {
        return;
    }
    vec3 origin = frame.cameraPosition.xyz;
    vec3 dir = cameraRayDirection(frame, float(pixel.x), float(pixel.y));
    float jitter = pixelRandom(pixel.x, pixel.y, uint(frame.size.z), uint(frame.size.w));
    MarchResult march = marchClouds(origin, dir, jitter, cloud);
    uint index = pixel.y * uint(frame.size.x) + pixel.x;
    cloudRadianceTransmittance[index] = vec4(march.radiance, march.transmittance);
    cloudDepth[index] = march.depth;
    composited[index] = vec4(compositeOver(march.radiance, march.transmittance,
                                           skyRadiance(dir, cloud)), 1.0f);
}
