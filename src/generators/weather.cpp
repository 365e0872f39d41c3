// The weather map: a procedural "data field" generator and the painted-image override.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include "generators/tileable_noise.h"
#include "model/weather.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cloudscape {
namespace {

void requireRange(const char* name, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi)) {
        std::ostringstream s;
        s << "weather parameter " << name << " = " << value << " is out of range [" << lo << ", "
          << hi << "]";
        throw Error(s.str());
    }
}

// Coverage from a field: the field (about [-1, 1]) scaled by a fixed spread around an offset that
// bisection chooses so the mean coverage equals the target. Most of the map holds partial
// coverage, which the density model turns into individual clouds of varying size; only a high
// target saturates large regions into overcast.
std::vector<float> coverageFromField(const std::vector<float>& field, float target) {
    std::vector<float> out(field.size());
    if (target <= 0.0f || target >= 1.0f) {
        std::fill(out.begin(), out.end(), target <= 0.0f ? 0.0f : 1.0f);
        return out;
    }
    const float spread = 1.0f;
    auto meanFor = [&](float offset) {
        double sum = 0.0;
        for (float v : field)
            sum += glm::clamp(offset + spread * v, 0.0f, 1.0f);
        return sum / static_cast<double>(field.size());
    };
    float lo = -2.0f, hi = 3.0f; // offsets well beyond what any target needs
    for (int i = 0; i < 40; ++i) {
        const float mid = 0.5f * (lo + hi);
        (meanFor(mid) > target ? hi : lo) = mid;
    }
    const float offset = 0.5f * (lo + hi);
    for (size_t i = 0; i < field.size(); ++i)
        out[i] = glm::clamp(offset + spread * field[i], 0.0f, 1.0f);
    return out;
}

// The nearest 8-bit level, as quantizeToUnorm8 rounds.
float toUnorm8(float v) {
    return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

void finishWeather(Texture2D& t) {
    // The precipitation rule, the same code the renderer applies when sampling, evaluated on the
    // 8-bit values the GPU will read: a texel stored with precipitation 1 then also stores
    // coverage >= 0.7 and type 1 exactly (on unrounded input, precipitation 0.999 rounds up to 1
    // while its coverage 0.6999 rounds down to 178/255).
    for (size_t i = 0; i < t.mips[0].size(); i += 4) {
        const glm::vec3 w = model::applyPrecipitationRule(glm::vec3(
            toUnorm8(t.mips[0][i]), toUnorm8(t.mips[0][i + 1]), toUnorm8(t.mips[0][i + 2])));
        t.mips[0][i] = w.x;
        t.mips[0][i + 1] = w.y;
        t.mips[0][i + 2] = w.z;
        t.mips[0][i + 3] = 1.0f;
    }
    buildMipChain(t);
    quantizeToUnorm8(t);
}

} // namespace

Texture2D generateWeatherMap(const WeatherParams& p) {
    requireRange("resolution", p.resolution, 16, 8192);
    requireRange("extent_m", p.extentM, 1.0, 1e9);
    requireRange("coverage", p.coverage, 0.0, 1.0);
    requireRange("feature_scale_m", p.featureScaleM, 1.0, 1e9);
    requireRange("type", p.typeMean, 0.0, 1.0);
    requireRange("type_variation", p.typeVariation, 0.0, 1.0);
    requireRange("rain_cells", p.rainCells, 0, 1000);
    requireRange("rain_cell_radius_m", p.rainCellRadiusM, 1.0, 1e9);

    const int n = p.resolution;
    const size_t texels = static_cast<size_t>(n) * n;
    // The lowest octave has a whole number of cells across the map so the map wraps. Features
    // smaller than a texel cannot be represented, so the period stops at one cell per texel
    // (which also keeps the octaves' doubled periods far from overflowing).
    const int period = static_cast<int>(
        std::clamp(std::lround(p.extentM / p.featureScaleM), 1L, static_cast<long>(n)));
    const uint32_t s = noise::hash32(p.seed * 7u + 0x4000u);
    const noise::PerlinFbm2 coverageFbm(period, 5, s),
        typeFbm(std::max(1, period / 2), 3, s + 500u);
    std::vector<float> field(texels), type(texels);
    tbb::parallel_for(0, n, [&](int y) {
        for (int x = 0; x < n; ++x) {
            const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / static_cast<float>(n);
            const size_t i = static_cast<size_t>(y) * n + x;
            field[i] = coverageFbm(uv);
            type[i] = typeFbm(uv);
        }
    });
    const std::vector<float> coverage = coverageFromField(field, p.coverage);

    // Rain cells: smooth bumps at seeded positions, distances on the torus.
    std::vector<glm::vec2> cells;
    for (int c = 0; c < p.rainCells; ++c) {
        const uint32_t h = noise::hashCombine(s + 900u, c);
        cells.emplace_back(static_cast<float>(h >> 8) / 16777216.0f,
                           static_cast<float>(noise::hash32(h) >> 8) / 16777216.0f);
    }
    const float radiusUv = p.rainCellRadiusM / p.extentM;

    Texture2D t;
    t.width = t.height = n;
    t.mips.assign(1, std::vector<float>(texels * 4));
    tbb::parallel_for(0, n, [&](int y) {
        for (int x = 0; x < n; ++x) {
            const size_t i = static_cast<size_t>(y) * n + x;
            const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / static_cast<float>(n);
            float rain = 0.0f;
            for (const glm::vec2& c : cells) {
                glm::vec2 d = glm::abs(uv - c);
                d = glm::min(d, 1.0f - d);
                // A core of full precipitation over the inner third, falling off outside.
                rain += 1.0f - glm::smoothstep(0.3f * radiusUv, radiusUv, glm::length(d));
            }
            float* out = &t.mips[0][i * 4];
            out[0] = coverage[i];
            out[1] = std::min(rain, 1.0f);
            // The 3-octave FBM rarely leaves [-0.6, 0.6]; 1.6 stretches it to about [-1, 1] so
            // type_variation is the amplitude of the type's variation.
            out[2] = glm::clamp(p.typeMean + p.typeVariation * type[i] * 1.6f, 0.0f, 1.0f);
        }
    });
    finishWeather(t);
    return t;
}

Texture2D loadWeatherImage(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    const std::vector<uint8_t> pixels = readPng(path, w, h, channels);
    if (channels != 3 && channels != 4)
        throw Error(path + ": weather image has " + std::to_string(channels) +
                    " channels, expected 3 (RGB) or 4 (RGBA)");
    Texture2D t;
    t.width = w;
    t.height = h;
    t.mips.assign(1, std::vector<float>(static_cast<size_t>(w) * h * 4));
    for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i)
        for (int c = 0; c < 3; ++c)
            t.mips[0][i * 4 + c] = pixels[i * channels + c] / 255.0f;
    finishWeather(t);
    return t;
}

} // namespace cloudscape
