#include "core/model_params.h"

#include <cloudscape/data_field.h>

#include "core/cloud_top_grid.h"
#include "core/lightning.h"
#include "core/weather_control.h"
#include "cpu/cpu_textures.h"
#include "model/noise_clearance.glsl.h"
#include "model/sky.glsl.h"

#include <cloudscape/solar_position.h>

#include "model/cloud_shadow.glsl.h"
#include "model/temporal.glsl.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace cloudscape {

glm::vec3 directionFromAngles(float headingDeg, float elevationDeg) {
    const float h = glm::radians(headingDeg);
    const float e = glm::radians(elevationDeg);
    return {std::sin(h) * std::cos(e), std::sin(e), std::cos(h) * std::cos(e)};
}

float oneMinusCosOf(float angle) {
    const double half = std::sin(0.5 * static_cast<double>(angle));
    return static_cast<float>(2.0 * half * half);
}

// The Moon's brightness against its phase angle (degrees), relative to full: Allen's law as
// Krisciunas and Schaefer 1991 (PASP 103, 1033, eq. 8) give it, 10^(-0.4 (0.026 a + 4e-9 a^4)).
// With the geometric albedo 0.12 and (radius / distance)^2 = 2.04e-5 the full moon is 2.45e-6 of
// the sun, the difference of their magnitudes (-12.74 and -26.74: 2.5e-6).
double moonPhaseBrightness(double phaseAngleDeg) {
    const double a = std::abs(phaseAngleDeg);
    return std::pow(10.0, -0.4 * (0.026 * a + 4e-9 * a * a * a * a));
}

