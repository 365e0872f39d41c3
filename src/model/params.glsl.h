// The parameters the model reads, declared once for GLSL and C++. Members are grouped into 16-byte
// rows (a vec3 and a scalar, or four scalars) so the std140 and std430 layouts equal the C++
// layout; the C++ side checks the sizes, and src/vulkan/tests/interface_test.cpp that the
// compiled shaders lay them out without padding. Units are physical: metres, seconds, 1/m,
// linear radiance.
#ifndef CLOUDSCAPE_MODEL_PARAMS_GLSL_H
#define CLOUDSCAPE_MODEL_PARAMS_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
#include <cstddef>
#endif

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The atmosphere (atmosphere.glsl.h): Rayleigh and Mie scattering with exponential profiles,
// ozone absorption in a tent, between the planet's surface and the top. Coefficients in 1/m.
struct AtmosphereParams {
    vec3 rayleighScattering;   // at the ground
    float rayleighScaleHeight; // m
    vec3 ozoneAbsorption;      // at the tent's peak
    float mieScattering;       // at the ground
    vec3 groundAlbedo;         // Lambertian, of the planet's surface
    float mieExtinction;       // at the ground (>= mieScattering)
    float mieScaleHeight;      // m
    float mieG;                // Cornette-Shanks asymmetry
    float ozoneCentre;         // m, altitude of the tent's peak
    float ozoneHalfWidth;      // m
    float bottomRadius;        // m, the planet's radius
    float topRadius;           // m
    float skyViewRadius;       // m from the centre: where the sky-view table was made (the camera)
    int enabled;               // 0: the placeholder gradient sky (sky.model "gradient")
    float limbDarkening;       // of the sun disc: I(mu) = 1 - u (1 - mu)
    int aerialPerspective;     // 1: the air between the camera and a cloud scatters and absorbs
    float unused0;
    float unused1;
};

// The sky's parameters. The clouds ask the sky (sky.glsl.h) for radiance along a direction, the
// sun (direction, irradiance) and the ambient light, and read nothing else of it, so an
// atmosphere model can replace this block and sky.glsl.h without touching the cloud model.
struct SkyParams {
    vec3 sunDirection;      // unit vector toward the sun
    float sunAngularRadius; // rad
    vec3 sunIrradiance;     // on a surface facing the sun, at the top of the clouds (linear RGB)
    float sunOneMinusCos;   // 1 - cos(angular radius), from the host in double precision
    vec3 zenith;            // placeholder sky radiance straight up
    float unused0;
    vec3 horizon; // placeholder sky radiance at the horizon
    float unused1;
    vec3 ground; // radiance of the ground below the horizon
    float unused2;
    vec3 ambientTop;       // sky radiance lighting cloud tops
    float ambientStrength; // multiplier on the ambient term
    vec3 ambientBottom;    // radiance from below (ground bounce) lighting cloud bases
    float unused3;
    AtmosphereParams atmosphere;
    // The moon (sky.glsl.h): a second, dim source read through the same per-unit-irradiance
    // tables, and the night sky's floor (airglow and starlight). All zero with moon.enabled off
    // and sky.night_radiance 0, so a day scene's block is what it was.
    vec3 moonDirection;      // unit vector toward the moon
    float moonAngularRadius; // rad
    vec3 moonIrradiance;     // above the atmosphere, at its phase (linear RGB); 0 if off
    float moonOneMinusCos;   // 1 - cos(angular radius), from the host in double precision
    vec3 moonBrightLimb;     // unit, across the line of sight: the way the lit limb faces
    float moonPhaseAngle;    // rad, sun-moon-observer: 0 full, pi new
    vec3 nightRadiance;      // the night sky's own radiance above the atmosphere (linear RGB)
    int moonEnabled;         // 1: the moon is drawn and lights the sky, air and clouds
    int moonLightsClouds;    // 1: the moon, not the sun, is the clouds' direct light
    float unused4;
    float unused5;
    float unused6;
};

