#pragma once
// CPU-side texture storage shared by the generators, the CPU backend's samplers, the exporters
// and (later) the GPU upload. Every texture is stored as RGBA float with a full mip chain; level
// 0 is the finest. Values of the noise and weather textures are quantised to 8-bit levels at
// generation time so that an RGBA8 GPU upload holds exactly the same numbers.
#include <cstddef>
#include <vector>

namespace cloudscape {

struct Texture3D {
    int size = 0;                         // edge length of level 0 (cube, power of two)
    std::vector<std::vector<float>> mips; // mips[l]: (size>>l)^3 texels * 4 floats, x fastest
    // The same values as 8-bit levels (mips[l][i] == unorm8[l][i] / 255.0f exactly), filled by
    // quantizeToUnorm8 so that the CPU sampler reads a quarter of the bytes, as an RGBA8 GPU
    // image does; empty when the levels were written otherwise. Whoever changes mips after
    // quantising must clear it.
    std::vector<std::vector<unsigned char>> unorm8;

    int levelSize(int level) const { return size >> level; }
    int levelCount() const { return static_cast<int>(mips.size()); }
    float* texel(int level, int x, int y, int z) {
        const int n = levelSize(level);
        return &mips[level][(static_cast<size_t>(z) * n * n + static_cast<size_t>(y) * n + x) * 4];
    }
    const float* texel(int level, int x, int y, int z) const {
        return const_cast<Texture3D*>(this)->texel(level, x, y, z);
    }
};

struct Texture2D {
    int width = 0;
    int height = 0;
    std::vector<std::vector<float>> mips; // mips[l]: max(1,w>>l)*max(1,h>>l) texels * 4 floats

    int levelWidth(int level) const { return width >> level > 0 ? width >> level : 1; }
    int levelHeight(int level) const { return height >> level > 0 ? height >> level : 1; }
    int levelCount() const { return static_cast<int>(mips.size()); }
    float* texel(int level, int x, int y) {
        return &mips[level][(static_cast<size_t>(y) * levelWidth(level) + x) * 4];
    }
    const float* texel(int level, int x, int y) const {
        return const_cast<Texture2D*>(this)->texel(level, x, y);
    }
};

// Box-filtered mip chains with wrap-around (the textures tile). Level 0 must be filled.
void buildMipChain(Texture3D& texture);
void buildMipChain(Texture2D& texture);

// Round every value of every level to the nearest of 256 levels in [0, 1] (RGBA8 UNORM).
void quantizeToUnorm8(Texture3D& texture);
void quantizeToUnorm8(Texture2D& texture);

} // namespace cloudscape
