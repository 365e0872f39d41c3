// The texture reads the model needs. Each backend defines these functions: the shaders with
// textureLod on wrap/trilinear samplers, the CPU backend with its own trilinear sampler over the
// same mip chains (src/cpu/cpu_textures.cpp). Coordinates are normalised texture coordinates;
// every texture wraps.
#ifndef CLOUDSCAPE_MODEL_SAMPLING_GLSL_H
#define CLOUDSCAPE_MODEL_SAMPLING_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Base noise 128^3: R Perlin-Worley, GBA Worley FBM at rising frequencies.
vec4 sampleBaseNoise(vec3 uvw, float lod);
// Detail noise 32^3: RGB Worley FBM at rising frequencies.
vec4 sampleDetailNoise(vec3 uvw, float lod);
// Curl noise 128^2: RGB curl vector encoded as 0.5 + 0.5 * v.
vec4 sampleCurlNoise(vec2 uv);
// Weather map: R coverage, G precipitation, B type (before the precipitation rule).
vec4 sampleWeatherMap(vec2 uv);

// Per-pixel reads, used only by pixel.glsl.h (so kernels that never render pixels need not
// define them). Blue noise 64^2 (src/generators/blue_noise.cpp): the rank in [0, 1] of the texel
// at pixel mod 64, unfiltered; it tiles.
float sampleBlueNoise(ivec2 pixel);
// The scene depth buffer: metres along the view ray to opaque geometry at an output pixel.
float sampleSceneDepth(ivec2 pixel);
// The high-altitude layer's texture 512^2 (src/generators/high_clouds.cpp): R cirrostratus,
// G cirrus, B cirrocumulus; filtered, wrapping, mip 0.
vec4 sampleHighClouds(vec2 uv);
// The terrain's height field: texel `index` (row-major, TerrainParams.width a row) in metres,
// unfiltered (terrain.glsl.h interpolates in full float precision on both backends).
float terrainHeightTexel(int index);
// The base noise's clearance field (noise_clearance.glsl.h's layout), texel `index`, unfiltered;
// read by the march only.
uint noiseClearanceTexel(int index);

#ifndef __cplusplus
// GLSL only: cell `index` of CloudParams.cloudTops, read from the shader's parameter block
// (cloud_bound.glsl.h says why not from the by-value P; C++ reads P.cloudTops directly).
float cloudTopTexel(int index);
#endif

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
