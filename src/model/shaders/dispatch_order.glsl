// Shader plumbing (GLSL only): which part of the image a workgroup covers. Every pixel is
// computed exactly as it would be in image order; only the order in which a dispatch's
// workgroups visit the image changes (interface.glsl.h's interleavedRow). Include after
// interface.glsl.h.
//
// Why: lavapipe (Mesa 22's llvmpipe compute) gives each of its N threads one contiguous Nth of a
// dispatch's workgroups, x fastest, and waits for the slowest. In image order one thread took the
// upper half of a tile and another the lower, whose costs differ where the horizon or a cloud
// bank crosses it: a still's march ran 1.35x faster on two threads than on one, 1.86x with the
// rows interleaved (docs/PERFORMANCE.md). GPUs schedule workgroups as they free up and are
// indifferent to the order.
//
// Positions are counted in PASS_WORKGROUP_SIDE, not gl_WorkGroupSize: the passes include this
// file before they declare their local size, and glslang takes gl_WorkGroupSize as 1 there.

// The invocation's position (pixel, block, cell or texel, before any origin the pass adds) for
// a workgroup at group in a dispatch from base.
ivec2 balancedInvocationAt(uvec2 base, uvec2 group) {
    uvec2 placed = base + uvec2(group.x, interleavedRow(group.y, gl_NumWorkGroups.y));
    return ivec2(placed * uint(PASS_WORKGROUP_SIDE) + gl_LocalInvocationID.xy);
}

// In a dispatch from workgroup zero.
ivec2 balancedInvocation() { return balancedInvocationAt(uvec2(0u), gl_WorkGroupID.xy); }

// In a tile of the march, whose base workgroup is a multiple of MARCH_TILE_WORKGROUPS (the base
// included, as in gl_GlobalInvocationID).
ivec2 balancedTileInvocation() {
    uvec2 inTile = gl_WorkGroupID.xy % uint(MARCH_TILE_WORKGROUPS);
    return balancedInvocationAt(gl_WorkGroupID.xy - inTile, inTile);
}
