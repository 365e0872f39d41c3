// The weather brush (view_paint.h).
#include "view_paint.h"

#include "model/brush.glsl.h"
#include "model/weather.glsl.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/weather.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

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
    }
}

} // namespace

BrushStroke::Channel brushChannel(const std::string& name) {
    for (auto c : {BrushStroke::Channel::Coverage, BrushStroke::Channel::Precipitation,
                   BrushStroke::Channel::Type})
        if (name == brushChannelName(c))
            return c;
    throw Error("brush channel '" + name.substr(0, 40) +
                "': expected coverage, precipitation or type");
}

const char* brushChannelName(BrushStroke::Channel channel) {
    switch (channel) {
    case BrushStroke::Channel::Coverage:
        return "coverage";
    case BrushStroke::Channel::Precipitation:
        return "precipitation";
    case BrushStroke::Channel::Type:
        return "type";
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

void WeatherPainter::paint(Renderer& renderer, Scene& scene, const BrushStroke& stroke) {
    const auto start = std::chrono::steady_clock::now();
    const SceneResources& resources = renderer.resources();
    const float bias = resources.weatherCoverage.empty()
                           ? CoverageField(resources.weather).biasFor(scene.coverage)
                           : resources.weatherCoverage.biasFor(scene.coverage);
    history_.push_back({resources.weather, scene.coverage});
    if (history_.size() > kUndoSteps)
        history_.pop_front();

    Texture2D map = resources.weather;
    // Texel (i, j)'s centre lies at origin + ((i + 0.5) / width - 0.5) * extent in x, and so in
    // z for rows (weatherUv in density.glsl.h); the map wraps, and so does the brush.
    const float extent = scene.weatherExtentM;
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const float x = scene.weatherOffsetXM + ((i + 0.5f) / map.width - 0.5f) * extent;
            const float z = scene.weatherOffsetZM + ((j + 0.5f) / map.height - 0.5f) * extent;
            float dx = x - stroke.xM, dz = z - stroke.zM;
            dx -= extent * std::round(dx / extent);
            dz -= extent * std::round(dz / extent);
            const float weight = model::brushWeight(std::sqrt(dx * dx + dz * dz), stroke.radiusM);
            if (weight > 0.0f)
                paintTexel(map.texel(0, i, j), stroke, weight);
        }
    buildMipChain(map);
    quantizeToUnorm8(map);
    // The same bias over the new map: its mean coverage is the scene's coverage now.
    const CoverageField field(map);
    scene.coverage = static_cast<float>(std::clamp(field.meanCoverage(bias), 0.0, 1.0));
    renderer.replaceWeatherMap(std::move(map));
    ++strokes_;
    ++edits_;
    editSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool WeatherPainter::undo(Renderer& renderer, Scene& scene) {
    if (history_.empty())
        return false;
    const auto start = std::chrono::steady_clock::now();
    scene.coverage = history_.back().coverage;
    renderer.replaceWeatherMap(std::move(history_.back().map));
    history_.pop_back();
    ++edits_;
    editSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
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
