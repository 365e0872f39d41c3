#version 450
// Compiles the shared weather header as GLSL; a unit-kernel entry point for the GPU tests.
#include "weather.glsl.h"
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    values[i] = vec4(applyPrecipitationRule(values[i].xyz), remap(values[i].w, 0.0f, 1.0f, 2.0f, 4.0f));
}
