#pragma once
// The viewer's debug views: instead of the picture, the cloud layer's transmittance, the depth
// of the first cloud, the weather map as the renderer reads it, the data field's regions (bottom
// type, anvil coverage, height range), the clouds' shadow map the frame
// read (the sun's transmittance through each texel's ray), a density slice (a vertical plane
// through the camera along its heading, to scale), where each pixel's value came from
// (marched, reprojected, fallback) or how many density samples its block's march took (a heat
// map); the last two exist for temporal frames only (no data after a still). Each is made on the
// host from the frame's layers (read back for it), the map, the renderer's shadow map or the
// density function, by the model's rules (src/model/debug_view.glsl.h), and drawn as display values
// without the tone curve.
#include <cloudscape/persistent_renderer.h>

#include <string>
#include <vector>

namespace cloudscape::cli {

enum class DebugView {
    Picture,
    Transmittance,
    Depth,
    Weather,
    DataField,
    ShadowMap,
    DensitySlice,
    TemporalSource,
    Samples
};
// "picture", "transmittance", "depth", "weather", "data-field", "shadow-map", "density-slice",
// "temporal-source", "samples", indexed by DebugView.
const std::vector<std::string>& debugViewNames();
// Throws cloudscape::Error naming the known views.
DebugView parseDebugView(const std::string& name);

// Fills `rgba` (width x height x 4 floats, the frame's size) with the view of the frame
// `frame` (rendered with Readback::All) of `renderer`'s scene.
void fillDebugView(DebugView view, const RenderResult& frame, const Renderer& renderer,
                   float* rgba);

} // namespace cloudscape::cli
