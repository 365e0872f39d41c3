#pragma once
// A tileable blue-noise threshold map for the march's per-pixel start offset. Blue noise has
// (almost) no energy at low spatial frequencies, so the step-jitter error it leaves looks like
// fine grain that a small blur or the temporal filter removes, instead of the clumps of white
// noise (a hash).
#include <cloudscape/texture.h>

#include <cstdint>

namespace cloudscape {

// Ulichney's void-and-cluster method (Proc. SPIE 1913, 1993): a size x size map whose values are
// the ranks of a progressively filled dither pattern, uniformly spread over [0, 1] and quantised
// to RGBA8 levels (R = G = B = rank, A = 1). Wraps seamlessly; deterministic for a seed; one mip
// level (it is read unfiltered, one texel per pixel). size is a power of two in [8, 256].
Texture2D generateBlueNoise(int size = 64, uint32_t seed = 1);

// The renderer's map (64 x 64, seed 1), generated once per process on first use (thread-safe).
const Texture2D& blueNoiseTexture();

} // namespace cloudscape
