// The image loop of the path tracer: camera rays through the shared camera model, one sample per
// pixel per pass, in parallel tiles. All light transport is in integrator.h.
#include <cloudscape/error.h>
#include <cloudscape/pathtrace.h>

#include "core/fnv1a.h"
#include "core/model_params.h"
#include "cpu/cpu_model.h"
#include "pathtrace/air_integrator.h"
#include "pathtrace/cloud_medium.h"
#include "pathtrace/integrator.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <mutex>

namespace cloudscape {

namespace {

// Sample k (0-based) moves the mean a 1/(k+1) of the way to the sample, in double, and the result
// is rounded to float: the stored state is the whole state, so a resumed image continues exactly.
// Each rounding is at most half a float ulp (6e-8 relative); they are unbiased, so they add up
// like a random walk (about 1e-5 relative after 64k samples), far below that many samples' noise.
inline float addToMean(float mean, float sample, uint64_t k) {
    const double m = mean;
    return static_cast<float>(m + (static_cast<double>(sample) - m) / static_cast<double>(k + 1));
}

// A ground discharge's bolt seen along a camera ray: the model's polyline (lightning.glsl.h) at
// its own core width (the real-time composite widens it to the pixel's footprint to keep its
// energy; the jittered samples here spread it over the pixel instead), hidden by the surface in
// front of it and seen through the clouds' transmittance up to its brightest point, traced
// (the composite takes the whole march's transmittance when the first cloud lies in front).
// Rays that pass more than about two widths from it see nothing and draw no random numbers.
glm::vec3 boltSeen(const pathtrace::CloudMedium& medium, const model::CloudParams& params,
                   float surfaceDistance, glm::vec3 camera, glm::vec3 dir,
                   pathtrace::Random& random) {
    if (!model::lightningOn(params) || params.lightning.boltIntensity <= 0.0f)
        return glm::vec3(0.0f);
    const float geometryDepth = std::min(surfaceDistance, params.maxDistance);
    float t = 0.0f;
    const float b = model::boltBrightness(camera, dir, 0.0f, geometryDepth, params, t);
    if (b < 1e-8f)
        return glm::vec3(0.0f);
    const float transmittance = pathtrace::estimateTransmittance(medium, camera, dir, t, random);
    return model::lightningBoltCore(params) * (b * transmittance * params.lightning.boltIntensity);
}

} // namespace

std::string pathTraceFingerprint(const Scene& scene, const SceneResources& resources) {
    model::CloudParams cloud = makeCloudParams(scene, resources);
    model::FrameParams frame = makeFrameParams(scene);
    frame.exposure = 0.0f;
    frame.samplesPerPixel = frame.temporalAccumulation = frame.hasSceneDepth = 0;
    // Only what the path tracer reads: the real-time lighting and march settings may change
    // without invalidating a ground truth.
    cloud.sky.ambientTop = cloud.sky.ambientBottom = glm::vec3(0.0f);
    cloud.sky.ambientStrength = 0.0f;
    cloud.sky.atmosphere.aerialPerspective = 0; // the real-time composite's, not the tracer's
    cloud.rainAbsorption = cloud.coneLength = cloud.longSampleDistance = cloud.coneSpread = 0.0f;
    cloud.lightSamples = cloud.longSample = cloud.lightMipBias = cloud.scatteringOctaves = 0;
    cloud.octaveFactors = glm::vec3(0.0f);
    cloud.coarseStepFactor = cloud.distanceLod = cloud.blueNoise = 0;
    cloud.stepOptimisation = cloud.cheapLightAlpha = cloud.log2BaseTexel = cloud.log2DetailTexel =
        0.0f;
    // maxDistance and horizonFade stay: the medium fades with them.
    cloud.zenithSteps = cloud.horizonSteps = 0;
    cloud.minTransmittance = 0.0f;
    cloud.energyConservingSteps = 0;
    cloud.powder = 0.0f;
    // The storm's lighting fields are the real-time lighting's, except the glow when it emits
    // (the path tracer's emission); its density fields stay.
    const bool emits = pathtrace::CloudMedium::emitsLight(cloud);
    if (!emits) {
        cloud.stormGlow = glm::vec3(0.0f);
        cloud.stormGlowRadius = cloud.stormGlowAltitude = 0.0f;
    }
    cloud.stormLightDensityScale = cloud.stormAmbientScale = 0.0f;
    cloud.stormMotionVectors = 0;
    // The shadow map and the shafts are the real-time renderer's (the tracer traces shadows).
    cloud.cloudShadow = model::CloudShadowParams{};
    cloud.shafts = model::LightShaftParams{};
    if (cloud.phaseKind == model::PHASE_HG_DRAINE)
        cloud.phaseG = cloud.silverG = cloud.silverWeight = 0.0f;
    else
        cloud.dropletDiameter = 0.0f; // unused
    // Bump when the model or the path tracer changes what an image means.
    constexpr uint64_t kVersion = 2; // 2: named parameter fields
    uint64_t h = fnv1a(&kVersion, sizeof(kVersion));
    h = fnv1a(&cloud, sizeof(cloud), h);
    h = fnv1a(&frame, sizeof(frame), h);
    for (const auto& level : resources.weather.mips)
        h = fnv1a(level.data(), level.size() * sizeof(float), h);
    const int extras[] = {scene.seed, scene.pathMaxBounces};
    h = fnv1a(extras, sizeof(extras), h);
    h = fnv1a(&scene.groundAlbedo, sizeof(scene.groundAlbedo), h);
    if (scene.pathAtmosphere) { // only when on, so the images made without it keep theirs
        const char air = 1;
        h = fnv1a(&air, sizeof(air), h);
    }
    if (emits) { // the glow and the flashes are emission (only then hashed)
        const char emission = 'e';
        h = fnv1a(&emission, sizeof(emission), h);
    }
    if (cloud.terrain.enabled != 0) { // the path tracer sees the terrain (only then hashed)
        const char terrain = 't';
        h = fnv1a(&terrain, sizeof(terrain), h);
        h = fnv1a(resources.terrain.heights.data(),
                  resources.terrain.heights.size() * sizeof(float), h);
    }
    char text[32];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h));
    return text;
}

