// The data field's extra channels: generated from tileable noises, or read from a painted image.
#include <cloudscape/data_field.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/scene.h>

#include "generators/key_range.h"
#include "generators/tileable_noise.h"
#include "model/data_field.glsl.h"

#include <algorithm>
#include <cmath>

namespace cloudscape {
namespace {

constexpr int kGrid = model::DATA_FIELD_GRID;

// A 3-octave FBM rarely leaves [-0.6, 0.6]: stretched to about [-1, 1] and clamped there.
float stretched(float fbm) {
    return std::clamp(fbm * 1.6f, -1.0f, 1.0f);
}

} // namespace

std::vector<glm::vec4> generateDataField(const DataFieldParams& p) {
    requireWeatherKeyRange("weather.extent_m", p.extentM);
    requireWeatherKeyRange("weather.feature_scale_m", p.featureScaleM);
    requireWeatherKeyRange("weather.bottom_type", p.bottomType);
    requireWeatherKeyRange("weather.base_variation", p.baseVariation);
    requireWeatherKeyRange("weather.top_variation", p.topVariation);
    // Regions vary about three times more slowly than the coverage; the lowest octave has a
    // whole number of cells across the map, so the field wraps with it.
    const int period = static_cast<int>(
        std::clamp(std::lround(p.extentM / (3.0f * p.featureScaleM)), 1L, long(kGrid / 4)));
    const uint32_t s = noise::hash32(p.seed * 13u + 0x7000u);
    const noise::PerlinFbm2 bottomFbm(period, 3, s), baseFbm(period, 3, s + 300u),
        topFbm(period, 3, s + 600u);
    std::vector<glm::vec4> field(static_cast<size_t>(kGrid) * kGrid);
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const glm::vec2 uv = (glm::vec2(i, j) + 0.5f) / float(kGrid);
            glm::vec4& cell = field[static_cast<size_t>(j) * kGrid + i];
            cell.x = std::clamp(p.bottomType * (1.0f + stretched(bottomFbm(uv))), 0.0f, 1.0f);
            cell.y = 0.0f;
            cell.z = p.baseVariation * (0.5f + 0.5f * stretched(baseFbm(uv)));
            cell.w = 1.0f - p.topVariation * (0.5f + 0.5f * stretched(topFbm(uv)));
        }
    return field;
}

std::vector<glm::vec4> loadDataFieldImage(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    const std::vector<uint8_t> pixels = readPng(path, w, h, channels);
    if (channels != 3 && channels != 4)
        throw Error(path + ": data field image has " + std::to_string(channels) +
                    " channels, expected 4 (RGBA: bottom type, anvil coverage, minimum and "
                    "maximum height) or 3 (RGB, maximum height 1)");
    // Region i averages the pixels [i w / n, (i + 1) w / n), at least one.
    auto span = [](int i, int size, int& first, int& last) {
        first = std::min(i * size / kGrid, size - 1);
        last = std::max((i + 1) * size / kGrid, first + 1);
    };
    std::vector<glm::vec4> field(static_cast<size_t>(kGrid) * kGrid);
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
            span(i, w, x0, x1);
            span(j, h, y0, y1);
            glm::dvec4 sum(0.0);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const uint8_t* px = &pixels[(static_cast<size_t>(y) * w + x) * channels];
                    sum += glm::dvec4(px[0], px[1], px[2], channels == 4 ? px[3] : 255) / 255.0;
                }
            field[static_cast<size_t>(j) * kGrid + i] =
                glm::vec4(sum / double((x1 - x0) * (y1 - y0)));
        }
    return field;
}

bool isNeutralDataField(const std::vector<glm::vec4>& field) {
    const glm::vec4 neutral = model::neutralDataField();
    return std::all_of(field.begin(), field.end(),
                       [&](const glm::vec4& c) { return c == neutral; });
}

} // namespace cloudscape
