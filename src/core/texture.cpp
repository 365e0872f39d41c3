#include <cloudscape/texture.h>

#include <algorithm>
#include <cmath>

namespace cloudscape {

void buildMipChain(Texture3D& texture) {
    texture.mips.resize(1);
    for (int level = 1; (texture.size >> level) >= 1; ++level) {
        const int n = texture.size >> level;
        const int parent = n * 2;
        std::vector<float> data(static_cast<size_t>(n) * n * n * 4);
        const std::vector<float>& src = texture.mips[level - 1];
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    for (int c = 0; c < 4; ++c) {
                        float sum = 0.0f;
                        for (int dz = 0; dz < 2; ++dz)
                            for (int dy = 0; dy < 2; ++dy)
                                for (int dx = 0; dx < 2; ++dx) {
                                    const size_t i =
                                        (static_cast<size_t>(2 * z + dz) * parent * parent +
                                         static_cast<size_t>(2 * y + dy) * parent + (2 * x + dx)) *
                                            4 +
                                        c;
                                    sum += src[i];
                                }
                        data[(static_cast<size_t>(z) * n * n + static_cast<size_t>(y) * n + x) * 4 +
                             c] = sum * 0.125f;
                    }
        texture.mips.push_back(std::move(data));
    }
}

void buildMipChain(Texture2D& texture) {
    texture.mips.resize(1);
    for (int level = 1; (texture.width >> level) >= 1 || (texture.height >> level) >= 1; ++level) {
        const int w = texture.levelWidth(level);
        const int h = texture.levelHeight(level);
        const int pw = texture.levelWidth(level - 1);
        const int ph = texture.levelHeight(level - 1);
        std::vector<float> data(static_cast<size_t>(w) * h * 4);
        const std::vector<float>& src = texture.mips[level - 1];
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 4; ++c) {
                    float sum = 0.0f;
                    for (int dy = 0; dy < 2; ++dy)
                        for (int dx = 0; dx < 2; ++dx) {
                            const int sx = std::min(2 * x + dx, pw - 1);
                            const int sy = std::min(2 * y + dy, ph - 1);
                            sum += src[(static_cast<size_t>(sy) * pw + sx) * 4 + c];
                        }
                    data[(static_cast<size_t>(y) * w + x) * 4 + c] = sum * 0.25f;
                }
        texture.mips.push_back(std::move(data));
    }
}

namespace {
void quantize(std::vector<float>& values) {
    for (float& v : values)
        v = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}
} // namespace

void quantizeToUnorm8(Texture3D& texture) {
    texture.unorm8.clear();
    for (auto& level : texture.mips) {
        quantize(level);
        std::vector<unsigned char> bytes(level.size());
        for (size_t i = 0; i < level.size(); ++i)
            bytes[i] = static_cast<unsigned char>(std::lround(level[i] * 255.0f));
        texture.unorm8.push_back(std::move(bytes));
    }
}

void quantizeToUnorm8(Texture2D& texture) {
    for (auto& level : texture.mips)
        quantize(level);
}

} // namespace cloudscape
