#pragma once
// A scene: everything a user can set, with physical units and documented defaults. Scenes are
// JSON files of nested objects ({"camera": {"fov_deg": 60}}) whose leaves are the keys of the
// table in scene.cpp; the same table validates files, applies --set overrides and generates
// docs/SCENE.md, so the documentation cannot drift from the validator.
#include <glm/vec3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace cloudscape {

// lighting.phase past the parser.
enum class PhaseFunctionKind { TwoLobe, HgDraine };
enum class SkyModel { Atmosphere, Gradient };

struct Scene {
    // Output
    int width = 960;
    int height = 540;
    float exposure = 1.0f;
    int samplesPerPixel = 1;
    int backgroundSamples = 1; // rays averaged per pixel for the reconstruction passes' background
    int temporalAccumulation = 8;
    bool temporal = true;
    bool historyClamp = true;
    bool movingBlock2x2 = false; // a moving camera marches 1/4 of the pixels a frame, not 1/16
    bool stillBlock2x2 = false;  // so does a still one
    // A moving camera's pixel gathers the marches of this many recent frames (0: it resamples
    // the last frame's image instead; sample_gather.glsl.h).
    int movingGatherFrames = 0;
    // Reduced-resolution clouds and a moving camera: the background made at the clouds' pass
    // size and brought up as the clouds are (upsample.glsl.h's upsampledBackground).
    bool movingBackgroundReduced = false;
    int seed = 1;
    std::string depthFile;        // scene depth buffer (EXR, metres along each view ray)
    float cloudResolution = 1.0f; // clouds marched at this fraction of the output size

    // Camera
    glm::vec3 cameraPosition{0.0f, 2.0f, 0.0f};
    float cameraHeadingDeg = 0.0f;
    float cameraPitchDeg = 12.0f;
    float cameraFovDeg = 60.0f;

    // Sun and sky
    float sunElevationDeg = 38.0f;
    float sunHeadingDeg = 35.0f;
    glm::vec3 sunIrradiance{9.5f, 9.0f, 8.3f};
    float sunAngularDiameterDeg = 0.53f;
    // The sun from a place and a time (sun.from_time; solar_position.h): when on, these set the
    // sun's direction and sunElevationDeg/sunHeadingDeg are ignored.
    bool sunFromTime = false;
    float sunLatitudeDeg = 45.0f;
    float sunDayOfYear = 172.0f; // 21 June
    float sunLocalSolarTimeH = 10.0f;
    // The moon (moon.*): a second, dim source for the night sky and the clouds; off by default.
    bool moonEnabled = false;
    float moonElevationDeg = 30.0f;
    float moonHeadingDeg = 180.0f;
    float moonPhase = 1.0f;               // illuminated fraction of the disc: 0 new, 1 full
    float moonAlbedo = 0.12f;             // geometric albedo (the Moon's, V band)
    float moonAngularDiameterDeg = 0.52f; // the Moon's mean: 2 x 1737.4 km / 384400 km
    // The night sky's floor (airglow and starlight) as a radiance per unit sun.irradiance; 0 off.
    float nightRadiance = 0.0f;
    glm::vec3 skyZenith{0.16f, 0.32f, 0.78f};
    glm::vec3 skyHorizon{0.60f, 0.74f, 0.95f};
    glm::vec3 ground{0.12f, 0.12f, 0.11f};

    // Atmosphere (sky.model "atmosphere"): Earth's, after Bruneton 2017 and Hillaire 2020
    SkyModel skyModel = SkyModel::Atmosphere;
    glm::vec3 rayleighScattering{5.802e-6f, 13.558e-6f, 33.1e-6f};
    float rayleighScaleHeightM = 8000.0f;
    float mieScattering = 3.996e-6f;
    float mieExtinction = 4.44e-6f;
    float mieScaleHeightM = 1200.0f;
    float mieG = 0.8f;
    glm::vec3 ozoneAbsorption{0.650e-6f, 1.881e-6f, 0.085e-6f};
    float ozoneCentreM = 25000.0f;
    float ozoneHalfWidthM = 15000.0f;
    float atmosphereTopM = 100000.0f;
    glm::vec3 atmosphereGroundAlbedo{0.15f, 0.15f, 0.15f}; // land; Hillaire uses 0.3
    bool aerialPerspective = true;
    float sunLimbDarkening = 0.6f;

    // Planet and cloud layer
    float planetRadiusM = 6371000.0f;
    float cloudBottomM = 1500.0f;
    float cloudTopM = 8000.0f;

    // Cloud shape
    float extinctionPerM = 0.05f;
    float albedo = 1.0f;
    float erosion = 0.3f;
    float baseNoisePeriodM = 7000.0f;
    float detailNoisePeriodM = 1200.0f;
    float curlPeriodM = 8000.0f;
    float curlStrengthM = 250.0f;

    // Wind and animation
    float timeS = 0.0f;
    float windHeadingDeg = 90.0f;
    float windSpeedMps = 10.0f;
    float windShearM = 500.0f;
    float detailSpeedRatio = 1.8f;
    float updraft = 0.1f;

