// The debug views (view_debug.h).
#include "view_debug.h"

#include "model/debug_view.glsl.h"

#include <cloudscape/error.h>

namespace cloudscape::cli {

const std::vector<std::string>& debugViewNames() {
    static const std::vector<std::string> names = {"picture", "transmittance", "depth", "weather"};
    return names;
}

DebugView parseDebugView(const std::string& name) {
    const std::vector<std::string>& names = debugViewNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return static_cast<DebugView>(i);
    throw Error("view '" + name.substr(0, 40) +
                "': expected picture, transmittance, depth or weather");
}

void fillDebugView(DebugView view, const RenderResult& frame, const Renderer& renderer,
                   float* rgba) {
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
        }
        rgba[p * 4] = c.x;
        rgba[p * 4 + 1] = c.y;
        rgba[p * 4 + 2] = c.z;
        rgba[p * 4 + 3] = 1.0f;
    }
}

} // namespace cloudscape::cli
