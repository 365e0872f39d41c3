// Shader plumbing (GLSL only): the world's tables that the march, the resolve and the upsample
// read per pixel, as uniform texel buffers (texel_rows.glsl says why), and the reads the model
// declares for them. Define ATMOSPHERE_BINDING, TERRAIN_BINDING and CLOUD_SHADOW_BINDING first.

// The atmosphere's lookup tables, one RGBA32F texel per table texel (atmosphere.glsl.h's layout).
layout(binding = ATMOSPHERE_BINDING) uniform samplerBuffer atmosphereLut;
vec4 atmosphereLutTexel(int index) { return texelFetch(atmosphereLut, index); }
// The terrain's height field, one R32F texel per height (terrain.glsl.h).
layout(binding = TERRAIN_BINDING) uniform samplerBuffer terrainHeights;
float terrainHeightTexel(int index) { return texelFetch(terrainHeights, index).x; }
// The clouds' shadow map of this frame (cloud_shadow.glsl.h), written by cloud_shadow.comp.
layout(binding = CLOUD_SHADOW_BINDING) uniform samplerBuffer cloudShadowMap;
vec4 cloudShadowTexel(int index) { return texelFetch(cloudShadowMap, index); }
