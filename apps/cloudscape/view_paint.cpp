// The weather brush (view_paint.h).
#include "view_paint.h"

#include "model/brush.glsl.h"
#include "model/data_field.glsl.h"
#include "model/weather.glsl.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace cloudscape::cli {
namespace {

constexpr size_t kUndoSteps = 16;

std::string metres(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

float toUnorm8(float v) {
    return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

// The texel's coverage field stored back as 16 bits (high byte in R, low byte in A).
void storeField(float* texel, float field) {
    const long code = std::lround(std::clamp(field, 0.0f, 1.0f) * 65535.0f);
    texel[0] = static_cast<float>(code >> 8) / 255.0f;
    texel[3] = static_cast<float>(code & 255) / 255.0f;
}

void paintTexel(float* texel, const BrushStroke& stroke, float weight) {
    switch (stroke.channel) {
    case BrushStroke::Channel::Coverage:
        storeField(texel, model::paintedValue(coverageFieldOf(texel), stroke.strength, weight));
        break;
    case BrushStroke::Channel::Precipitation:
        texel[1] = toUnorm8(model::paintedValue(texel[1], stroke.strength, weight));
        // Rain makes cumulonimbus, as every loaded or generated map has it.
        texel[2] = toUnorm8(model::precipitationType(texel[2], texel[1]));
        break;
    case BrushStroke::Channel::Type:
        texel[2] = toUnorm8(model::paintedValue(texel[2], stroke.strength, weight));
        break;
    case BrushStroke::Channel::BottomType:
    case BrushStroke::Channel::AnvilCoverage:
    case BrushStroke::Channel::MinHeight:
    case BrushStroke::Channel::MaxHeight:
        break; // the data field's channels (isDataFieldChannel), never painted into the map
    }
}

// The brush's weight at the centre of cell (i, j) of a width x height grid laid over the weather
// map (a texel, or a data-field region): cell i's centre lies at offset + ((i + 0.5) / width -
// 0.5) extent in x, and so in z for rows (weatherUv in density.glsl.h); the map wraps, and so does
// the brush.
float cellWeight(const Scene& scene, const BrushStroke& stroke, int i, int j, int width,
                 int height) {
    const float extent = scene.weatherExtentM;
    float dx = scene.weatherOffsetXM + ((i + 0.5f) / width - 0.5f) * extent - stroke.xM;
    float dz = scene.weatherOffsetZM + ((j + 0.5f) / height - 0.5f) * extent - stroke.zM;
    dx -= extent * std::round(dx / extent);
    dz -= extent * std::round(dz / extent);
    return model::brushWeight(std::sqrt(dx * dx + dz * dz), stroke.radiusM);
}

// The texel columns (or rows) a brush of `radius` centred at `centre` can reach on a map of n
// texels over `extent` metres from `origin`, with a texel to spare each side for the rounding:
// one interval [first, end) inside [0, n), or two where it wraps around the map's edge.
std::vector<std::pair<int, int>> brushSpan(float centre, float radius, float origin, float extent,
                                           int n) {
    const double u = ((double(centre) - origin) / extent + 0.5) * n - 0.5; // in texels
    const double reach = double(radius) / extent * n;
    const long first = std::lround(std::floor(u - reach)) - 1;
    const long end = std::lround(std::ceil(u + reach)) + 2;
    if (end - first >= n)
        return {{0, n}};
    const int a = static_cast<int>(((first % n) + n) % n);
    const int length = static_cast<int>(end - first);
    if (a + length <= n)
        return {{a, a + length}};
    return {{a, n}, {0, a + length - n}};
}

std::vector<float> copyOut(const Texture2D& t, int level, const std::vector<TexelRect>& rects) {
    std::vector<float> out;
    for (const TexelRect& r : rects)
        for (int j = r.y; j < r.y + r.height; ++j) {
            const float* row = t.texel(level, r.x, j);
            out.insert(out.end(), row, row + 4 * static_cast<size_t>(r.width));
        }
    return out;
}

void copyIn(Texture2D& t, int level, const std::vector<TexelRect>& rects,
            const std::vector<float>& values) {
    size_t k = 0;
    for (const TexelRect& r : rects)
        for (int j = r.y; j < r.y + r.height; ++j) {
            std::copy_n(&values[k], 4 * static_cast<size_t>(r.width), t.texel(level, r.x, j));
            k += 4 * static_cast<size_t>(r.width);
        }
}

// Level l's texels inside r made again from level l - 1 of the unrounded chain, by
// buildMipChain's sum (in its order), and stored rounded into the map as quantizeToUnorm8 does.
void averageLevel(Texture2D& exact, Texture2D& map, int l, const TexelRect& r) {
    const int pw = exact.levelWidth(l - 1), ph = exact.levelHeight(l - 1);
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x)
            for (int c = 0; c < 4; ++c) {
                float sum = 0.0f;
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) {
                        const int sx = std::min(2 * x + dx, pw - 1);
                        const int sy = std::min(2 * y + dy, ph - 1);
                        sum += exact.texel(l - 1, sx, sy)[c];
                    }
                const float v = sum * 0.25f;
                exact.texel(l, x, y)[c] = v;
                map.texel(l, x, y)[c] = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
            }
}

} // namespace

