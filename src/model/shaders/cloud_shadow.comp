#version 450
// Thin entry point of the shadow-map pass: one invocation per texel of a region of the map (the
// whole map, or the rows and columns a moving camera brings in) runs the model's
// cloudShadowMapTexel (cloud_shadow.glsl.h) and stores it, before the passes that read the map.
// The bindings are interface.glsl.h's SHADOW_*.
#include "interface.glsl.h"
#include "cloud_shadow.glsl.h"

layout(local_size_x = PASS_WORKGROUP_SIDE, local_size_y = PASS_WORKGROUP_SIDE) in;

layout(std430, binding = SHADOW_CLOUD_PARAMS) readonly buffer CloudBlock { CloudParams cloud; };
// The cloud-top grid and the data field straight from the block, never from a by-value copy
// (sampling.glsl.h).
float cloudTopTexel(int index) { return cloud.cloudTops[index >> 2][index & 3]; }
vec4 dataFieldTexel(int index) { return cloud.dataField[index]; }
layout(binding = SHADOW_BASE_NOISE) uniform sampler3D baseNoise;
layout(binding = SHADOW_DETAIL_NOISE) uniform sampler3D detailNoise;
layout(binding = SHADOW_CURL_NOISE) uniform sampler2D curlNoise;
layout(binding = SHADOW_WEATHER_MAP) uniform sampler2D weatherMap;
// A storage texel buffer rather than a storage buffer: one vector store on lavapipe
// (texel_rows.glsl).
layout(binding = SHADOW_OUT_MAP, rgba32f) uniform writeonly imageBuffer outMap;
layout(push_constant) uniform Push { ShadowPush push; };

vec4 sampleBaseNoise(vec3 uvw, float lod) { return textureLod(baseNoise, uvw, lod); }
vec4 sampleDetailNoise(vec3 uvw, float lod) { return textureLod(detailNoise, uvw, lod); }
vec4 sampleCurlNoise(vec2 uv) { return textureLod(curlNoise, uv, 0.0f); }
vec4 sampleWeatherMap(vec2 uv) { return textureLod(weatherMap, uv, 0.0f); }

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy) + ivec2(push.originX, push.originY);
    if (texel.x >= push.endX || texel.y >= push.endY) {
        return;
    }
    imageStore(outMap, cloudShadowStorageIndex(texel, cloud.cloudShadow),
               cloudShadowMapTexel(texel, cloud));
}
