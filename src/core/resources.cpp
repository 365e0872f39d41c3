// Resource preparation for every backend and the path tracer: the noise textures, the weather
// map (procedural or painted) with its coverage-field distribution, and the scene depth buffer,
// each on its own so that a persistent Renderer regenerates only what a scene change touches.
#include <cloudscape/data_field.h>
#include <cloudscape/renderer.h>
#include <cloudscape/weather.h>

#include <cloudscape/error.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_textures.h"
#include "model/sky.glsl.h"
#include "model/terrain.glsl.h"

#include <cstdio>

#include <chrono>
#include <filesystem>
#include <optional>

namespace cloudscape {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string formatCoordinate(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", static_cast<double>(v));
    return text;
}

std::string resolvePath(const std::string& path, const Scene& scene) {
    std::filesystem::path p(path);
    if (p.is_relative() && !scene.baseDirectory.empty())
        p = std::filesystem::path(scene.baseDirectory) / p;
    return p.string();
}

WeatherParams weatherParamsOf(const Scene& s) {
    WeatherParams w;
    w.seed = static_cast<uint32_t>(s.seed) * 2654435761u + 17u;
    w.resolution = s.weatherResolution;
    w.extentM = s.weatherExtentM;
    w.featureScaleM = s.featureScaleM;
    w.typeMean = s.cloudType;
    w.typeVariation = s.typeVariation;
    w.rainCells = s.rainCells;
    w.rainCellRadiusM = s.rainCellRadiusM;
    return w;
}

} // namespace

Texture2D prepareWeather(const Scene& scene) {
    if (scene.weatherImage.empty())
        return generateWeatherMap(weatherParamsOf(scene));
    return loadWeatherImage(resolvePath(scene.weatherImage, scene));
}

bool wantsNoiseClearance(const Scene& scene) {
    return scene.noiseSkipping && scene.emptySpaceSkipping;
}

void prepareNoise(const Scene& scene, SceneResources& r) {
    const auto start = std::chrono::steady_clock::now();
    r.noise = generateNoiseTextures(static_cast<uint32_t>(scene.seed), wantsNoiseClearance(scene));
    r.noiseSeconds = secondsSince(start);
}

bool prepareNoiseClearance(const Scene& scene, SceneResources& r) {
    if (!wantsNoiseClearance(scene) || !r.noise.baseClearance.empty())
        return false;
    r.noise.baseClearance = generateNoiseClearance(r.noise.base);
    return true;
}

void prepareWeather(const Scene& scene, SceneResources& r) {
    const auto start = std::chrono::steady_clock::now();
    r.weather = prepareWeather(scene);
    r.weatherCoverage = CoverageField(r.weather);
    r.weatherCells = weatherCellMaxima(r.weather);
    r.weatherSeconds = secondsSince(start);
}

void prepareDataField(const Scene& scene, SceneResources& r) {
    if (!scene.fieldImage.empty()) {
        r.dataField = loadDataFieldImage(resolvePath(scene.fieldImage, scene));
        return;
    }
    DataFieldParams d;
    d.seed = static_cast<uint32_t>(scene.seed) * 2654435761u + 29u;
    d.extentM = scene.weatherExtentM;
    d.featureScaleM = scene.featureScaleM;
    d.bottomType = scene.bottomType;
    d.baseVariation = scene.baseVariation;
    d.topVariation = scene.topVariation;
    r.dataField = generateDataField(d);
}

void prepareDepth(const Scene& scene, SceneResources& r) {
    r.depth = DepthBuffer{};
    if (!scene.depthFile.empty())
        r.depth = loadDepthBuffer(resolvePath(scene.depthFile, scene), scene.width, scene.height);
}

void prepareTerrain(const Scene& scene, SceneResources& r) {
    const auto start = std::chrono::steady_clock::now();
    r.terrain = HeightField{};
    if (scene.terrainEnabled && scene.terrainFile.empty()) {
        TerrainGenerator g;
        g.seed = static_cast<uint32_t>(scene.seed) * 2246822519u + 101u;
        g.resolution = scene.terrainResolution;
        g.extentM = scene.terrainExtentM;
        g.heightM = scene.terrainHeightM;
        g.featureSizeM = scene.terrainFeatureSizeM;
        r.terrain = generateTerrain(g);
    } else if (scene.terrainEnabled) {
        r.terrain = loadHeightMap(resolvePath(scene.terrainFile, scene), scene.terrainHeightMinM,
                                  scene.terrainHeightM);
        const float texel = scene.terrainExtentM / float(r.terrain.width);
        measureHeightField(r.terrain, texel, texel);
    }
    r.terrainSeconds = secondsSince(start);
}

