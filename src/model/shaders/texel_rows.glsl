// Shader plumbing (GLSL only): the per-pixel records as rows of RGBA32F texels. Every record a
// pass keeps per pixel is whole vec4 rows (interface.glsl.h's 16-byte rule), so its buffer is also
// a texel buffer, and the passes read and write it as one: on lavapipe (Mesa 22.3) a
// storage-buffer load or store is a loop over the SIMD lanes with a branch per lane and
// component, a texel fetch or image load/store one vector gather or scatter. The bytes are the
// same either way (the host and the CPU backend see the std430 records).

// A CloudTexel from its two rows in a uniform texel buffer (record `index`).
CloudTexel fetchCloudTexel(samplerBuffer texels, int index) {
    vec4 second = texelFetch(texels, CLOUD_TEXEL_ROWS * index + 1);
    CloudTexel t;
    t.cloud = texelFetch(texels, CLOUD_TEXEL_ROWS * index);
    t.depth = second.x;
    t.weight = second.y;
    t.flash = second.z;
    t.debug = second.w;
    return t;
}

// The row after CloudTexel.cloud, for a pass that stores the record: image parameters would need
// the format the declaration gives, so each shader stores the two rows itself.
vec4 cloudTexelSecondRow(CloudTexel t) { return vec4(t.depth, t.weight, t.flash, t.debug); }
