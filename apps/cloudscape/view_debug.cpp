// The debug views (view_debug.h).
#include "view_debug.h"

#include "cpu/cpu_model.h"
#include "model/debug_view.glsl.h"

#include "cpu/cpu_density_slice.h"

#include <cloudscape/error.h>

#include <cmath>

namespace cloudscape::cli {

const std::vector<std::string>& debugViewNames() {
    static const std::vector<std::string> names = {"picture",       "transmittance",   "depth",
                                                   "weather",       "data-field",      "shadow-map",
                                                   "density-slice", "temporal-source", "samples"};
    return names;
}

DebugView parseDebugView(const std::string& name) {
    const std::vector<std::string>& names = debugViewNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return static_cast<DebugView>(i);
    throw Error("view '" + name.substr(0, 40) +
                "': expected picture, transmittance, depth, weather, data-field, shadow-map, "
                "density-slice, temporal-source or samples");
}

namespace {

void store(float* rgba, size_t p, glm::vec3 c) {
    rgba[p * 4] = c.x;
    rgba[p * 4 + 1] = c.y;
    rgba[p * 4 + 2] = c.z;
    rgba[p * 4 + 3] = 1.0f;
}

// The map stretched over the image, nearest texel, its row 0 (smallest z) at the top as the
// weather view draws the weather map; the no-data colour while the map is off.
void fillShadowMap(const std::vector<glm::vec4>& map, int width, int height, float* rgba) {
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(map.size()))));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t p = static_cast<size_t>(y) * width + x;
            store(rgba, p,
                  map.empty() ? model::debugNoData()
                              : model::debugShadowMap(
                                    map[static_cast<size_t>(y * n / height) * n + x * n / width]));
        }
}

// The last temporal frame's record (at the cloud pass's size) stretched over the image, nearest
// pixel; the no-data colour after a still.
void fillTemporalDebug(DebugView view, const TemporalDebugImage& image, int width, int height,
                       float* rgba) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t p = static_cast<size_t>(y) * width + x;
            if (image.empty()) {
                store(rgba, p, model::debugNoData());
                continue;
            }
            const size_t i = static_cast<size_t>(y * image.height / height) * image.width +
                             static_cast<size_t>(x * image.width / width);
            store(rgba, p,
                  view == DebugView::Samples
                      ? model::debugSampleHeat(image.samples[i])
                      : model::debugTemporalSource(static_cast<int>(image.source[i])));
        }
}

// The field's regions stretched over the map's place in the image as the weather view draws the
// map, nearest region; the no-data colour without a field.
void fillDataField(const std::vector<glm::vec4>& field, int width, int height, float* rgba) {
    const int n = model::DATA_FIELD_GRID;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t p = static_cast<size_t>(y) * width + x;
            const size_t region = static_cast<size_t>(y * n / height) * n + x * n / width;
            store(rgba, p,
                  region < field.size() ? model::debugDataField(field[region])
                                        : model::debugNoData());
        }
}

void fillDensitySlice(const Renderer& renderer, int width, int height, float* rgba) {
    const std::vector<glm::vec3> slice =
        cpu::densitySlice(renderer.scene(), renderer.resources(), width, height);
    for (size_t p = 0; p < slice.size(); ++p)
        store(rgba, p, slice[p]);
}

} // namespace

void fillDebugView(DebugView view, const RenderResult& frame, const Renderer& renderer,
                   float* rgba) {
    if (view == DebugView::ShadowMap)
        return fillShadowMap(renderer.cloudShadowMap(), frame.width, frame.height, rgba);
    if (view == DebugView::DataField)
        return fillDataField(renderer.resources().dataField, frame.width, frame.height, rgba);
    if (view == DebugView::DensitySlice)
        return fillDensitySlice(renderer, frame.width, frame.height, rgba);
    if (view == DebugView::TemporalSource || view == DebugView::Samples)
        return fillTemporalDebug(view, renderer.temporalDebug(), frame.width, frame.height, rgba);
    const Scene& scene = renderer.scene();
    const SceneResources& resources = renderer.resources();
    const size_t pixels = static_cast<size_t>(frame.width) * frame.height;
    const Texture2D& map = resources.weather;
    const float bias = view == DebugView::Weather
                           ? (resources.weatherCoverage.empty()
                                  ? CoverageField(map).biasFor(scene.coverage)
                                  : resources.weatherCoverage.biasFor(scene.coverage))
                           : 0.0f;
    for (size_t p = 0; p < pixels; ++p) {
        glm::vec3 c(0.0f);
        switch (view) {
        case DebugView::Picture:
            c = glm::vec3(frame.composite[p * 4], frame.composite[p * 4 + 1],
                          frame.composite[p * 4 + 2]);
            break;
        case DebugView::Transmittance:
            c = model::debugTransmittance(frame.cloud[p * 4 + 3]);
            break;
        case DebugView::Depth:
            c = model::debugDepth(frame.depth[p], scene.maxDistanceM);
            break;
        case DebugView::Weather: { // the whole map stretched over the image, nearest texel
            const int x = static_cast<int>(p % static_cast<size_t>(frame.width));
            const int y = static_cast<int>(p / static_cast<size_t>(frame.width));
            const float* t =
                map.texel(0, x * map.width / frame.width, y * map.height / frame.height);
            c = model::debugWeather(glm::vec4(t[0], t[1], t[2], t[3]), bias);
            break;
        }
        default: // drawn above
            break;
        }
        store(rgba, p, c);
    }
}

} // namespace cloudscape::cli
