// Shader plumbing (GLSL only): which part of the image a workgroup of the full-frame march
// covers. Every pixel is computed exactly as it would be in image order; only the order in which
// a dispatch's workgroups visit the image changes (interface.glsl.h's interleavedRow). Include
// after interface.glsl.h.
//
// Why: lavapipe (Mesa 22's llvmpipe compute) gives each of its N threads one contiguous Nth of a
// dispatch's workgroups, x fastest, and waits for the slowest. In image order one thread took the
// upper half of a tile and another the lower, whose costs differ where the horizon or a cloud
// bank crosses it: a still's march ran 1.35x faster on two threads than on one, 1.86x with the
// rows interleaved (docs/PERFORMANCE.md). The temporal passes, whose dispatches span the whole
// image, already ran 1.9x faster on two threads, and the block march measured 0-20 % slower
// interleaved, so they keep image order. GPUs schedule workgroups as they free up and are
// indifferent to the order.
//
// Positions are counted in PASS_WORKGROUP_SIDE, not gl_WorkGroupSize: a pass including this file
// before it declares its local size would get a gl_WorkGroupSize of 1 from glslang.

// The invocation's position in a tile of the full-frame march, whose base workgroup is a
// multiple of MARCH_TILE_WORKGROUPS: the pixel, the base included as in gl_GlobalInvocationID.
ivec2 balancedTileInvocation() {
    uvec2 inTile = gl_WorkGroupID.xy % uint(MARCH_TILE_WORKGROUPS);
    uvec2 visited = uvec2(inTile.x, interleavedRow(inTile.y, gl_NumWorkGroups.y));
    uvec2 group = gl_WorkGroupID.xy - inTile + visited;
    return ivec2(group * uint(PASS_WORKGROUP_SIDE) + gl_LocalInvocationID.xy);
}
