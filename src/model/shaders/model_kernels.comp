#version 450
// Unit kernels: the shared model functions evaluated on the GPU for inputs written by the tests,
// so the GPU compilation can be compared with the C++ one.
#include "lighting.glsl.h"
#include "phase.glsl.h"
#include "profiles.glsl.h"
#include "shell.glsl.h"
#include "weather.glsl.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) buffer Outputs { vec4 outputs[]; }; // three per input

// The density headers declare these; the kernels never call them.
vec4 sampleBaseNoise(vec3 uvw, float lod) { return vec4(0.0f); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return vec4(0.0f); }
vec4 sampleCurlNoise(vec2 uv) { return vec4(0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return vec4(0.0f); }
// The kernels run the gradient sky (sky.model "gradient"): the atmosphere's tables are never read.
vec4 atmosphereLutTexel(int index) { return vec4(0.0f); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(inputs.length())) {
        return;
    }
    vec4 v = inputs[i];
    float cosTheta = v.x * 2.0f - 1.0f;
    float g = v.y * 1.8f - 0.9f;
    outputs[i * 3u] = vec4(henyeyGreenstein(cosTheta, g), remap(v.x, v.y, v.z + 1.0f, -1.0f, 2.0f),
                           verticalProfile(v.z, v.w), beerPowder(v.w * 3.0f, cosTheta, v.y));
    vec3 origin = vec3(0.0f, v.z * 12000.0f + 1.0f, 0.0f);
    vec3 dir = normalize(vec3(v.x - 0.5f, v.y - 0.5f, 0.3f));
    outputs[i * 3u + 1u] = shellIntervals(origin, dir, 6371000.0f, 1500.0f, 8000.0f);
    outputs[i * 3u + 2u] = vec4(applyPrecipitationRule(vec3(v.x, v.y, v.z)),
                                twoLobePhase(cosTheta, 0.2f, 0.85f, v.w));
}