// The high-altitude layer (high_clouds.glsl.h): a thin shell of ice cloud drawn from a 2D texture.
struct HighCloudParams {
    vec2 windVelocity;  // m/s over the ground (x east, z north)
    float altitude;     // m
    float coverage;     // 0: no layer (the image is exactly that without it)
    float type;         // 0 cirrostratus, 1 cirrus, 2 cirrocumulus; fractions blend neighbours
    float opticalDepth; // vertical optical depth where the layer's density is 1
    float period;       // m over which the texture repeats
    float phaseG;       // Henyey-Greenstein asymmetry of the ice crystals
    // The storm's cirrus (high_clouds.glsl.h, stormCirrusDensity): coverage at the centre of the
    // patch downwind of a storm's anvil, before the storm's blend; 0 without a storm or without
    // the texture (which the patch reads as the layer does).
    float stormCirrus;
    float stormCirrusPad0;
    float stormCirrusPad1;
    float stormCirrusPad2;
};

// The terrain (terrain.glsl.h): a height field of width x height float texels (metres above the
// planet's surface, row-major, row 0 at the field's smallest z) covering extent metres of world
// xz around origin; beyond it the ground is the flat planet (height 0).
struct TerrainParams {
    vec3 albedo;          // Lambertian albedo of gentle slopes
    int enabled;          // 0: no terrain (the flat planet of ground.glsl.h)
    vec3 rockAlbedo;      // of steep slopes
    float snowLine;       // m; gentle slopes above it are snow
    vec2 origin;          // world xz (m) of the field's centre
    vec2 extent;          // world size (m) in x and z
    int width;            // texels along x
    int height;           // texels along z
    float maxHeight;      // m, the highest texel: the march's ceiling
    float lipschitz;      // sqrt(1 + s^2) for the steepest slope s of the field: the march's bound
    int maxSteps;         // of the terrain ray march
    float fieldSize;      // m: side of the fields whose albedo varies (fieldAlbedoFactor)
    float fieldVariation; // 0: the plain albedo everywhere; up to 1: +-100 % from field to field
    float pixelAngle;     // rad: a pixel's angular size, for the fields' distance fade
    int cellGrid;         // level 0's cells of maxima a side, a power of two (terrain.glsl.h)
    int cellLevels;       // levels of cell maxima after the field's texels (0: none)
    int lightHorizon; // index of the light's horizon in the texels (terrainLightHorizonAt; 0: none)
    int cellPad1;
};

// Lightning (lightning.glsl.h): the flash of this moment and the bolt of a ground discharge, set
// by the host's schedule (src/core/lightning.cpp); all zero while storm.lightning is off.
struct LightningParams {
    vec3 flashPosition;   // m, world: centre of the current (or next) flash
    float flashRadius;    // m: the flash's potential falls to 0 there
    vec3 flashLight;      // radiance of a flash at unit intensity (colour times strength)
    float flashIntensity; // the flash's animated intensity now (0 between flashes)
    vec3 boltTop;         // m, world: where the ground discharge leaves the cloud base
    float boltIntensity;  // the bolt's intensity now (0 unless a ground discharge is lit)
    vec3 boltBottom;      // m, world: where it meets the ground (before its random walk)
    float boltWidth;      // m, width of the bolt's bright core
    float flashExternal;  // weight of the external flash (the underside's highlights)
    int flashMask;        // 1: the march writes the flash at unit intensity to its own channel
    int boltSeed;         // the bolt's shape
    int enabled;          // 0: no lightning (nothing is evaluated)
};

// The clouds' shadow map (cloud_shadow.glsl.h) and the light shafts (light_shafts.glsl.h).
struct CloudShadowParams {
    // The world texel (x, z) of the map's first column and row: map texel (i, j) is the world's
    // texel firstTexel + (i, j) of side extent / resolution on the plane y = 0
    // (cloud_shadow.glsl.h).
    ivec2 firstTexel;
    float extent;     // m, the side of the map on that plane
    int resolution;   // texels a side; 0: no map (the ground's per-pixel groundCloudShadow)
    int steps;        // density samples along each texel's sun ray
    int lightsClouds; // 1: the clouds' light march reads the map beyond its cone (lighting.glsl.h)
    // Where map texel (0, 0) is stored: the buffer is toroidal, each world texel kept at the same
    // place while the map follows the camera (firstTexel modulo resolution, on the host).
    int storageShiftX;
    int storageShiftZ;
};