namespace {

// The terrain under the scene's camera: its surface's altitude and the camera's (m).
struct CameraOverTerrain {
    float ground;
    float camera;
};

std::optional<CameraOverTerrain> terrainUnderCamera(const Scene& scene,
                                                    const SceneResources& resources) {
    if (!scene.terrainEnabled || resources.terrain.empty())
        return std::nullopt;
    const model::CloudParams p = makeCloudParams(scene, resources);
    cpu::TextureSet textures;
    textures.terrain = resources.terrain.heights.data();
    const cpu::ScopedTextureBinding bind(textures);
    const glm::vec3 c = scene.cameraPosition;
    return CameraOverTerrain{model::terrainHeightAt(glm::vec2(c.x, c.z), p.terrain),
                             model::terrainAltitude(c, p.planetRadius)};
}

} // namespace

void checkCameraAboveTerrain(const Scene& scene, const SceneResources& resources) {
    const std::optional<CameraOverTerrain> over = terrainUnderCamera(scene, resources);
    const glm::vec3 c = scene.cameraPosition;
    if (over && over->camera <= over->ground + 1.0f)
        throw Error("camera.position [" + formatCoordinate(c.x) + ", " + formatCoordinate(c.y) +
                    ", " + formatCoordinate(c.z) + "] is below the terrain, whose surface is " +
                    formatCoordinate(over->ground) +
                    " m high there; expected the camera at least 1 m above it");
}

bool liftCameraAboveTerrain(Scene& scene, const SceneResources& resources, float clearanceM) {
    const std::optional<CameraOverTerrain> over = terrainUnderCamera(scene, resources);
    if (!over)
        return false;
    glm::vec3& c = scene.cameraPosition;
    const float rise = over->ground + clearanceM - over->camera;
    if (rise <= 0.0f)
        return false;
    c += glm::normalize(c - model::planetCentre(scene.planetRadiusM)) * rise;
    return true;
}

SceneResources prepareResourcesWithoutAtmosphere(const Scene& scene) {
    SceneResources r;
    prepareNoise(scene, r);
    prepareWeather(scene, r);
    prepareDataField(scene, r);
    prepareDepth(scene, r);
    prepareTerrain(scene, r);
    prepareTerrainLight(scene, r);
    return r;
}

SceneResources prepareResources(const Scene& scene) {
    SceneResources r = prepareResourcesWithoutAtmosphere(scene);
    prepareAtmosphere(scene, r);
    prepareTerrainLight(scene, r); // the moon may light the clouds now
    return r;
}

bool prepareTerrainLight(const Scene& scene, SceneResources& r) {
    if (r.terrain.empty())
        return false;
    const glm::vec3 light = model::cloudLightDirection(makeSkyParams(scene, r));
    if (r.terrain.lightHorizonOffset > 0 && r.terrain.lightHorizonDirection == light)
        return false;
    const float texel = scene.terrainExtentM / float(r.terrain.width);
    appendLightHorizon(r.terrain, light, texel, texel);
    return true;
}

ResourceChanges resourceChanges(const Scene& before, const Scene& after) {
    ResourceChanges c;
    c.noise = before.seed != after.seed;
    const bool painted = !after.weatherImage.empty();
    if (painted)
        c.weather = before.weatherImage != after.weatherImage ||
                    before.baseDirectory != after.baseDirectory;
    else
        c.weather =
            !before.weatherImage.empty() || before.seed != after.seed ||
            before.weatherResolution != after.weatherResolution ||
            before.weatherExtentM != after.weatherExtentM ||
            before.featureScaleM != after.featureScaleM || before.cloudType != after.cloudType ||
            before.typeVariation != after.typeVariation || before.rainCells != after.rainCells ||
            before.rainCellRadiusM != after.rainCellRadiusM;
    c.dataField = before.fieldImage != after.fieldImage ||
                  (!after.fieldImage.empty() ? before.baseDirectory != after.baseDirectory
                                             : before.seed != after.seed ||
                                                   before.weatherExtentM != after.weatherExtentM ||
                                                   before.featureScaleM != after.featureScaleM ||
                                                   before.bottomType != after.bottomType ||
                                                   before.baseVariation != after.baseVariation ||
                                                   before.topVariation != after.topVariation);
    c.depth = before.depthFile != after.depthFile ||
              (!after.depthFile.empty() &&
               (before.baseDirectory != after.baseDirectory || before.width != after.width ||
                before.height != after.height));
    c.terrain = before.terrainEnabled != after.terrainEnabled ||
                (after.terrainEnabled &&
                 (before.terrainFile != after.terrainFile || before.seed != after.seed ||
                  before.terrainExtentM != after.terrainExtentM ||
                  before.terrainHeightM != after.terrainHeightM ||
                  before.terrainHeightMinM != after.terrainHeightMinM ||
                  before.terrainFeatureSizeM != after.terrainFeatureSizeM ||
                  before.terrainResolution != after.terrainResolution ||
                  (!after.terrainFile.empty() && before.baseDirectory != after.baseDirectory)));
    return c;
}

} // namespace cloudscape