const std::vector<BrushStroke::Channel>& brushChannels() {
    using C = BrushStroke::Channel;
    static const std::vector<C> all = {C::Coverage,   C::Precipitation, C::Type,
                                       C::BottomType, C::AnvilCoverage, C::MinHeight,
                                       C::MaxHeight};
    return all;
}

bool isDataFieldChannel(BrushStroke::Channel channel) {
    return channel == BrushStroke::Channel::BottomType ||
           channel == BrushStroke::Channel::AnvilCoverage ||
           channel == BrushStroke::Channel::MinHeight || channel == BrushStroke::Channel::MaxHeight;
}

BrushStroke::Channel brushChannel(const std::string& name) {
    for (BrushStroke::Channel c : brushChannels())
        if (name == brushChannelName(c))
            return c;
    throw Error("brush channel '" + name.substr(0, 40) +
                "': expected coverage, precipitation, type, bottom_type, anvil, min_height or "
                "max_height");
}

const char* brushChannelName(BrushStroke::Channel channel) {
    switch (channel) {
    case BrushStroke::Channel::Coverage:
        return "coverage";
    case BrushStroke::Channel::Precipitation:
        return "precipitation";
    case BrushStroke::Channel::Type:
        return "type";
    case BrushStroke::Channel::BottomType:
        return "bottom_type";
    case BrushStroke::Channel::AnvilCoverage:
        return "anvil";
    case BrushStroke::Channel::MinHeight:
        return "min_height";
    case BrushStroke::Channel::MaxHeight:
        return "max_height";
    }
    return "?";
}

void checkStroke(const Scene& scene, const BrushStroke& stroke, const std::string& where) {
    const double half = scene.weatherExtentM / 2.0;
    const double x0 = scene.weatherOffsetXM - half, x1 = scene.weatherOffsetXM + half;
    const double z0 = scene.weatherOffsetZM - half, z1 = scene.weatherOffsetZM + half;
    if (!(stroke.xM >= x0 && stroke.xM <= x1 && stroke.zM >= z0 && stroke.zM <= z1))
        throw Error(where + ": the brush at x " + metres(stroke.xM) + " m, z " + metres(stroke.zM) +
                    " m is outside the weather map (x in [" + metres(x0) + ", " + metres(x1) +
                    "], z in [" + metres(z0) + ", " + metres(z1) + "] m)");
    if (!(stroke.radiusM > 0.0f && stroke.radiusM <= scene.weatherExtentM))
        throw Error(where + ": brush radius " + metres(stroke.radiusM) +
                    " m: expected (0, weather.extent_m = " + metres(scene.weatherExtentM) + "]");
    if (!(stroke.strength >= -1.0f && stroke.strength <= 1.0f))
        throw Error(where + ": brush strength " + metres(stroke.strength) +
                    ": expected [-1, 1] (negative lowers)");
}