struct LightShaftParams {
    int steps;         // along each view ray; 0: no shafts (the image is exactly that without)
    float maxDistance; // m along the view ray
    // The temporal resolve's grid (shaft_grid.glsl.h): 1, every pixel's own shafts; N > 1, one
    // shaft ray per N x N pixels, upsampled depth-aware. Full frames ignore it.
    int gridFactor;
    float unused1;
};

// Cells along each side of the march's cloud-top grid (cloud_bound.glsl.h); a power of two.
CONST_INT CLOUD_TOP_GRID = 32;
// Regions along each side of the data field (data_field.glsl.h); a power of two.
CONST_INT DATA_FIELD_GRID = 64;

// Per-scene cloud model and lighting parameters, one named member per quantity, in 16-byte rows
// (interface.glsl.h's layout rule).
struct CloudParams {
    // Planet and cloud layer
    float planetRadius;  // m
    float layerBottom;   // altitude of the cloud layer's bottom (m)
    float layerTop;      // altitude of its top (m)
    float weatherExtent; // world size (m) the weather map covers; it wraps beyond
    // Weather map (weather.glsl.h: coverage = saturate(coverage field + coverageBias))
    vec2 weatherOrigin;      // world xz (m) of the map's centre
    float coverageBias;      // chosen so the map's mean coverage is weather.coverage
    float typeOffset;        // added to the map's type, then clamped
    float baseNoisePeriod;   // m over which the base noise repeats
    float detailNoisePeriod; // m, the detail noise
    float curlNoisePeriod;   // m, the curl noise
    float curlStrength;      // m, largest curl displacement of the detail lookup
    float erosion;           // detail erosion strength
    float extinction;        // 1/m at density 1
    float albedo;            // single-scattering albedo
    int emptySpaceSkipping;  // 1: the march skips what cloudTops proves empty (cloud_bound.glsl.h)
    // Wind and animation
    vec3 windDirection;     // unit, horizontal, the way the wind blows
    float windSpeed;        // m/s
    float time;             // s
    float windShear;        // downwind offset of cloud tops (m)
    float detailSpeedRatio; // detail noise speed relative to the base noise
    float updraft;          // upward drift as a fraction of the wind speed
    // Lighting
    float phaseG;              // g of the main HG lobe (two-lobe phase)
    float silverG;             // g of the silver-lining lobe
    float silverWeight;        // weight of the silver-lining lobe
    float powder;              // powder strength (0 off, 1 full)
    int phaseKind;             // PHASE_TWO_LOBE or PHASE_HG_DRAINE (interface.glsl.h)
    float dropletDiameter;     // micrometres, for HG+Draine
    int energyConservingSteps; // 1: exact step integration (Hillaire 2015); 0: the seeds' sum
    int scatteringOctaves;     // 1 = single scattering
    vec3 octaveFactors;        // Wrenninge per-octave energy a, optical depth b, eccentricity c
    float rainAbsorption;      // extra absorption gain at full precipitation
    int lightSamples;          // cone samples toward the sun
    int longSample;            // 1: one long-distance light sample
    int lightMipBias;          // noise mip for light samples
    float coneLength;          // m
    float longSampleDistance;  // in cone lengths
    float coneSpread;          // sideways spread per sample, relative to the light step
    float cloudTopMax;         // m, the highest of cloudTops: nothing above it has cloud
    float nearStepLength;      // m, the longest view step near the camera (0: off; march.glsl.h)
    // March
    int zenithSteps;        // view steps straight up
    int horizonSteps;       // view steps along the horizon
    float minTransmittance; // the march stops below it
    float maxDistance;      // m
    float horizonFade;      // fade start as a fraction of maxDistance
    int coarseStepFactor;   // 1 = every step a full sample
    float stepOptimisation; // step optimisation gain (0 off)
    float cheapLightAlpha;  // view opacity above which light samples are cheap (>= 1 never)
    float log2BaseTexel;    // log2 of a base-noise texel (m), for the distance LOD
    float log2DetailTexel;  // log2 of a detail-noise texel (m)
    int distanceLod;        // 1: distance-based noise LOD on
    int blueNoise;          // 1: blue-noise march start offsets
    // Superstorm (storm.glsl.h): one storm stencil over the weather; off while stormBlend is 0
    vec2 stormCentre;             // world xz (m); the storm wraps with the weather map
    float stormRadius;            // m
    float stormBlend;             // 0 off .. 1 full storm
    float stormCoverage;          // coverage at the centre of the mesocyclone's foot
    float stormRotation;          // rad/s of the innermost vortex ring
    float stormRingTwist;         // rad of spiral twist of the detail noise across the radius
    float stormSpin;              // s: the time integral of the blend, the vortex's clock
    vec3 stormGlow;               // internal glow radiance (colour times strength)
    float stormLightDensityScale; // light-march optical depth scale at the storm's foot
    float stormGlowRadius;        // m
    float stormGlowAltitude;      // m, the glow's centre above the storm centre
    float stormAmbientScale;      // ambient multiplier under the storm
    int stormMotionVectors;       // 1: the reprojection follows the vortex (0: wind scroll only)
    int stormRingJitter;          // 1: one ring read in an overlap, picked at random (PS4)
    float stormPad0;
    float stormPad1;
    float stormPad2;
    // The data field (data_field.glsl.h): 1 when dataField holds anything but the neutral value
    int dataFieldEnabled;
    float dataFieldPad0;
    float dataFieldPad1;
    float dataFieldPad2;
    // The base noise's clearance field (noise_clearance.glsl.h): the noise's size in texels along
    // each side when the field is bound and the march may skip by it, else 0.
    int noiseClearanceSize;
    float noiseClearancePad0;
    float noiseClearancePad1;
    float noiseClearancePad2;
    SkyParams sky;
    HighCloudParams highClouds;
    TerrainParams terrain;
    LightningParams lightning;
    CloudShadowParams cloudShadow;
    LightShaftParams shafts;
    // Empty-space skipping's grid (cloud_bound.glsl.h): the altitude (m) above which each of
    // CLOUD_TOP_GRID^2 columns tiling the weather map is empty, row-major in weather-map
    // (x, z), four to a row; written by the host from the weather map (makeCloudParams).
    vec4 cloudTops[CLOUD_TOP_GRID * CLOUD_TOP_GRID / 4];
    // The same columns' clearance level (noise_clearance.glsl.h): the highest threshold level
    // k of the base noise's clearance field that the column's weather allows (the largest k with
    // k / NOISE_CLEARANCE_LEVELS at or below its lowest coverage threshold), -1 where none does
    // or the storm or the data field reshape the base noise; written with cloudTops.
    vec4 cloudNoiseLevels[CLOUD_TOP_GRID * CLOUD_TOP_GRID / 4];
    // The data field's regions (bottom type, anvil coverage, minimum and maximum height),
    // row-major in weather-map (x, z); written by the host (makeCloudParams).
    vec4 dataField[DATA_FIELD_GRID * DATA_FIELD_GRID];
};

