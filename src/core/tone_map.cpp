// Display output of a render, for every backend and the path tracer: the composite as RGB and
// its tone mapping through the model's one curve (output.glsl.h).
#include <cloudscape/renderer.h>

#include "model/output.glsl.h"

#include <cmath>

namespace cloudscape {

std::vector<float> compositeRgb(const RenderResult& result) {
    std::vector<float> out;
    out.reserve(result.composite.size() / 4 * 3);
    for (size_t i = 0; i < result.composite.size(); i += 4)
        out.insert(out.end(),
                   {result.composite[i], result.composite[i + 1], result.composite[i + 2]});
    return out;
}

std::vector<uint8_t> toneMapRgbToSrgb8(const std::vector<float>& rgb, float exposure) {
    const size_t pixels = rgb.size() / 3;
    std::vector<uint8_t> rgba(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        const glm::vec3 c(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]);
        const glm::vec3 s = model::toneMap(c, exposure);
        rgba[i * 4 + 0] = static_cast<uint8_t>(std::lround(s.x * 255.0f));
        rgba[i * 4 + 1] = static_cast<uint8_t>(std::lround(s.y * 255.0f));
        rgba[i * 4 + 2] = static_cast<uint8_t>(std::lround(s.z * 255.0f));
        rgba[i * 4 + 3] = 255;
    }
    return rgba;
}

std::vector<uint8_t> toneMapToSrgb8(const RenderResult& result, float exposure) {
    return toneMapRgbToSrgb8(compositeRgb(result), exposure);
}

} // namespace cloudscape