PathTraceStats pathTrace(const Scene& scene, const SceneResources& resources, PathTraceImage& image,
                         int samples, const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (image.mean.empty()) {
        image.width = scene.width;
        image.height = scene.height;
        image.samplesPerPixel = 0;
        image.mean.assign(static_cast<size_t>(scene.width) * scene.height * 3, 0.0f);
    } else if (image.width != scene.width || image.height != scene.height) {
        throw Error("path tracer: the image to continue is " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " but the scene renders " +
                    std::to_string(scene.width) + "x" + std::to_string(scene.height));
    }

    if (scene.pathAtmosphere && scene.skyModel != SkyModel::Atmosphere)
        throw Error("pathtrace.atmosphere: needs sky.model \"atmosphere\" (the air it traces)");
    const model::CloudParams params = makeCloudParams(scene, resources);
    const model::FrameParams frame = makeFrameParams(scene);
    const glm::vec3 camera(frame.cameraPosition);
    const pathtrace::CloudMedium medium(params, camera, resources.weather);

    const pathtrace::SunLight sun = pathtrace::makeCloudLight(params.sky);
    pathtrace::Ground ground;
    ground.enabled = true;
    ground.radius = params.planetRadius;
    ground.albedo = scene.groundAlbedo;
    ground.terrain = &params; // the surface is the terrain when terrain.enabled is on
    pathtrace::PathLimits limits;
    limits.maxBounces = scene.pathMaxBounces;
    // With pathtrace.atmosphere: the air as a medium, one per channel (air_integrator.h).
    const pathtrace::AtmosphereMedium airs[3] = {
        {params.sky.atmosphere, 0}, {params.sky.atmosphere, 1}, {params.sky.atmosphere, 2}};
    pathtrace::AirPathOptions airOptions;
    airOptions.limits = limits;
    airOptions.discSky = &params.sky;
    airOptions.terrain = &ground;
    const glm::dvec3 cameraFromCentre =
        glm::dvec3(camera) + glm::dvec3(0.0, double(params.sky.atmosphere.bottomRadius), 0.0);
    auto environment = [&params](glm::vec3 dir, bool withSunDisc) {
        return withSunDisc ? model::skyRadiance(dir, params.sky)
                           : model::skyBackground(dir, params.sky);
    };

    cpu::TextureSet textures;
    textures.baseNoise = &resources.noise.base;
    textures.detailNoise = &resources.noise.detail;
    textures.curlNoise = &resources.noise.curl;
    textures.weatherMap = &resources.weather;
    textures.atmosphere = resources.atmosphere.empty() ? nullptr : resources.atmosphere.data();
    textures.highClouds =
        resources.noise.highClouds.mips.empty() ? nullptr : &resources.noise.highClouds;
    textures.terrain =
        resources.terrain.heights.empty() ? nullptr : resources.terrain.heights.data();

    const uint64_t violationsBefore = pathtrace::majorantViolations().load();
    tbb::enumerable_thread_specific<pathtrace::PathCounters> counters;
    const int width = image.width;
    const int height = image.height;
    constexpr int kTile = 8;
    const int tilesX = (width + kTile - 1) / kTile;
    const int tilesY = (height + kTile - 1) / kTile;
    const double totalTiles = static_cast<double>(tilesX) * tilesY * samples;
    uint64_t tilesDone = 0; // guarded by progressMutex
    std::mutex progressMutex;
    const uint64_t seed =
        pathtrace::mixBits(static_cast<uint64_t>(scene.seed) + 0x5eed + (image.stream << 32));

    for (int pass = 0; pass < samples; ++pass) {
        const uint64_t sampleIndex = image.samplesPerPixel;
        tbb::parallel_for(
            tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1),
            [&](const tbb::blocked_range2d<int>& range) {
                cpu::ScopedTextureBinding binding(textures);
                pathtrace::PathCounters& local = counters.local();
                for (int ty = range.rows().begin(); ty != range.rows().end(); ++ty) {
                    for (int tx = range.cols().begin(); tx != range.cols().end(); ++tx) {
                        for (int y = ty * kTile; y < std::min(height, (ty + 1) * kTile); ++y) {
                            for (int x = tx * kTile; x < std::min(width, (tx + 1) * kTile); ++x) {
                                const size_t pixel = static_cast<size_t>(y) * width + x;
                                pathtrace::Random random(
                                    seed ^ pathtrace::mixBits(pixel),
                                    pathtrace::mixBits(sampleIndex + (seed << 20)));
                                // A uniformly jittered point in the pixel (box filter).
                                const float px = float(x) - 0.5f + random.uniform();
                                const float py = float(y) - 0.5f + random.uniform();
                                const glm::vec3 dir = model::cameraRayDirection(frame, px, py);
                                glm::vec3 radiance;
                                if (scene.pathAtmosphere) {
                                    for (int c = 0; c < 3; ++c)
                                        radiance[c] = pathtrace::traceRadianceInAir(
                                            medium, airs[c], sun, cameraFromCentre, glm::dvec3(dir),
                                            random, airOptions, local);
                                } else {
                                    radiance = pathtrace::traceRadiance(medium, sun, ground,
                                                                        environment, camera, dir,
                                                                        random, limits, local);
                                }
                                if (model::lightningOn(params))
                                    radiance +=
                                        boltSeen(medium, params, ground.intersect(camera, dir),
                                                 camera, dir, random);
                                float* mean = &image.mean[pixel * 3];
                                for (int c = 0; c < 3; ++c)
                                    mean[c] = addToMean(mean[c], radiance[c], sampleIndex);
                            }
                        }
                        if (progress) {
                            std::lock_guard<std::mutex> lock(progressMutex);
                            progress(static_cast<double>(++tilesDone) / totalTiles);
                        }
                    }
                }
            });
        image.samplesPerPixel += 1;
    }

    PathTraceStats stats;
    for (const pathtrace::PathCounters& c : counters) {
        stats.paths += c.paths;
        stats.collisions += c.collisions;
        stats.truncated += c.truncated;
    }
    stats.majorantViolations = pathtrace::majorantViolations().load() - violationsBefore;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

} // namespace cloudscape
