// The weather map: a procedural "data field" generator and the painted-image override.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include "generators/key_range.h"
#include "generators/tileable_noise.h"
#include "model/weather.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace cloudscape {
namespace {

// The nearest 8-bit level, as quantizeToUnorm8 rounds.
float toUnorm8(float v) {
    return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

// A coverage field in [0, 1] as 16 bits: the high byte in R, the low byte in A (out[0], out[3]).
void storeField(float* out, float field) {
    const long code = std::lround(std::clamp(field, 0.0f, 1.0f) * 65535.0f);
    out[0] = static_cast<float>(code >> 8) / 255.0f;
    out[3] = static_cast<float>(code & 255) / 255.0f;
}

void finishWeather(Texture2D& t) {
    // The type part of the precipitation rule, the same code the renderer applies when sampling,
    // evaluated on the 8-bit values the GPU will read, so that a texel stored with precipitation
    // 1 also stores type 1 exactly. The coverage part (>= 0.7 where it rains) depends on the
    // scene's coverage bias, so the model applies it after the bias (weatherFromRaw).
    for (size_t i = 0; i < t.mips[0].size(); i += 4) {
        const float rain = toUnorm8(t.mips[0][i + 1]);
        t.mips[0][i + 1] = rain;
        t.mips[0][i + 2] = model::precipitationType(toUnorm8(t.mips[0][i + 2]), rain);
    }
    buildMipChain(t);
    quantizeToUnorm8(t);
}

} // namespace

Texture2D generateWeatherMap(const WeatherParams& p) {
    requireWeatherKeyRange("weather.resolution", p.resolution);
    requireWeatherKeyRange("weather.extent_m", p.extentM);
    requireWeatherKeyRange("weather.feature_scale_m", p.featureScaleM);
    requireWeatherKeyRange("weather.type", p.typeMean);
    requireWeatherKeyRange("weather.type_variation", p.typeVariation);
    requireWeatherKeyRange("weather.rain_cells", p.rainCells);
    requireWeatherKeyRange("weather.rain_cell_radius_m", p.rainCellRadiusM);

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
            // The field about 0.5: with bias b the coverage is clamp(field - 0.5 + 0.5 + b),
            // the FBM spread around an offset.
            storeField(out, 0.5f + field[i]);
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
    for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i) {
        for (int c = 0; c < 3; ++c)
            t.mips[0][i * 4 + c] = pixels[i * channels + c] / 255.0f;
        // Low byte = high byte: the 16-bit field r * 257 / 65535 is exactly the painted r / 255.
        t.mips[0][i * 4 + 3] = t.mips[0][i * 4];
    }
    finishWeather(t);
    return t;
}

float coverageFieldOf(const float* texel) {
    return model::coverageField(glm::vec4(texel[0], texel[1], texel[2], texel[3]));
}

std::vector<float> weatherAsSeen(const Texture2D& map, float coverageBias) {
    const std::vector<float>& level = map.mips.at(0);
    std::vector<float> out;
    out.reserve(level.size() / 4 * 3);
    for (size_t i = 0; i < level.size(); i += 4) {
        const glm::vec3 w = model::weatherFromTexel(
            glm::vec4(level[i], level[i + 1], level[i + 2], level[i + 3]), coverageBias, 0.0f);
        out.insert(out.end(), {w.x, w.y, w.z});
    }
    return out;
}

namespace {

// The 16-bit code of a texel's field (high byte * 256 + low byte).
size_t fieldCode(const float* texel) {
    return static_cast<size_t>(std::lround(texel[0] * 255.0f)) * 256 +
           static_cast<size_t>(std::lround(texel[3] * 255.0f));
}

} // namespace

CoverageField::CoverageField(const Texture2D& map) {
    count_.assign(65536, 0);
    const std::vector<float>& level = map.mips.at(0);
    for (size_t i = 0; i < level.size(); i += 4)
        ++count_[fieldCode(&level[i])];
    texels_ = level.size() / 4;
    accumulate();
}

void CoverageField::replaceTexels(const float* before, const float* after, size_t count) {
    for (size_t i = 0; i < count * 4; i += 4) {
        --count_[fieldCode(&before[i])];
        ++count_[fieldCode(&after[i])];
    }
    accumulate();
}

// The same sums in the same order however the counts were reached: an edited distribution is
// bit for bit the one made from the edited map.
void CoverageField::accumulate() {
    countBelow_.assign(65537, 0);
    sumBelow_.assign(65537, 0.0);
    for (size_t k = 0; k < 65536; ++k) {
        countBelow_[k + 1] = countBelow_[k] + count_[k];
        sumBelow_[k + 1] = sumBelow_[k] + static_cast<double>(count_[k]) * (k / 65535.0);
    }
}

double CoverageField::meanCoverage(float bias) const {
    if (empty())
        return 0.0;
    const double b = bias;
    // Code k (field k / 65535) gives 0 for k <= -b * 65535, 1 for k >= (1 - b) * 65535, and
    // k / 65535 + b between: [lo, hi) is that middle range.
    auto code = [](double v) { return static_cast<size_t>(std::clamp(v, 0.0, 65536.0)); };
    const size_t lo = code(std::floor(-b * 65535.0) + 1.0);
    const size_t hi = std::max(lo, code(std::ceil((1.0 - b) * 65535.0)));
    const double partial = (sumBelow_[hi] - sumBelow_[lo]) +
                           b * static_cast<double>(countBelow_[hi] - countBelow_[lo]);
    const double full = static_cast<double>(countBelow_[65536] - countBelow_[hi]);
    return (partial + full) / static_cast<double>(texels_);
}

float CoverageField::biasFor(float coverage) const {
    if (coverage <= 0.0f)
        return -1.0f;
    if (coverage >= 1.0f)
        return 1.0f;
    float lo = -1.0f, hi = 1.0f;
    for (int i = 0; i < 40; ++i) {
        const float mid = 0.5f * (lo + hi);
        (meanCoverage(mid) > coverage ? hi : lo) = mid;
    }
    return 0.5f * (lo + hi);
}

} // namespace cloudscape