// The moon's block of SkyParams: off (all zero) unless moon.enabled and the moon is high enough
// to light any of the air (above the horizon's dip from the atmosphere's top, with its disc and
// refraction), so a moon far below the horizon costs nothing.
static void setMoonParams(model::SkyParams& sky, const Scene& s) {
    const model::AtmosphereParams& a = sky.atmosphere;
    sky.nightRadiance = s.sunIrradiance * s.nightRadiance;
    const double dip = std::acos(double(a.bottomRadius) / double(a.topRadius));
    const double radius = glm::radians(double(s.moonAngularDiameterDeg)) * 0.5;
    const double lowest = -(dip + radius + double(model::GRAZING_REFRACTION));
    if (!s.moonEnabled || glm::radians(double(s.moonElevationDeg)) <= lowest)
        return;
    sky.moonEnabled = 1;
    sky.moonDirection = directionFromAngles(s.moonHeadingDeg, s.moonElevationDeg);
    sky.moonAngularRadius = static_cast<float>(radius);
    sky.moonOneMinusCos = oneMinusCosOf(sky.moonAngularRadius);
    // Phase angle from the illuminated fraction k = (1 + cos a) / 2.
    const double phaseAngle = std::acos(std::clamp(2.0 * double(s.moonPhase) - 1.0, -1.0, 1.0));
    sky.moonPhaseAngle = static_cast<float>(phaseAngle);
    const double sinRadius = std::sin(radius);
    const double full = double(s.moonAlbedo) * sinRadius * sinRadius;
    sky.moonIrradiance =
        s.sunIrradiance * static_cast<float>(full * moonPhaseBrightness(glm::degrees(phaseAngle)));
    // The bright limb faces the sun: the sun's direction across the line of sight to the moon
    // (any direction across it when the sun is straight behind or in front of the moon).
    const glm::vec3 m = sky.moonDirection;
    glm::vec3 across = sky.sunDirection - m * glm::dot(m, sky.sunDirection);
    if (glm::length(across) < 1e-6f)
        across = glm::cross(m, std::abs(m.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    sky.moonBrightLimb = glm::normalize(across);
}

model::SkyParams makeSkyParams(const Scene& s) {
    model::SkyParams sky{};
    // sun.elevation_deg/heading_deg, or the place and time of sun.from_time: decided here, where
    // every backend and the path tracer take their sun from.
    const SunAngles sun = sunAnglesOf(s);
    sky.sunDirection = directionFromAngles(static_cast<float>(sun.headingDeg),
                                           static_cast<float>(sun.elevationDeg));
    sky.sunAngularRadius = glm::radians(s.sunAngularDiameterDeg) * 0.5f;
    sky.sunOneMinusCos = oneMinusCosOf(sky.sunAngularRadius);
    sky.sunIrradiance = s.sunIrradiance;
    sky.zenith = s.skyZenith;
    sky.horizon = s.skyHorizon;
    sky.ground = s.ground;
    sky.ambientTop = s.ambientTop;
    sky.ambientStrength = s.ambientStrength;
    sky.ambientBottom = s.ambientBottom;
    model::AtmosphereParams& a = sky.atmosphere;
    a.enabled = s.skyModel == SkyModel::Atmosphere ? 1 : 0;
    a.rayleighScattering = s.rayleighScattering;
    a.rayleighScaleHeight = s.rayleighScaleHeightM;
    a.ozoneAbsorption = s.ozoneAbsorption;
    a.mieScattering = s.mieScattering;
    a.groundAlbedo = s.atmosphereGroundAlbedo;
    a.mieExtinction = s.mieExtinction;
    a.mieScaleHeight = s.mieScaleHeightM;
    a.mieG = s.mieG;
    a.ozoneCentre = s.ozoneCentreM;
    a.ozoneHalfWidth = s.ozoneHalfWidthM;
    a.bottomRadius = s.planetRadiusM;
    a.topRadius = s.planetRadiusM + s.atmosphereTopM;
    // The sky-view table is made for the camera's altitude (the sky treats the camera's zenith as
    // +y, so moving sideways does not remake it).
    a.skyViewRadius = s.planetRadiusM + s.cameraPosition.y;
    a.limbDarkening = s.sunLimbDarkening;
    a.aerialPerspective = s.aerialPerspective ? 1 : 0;
    setMoonParams(sky, s);
    return sky;
}

// The superstorm's parameters; all zero while it is off (blend 0), so a scene without a storm
// has the same parameter block whatever its storm.* keys say.
static void setStormParams(model::CloudParams& p, const Scene& s) {
    const StormState storm = stormStateAt(s, s.timeS);
    if (storm.blend <= 0.0f)
        return;
    p.stormCentre = storm.centre;
    p.stormRadius = s.stormRadiusM;
    p.stormBlend = storm.blend;
    p.stormCoverage = s.stormCoverage;
    p.stormRotation = glm::radians(s.stormRotationDegPerS);
    p.stormRingTwist = glm::radians(s.stormRingTwistDeg);
    // The vortex's clock is the integral of the blend over time, so that a blend that changes
    // turns the rings at speed * blend without the angle jumping (constant blend: blend * t).
    p.stormSpin = storm.spin;
    p.stormGlow = s.stormGlowColour * s.stormGlowStrength;
    p.stormLightDensityScale = s.stormLightDensityScale;
    p.stormGlowRadius = s.stormGlowRadiusM;
    p.stormGlowAltitude = s.stormGlowAltitudeM;
    p.stormAmbientScale = s.stormAmbientScale;
    p.stormMotionVectors = s.stormMotionVectors ? 1 : 0;
    p.stormRingJitter = s.stormRingJitter ? 1 : 0;
}

// The lightning of this moment (src/core/lightning.h); all zero while it is off or the storm does
// not hold.
static void setLightningParams(model::CloudParams& p, const Scene& s) {
    const LightningState l = lightningStateAt(s, s.timeS);
    if (!l.active || p.stormBlend <= 0.0f)
        return;
    model::LightningParams& m = p.lightning;
    m.enabled = 1;
    m.flashPosition = l.position;
    m.flashRadius = s.stormLightningRadiusM;
    m.flashLight = s.stormLightningColour * (s.stormLightningStrength * p.stormBlend);
    m.flashIntensity = l.intensity;
    m.flashExternal = l.ground ? s.stormLightningExternal : 0.0f;
    m.flashMask = s.stormLightningFlashMask ? 1 : 0;
    if (l.ground) {
        m.boltTop = l.boltTop;
        m.boltBottom = l.boltBottom;
        m.boltIntensity = l.intensity;
        m.boltWidth = s.stormBoltWidthM;
        m.boltSeed = l.boltSeed;
    }
}

namespace {
bool weatherReady(const Texture2D& weather) {
    return weather.width > 0 && weather.height > 0 && !weather.mips.empty();
}
} // namespace

model::SkyParams makeSkyParams(const Scene& scene, const SceneResources& resources) {
    model::SkyParams sky = makeSkyParams(scene);
    // The atmosphere is on when the scene asks for it and its tables exist (resources made by
    // prepareResources or a Renderer always have them; hand-made ones get the gradient sky). The
    // sky view is read at the radius its table was made for.
    const bool tables = !resources.atmosphere.empty();
    sky.atmosphere.enabled = scene.skyModel == SkyModel::Atmosphere && tables ? 1 : 0;
    if (tables)
        sky.atmosphere.skyViewRadius = resources.atmosphereSkyViewRadius;
    // The moon reads the same tables (and its own sky view): on only with them.
    if (sky.atmosphere.enabled == 0)
        sky.moonEnabled = 0;
    sky.moonLightsClouds = 0;
    if (sky.moonEnabled != 0) {
        // Which source lights the clouds, once per frame, by the model's rule over the
        // transmittance table.
        cpu::TextureSet set;
        set.atmosphere = resources.atmosphere.data();
        cpu::ScopedTextureBinding bind(set);
        sky.moonLightsClouds =
            model::moonOutshinesSun(scene.cameraPosition, scene.cloudTopM, scene.maxDistanceM, sky)
                ? 1
                : 0;
    }
    return sky;
}

model::CloudParams makeCloudParams(const Scene& scene, const SceneResources& resources) {
    const float bias = resources.weatherCoverage.empty()
                           ? CoverageField(resources.weather).biasFor(scene.coverage)
                           : resources.weatherCoverage.biasFor(scene.coverage);
    model::CloudParams p = makeCloudParams(scene, bias);
    p.sky = makeSkyParams(scene, resources);
    p.terrain = makeTerrainParams(scene, resources.terrain);
    // The light's horizon stands in for the terrain's shadow rays only if it was made for the
    // light of this scene (prepareTerrainLight); otherwise they are marched.
    const HeightField& field = resources.terrain;
    if (p.terrain.enabled != 0 && field.lightHorizonOffset > 0 &&
        field.lightHorizonDirection == model::cloudLightDirection(p.sky))
        p.terrain.lightHorizon = static_cast<int>(field.lightHorizonOffset);
    setCloudShadowParams(p, scene);
    // Likewise the high layer needs its texture (generateNoiseTextures makes it).
    if (!resources.noise.highClouds.mips.empty()) {
        p.highClouds.coverage = scene.highCloudCoverage;
        // The storm's cirrus reads the same texture (0 without a storm: nothing is evaluated).
        if (p.stormBlend > 0.0f)
            p.highClouds.stormCirrus = scene.stormCirrus;
    }
    // The data field, unless neutral (then the model is exactly the one without it). Before
    // the cloud-top grid, which bounds the columns by it.
    if (!resources.dataField.empty() && !isNeutralDataField(resources.dataField)) {
        std::copy(resources.dataField.begin(), resources.dataField.end(), p.dataField);
        p.dataFieldEnabled = 1;
    }
    // Empty-space skipping needs the grid of column tops, which needs the map (hand-made
    // parameters without one march every sample).
    if (scene.emptySpaceSkipping && weatherReady(resources.weather)) {
        fillCloudTopGrid(p, resources.weather, &resources.weatherCells);
        p.emptySpaceSkipping = 1;
        // The noise's clearance field skips too where it was made for this base noise.
        const Texture3D& base = resources.noise.base;
        const std::vector<uint32_t>& field = resources.noise.baseClearance;
        if (scene.noiseSkipping && !field.empty() &&
            field.size() == size_t(model::noiseClearanceWords(base.size)))
            p.noiseClearanceSize = base.size;
    }
    return p;
}

void setCloudShadowParams(model::CloudParams& p, const Scene& s) {
    p.cloudShadow = model::CloudShadowParams{};
    p.shafts = model::LightShaftParams{};
    if (!s.cloudShadowEnabled)
        return;
    model::CloudShadowParams& c = p.cloudShadow;
    c.resolution = s.cloudShadowResolution;
    c.extent = s.cloudShadowExtentM;
    c.steps = s.cloudShadowSteps;
    c.lightsClouds = s.cloudShadowOnClouds ? 1 : 0;
    // Centred on the sun ray through the point halfway between the camera and the ground below
    // it (clamped under the cloud base): the ground around the camera and the air the camera
    // looks through both project near the middle of the map.
    const glm::vec3 sun = model::cloudLightDirection(p.sky); // the moon when it lights the clouds
    const float y = 0.5f * std::clamp(s.cameraPosition.y, 0.0f, s.cloudBottomM);
    const float along = sun.y >= model::CLOUD_SHADOW_MIN_SUN_Y ? y / sun.y : 0.0f;
    const glm::dvec2 centre = {s.cameraPosition.x - sun.x * along,
                               s.cameraPosition.z - sun.z * along};
    // On whole texels of one world grid, as cascaded shadow maps are stabilised: a moving camera
    // then keeps each texel's ray (and its sample phase, cloud_shadow.glsl.h) where it was, so
    // the shadows do not shimmer as the map follows it, and a renderer remakes only the texels
    // the move brings in (the storage is toroidal).
    if (c.resolution > 0) {
        const double texel = static_cast<double>(model::cloudShadowTexelSize(c));
        const int n = c.resolution;
        c.firstTexel = glm::ivec2(glm::round(centre / texel)) - glm::ivec2(n / 2);
        c.storageShiftX = ((c.firstTexel.x % n) + n) % n;
        c.storageShiftZ = ((c.firstTexel.y % n) + n) % n;
    }
    if (s.shaftsEnabled) {
        p.shafts.steps = s.shaftsSteps;
        p.shafts.maxDistance = s.shaftsMaxDistanceM;
        p.shafts.gridFactor = s.shaftsGridFactor;
    }
}

model::TerrainParams makeTerrainParams(const Scene& s, const HeightField& field) {
    model::TerrainParams t{};
    t.albedo = s.terrainAlbedo;
    t.rockAlbedo = s.terrainRockAlbedo;
    t.snowLine = s.terrainSnowLineM;
    t.maxSteps = s.terrainMaxSteps;
    t.fieldSize = s.terrainFieldSizeM;
    t.fieldVariation = s.terrainFieldVariation;
    // The angle a pixel of the image spans at its centre (the fields fade where it spans several).
    t.pixelAngle = 2.0f * std::tan(glm::radians(0.5f * s.cameraFovDeg)) / float(s.height);
    t.origin = {s.terrainOffsetXM, s.terrainOffsetZM};
    t.lipschitz = 1.0f;
    // On when the scene asks for it and the field exists (prepareResources or a Renderer made
    // it; hand-made resources have none).
    if (!s.terrainEnabled || field.empty())
        return t;
    t.enabled = 1;
    t.width = field.width;
    t.height = field.height;
    t.extent = {s.terrainExtentM, s.terrainExtentM * float(field.height) / float(field.width)};
    t.maxHeight = field.maxHeightM;
    t.lipschitz = std::sqrt(1.0f + field.maxSlope * field.maxSlope);
    t.cellGrid = field.cellGrid;
    t.cellLevels = field.cellLevels;
    return t;
}

model::CloudParams makeCloudParams(const Scene& s, float coverageBias) {
    model::CloudParams p{};
    // No column allows the noise's clearance until fillCloudTopGrid says which (0 would be a
    // level, and a wrong one).
    for (glm::vec4& four : p.cloudNoiseLevels)
        four = glm::vec4(-1.0f);
    p.planetRadius = s.planetRadiusM;
    p.layerBottom = s.cloudBottomM;
    p.layerTop = s.cloudTopM;
    p.weatherExtent = s.weatherExtentM;
    p.weatherOrigin = {s.weatherOffsetXM, s.weatherOffsetZM};
    if (s.weatherDriftRatio > 0.0f) {
        // The map drifts downwind with time (weather.drift_ratio); the path tracer's majorant
        // reads the map through the same origin.
        const glm::vec3 wind = directionFromAngles(s.windHeadingDeg, 0.0f);
        const float travel = s.windSpeedMps * s.weatherDriftRatio * s.timeS;
        p.weatherOrigin += glm::vec2(wind.x, wind.z) * travel;
    }
    p.coverageBias = coverageBias;
    p.typeOffset = 0.0f;
    p.baseNoisePeriod = s.baseNoisePeriodM;
    p.detailNoisePeriod = s.detailNoisePeriodM;
    p.curlNoisePeriod = s.curlPeriodM;
    p.curlStrength = s.curlStrengthM;
    p.erosion = s.erosion;
    p.extinction = s.extinctionPerM;
    p.albedo = s.albedo;
    p.windDirection = directionFromAngles(s.windHeadingDeg, 0.0f);
    p.windSpeed = s.windSpeedMps;
    p.time = s.timeS;
    p.windShear = s.windShearM;
    p.detailSpeedRatio = s.detailSpeedRatio;
    p.updraft = s.updraft;
    p.phaseG = s.phaseG;
    p.silverG = s.silverG;
    p.silverWeight = s.silverWeight;
    p.powder = s.powder;
    p.phaseKind = s.phaseFunction == PhaseFunctionKind::HgDraine ? model::PHASE_HG_DRAINE
                                                                 : model::PHASE_TWO_LOBE;
    p.dropletDiameter = s.dropletDiameterUm;
    p.energyConservingSteps = s.energyConservingSteps ? 1 : 0;
    p.scatteringOctaves = s.scatteringOctaves;
    p.octaveFactors = s.octaveFactors;
    p.rainAbsorption = s.rainAbsorption;
    p.lightSamples = s.lightSamples;
    p.longSample = s.longSample ? 1 : 0;
    p.lightMipBias = s.lightMipBias;
    p.coneLength = s.coneLengthM;
    p.longSampleDistance = s.longSampleDistance;
    p.coneSpread = s.coneSpread;
    p.zenithSteps = s.zenithSteps;
    p.horizonSteps = s.horizonSteps;
    p.nearStepLength = s.nearStepM;
    p.minTransmittance = s.minTransmittance;
    p.maxDistance = s.maxDistanceM;
    p.horizonFade = s.horizonFade;
    p.coarseStepFactor = s.coarseStepFactor;
    p.stepOptimisation = s.stepOptimisation;
    p.cheapLightAlpha = s.cheapLightAlpha;
    // Texel sizes of the generated noise (128^3 base, 32^3 detail) in metres, as log2.
    p.log2BaseTexel = std::log2(s.baseNoisePeriodM / 128.0f);
    p.log2DetailTexel = std::log2(s.detailNoisePeriodM / 32.0f);
    p.distanceLod = s.distanceLod ? 1 : 0;
    p.blueNoise = s.blueNoise ? 1 : 0;
    setStormParams(p, s);
    setLightningParams(p, s);
    p.sky = makeSkyParams(s);
    p.sky.atmosphere.enabled = 0; // no tables here: see makeCloudParams(scene, resources)
    p.sky.moonEnabled = 0;        // nor the moon, which reads them
    const glm::vec3 highWind = directionFromAngles(s.highCloudWindHeadingDeg, 0.0f);
    p.highClouds.windVelocity = glm::vec2(highWind.x, highWind.z) * s.highCloudWindSpeedMps;
    p.highClouds.altitude = s.highCloudAltitudeM;
    p.highClouds.coverage = 0.0f;    // no texture here: see makeCloudParams(scene, resources)
    p.highClouds.stormCirrus = 0.0f; // nor the storm's cirrus, which reads it
    p.highClouds.type = s.highCloudType;
    p.highClouds.opticalDepth = s.highCloudOpticalDepth;
    p.highClouds.period = s.highCloudPeriodM;
    p.highClouds.phaseG = s.highCloudPhaseG;
    return p;
}

model::FrameParams makeFrameParams(const Scene& s, int frameIndex) {
    model::FrameParams f{};
    const glm::vec3 forward = directionFromAngles(s.cameraHeadingDeg, s.cameraPitchDeg);
    const glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    // x east, y up, z north is a left-handed frame (as in Unity): facing north, east is on the
    // right, which is up x forward here.
    const glm::vec3 right = glm::normalize(glm::cross(worldUp, forward));
    const glm::vec3 up = glm::cross(forward, right);
    f.cameraPosition = s.cameraPosition;
    f.exposure = s.exposure;
    f.cameraForward = forward;
    f.tanHalfFov = std::tan(glm::radians(s.cameraFovDeg) * 0.5f);
    f.cameraRight = right;
    f.aspect = static_cast<float>(s.width) / static_cast<float>(s.height);
    f.cameraUp = up;
    f.width = s.width;
    f.height = s.height;
    f.frameIndex = frameIndex;
    f.seed = s.seed;
    f.samplesPerPixel = s.samplesPerPixel;
    f.backgroundSamples = s.backgroundSamples;
    f.gatherFrames = s.movingGatherFrames; // a temporal renderer sets gatherValid
    f.sequenceTime = s.timeS;
    f.temporalAccumulation = s.temporalAccumulation;
    f.historyClamp = s.historyClamp ? 1 : 0;
    f.temporalBlock = model::TEMPORAL_BLOCK; // a temporal renderer sets each frame's own
    // hasSceneDepth is set by the backend that binds a depth buffer.
    f.hasSceneDepth = 0;
    return f;
}

} // namespace cloudscape
