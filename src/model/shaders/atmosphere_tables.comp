#version 450
// Thin entry point of the atmosphere's tables pass: one invocation per texel of the table named
// by the push constant runs the model's atmosphereTableTexel (atmosphere.glsl.h) and stores it in
// the buffer the march, resolve and upsample passes read. The host dispatches the tables in the
// model's order with a barrier between them, since each reads those before it through
// atmosphereLutTexel (src/vulkan/atmosphere_tables.cpp). The bindings are interface.glsl.h's
// TABLES_*.
#include "interface.glsl.h"
#include "atmosphere.glsl.h"

layout(local_size_x = PASS_WORKGROUP_SIDE, local_size_y = PASS_WORKGROUP_SIDE) in;

layout(std430, binding = TABLES_SKY_PARAMS) readonly buffer SkyBlock { SkyParams sky; };
layout(std430, binding = TABLES_ATMOSPHERE) buffer Atmosphere { vec4 atmosphereLut[]; };
layout(push_constant) uniform Push { TablesPush push; };

vec4 atmosphereLutTexel(int index) { return atmosphereLut[index]; }

void main() {
    ivec3 region = atmosphereTableLayout(push.table);
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= region.y || texel.y >= region.z) {
        return;
    }
    atmosphereLut[region.x + texel.y * region.y + texel.x] =
        atmosphereTableTexel(push.table, texel, sky);
}