void WeatherPainter::prepareExact(const Renderer& renderer) {
    const Texture2D& map = renderer.resources().weather;
    if (!exact_.mips.empty() && exactVersion_ == renderer.weatherMapVersion() &&
        exact_.width == map.width && exact_.height == map.height &&
        exact_.mips.size() == map.mips.size())
        return;
    history_.clear(); // strokes on another map
    exact_.width = map.width;
    exact_.height = map.height;
    exact_.mips.assign(1, map.mips.at(0));
    buildMipChain(exact_);
    exact_.mips.resize(map.mips.size()); // as many levels as the map the device holds
    exactVersion_ = renderer.weatherMapVersion();
}

// The field's regions under the brush, each channel value moved by the model's brush rule and
// every region kept on the 8-bit levels the saved PNG holds, so a saved field reloads exactly.
void WeatherPainter::paintField(Renderer& renderer, const Scene& scene, const BrushStroke& stroke) {
    const int n = model::DATA_FIELD_GRID;
    if (fieldVersion_ != renderer.dataFieldVersion())
        history_.clear(); // strokes on another field
    fieldVersion_ = renderer.dataFieldVersion();
    std::vector<glm::vec4> field = renderer.resources().dataField;
    if (field.empty())
        field.assign(static_cast<size_t>(n) * n, model::neutralDataField());
    Step step;
    step.coverage = scene.coverage;
    step.field = field;
    const int c =
        static_cast<int>(stroke.channel) - static_cast<int>(BrushStroke::Channel::BottomType);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::vec4& region = field[static_cast<size_t>(j) * n + i];
            const float weight = cellWeight(scene, stroke, i, j, n, n);
            if (weight > 0.0f)
                region[c] = model::paintedValue(region[c], stroke.strength, weight);
            for (int k = 0; k < 4; ++k)
                region[k] = toUnorm8(region[k]);
        }
    renderer.replaceDataField(std::move(field));
    history_.push_back(std::move(step));
    if (history_.size() > kUndoSteps)
        history_.pop_front();
}

