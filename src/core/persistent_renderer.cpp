// The persistent Renderer: owns the scene and its resources, regenerates only what a change of
// scene touches, and hands the renders to one backend (renderer_backend.h) for its whole life.
#include <cloudscape/persistent_renderer.h>

#include "core/atmosphere_luts.h"
#include "core/renderer_backend.h"
#include "core/resources.h"
#include "core/temporal_impl.h"

#include <chrono>

namespace cloudscape {
namespace {

std::unique_ptr<Renderer::Backend> openBackend(const SceneResources& resources,
                                               const BackendOptions& options, std::string* notice) {
    const bool vulkan = options.choice == BackendChoice::Vulkan ||
                        (options.choice == BackendChoice::Auto && autoChoosesVulkan(notice));
    return vulkan ? makeVulkanRendererBackend(resources, options)
                  : makeCpuRendererBackend(resources);
}

} // namespace

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
    backend_ = openBackend(resources_, options, notice);
    // Tables the resources lack or that were made for another scene: made now, as the first
    // update would, so resources() is complete from the start.
    if (atmosphereChanged(scene_, resources_))
        remakeAtmosphere(scene_);
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
}

UpdateReport Renderer::update(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    const ResourceChanges changes = resourceChanges(scene_, scene);
    UpdateReport report;
    report.noise = changes.noise;
    report.weather = changes.weather;
    report.depth = changes.depth;
    if (changes.noise)
        prepareNoise(scene, resources_);
    if (changes.weather)
        prepareWeather(scene, resources_);
    if (changes.depth)
        prepareDepth(scene, resources_);
    if (changes.noise || changes.weather)
        backend_->texturesChanged(changes.noise, changes.weather);
    report.terrain = changes.terrain;
    if (changes.terrain) {
        prepareTerrain(scene, resources_);
        backend_->terrainChanged();
    }
    checkCameraAboveTerrain(scene, resources_);
    report.atmosphere = atmosphereChanged(scene, resources_);
    if (report.atmosphere)
        remakeAtmosphere(scene);
    scene_ = scene;
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