    // Weather map
    std::string weatherImage;
    float weatherExtentM = 60000.0f;
    float weatherOffsetXM = 0.0f;
    float weatherOffsetZM = 0.0f;
    int weatherResolution = 512;
    float coverage = 0.45f;
    float featureScaleM = 6000.0f;
    float cloudType = 0.67f;
    float typeVariation = 0.12f;
    int rainCells = 0;
    float rainCellRadiusM = 4000.0f;
    float weatherDriftRatio = 0.0f;
    // The data field (src/model/data_field.glsl.h): painted, or generated from these
    std::string fieldImage;
    float bottomType = 0.0f;
    float baseVariation = 0.0f;
    float topVariation = 0.0f;

    // Superstorm (one storm stencil over the weather; off while stormBlend is 0)
    float stormBlend = 0.0f;
    float stormXM = 0.0f;
    float stormZM = 0.0f;
    float stormRadiusM = 12000.0f;
    float stormCoverage = 1.0f;
    float stormRotationDegPerS = 1.0f;
    float stormRingTwistDeg = 120.0f;
    float stormLightDensityScale = 4.0f;
    float stormAmbientScale = 1.0f; // 1 matches the path tracer (docs/QUALITY.md section 8)
    glm::vec3 stormGlowColour{1.0f, 0.12f, 0.05f};
    float stormGlowStrength = 0.0f;
    float stormGlowRadiusM = 6000.0f;
    float stormGlowAltitudeM = 2500.0f;
    bool stormMotionVectors = true;
    bool stormRingJitter = false; // the low tier's (PS4) vortex overlap
    float stormCirrus = 0.8f;
    // The weather controller (src/core/weather_control.h)
    bool stormCycle = false;
    int stormCycleSites = 5;
    float stormCycleBuildS = 120.0f;
    float stormCycleHoldS = 240.0f;
    float stormCycleDissipateS = 120.0f;
    float stormCycleCalmS = 180.0f;
    // Lightning (src/core/lightning.h): flashes while the storm holds
    bool stormLightning = false;
    glm::vec3 stormLightningColour{1.0f, 0.35f, 0.3f};
    float stormLightningStrength = 8.0f; // visible in a daylit storm's foot, not flooding it
    float stormLightningRadiusM = 6000.0f;
    float stormLightningIntervalS = 3.0f;
    int stormLightningIntraFlashes = 4;
    float stormLightningExternal = 2.0f;
    bool stormLightningFlashMask = true;
    float stormBoltWidthM = 6.0f;

    // The high-altitude layer (cirrus and its kin); coverage 0: none
    float highCloudCoverage = 0.0f;
    float highCloudType = 1.0f;
    float highCloudAltitudeM = 10000.0f;
    float highCloudOpticalDepth = 0.3f;
    float highCloudPeriodM = 40000.0f;
    float highCloudWindHeadingDeg = 60.0f;
    float highCloudWindSpeedMps = 25.0f;
    float highCloudPhaseG = 0.75f;

    // Lighting
    float phaseG = 0.2f;
    float silverG = 0.85f;
    float silverWeight = 0.3f;
    float powder = 1.0f;
    int scatteringOctaves = 4;
    glm::vec3 octaveFactors{0.6f, 0.3f, 0.5f};
    float rainAbsorption = 4.0f;
    int lightSamples = 6;
    float coneLengthM = 900.0f;
    bool longSample = true;
    float longSampleDistance = 3.0f;
    float coneSpread = 1.0f;
    int lightMipBias = 1;
    glm::vec3 ambientTop{0.35f, 0.48f, 0.75f};
    glm::vec3 ambientBottom{0.14f, 0.15f, 0.17f};
    float ambientStrength = 1.0f;
    PhaseFunctionKind phaseFunction = PhaseFunctionKind::HgDraine;
    float dropletDiameterUm = 20.0f;
    bool energyConservingSteps = true;

    // Terrain (terrain.*): a height field under the clouds, generated or loaded
    bool terrainEnabled = false;
    std::string terrainFile; // 16-bit PNG or float EXR; empty: generated
    float terrainExtentM = 40000.0f;
    float terrainOffsetXM = 0.0f;
    float terrainOffsetZM = 0.0f;
    float terrainHeightM = 2500.0f;
    float terrainHeightMinM = 0.0f;
    float terrainFeatureSizeM = 8000.0f;
    int terrainResolution = 512;
    glm::vec3 terrainAlbedo{0.10f, 0.12f, 0.07f};
    glm::vec3 terrainRockAlbedo{0.20f, 0.18f, 0.16f};
    float terrainSnowLineM = 100000.0f;
    float terrainFieldSizeM = 300.0f;
    float terrainFieldVariation = 0.0f;
    int terrainMaxSteps = 256;

