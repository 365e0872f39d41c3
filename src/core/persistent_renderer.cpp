// The persistent Renderer: owns the scene and its resources, regenerates only what a change of
// scene touches, and hands the renders to one backend (renderer_backend.h) for its whole life.
#include <cloudscape/persistent_renderer.h>

#include "core/atmosphere_luts.h"
#include "core/cloud_top_grid.h"
#include "core/renderer_backend.h"
#include "core/resources.h"
#include "core/temporal_impl.h"
#include "model/params.glsl.h"

#include <cloudscape/error.h>

#include <algorithm>
#include <chrono>
#include <string>

namespace cloudscape {
namespace {

std::unique_ptr<Renderer::Backend> openBackend(const SceneResources& resources,
                                               const BackendOptions& options, std::string* notice) {
    const bool vulkan = options.choice == BackendChoice::Vulkan ||
                        (options.choice == BackendChoice::Auto && autoChoosesVulkan(notice));
    return vulkan ? makeVulkanRendererBackend(resources, options)
                  : makeCpuRendererBackend(resources);
}

bool overlap(const TexelRect& a, const TexelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

// The level-0 texels of `rects`, RGBA, rectangle after rectangle, row by row.
std::vector<float> gather(const Texture2D& map, const std::vector<TexelRect>& rects) {
    std::vector<float> out;
    for (const TexelRect& r : rects)
        for (int j = r.y; j < r.y + r.height; ++j) {
            const float* row = map.texel(0, r.x, j);
            out.insert(out.end(), row, row + 4 * static_cast<size_t>(r.width));
        }
    return out;
}

} // namespace

std::vector<TexelRect> weatherFootprint(const std::vector<TexelRect>& rects, const Texture2D& map,
                                        int level) {
    const int w = map.levelWidth(level), h = map.levelHeight(level);
    std::vector<TexelRect> out;
    for (const TexelRect& r : rects) {
        if (r.width <= 0 || r.height <= 0)
            continue;
        const int x0 = std::min(r.x >> level, w - 1), y0 = std::min(r.y >> level, h - 1);
        const int x1 = std::min((r.x + r.width - 1) >> level, w - 1);
        const int y1 = std::min((r.y + r.height - 1) >> level, h - 1);
        out.push_back({x0, y0, x1 - x0 + 1, y1 - y0 + 1});
    }
    // Merge until none overlap (a copy's destinations must not; a handful of rectangles).
    for (bool merged = true; merged;) {
        merged = false;
        for (size_t a = 0; a < out.size() && !merged; ++a)
            for (size_t b = a + 1; b < out.size() && !merged; ++b)
                if (overlap(out[a], out[b])) {
                    const int x0 = std::min(out[a].x, out[b].x), y0 = std::min(out[a].y, out[b].y);
                    const int x1 = std::max(out[a].x + out[a].width, out[b].x + out[b].width);
                    const int y1 = std::max(out[a].y + out[a].height, out[b].y + out[b].height);
                    out[a] = {x0, y0, x1 - x0, y1 - y0};
                    out.erase(out.begin() + static_cast<std::ptrdiff_t>(b));
                    merged = true;
                }
    }
    return out;
}

Camera cameraOf(const Scene& scene) {
    return {scene.cameraPosition, scene.cameraHeadingDeg, scene.cameraPitchDeg, scene.cameraFovDeg};
}

Scene withCamera(Scene scene, const Camera& camera, float timeS) {
    scene.cameraPosition = camera.position;
    scene.cameraHeadingDeg = camera.headingDeg;
    scene.cameraPitchDeg = camera.pitchDeg;
    scene.cameraFovDeg = camera.fovDeg;
    scene.timeS = timeS;
    return scene;
}

// Without the atmosphere's tables: the backend, once open, makes them (remakeAtmosphere).
Renderer::Renderer(const Scene& scene, const BackendOptions& options, std::string* notice)
    : Renderer(scene, prepareResourcesWithoutAtmosphere(scene), options, notice) {}

Renderer::Renderer(const Scene& scene, SceneResources resources, const BackendOptions& options,
                   std::string* notice)
    : scene_(scene), resources_(std::move(resources)) {
    checkCameraAboveTerrain(scene_, resources_);
    if (resources_.weatherCoverage.empty())
        resources_.weatherCoverage = CoverageField(resources_.weather);
    if (!resources_.weatherCells.isFor(resources_.weather))
        resources_.weatherCells = weatherCellMaxima(resources_.weather);
    prepareNoiseClearance(scene_, resources_); // before the backend uploads the noise
    backend_ = openBackend(resources_, options, notice);
    // Tables the resources lack or that were made for another scene: made now, as the first
    // update would, so resources() is complete from the start.
    if (atmosphereChanged(scene_, resources_))
        remakeAtmosphere(scene_);
    if (prepareTerrainLight(scene_, resources_))
        backend_->terrainChanged();
}

void Renderer::remakeAtmosphere(const Scene& scene) {
    if (backend_->makesAtmosphere())
        prepareAtmosphere(scene, resources_, [&](const model::SkyParams& sky) {
            return backend_->makeAtmosphere(sky);
        });
    else
        prepareAtmosphere(scene, resources_);
    if (!resources_.atmosphereOnDevice)
        backend_->atmosphereChanged(); // the host's tables, or none (the gradient sky)
}

Renderer::~Renderer() = default;

void Renderer::replaceWeatherMap(Texture2D map) {
    resources_.weather = std::move(map);
    resources_.weatherCoverage = CoverageField(resources_.weather);
    resources_.weatherCells = weatherCellMaxima(resources_.weather);
    backend_->texturesChanged(false, true);
    ++weatherVersion_;
}

void Renderer::editWeatherMap(const std::vector<TexelRect>& rects,
                              const std::function<void(Texture2D&)>& edit) {
    Texture2D& map = resources_.weather;
    for (size_t a = 0; a < rects.size(); ++a) {
        const TexelRect& r = rects[a];
        if (r.x < 0 || r.y < 0 || r.width <= 0 || r.height <= 0 || r.x + r.width > map.width ||
            r.y + r.height > map.height)
            throw Error("weather edit: texels x " + std::to_string(r.x) + " + " +
                        std::to_string(r.width) + ", y " + std::to_string(r.y) + " + " +
                        std::to_string(r.height) + " are outside the " + std::to_string(map.width) +
                        "x" + std::to_string(map.height) + " map");
        for (size_t b = a + 1; b < rects.size(); ++b)
            if (overlap(r, rects[b]))
                throw Error("weather edit: rectangles " + std::to_string(a) + " and " +
                            std::to_string(b) + " overlap");
    }
    const std::vector<float> before = gather(map, rects);
    edit(map);
    const std::vector<float> after = gather(map, rects);
    if (resources_.weatherCoverage.empty())
        resources_.weatherCoverage = CoverageField(map);
    else
        resources_.weatherCoverage.replaceTexels(before.data(), after.data(), before.size() / 4);
    for (const TexelRect& r : rects)
        refreshWeatherCells(resources_.weatherCells, map, r.x, r.y, r.x + r.width, r.y + r.height);
    backend_->weatherEdited(rects);
}

void Renderer::replaceDataField(std::vector<glm::vec4> field) {
    const size_t regions = static_cast<size_t>(model::DATA_FIELD_GRID) * model::DATA_FIELD_GRID;
    if (field.size() != regions)
        throw Error("data field: " + std::to_string(field.size()) + " regions, expected " +
                    std::to_string(regions));
    resources_.dataField = std::move(field);
}

std::vector<uint8_t> Renderer::deviceWeatherMap() const {
    return backend_->deviceWeatherMap();
}

UpdateReport Renderer::update(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    ResourceChanges changes = resourceChanges(scene_, scene);
    // What an update that threw half-way had already remade for its scene is made again: the
    // resources must be this scene's, whatever scene_ says they were made for.
    changes.noise |= unsettled_.noise;
    changes.weather |= unsettled_.weather;
    changes.depth |= unsettled_.depth;
    changes.terrain |= unsettled_.terrain;
    changes.dataField |= unsettled_.dataField;
    unsettled_ = {changes.noise, changes.weather, changes.depth, changes.terrain,
                  changes.dataField}; // until done
    UpdateReport report;
    report.noise = changes.noise;
    report.weather = changes.weather;
    report.depth = changes.depth;
    report.dataField = changes.dataField;
    if (changes.noise)
        prepareNoise(scene, resources_);
    // The clearance field is made with the noise only for a scene that reads it; a scene that
    // turns march.noise_skipping on makes it now, and the device takes it at once: a later step
    // that throws must not leave a field on the host that the device never received.
    report.noiseClearance = prepareNoiseClearance(scene, resources_);
    if (report.noiseClearance && !changes.noise) {
        try {
            backend_->texturesChanged(true, false);
        } catch (...) {
            resources_.noise.baseClearance.clear(); // made again by the next update
            throw;
        }
    }
    if (changes.weather) {
        prepareWeather(scene, resources_);
        ++weatherVersion_;
    }
    if (changes.dataField) {
        prepareDataField(scene, resources_); // reaches the model in its parameter block
        ++dataFieldVersion_;
    }
    if (changes.depth)
        prepareDepth(scene, resources_);
    if (changes.noise || changes.weather)
        backend_->texturesChanged(changes.noise, changes.weather);
    report.terrain = changes.terrain;
    if (changes.terrain) {
        prepareTerrain(scene, resources_);
        prepareTerrainLight(scene, resources_); // made again below if the light moves too
        backend_->terrainChanged();
    }
    checkCameraAboveTerrain(scene, resources_);
    report.atmosphere = atmosphereChanged(scene, resources_);
    if (report.atmosphere)
        remakeAtmosphere(scene);
    if (prepareTerrainLight(scene, resources_)) // the light moved
        backend_->terrainChanged();
    scene_ = scene;
    unsettled_ = {};
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

RenderResult Renderer::render(const Scene& scene, const ProgressCallback& progress,
                              Readback readback) {
    update(scene);
    return backend_->still(scene_, progress, readback);
}

RenderResult Renderer::renderFrame(const Scene& scene, int frameIndex, Readback readback) {
    update(scene);
    lastFrame_ = frameIndex;
    return backend_->frame(scene_, frameIndex, readback);
}

RenderResult Renderer::renderFrame(const Camera& camera, float timeS, Readback readback) {
    return renderFrame(withCamera(scene_, camera, timeS), lastFrame_ + 1, readback);
}

TemporalState Renderer::saveState() const {
    return backend_->saveState();
}

void Renderer::restoreState(const TemporalState& state) {
    checkTemporalState(state);
    backend_->restoreState(state);
    lastFrame_ = state.frameIndex;
}

std::string Renderer::backendName() const {
    return backend_->name();
}

TemporalRenderer::Breakdown Renderer::lastBreakdown() const {
    return backend_->breakdown();
}

Renderer::DeviceImage Renderer::deviceImage() const {
    return backend_->deviceImage();
}

TemporalDebugImage Renderer::temporalDebug() const {
    return backend_->temporalDebug();
}

std::vector<glm::vec4> Renderer::cloudShadowMap() const {
    return backend_->cloudShadowMap();
}

Renderer::DeviceHandles Renderer::deviceHandles() const {
    return backend_->deviceHandles();
}

} // namespace cloudscape