void WeatherPainter::paint(Renderer& renderer, Scene& scene, const BrushStroke& stroke) {
    const auto start = std::chrono::steady_clock::now();
    if (isDataFieldChannel(stroke.channel)) {
        paintField(renderer, scene, stroke);
        ++strokes_;
        ++edits_;
        editSeconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return;
    }
    prepareExact(renderer);
    const SceneResources& resources = renderer.resources();
    const float bias = resources.weatherCoverage.empty()
                           ? CoverageField(resources.weather).biasFor(scene.coverage)
                           : resources.weatherCoverage.biasFor(scene.coverage);
    const Texture2D& current = resources.weather;
    // The texels under the brush's square (cellWeight says where a texel lies).
    const float extent = scene.weatherExtentM;
    Step step;
    step.coverage = scene.coverage;
    for (auto [x0, x1] :
         brushSpan(stroke.xM, stroke.radiusM, scene.weatherOffsetXM, extent, current.width))
        for (auto [y0, y1] :
             brushSpan(stroke.zM, stroke.radiusM, scene.weatherOffsetZM, extent, current.height))
            step.rects.push_back({x0, y0, x1 - x0, y1 - y0});

    renderer.editWeatherMap(step.rects, [&](Texture2D& map) {
        for (int l = 0; l < map.levelCount(); ++l) {
            const std::vector<TexelRect> footprint = weatherFootprint(step.rects, map, l);
            step.map.push_back(copyOut(map, l, footprint));
            step.exact.push_back(copyOut(exact_, l, footprint));
        }
        for (const TexelRect& r : step.rects)
            for (int j = r.y; j < r.y + r.height; ++j)
                for (int i = r.x; i < r.x + r.width; ++i) {
                    const float weight = cellWeight(scene, stroke, i, j, map.width, map.height);
                    if (weight > 0.0f)
                        paintTexel(map.texel(0, i, j), stroke, weight);
                    std::copy_n(map.texel(0, i, j), 4, exact_.texel(0, i, j));
                }
        // Level by level, so each level averages its parent's finished texels, as buildMipChain.
        for (int l = 1; l < map.levelCount(); ++l)
            for (const TexelRect& r : weatherFootprint(step.rects, map, l))
                averageLevel(exact_, map, l, r);
    });
    // The same bias over the new map: its mean coverage is the scene's coverage now.
    scene.coverage = static_cast<float>(
        std::clamp(renderer.resources().weatherCoverage.meanCoverage(bias), 0.0, 1.0));
    history_.push_back(std::move(step));
    if (history_.size() > kUndoSteps)
        history_.pop_front();
    ++strokes_;
    ++edits_;
    editSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool WeatherPainter::undo(Renderer& renderer, Scene& scene) {
    if (history_.empty())
        return false;
    const auto start = std::chrono::steady_clock::now();
    const Step& step = history_.back();
    if (!step.field.empty()) {
        if (fieldVersion_ != renderer.dataFieldVersion())
            return false;
        renderer.replaceDataField(step.field);
        history_.pop_back();
        ++edits_;
        editSeconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return true;
    }
    if (exactVersion_ != renderer.weatherMapVersion())
        return false;
    renderer.editWeatherMap(step.rects, [&](Texture2D& map) {
        for (int l = 0; l < map.levelCount(); ++l) {
            const std::vector<TexelRect> footprint = weatherFootprint(step.rects, map, l);
            copyIn(map, l, footprint, step.map[static_cast<size_t>(l)]);
            copyIn(exact_, l, footprint, step.exact[static_cast<size_t>(l)]);
        }
    });
    scene.coverage = step.coverage;
    history_.pop_back();
    ++edits_;
    editSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

size_t checkDeviceWeather(const Renderer& renderer, const std::string& where) {
    const std::vector<uint8_t> device = renderer.deviceWeatherMap();
    if (device.empty())
        return 0;
    const Texture2D& map = renderer.resources().weather;
    size_t k = 0;
    for (int l = 0; l < map.levelCount(); ++l) {
        const std::vector<float>& level = map.mips[static_cast<size_t>(l)];
        if (k + level.size() > device.size())
            throw Error(where +
                        ": check-weather: the device's map has fewer levels or texels "
                        "than the host's (" +
                        std::to_string(device.size()) + " bytes)");
        for (size_t i = 0; i < level.size(); ++i, ++k) {
            const long host = std::lround(std::clamp(level[i], 0.0f, 1.0f) * 255.0f);
            if (host != device[k]) {
                const size_t texel = i / 4;
                const int w = map.levelWidth(l);
                throw Error(where + ": check-weather: level " + std::to_string(l) + " texel (" +
                            std::to_string(texel % w) + ", " + std::to_string(texel / w) +
                            ") channel " + std::to_string(i % 4) + ": the device holds " +
                            std::to_string(device[k]) + ", the host " + std::to_string(host));
            }
        }
    }
    if (k != device.size())
        throw Error(where + ": check-weather: the device's map has " +
                    std::to_string(device.size()) + " bytes, the host's " + std::to_string(k));
    return k / 4;
}

void WeatherPainter::saveFieldImage(const std::vector<glm::vec4>& field, const std::string& path) {
    const int n = model::DATA_FIELD_GRID;
    std::vector<uint8_t> rgba(static_cast<size_t>(n) * n * 4);
    for (size_t r = 0; r < rgba.size() / 4; ++r) {
        const glm::vec4 v = field.empty() ? model::neutralDataField() : field.at(r);
        for (int k = 0; k < 4; ++k)
            rgba[r * 4 + k] =
                static_cast<uint8_t>(std::lround(std::clamp(v[k], 0.0f, 1.0f) * 255.0f));
    }
    writePngChannels(path, n, n, 4, rgba);
}

void WeatherPainter::saveImage(const Texture2D& map, const std::string& path) {
    std::vector<uint8_t> rgb(static_cast<size_t>(map.width) * map.height * 3);
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const float* t = map.texel(0, i, j);
            uint8_t* p = &rgb[(static_cast<size_t>(j) * map.width + i) * 3];
            p[0] = static_cast<uint8_t>(
                std::lround(std::clamp(coverageFieldOf(t), 0.0f, 1.0f) * 255.0f));
            p[1] = static_cast<uint8_t>(std::lround(t[1] * 255.0f));
            p[2] = static_cast<uint8_t>(std::lround(t[2] * 255.0f));
        }
    writePngChannels(path, map.width, map.height, 3, rgb);
}

} // namespace cloudscape::cli
