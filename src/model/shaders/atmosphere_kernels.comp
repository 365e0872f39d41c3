#version 450
// The atmosphere's per-texel functions (atmosphere.glsl.h) on the GPU, for a test that compares
// them with the host's tables (src/vulkan/tests/atmosphere_kernels_test.cpp), texel by texel
// at chosen texels: the GLSL build of the code that fills the tables on the host and, through
// atmosphere_tables.comp, on the device.
#include "atmosphere.glsl.h"

layout(local_size_x = 64) in;
// The sky: AtmosphereParams as 6 vec4 rows, then (sun direction, sun angular radius).
layout(std430, binding = 0) buffer Params { AtmosphereParams atmosphere; vec4 sun; };
// The host's tables (the multiple-scattering, sky-view and ambient texels read the earlier ones).
layout(std430, binding = 1) buffer Tables { vec4 atmosphereLut[]; };
// Per query: (table kind, x, y, -); per result: the texel.
layout(std430, binding = 2) buffer Queries { vec4 queries[]; };
layout(std430, binding = 3) buffer Results { vec4 results[]; };

vec4 atmosphereLutTexel(int index) { return atmosphereLut[index]; }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(queries.length())) {
        return;
    }
    vec4 q = queries[i];
    ivec2 texel = ivec2(int(q.y), int(q.z));
    int kind = int(q.x);
    vec3 sunDir = vec3(sun.x, sun.y, sun.z);
    vec4 r = vec4(0.0f);
    if (kind == 0) {
        r = transmittanceLutTexel(texel, atmosphere);
    } else if (kind == 1) {
        r = multiScatterLutTexel(texel, atmosphere);
    } else if (kind == 2) {
        r = skyViewLutTexel(texel, sunDir, sun.w, atmosphere);
    } else {
        r = ambientLutTexel(texel, kind == 4, sun.w, atmosphere);
    }
    results[i] = r;
}