    // The clouds' shadow map (cloud_shadow.*) and light shafts (shafts.*)
    bool cloudShadowEnabled = false;
    int cloudShadowResolution = 256;
    float cloudShadowExtentM = 50000.0f;
    int cloudShadowSteps = 32;
    bool cloudShadowOnClouds = true; // the clouds' light march reads the map beyond its cone
    bool shaftsEnabled = false;
    int shaftsSteps = 32;
    int shaftsGridFactor = 1; // temporal frames: one shaft ray per N x N pixels
    float shaftsMaxDistanceM = 30000.0f;

    // Path tracer (cloudscape pathtrace)
    float groundAlbedo = 0.0f;
    int pathMaxBounces = 1024;
    bool pathAtmosphere = false; // trace the air too (per RGB channel); sky.model atmosphere only

    // March
    int zenithSteps = 64;
    int horizonSteps = 128;
    float nearStepM = 60.0f;
    float minTransmittance = 0.01f;
    float maxDistanceM = 60000.0f;
    float horizonFade = 0.55f;
    int coarseStepFactor = 2;
    bool distanceLod = true;
    float cheapLightAlpha = 1.0f;
    float stepOptimisation = 0.0f;
    bool blueNoise = false;
    bool emptySpaceSkipping = true;
    // With it, the base noise's clearance field too: exact, fewer samples, but no faster on
    // lavapipe or the CPU backend (docs/PERFORMANCE.md), so off.
    bool noiseSkipping = false;

    // Where relative paths in the scene (weather.image) are resolved; set by the loader.
    std::string baseDirectory;
};

// Load a scene file: defaults overlaid with the file's keys. `source` names the file in errors.
// Throws cloudscape::Error with one line naming the file and key on any problem.
Scene loadScene(const std::string& path);
// The same over other defaults than Scene{} (the CLI's still renders default to more samples).
Scene loadScene(const std::string& path, const Scene& defaults);

// Parse a scene from JSON text (for tests and built-in presets); `source` is used in messages.
Scene parseScene(const std::string& jsonText, const std::string& source,
                 const Scene& base = Scene{});

// Apply one "key=value" override (the value is JSON: 0.3, true, [1,2,3], or a bare string).
// `where` names the option in error messages.
void applyOverride(Scene& scene, const std::string& assignment, const std::string& where = "--set");

// Cross-key checks (layer top above bottom, camera above ground, ...). Throws cloudscape::Error.
void validateScene(const Scene& scene, const std::string& source);

// Quality tiers after the Forbidden West PS4/PS5 table: "low" (clouds at half resolution, 6
// light samples, 60-90 view steps, cheap light after alpha 0.3, noise mip +1 for light, step
// optimisation, longer accumulation), "high" (10 light samples, 96-180 steps, mip 0) and
// "reference" (every pixel every frame, no shortcuts, 256-512 steps, 4 samples per pixel). A tier
// is an overlay of key = value pairs applied through the key table (so it is validated and
// documented like every key; docs/SCENE.md lists them). Throws on an unknown name.
void applyTier(Scene& scene, const std::string& tier);
const std::vector<std::string>& tierNames();

// The defaults every key takes (a Scene as constructed), for the generators' own parameter
// structs, and the inclusive range the key table allows a number (or each vector component).
const Scene& defaultScene();
struct KeyRange {
    double min = 0.0;
    double max = 0.0;
};
// Also for checks of scenes computed from validated ones (the frames of a camera path). Throws
// cloudscape::Error for a key that is not in the table or is not a number (or a vector of them).
KeyRange sceneKeyRange(const std::string& key);

// Every key of the table with its exact value, one `key=value` a line (numbers as hex floats),
// for fingerprints: two scenes have the same text exactly when every setting is the same.
std::string sceneSettingsText(const Scene& scene);

// The key table as data, for interfaces generated from it (the viewer's panels): every key with
// its type, unit, inclusive range (numbers and vector components), choices and documentation.
enum class SceneKeyType { Integer, Number, Boolean, String, Vector3, Choice };
struct SceneKeyInfo {
    std::string key; // "weather.coverage": the section is the part before the first dot
    SceneKeyType type = SceneKeyType::Number;
    std::string unit;
    double min = 0.0;
    double max = 0.0;
    std::vector<std::string> choices; // SceneKeyType::Choice
    std::string doc;
};
const std::vector<SceneKeyInfo>& sceneKeyInfos();
// A key's value as JSON text ("0.45", "[1, 2, 3]", "\"atmosphere\"", "true"), which --set and
// applyOverride read back to the same value; throws cloudscape::Error for an unknown key.
std::string sceneKeyValue(const Scene& scene, const std::string& key);
// The scene as a scene file: exactly the keys whose value differs from the defaults, nested by
// section, so loading it gives the same settings.
std::string sceneJson(const Scene& scene);

// docs/SCENE.md, generated from the key table.
std::string sceneDocumentationMarkdown();

// Names of the shipped presets (scenes/*.json, without extension) and the path of one.
std::string presetDirectory();
std::string resolveScenePath(const std::string& nameOrPath);

} // namespace cloudscape
