#pragma once
// Rendering a scene. The CPU backend runs the single-source model over tiles on all cores.
#include <cloudscape/noise.h>
#include <cloudscape/scene.h>
#include <cloudscape/terrain.h>
#include <cloudscape/texture.h>
#include <cloudscape/weather.h>

#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cloudscape {

// A scene depth buffer: metres along each pixel's view ray to opaque geometry, row-major, top
// row first; +infinity (or anything beyond march.max_distance_m) where there is only sky.
struct DepthBuffer {
    int width = 0;
    int height = 0;
    std::vector<float> metres;
    bool empty() const { return metres.empty(); }
};

// Reads render.depth_file: the EXR's R channel, else Z, else its only channel. Throws a one-line
// cloudscape::Error for a missing or unreadable file, no usable channel, a negative depth, or a
// size other than width x height.
DepthBuffer loadDepthBuffer(const std::string& path, int width, int height);

// The textures a scene needs: generated noise, and the weather map (generated or painted) with
// its coverage field's distribution (for the coverage bias; computed from the map when empty),
// and the scene depth buffer if render.depth_file names one.
struct SceneResources {
    NoiseTextures noise;
    Texture2D weather;
    CoverageField weatherCoverage;
    WeatherCellMaxima weatherCells; // made with the map; stale or empty: read from the map
    // The data field's regions (cloudscape/data_field.h), generated or painted; empty: neutral.
    std::vector<glm::vec4> dataField;
    DepthBuffer depth;
    // The atmosphere's lookup tables (sky.model "atmosphere"; empty for the gradient sky): RGBA
    // float texels in the model's layout (src/model/atmosphere.glsl.h), made for the sun's
    // elevation and the camera's distance from the planet's centre (the sky-view radius), with
    // what they were made from, so a persistent Renderer remakes them only when that changes.
    // prepareResources makes them on the host's cores. A Renderer on the Vulkan backend makes
    // them on its device instead (atmosphereOnDevice) and keeps here a copy read back from it,
    // for what reads them on the host (which light the clouds at night, makeCloudParams).
    std::vector<glm::vec4> atmosphere;
    std::vector<float> atmosphereInputs;
    float atmosphereSkyViewRadius = 0.0f;
    bool atmosphereOnDevice = false; // made by the Vulkan backend's compute pass
    // The terrain's height field (terrain.enabled; empty when off).
    HeightField terrain;
    double noiseSeconds = 0.0;
    double weatherSeconds = 0.0;
    double atmosphereSeconds = 0.0; // host fill, or device fill and read-back
    double terrainSeconds = 0.0;
};
SceneResources prepareResources(const Scene& scene);
// Only the weather map (generated or loaded), for callers that already hold the noise.
Texture2D prepareWeather(const Scene& scene);

struct RenderStats {
    std::string backend = "cpu"; // "cpu" or "vulkan: <device name>"
    uint64_t rays = 0;
    uint64_t densitySamples = 0; // along view rays
    uint64_t cloudSamples = 0;   // of those, the ones in cloud (with extinction)
    uint64_t emptySkips = 0;     // empty-space skips, no texture read
    uint64_t lightSamples = 0;   // along light rays
    double seconds = 0.0;        // march and composite, excluding texture generation
    double marchSeconds = 0.0;   // temporal renderer: the 1/16 march pass
    double resolveSeconds = 0.0; // temporal renderer: the full-resolution resolve pass
    // Vulkan only: GPU timestamps per pass (ms; negative if the queue has no timestamps), the
    // device memory the renderer held, and any validation-layer messages.
    double gpuUploadMs = -1.0;
    double gpuMarchMs = -1.0;     // the cloud march (the shadow map excluded)
    double gpuShadowMs = -1.0;    // the clouds' shadow map pass (cloud_shadow.comp), 0 while off
    double gpuShaftGridMs = -1.0; // temporal: the light shafts' grid dispatch, 0 without a grid
    double gpuUpsampleMs = -1.0;  // temporal: the reduced-resolution pass's upsample, 0 without
    // The frame made its clouds' shadow map (false while the map is off, or when the Vulkan
    // backend kept the last one: the same parameters and textures make the same map), and how
    // many of its texels it made: all of them, or on Vulkan, when only the map's place moved
    // with the camera, the rows and columns the move brought in.
    bool shadowMapMade = false;
    int64_t shadowMapTexelsMade = 0;
    // The frame made the light of the background behind its clouds (pixel.glsl.h's
    // BackgroundLight: terrain, ground, sky), and applied its clouds' shadows and the high layer
    // to it. False only where the Vulkan temporal renderer kept the last frame's: the light for
    // the same camera, sun, terrain and air; the shaded background for the same scene too.
    bool backgroundMade = true;
    bool backgroundShaded = true;
    // Vulkan temporal: the pixels of the shaded background whose ground lies beyond the shadow
    // map, shaded again with the ground's two-sample fallback by a dispatch of their own (-1
    // where the frame had no such list: no shadow map, the background kept, another backend).
    int64_t groundFallbackPixels = -1;
    double gpuBackgroundMs = -1.0; // temporal: the background passes, 0 while both are kept
    uint64_t gpuMemoryBytes = 0;
    uint64_t gpuTextureBytes = 0;
    std::vector<std::string> validationMessages;
};

// What a render copies back to the host. The Vulkan backend keeps its images on the device; the
// temporal path reads back no more than it is asked for.
enum class Readback {
    All,     // the cloud layer, its depth and the composite (EXR output, metrics on the layer)
    Display, // the composite only (PNG output, a preview): cloud and depth stay empty
    None,    // nothing: the image stays on the device (a window presents it); statistics only
};

// Linear HDR results, row-major, top row first.
struct RenderResult {
    int width = 0;
    int height = 0;
    std::vector<float> cloud;     // 4 per pixel: premultiplied cloud radiance RGB, transmittance
    std::vector<float> depth;     // distance to the first cloud (m); +infinity where none
    std::vector<float> composite; // 4 per pixel: clouds over the sky, RGB, alpha 1
    RenderStats stats;
};

// Called with the fraction done, from the rendering thread that finished a tile.
using ProgressCallback = std::function<void(double)>;

RenderResult renderCpu(const Scene& scene, const SceneResources& resources,
                       const ProgressCallback& progress = {});

// The composite as interleaved linear RGB (3 floats per pixel), for metrics.
std::vector<float> compositeRgb(const RenderResult& result);

// Tone-mapped 8-bit sRGB RGBA of the composite (ACES curve, scene exposure).
std::vector<uint8_t> toneMapToSrgb8(const RenderResult& result, float exposure);
// The same for interleaved linear RGB (3 floats per pixel), e.g. a path-traced image.
std::vector<uint8_t> toneMapRgbToSrgb8(const std::vector<float>& rgb, float exposure);

} // namespace cloudscape
