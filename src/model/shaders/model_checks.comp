#version 450
// Checks of the model's behaviour on the GPU (src/vulkan/tests/model_checks_test.cpp): the GLSL
// build of the shared functions against expectations written out by hand in the test, not
// against the C++ build. The density field here is analytic (the texture reads below), so the
// light cone's sample positions can be recovered from the optical depth it gathers.
#include "lighting.glsl.h"
#include "temporal.glsl.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Params { CloudParams cloud; FrameParams frame; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
// Two vec4 per query: (kind, a, b, c), (d, e, f, unused); one vec4 of results per query.
layout(std430, binding = 1) buffer Queries { vec4 queries[]; };
layout(std430, binding = 2) buffer Results { vec4 results[]; };

CONST_FLOAT TWO_PI = 6.2831853f;
// Smooth, positive fields varying along every axis: features of a few hundred metres at the
// base noise's 7 km period, so a light sample moved by half a step reads another density.
vec4 sampleBaseNoise(vec3 uvw, float lod) {
    float v = 0.55f + 0.3f * sin(TWO_PI * (9.0f * uvw.x + 4.0f * uvw.y)) *
                         cos(TWO_PI * (7.0f * uvw.z - 3.0f * uvw.y)) + 0.1f * lod;
    return vec4(v, 1.0f, 1.0f, 1.0f);
}
vec4 sampleDetailNoise(vec3 uvw, float lod) {
    return vec4(0.3f + 0.2f * sin(TWO_PI * (uvw.x + uvw.y + uvw.z)), 0.2f, 0.2f, 0.0f);
}
vec4 sampleCurlNoise(vec2 uv) { return vec4(0.5f, 0.5f, 0.5f, 0.0f); }
// The coverage field in red (high byte) and alpha (low byte) alike decodes to exactly that value.
vec4 sampleWeatherMap(vec2 uv) {
    float field = 0.7f + 0.25f * sin(TWO_PI * 11.0f * uv.x);
    return vec4(field, 0.0f, 1.0f, field);
}
float sampleBlueNoise(ivec2 pixel) { return 0.5f; }
// The checks draw no high-altitude layer (its coverage is 0): the texture is never read.
vec4 sampleHighClouds(vec2 uv) { return vec4(0.0f); }
// The kernels run the gradient sky (sky.model "gradient"): the atmosphere's tables are never read.
vec4 atmosphereLutTexel(int index) { return vec4(0.0f); }
// The checks make no cloud shadow map (cloudShadow.resolution 0): the map is never read.
vec4 cloudShadowTexel(int index) { return vec4(0.0f); }
float sampleSceneDepth(ivec2 pixel) { return cloud.maxDistance; }
CloudTexel emptyTexel() { return CloudTexel(vec4(0.0f, 0.0f, 0.0f, 1.0f), NO_HIT, 0.0f, 0.0f, 0.0f); }
CloudTexel historyTexel(ivec2 pixel) { return emptyTexel(); }
CloudTexel freshTexel(ivec2 block) { return emptyTexel(); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i * 2u + 1u >= uint(queries.length())) {
        return;
    }
    vec4 q = queries[i * 2u];
    vec4 r = queries[i * 2u + 1u];
    int kind = int(q.x);
    vec4 result = vec4(0.0f);
    if (kind == 0) {
        // Sun light scattered toward the eye: (light optical depth, cos theta).
        result.x = directScattering(q.y, q.z, cloud);
    } else if (kind == 1) {
        // Where pixel (x, y) at a depth was dt seconds earlier, camera still.
        bool visible = false;
        result.xy = reprojectPixel(frame, frame, cloud, q.y, q.z, q.w, r.x, visible);
        result.z = visible ? 1.0f : 0.0f;
    } else if (kind == 2) {
        // The sun's optical depth from a point: (position), (precipitation, lod, cheap).
        LightSample s = sunOpticalDepth(q.yzw, r.x, r.y, r.z != 0.0f, cloud);
        result.x = s.opticalDepth;
        result.y = float(s.densitySamples);
    } else if (kind == 3) {
        // The density at a point: (position), (lod, cheap).
        result.x = cloudDensityAt(q.yzw, r.x, r.y != 0.0f, cloud);
    }
    results[i] = result;
}