// Per-frame camera and output parameters.
struct FrameParams {
    vec3 cameraPosition; // world position (m; y is altitude above the ground)
    float exposure;      // multiplier before tone mapping
    vec3 cameraForward;  // unit view direction
    float tanHalfFov;    // tan(vertical field of view / 2)
    vec3 cameraRight;    // unit right vector
    float aspect;        // width / height
    vec3 cameraUp;       // unit up vector
    // The temporal resolve's step (0 elsewhere). Per-frame values live here, in a uniform buffer,
    // never in push constants: lavapipe compiles a shader variant for every distinct value of a
    // push constant that steers control flow and keeps them all (6 MB a frame, never freed).
    float secondsSincePrevious;
    int width;  // pixels
    int height; // pixels
    int frameIndex;
    int seed; // for the jitter
    int samplesPerPixel;
    int temporalAccumulation; // cap on the marches a temporal pixel averages
    int hasSceneDepth;        // 1: a scene depth buffer is bound
    int sequenceFrame;        // the frame's index in its sequence (the resolve's Bayer order)
    int historyClamp;         // 1: clamp history to this frame's marches nearby (temporal.glsl.h)
    int temporalBlock;        // the temporal blocks' side in pixels, 4 or 2 (temporalBlockFor)
    int backgroundSamples;    // rays averaged per pixel for the kept background (backgroundLightAt)
    // Earlier frames' marches a moving camera's pixel gathers (sample_gather.glsl.h): the ring's
    // capacity in frames (render.moving_gather_frames; 0: none kept) and how many of its slots
    // hold frames of this sequence, this one included.
    int gatherFrames;
    int gatherValid;
    float sequenceTime; // seconds: the frame's scene time (the gathered marches' ages)
    int framePad2;
    int framePad3;
};

