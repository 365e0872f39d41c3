#pragma once
// Tileable cloud noise textures (GPU Pro 7 ch. 4, section 4.3.1). All of them tile seamlessly,
// lie in [0, 1], are deterministic for a seed, carry full mip chains, and are generated on all
// cores.
#include <cloudscape/texture.h>

#include <cstdint>
#include <vector>

namespace cloudscape {

// 128^3 RGBA: R = Perlin-Worley (Perlin FBM dilated by an inverted Worley FBM), G/B/A = inverted
// Worley FBM at rising frequencies. Defines the low-frequency base cloud shape.
Texture3D generateBaseNoise(uint32_t seed, int size = 128);

// 32^3 RGB (A = 1): inverted Worley FBM at rising frequencies; erodes the base shape's edges.
Texture3D generateDetailNoise(uint32_t seed, int size = 32);

// 128^2 RGB: curl of a tileable noise potential, each component encoded as 0.5 + 0.5 * v with
// |v| <= 1 (A = 1). Distorts the detail-noise lookup to suggest turbulence.
Texture2D generateCurlNoise(uint32_t seed, int size = 128);

// 512^2 RGB (A = 1): the high-altitude layer's formations (GPU Pro 7 4.5.4): R cirrostratus (a
// smooth veil), G cirrus (thin fibres 8 times longer along z than across), B cirrocumulus (small
// puffs in patches). Each channel is stretched to fill [0, 1], so high_clouds.coverage erodes it
// evenly.
Texture2D generateHighCloudTexture(uint32_t seed, int size = 512);

// The base noise's clearance field (src/model/noise_clearance.glsl.h says what and its layout):
// for each of a few thresholds, how far each 2^3-texel cell lies from a texel whose base shape
// could exceed it, for the march's exact skips. Empty for a texture that is not a multiple of a
// cell.
std::vector<uint32_t> generateNoiseClearance(const Texture3D& base);

// Everything together, as the renderer consumes them.
struct NoiseTextures {
    Texture3D base;
    std::vector<uint32_t> baseClearance; // generateNoiseClearance(base), or empty
    Texture3D detail;
    Texture2D curl;
    Texture2D highClouds;
};
// withClearance false leaves baseClearance empty: only march.noise_skipping reads it, and it
// costs 2 MB and a tenth of a second or so to make.
NoiseTextures generateNoiseTextures(uint32_t seed, bool withClearance = true);

} // namespace cloudscape