#ifdef __cplusplus
static_assert(sizeof(AtmosphereParams) == 6 * 16, "AtmosphereParams must match the GLSL layout");
static_assert(sizeof(SkyParams) == 18 * 16, "SkyParams must match the GLSL layout");
static_assert(sizeof(HighCloudParams) == 3 * 16, "HighCloudParams must match the GLSL layout");
static_assert(sizeof(TerrainParams) == 6 * 16, "TerrainParams must match the GLSL layout");
static_assert(sizeof(LightningParams) == 5 * 16, "LightningParams must match the GLSL layout");
static_assert(sizeof(CloudShadowParams) == 2 * 16, "CloudShadowParams must match the GLSL layout");
static_assert(sizeof(LightShaftParams) == 16, "LightShaftParams must match the GLSL layout");
// 56 rows of named members, then the three grids.
static_assert(sizeof(CloudParams) == 56 * 16 + sizeof(CloudParams::cloudTops) +
                                         sizeof(CloudParams::cloudNoiseLevels) +
                                         sizeof(CloudParams::dataField),
              "CloudParams must match the GLSL layout");
static_assert(offsetof(CloudParams, dataField) % 16 == 0, "the data field starts a row");
static_assert(sizeof(FrameParams) == 8 * 16, "FrameParams must match the GLSL layout");
// Every vec3 starts a 16-byte row (std140 aligns it to 16; C++ would not).
static_assert(offsetof(CloudParams, windDirection) % 16 == 0 &&
                  offsetof(CloudParams, octaveFactors) % 16 == 0 &&
                  offsetof(CloudParams, sky) % 16 == 0 &&
                  offsetof(CloudParams, highClouds) % 16 == 0 &&
                  offsetof(CloudParams, terrain) % 16 == 0 &&
                  offsetof(CloudParams, lightning) % 16 == 0 &&
                  offsetof(CloudParams, cloudShadow) % 16 == 0 &&
                  offsetof(CloudParams, cloudTops) % 16 == 0 &&
                  offsetof(TerrainParams, rockAlbedo) % 16 == 0 &&
                  offsetof(CloudParams, stormCentre) % 16 == 0 &&
                  offsetof(CloudParams, stormGlow) % 16 == 0 &&
                  offsetof(SkyParams, sunIrradiance) % 16 == 0 &&
                  offsetof(SkyParams, ambientBottom) % 16 == 0 &&
                  offsetof(SkyParams, atmosphere) % 16 == 0 &&
                  offsetof(FrameParams, cameraUp) % 16 == 0,
              "vec3 members must start a 16-byte row");
static_assert(offsetof(SkyParams, moonDirection) % 16 == 0 &&
                  offsetof(SkyParams, moonIrradiance) % 16 == 0 &&
                  offsetof(SkyParams, moonBrightLimb) % 16 == 0 &&
                  offsetof(SkyParams, nightRadiance) % 16 == 0,
              "the moon's vec3 members must start a 16-byte row");
#endif

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
