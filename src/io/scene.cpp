// The scene key table and everything built on it: file loading, --set overrides, validation
// and the generated documentation.
#include <cloudscape/error.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/scene.h>

#include "io/scene_keys.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>
#include <variant>

namespace cloudscape {
namespace {

// An enumeration: in a file or --set the value is one of `names` (the index is the enum's value);
// past the parser the Scene holds the enum itself.
struct EnumMember {
    std::vector<std::string> names;
    std::function<int(const Scene&)> get;
    std::function<void(Scene&, int)> set;
};

template <class E> EnumMember enumMember(E Scene::*member, std::vector<std::string> names) {
    return {std::move(names), [member](const Scene& s) { return static_cast<int>(s.*member); },
            [member](Scene& s, int v) { s.*member = static_cast<E>(v); }};
}

using Member = std::variant<int Scene::*, float Scene::*, bool Scene::*, std::string Scene::*,
                            glm::vec3 Scene::*, EnumMember>;

struct SceneKey {
    const char* key;
    Member member;
    const char* unit;
    double min; // inclusive range of a number or of each vector component
    double max;
    const char* description;
};

// The one table of scene keys. Order is the documentation's order.
const std::vector<SceneKey>& sceneKeys() {
    static const std::vector<SceneKey> keys = {
        {"render.width", &Scene::width, "px", 16, 16384, "Output image width."},
        {"render.height", &Scene::height, "px", 16, 16384, "Output image height."},
        {"render.exposure", &Scene::exposure, "-", 1e-4, 1e8,
         "Multiplier on linear radiance before the ACES tone curve (PNG output only). Moonlight "
         "is 2.4e-6 of sunlight: a moonlit night takes about 5e4 (the night preset's 6e4), a "
         "long exposure's look."},
        {"render.samples_per_pixel", &Scene::samplesPerPixel, "-", 1, 1024,
         "Jittered marches averaged per pixel (anti-aliasing and less step noise for stills)."},
        {"render.background_samples", &Scene::backgroundSamples, "-", 1, 64,
         "Sequences and reduced-resolution clouds: rays averaged per pixel for what lies behind "
         "the clouds (terrain, ground, sky), which those frames make apart from the clouds' "
         "marches and would otherwise see through each pixel's centre only: 4 anti-aliases the "
         "terrain's edges and the horizon about as a still's 4 samples do. Costs this many "
         "times the background's rays whenever it is made (once for a still camera, every frame "
         "while the camera moves). The high tier uses 4."},
        {"render.temporal_accumulation", &Scene::temporalAccumulation, "marches", 1, 256,
         "Sequences: each pixel averages up to this many of its marches through reprojection; "
         "1 replaces the history as Horizon does."},
        {"render.temporal", &Scene::temporal, "bool", 0, 0,
         "Sequences use the temporal reconstruction (1/16 of the pixels a frame); false marches "
         "every pixel every frame."},
        {"render.history_clamp", &Scene::historyClamp, "bool", 0, 0,
         "Sequences, while the camera moves: where a pixel's reprojected history is in doubt "
         "(it moves with its distance by more than a quarter of a pixel a frame, or a march "
         "around it sees cloud that would have placed it elsewhere) it is clamped to a box "
         "around this frame's four marches around the pixel, so cloud that appears in front of "
         "the history (flying into a cloud) replaces it instead of leaving a ghost. A still or "
         "turning camera is never clamped."},
        {"render.moving_block_2x2", &Scene::movingBlock2x2, "bool", 0, 0,
         "Sequences, while the camera moves (flies, turns or zooms): march one pixel of every "
         "2x2 block each frame instead of every 4x4, four times the march's cost for a history "
         "at most 4 frames old, so far clouds do not drift into blocks and streaks, resampled "
         "history does not soften, and clouds revealed or too near to reproject are upsampled "
         "from marches 2 pixels apart; the whole frame costs about 1.45x while moving. A still "
         "camera marches 1/16 of the pixels unless render.still_block_2x2 is on. Off by default "
         "(Horizon's budget); the high tier and the fly-through preset turn it on."},
        {"render.still_block_2x2", &Scene::stillBlock2x2, "bool", 0, 0,
         "Sequences, while the camera is still: march one pixel of every 2x2 block each frame "
         "instead of every 4x4, each march through a new point of its pixel with a new start "
         "offset, so a pixel averages 4 marches after 16 frames instead of 1 (less grain and "
         "anti-aliased cloud edges sooner); four times the march's cost while still. Off by "
         "default (Horizon's budget); the high tier turns it on."},
        {"render.moving_gather_frames", &Scene::movingGatherFrames, "-", 0, 32,
         "Sequences, while the camera moves (flies, turns or zooms): each pixel averages the "
         "marches of this many recent frames that land near it, each moved to where its own "
         "cloud distance puts it in this frame (a Gaussian of 0.3 pixel with the 2x2 block, "
         "0.6 with the 4x4), instead of resampling the last frame's image, whose blur grows "
         "with every frame: a moving pixel then averages several marches, not one or two. "
         "Keeps that many frames of marches (32 bytes a marched pixel each: 24 frames of the "
         "2x2 block are 192 bytes a pixel) and reads 4 of them a pixel per frame. 2x2 blocks "
         "showing what the previous frame did not (a turning camera's new edge) march all four "
         "pixels, kept 4 frames (96 bytes a pixel more). 0 (off) by default; the high tier "
         "gathers 24."},
        {"render.moving_background_reduced", &Scene::movingBackgroundReduced, "bool", 0, 0,
         "Sequences with reduced-resolution clouds (render.cloud_resolution < 1), while the "
         "camera moves (flies, turns or zooms): make what lies behind the clouds (terrain, "
         "ground, sky, the high layer) at the clouds' resolution too and bring it to the output "
         "size as the clouds are (radiance bilinearly, depths from the nearest pass pixel), "
         "instead of ray-marching the terrain for every output pixel each frame: a softer "
         "background in motion for about a third of a flying frame's cost at 640x360. A still "
         "camera's background is made at full size (and kept while nothing changes). Off by "
         "default; the low tier turns it on."},
        {"render.depth_file", &Scene::depthFile, "path", 0, 0,
         "Scene depth buffer: an EXR at the output size whose R channel (or Z, or its only "
         "channel) is metres along each pixel's view ray to opaque geometry (inf or beyond "
         "march.max_distance_m = sky). Marches end there; pixels whose geometry is nearer than "
         "the cloud layer are not marched. Empty: none. Relative to the scene file."},
        {"render.cloud_resolution", &Scene::cloudResolution, "-", 0.25, 1,
         "Clouds are marched at this fraction of the output width and height, then upsampled "
         "bilinearly (depth-aware with a depth file) and composited at full size; the low tier "
         "uses 0.5 (the PS4 half-resolution cap)."},
        {"seed", &Scene::seed, "-", 0, 2147483647,
         "Seed of the noise textures, the procedural weather map and the per-pixel jitter."},
        {"camera.position", &Scene::cameraPosition, "m", -1e7, 1e7,
         "Camera position [x, altitude, z]; x points east, z north, y up from the ground."},
        {"camera.heading_deg", &Scene::cameraHeadingDeg, "deg", -360, 360,
         "View azimuth, clockwise from north (+z) toward east (+x)."},
        {"camera.pitch_deg", &Scene::cameraPitchDeg, "deg", -89.9, 89.9,
         "View elevation above the horizontal."},
        {"camera.fov_deg", &Scene::cameraFovDeg, "deg", 1, 170, "Vertical field of view."},
        {"sun.elevation_deg", &Scene::sunElevationDeg, "deg", -90, 90,
         "Sun elevation above the horizon (negative: below it, night). Ignored when "
         "sun.from_time is true."},
        {"sun.heading_deg", &Scene::sunHeadingDeg, "deg", -360, 360,
         "Sun azimuth, clockwise from north. Ignored when sun.from_time is true."},
        {"sun.irradiance", &Scene::sunIrradiance, "linear RGB", 0, 1e6,
         "Sun irradiance on a surface facing it (colour times intensity)."},
        {"sun.angular_diameter_deg", &Scene::sunAngularDiameterDeg, "deg", 0.05, 10,
         "Apparent diameter of the sun disc."},
        // The sun from a place and a time (include/cloudscape/solar_position.h).
        {"sun.from_time", &Scene::sunFromTime, "bool", 0, 0,
         "Place the sun from sun.latitude_deg, sun.day_of_year and sun.local_solar_time_h "
         "(Spencer's declination and the hour angle) instead of sun.elevation_deg and "
         "sun.heading_deg, whatever order the keys are set in."},
        {"sun.latitude_deg", &Scene::sunLatitudeDeg, "deg", -90, 90,
         "Latitude of the scene, north positive (with sun.from_time)."},
        {"sun.day_of_year", &Scene::sunDayOfYear, "day", 1, 366,
         "Day of the year, 1 = 1 January, fractions allowed (with sun.from_time): sets the "
         "sun's declination."},
        {"sun.local_solar_time_h", &Scene::sunLocalSolarTimeH, "h", 0, 24,
         "Local solar time (with sun.from_time): 12 is solar noon, the sun at its highest; "
         "clock time differs by the equation of time and the longitude."},
        // The moon and the night sky (sky.glsl.h).
        {"moon.enabled", &Scene::moonEnabled, "bool", 0, 0,
         "Draw the moon and let it light the sky, the air and the clouds (atmosphere sky "
         "only): a second source read through the same tables as the sun. The clouds take "
         "their direct light from whichever of the two lights them more."},
        {"moon.elevation_deg", &Scene::moonElevationDeg, "deg", -90, 90,
         "Moon elevation above the horizon."},
        {"moon.heading_deg", &Scene::moonHeadingDeg, "deg", -360, 360,
         "Moon azimuth, clockwise from north."},
        {"moon.phase", &Scene::moonPhase, "-", 0, 1,
         "Illuminated fraction of the moon's disc: 0 new, 0.5 quarter, 1 full. Sets the phase "
         "angle (k = (1 + cos a) / 2), the lit part of the disc (its bright limb toward the "
         "sun) and the brightness (Allen's law, 10^(-0.4 (0.026 a + 4e-9 a^4)), a in degrees)."},
        {"moon.albedo", &Scene::moonAlbedo, "-", 0, 1,
         "Geometric albedo: the full moon's irradiance is sun.irradiance x albedo x (moon "
         "radius / distance)^2, 2.4e-6 of the sun's at the Moon's 0.12."},
        {"moon.angular_diameter_deg", &Scene::moonAngularDiameterDeg, "deg", 0.05, 10,
         "Apparent diameter of the moon's disc (its irradiance grows with it, as a nearer "
         "moon's would)."},
        {"sky.night_radiance", &Scene::nightRadiance, "1/sr", 0, 1e-3,
         "The night sky's own radiance (airglow, starlight, zodiacal light) above the "
         "atmosphere, per unit sun.irradiance, so a moonless night is not black; 1.35e-9 is a "
         "dark site's 22 mag/arcsec^2 (V). 0: none."},
        {"sky.zenith", &Scene::skyZenith, "linear RGB", 0, 1e6,
         "Placeholder sky radiance straight up."},
        {"sky.horizon", &Scene::skyHorizon, "linear RGB", 0, 1e6,
         "Placeholder sky radiance at the horizon."},
        {"sky.ground", &Scene::ground, "linear RGB", 0, 1e6,
         "Radiance of the ground below the horizon (gradient sky), and of opaque scene geometry "
         "from render.depth_file."},
        {"sky.model", enumMember(&Scene::skyModel, {"atmosphere", "gradient"}), "-", 0, 0,
         "atmosphere: a physically based sky (Rayleigh, Mie, ozone; Hillaire 2020) that lights "
         "the clouds, with sun.irradiance above the atmosphere; gradient: the placeholder "
         "sky.zenith/horizon gradient and lighting.ambient_* colours, sun.irradiance at the "
         "clouds."},
        {"atmosphere.rayleigh_scattering", &Scene::rayleighScattering, "1/m", 0, 1e-3,
         "Rayleigh scattering coefficient at sea level (per RGB channel)."},
        {"atmosphere.rayleigh_scale_height_m", &Scene::rayleighScaleHeightM, "m", 100, 1e5,
         "Altitude over which Rayleigh density falls by e."},
        {"atmosphere.mie_scattering", &Scene::mieScattering, "1/m", 0, 1e-3,
         "Mie (aerosol) scattering coefficient at sea level."},
        {"atmosphere.mie_extinction", &Scene::mieExtinction, "1/m", 0, 1e-3,
         "Mie extinction coefficient at sea level (scattering plus absorption; at least "
         "atmosphere.mie_scattering)."},
        {"atmosphere.mie_scale_height_m", &Scene::mieScaleHeightM, "m", 10, 1e5,
         "Altitude over which aerosol density falls by e."},
        {"atmosphere.mie_g", &Scene::mieG, "-", -0.99, 0.99,
         "Asymmetry of the aerosols' Cornette-Shanks phase function."},
        {"atmosphere.ozone_absorption", &Scene::ozoneAbsorption, "1/m", 0, 1e-3,
         "Ozone absorption coefficient at the peak of its layer (per RGB channel)."},
        {"atmosphere.ozone_centre_m", &Scene::ozoneCentreM, "m", 0, 1e6,
         "Altitude of the ozone layer's peak (a tent profile)."},
        {"atmosphere.ozone_half_width_m", &Scene::ozoneHalfWidthM, "m", 1, 1e6,
         "Half width of the ozone tent."},
        {"atmosphere.top_m", &Scene::atmosphereTopM, "m", 1000, 1e6,
         "Altitude of the top of the atmosphere."},
        {"atmosphere.ground_albedo", &Scene::atmosphereGroundAlbedo, "-", 0, 1,
         "Lambertian albedo of the planet's surface (the lit ground below the horizon and the "
         "light it bounces up)."},
        {"atmosphere.aerial_perspective", &Scene::aerialPerspective, "bool", 0, 0,
         "The air between the camera and the clouds scatters and absorbs (distant clouds take "
         "the sky's colour)."},
        {"sun.limb_darkening", &Scene::sunLimbDarkening, "-", 0, 1,
         "Limb darkening u of the sun disc, I = 1 - u (1 - mu), with the atmosphere."},
        {"planet.radius_m", &Scene::planetRadiusM, "m", 1000, 1e8,
         "Planet radius; the cloud layer is a spherical shell around it."},
        {"clouds.bottom_m", &Scene::cloudBottomM, "m", 0, 100000,
         "Altitude of the bottom of the cloud layer."},
        {"clouds.top_m", &Scene::cloudTopM, "m", 10, 100000,
         "Altitude of the top of the cloud layer (cumulonimbus reach it)."},
        {"clouds.extinction_per_m", &Scene::extinctionPerM, "1/m", 0, 10,
         "Extinction coefficient at density 1 (model densities are in [0, 1])."},
        {"clouds.albedo", &Scene::albedo, "-", 0, 1, "Single-scattering albedo of cloud droplets."},
        {"clouds.erosion", &Scene::erosion, "-", 0, 1,
         "How deeply the detail noise erodes the base shape's edges."},
        {"clouds.base_noise_period_m", &Scene::baseNoisePeriodM, "m", 100, 1e7,
         "World size over which the 128^3 base noise repeats."},
        {"clouds.detail_noise_period_m", &Scene::detailNoisePeriodM, "m", 10, 1e6,
         "World size over which the 32^3 detail noise repeats."},
        {"clouds.curl_period_m", &Scene::curlPeriodM, "m", 10, 1e7,
         "World size over which the curl noise repeats."},
        {"clouds.curl_strength_m", &Scene::curlStrengthM, "m", 0, 10000,
         "Largest displacement of the detail lookup by curl noise (at the cloud base)."},
        {"time_s", &Scene::timeS, "s", 0, 1e8, "Animation time."},
        {"wind.heading_deg", &Scene::windHeadingDeg, "deg", -360, 360,
         "Direction the wind blows toward, clockwise from north."},
        {"wind.speed_mps", &Scene::windSpeedMps, "m/s", 0, 500, "Speed of the base noise drift."},
        {"wind.shear_m", &Scene::windShearM, "m", -100000, 100000,
         "Downwind offset of cloud tops relative to their bases."},
        {"wind.detail_speed_ratio", &Scene::detailSpeedRatio, "-", 0, 100,
         "Speed of the detail noise relative to the base noise."},
        {"wind.updraft", &Scene::updraft, "-", 0, 10,
         "Upward drift as a fraction of the wind speed (clouds seem to grow)."},
        {"weather.image", &Scene::weatherImage, "path", 0, 0,
         "Painted weather map (RGB/RGBA PNG: coverage, precipitation, type); empty means the "
         "procedural generator. Relative to the scene file."},
        {"weather.extent_m", &Scene::weatherExtentM, "m", 1000, 1e7,
         "World size covered by the weather map before it wraps."},
        {"weather.offset_x_m", &Scene::weatherOffsetXM, "m", -1e7, 1e7,
         "World x of the weather map's centre: slides the map (and its storms) under the camera."},
        {"weather.offset_z_m", &Scene::weatherOffsetZM, "m", -1e7, 1e7,
         "World z of the weather map's centre."},
        {"weather.resolution", &Scene::weatherResolution, "texels", 16, 8192,
         "Size of the procedural weather map."},
        {"weather.coverage", &Scene::coverage, "-", 0, 1,
         "Mean cloud coverage of the weather map, procedural or painted: a uniform that shifts "
         "the map's coverage field until its mean is this (changing it regenerates nothing)."},
        {"weather.feature_scale_m", &Scene::featureScaleM, "m", 100, 1e7,
         "Typical size of coverage features in the procedural map."},
        {"weather.type", &Scene::cloudType, "-", 0, 1,
         "Mean cloud type: 0 stratus, 1/3 stratocumulus, 2/3 cumulus, 1 cumulonimbus."},
        {"weather.type_variation", &Scene::typeVariation, "-", 0, 1,
         "Amplitude of the type's variation across the map."},
        {"weather.rain_cells", &Scene::rainCells, "-", 0, 1000,
         "Number of precipitation cells (rain forces cumulonimbus, coverage >= 0.7)."},
        {"weather.rain_cell_radius_m", &Scene::rainCellRadiusM, "m", 10, 1e6,
         "Radius of a precipitation cell."},
        {"weather.field_image", &Scene::fieldImage, "path", 0, 0,
         "Painted data field (RGBA PNG: R bottom type, G anvil coverage, B minimum and A maximum "
         "cloud height as fractions of the layer's depth), averaged onto 64x64 regions over the "
         "weather map's extent; empty means the generated field. Relative to the scene file."},
        {"weather.bottom_type", &Scene::bottomType, "-", 0, 1,
         "Mean bottom type of the generated data field: 0 each type's own bottom gradient, 1 "
         "relaxed into ragged, wispy undersides (as under a storm); varies across regions."},
        {"weather.base_variation", &Scene::baseVariation, "-", 0, 0.5,
         "Most the generated data field raises the clouds' base across regions, as a fraction "
         "of the layer's depth (0: every base on clouds.bottom_m)."},
        {"weather.top_variation", &Scene::topVariation, "-", 0, 0.9,
         "Most the generated data field lowers the clouds' ceiling across regions, as a "
         "fraction of the layer's depth (0: the type alone sets the top)."},
        {"high_clouds.coverage", &Scene::highCloudCoverage, "-", 0, 1,
         "Coverage of the high-altitude layer (cirrus and its kin, GPU Pro 7 4.5.4): its texture "
         "eroded by the inverse of this; 0 draws no layer at all."},
        {"high_clouds.type", &Scene::highCloudType, "-", 0, 2,
         "Formation of the high layer: 0 cirrostratus (a veil), 1 cirrus (fibres), 2 "
         "cirrocumulus (small puffs); fractions blend neighbours."},
        {"high_clouds.altitude_m", &Scene::highCloudAltitudeM, "m", 1000, 30000,
         "Altitude of the high layer (above clouds.top_m when its coverage is above 0); the "
         "camera sees it from below."},
        {"high_clouds.optical_depth", &Scene::highCloudOpticalDepth, "-", 0, 10,
         "Vertical optical depth of the high layer where it is densest (cirrus: about 0.03-3)."},
        {"high_clouds.period_m", &Scene::highCloudPeriodM, "m", 1000, 1e7,
         "World size over which the high layer's 512^2 texture repeats."},
        {"high_clouds.wind_heading_deg", &Scene::highCloudWindHeadingDeg, "deg", -360, 360,
         "Direction the high layer drifts toward, clockwise from north (its own wind)."},
        {"high_clouds.wind_speed_mps", &Scene::highCloudWindSpeedMps, "m/s", 0, 500,
         "Speed of the high layer's drift (winds near the tropopause are fast)."},
        {"high_clouds.phase_g", &Scene::highCloudPhaseG, "-", -0.99, 0.99,
         "Henyey-Greenstein asymmetry of the high layer's ice crystals (strongly forward)."},
        {"weather.drift_ratio", &Scene::weatherDriftRatio, "-", 0, 10,
         "The weather map (coverage, rain, type) drifts downwind at this fraction of "
         "wind.speed_mps over time_s, so rain and clouds approach along the wind (GPU Pro 7 "
         "4.3.5); 0 keeps it still. The storm stays where it is."},
        {"storm.blend", &Scene::stormBlend, "-", 0, 1,
         "Superstorm blend factor (Forbidden West): 0 no storm (nothing is evaluated), 1 the full "
         "storm. One storm; it wraps with the weather map."},
        {"storm.x_m", &Scene::stormXM, "m", -1e7, 1e7, "World x of the storm's centre."},
        {"storm.z_m", &Scene::stormZM, "m", -1e7, 1e7, "World z of the storm's centre."},
        {"storm.radius_m", &Scene::stormRadiusM, "m", 100, 1e6,
         "Radius of the storm stencil: outside it nothing changes. At most half of "
         "weather.extent_m while the storm is on."},
        {"storm.coverage", &Scene::stormCoverage, "-", 0, 1,
         "Coverage at the centre of the mesocyclone's foot (and of the anvil)."},
        {"storm.rotation_deg_per_s", &Scene::stormRotationDegPerS, "deg/s", -360, 360,
         "Angular speed of the innermost of the 6 vortex rings; ring n turns at this / (n + 1) "
         "(counter-clockwise seen from above for positive values)."},
        {"storm.ring_twist_deg", &Scene::stormRingTwistDeg, "deg", -3600, 3600,
         "Spiral twist of the vortex's detail noise from the centre to the radius (ring skew)."},
        {"storm.light_density_scale", &Scene::stormLightDensityScale, "-", 1, 100,
         "Scale on light-march densities over the storm's foot (darker, thicker storm)."},
        {"storm.ambient_scale", &Scene::stormAmbientScale, "-", 0, 100,
         "The storm's ambient setting: multiplier on the ambient light low under the storm (the "
         "talk's art direction; 1, no change, is what the path tracer measures under the storm "
         "and from afar, docs/QUALITY.md section 8: 2 made the underside 1.6x too bright)."},
        {"storm.glow_colour", &Scene::stormGlowColour, "linear RGB", 0, 1e6,
         "Colour of the storm's internal glow (the game's red)."},
        {"storm.glow_strength", &Scene::stormGlowStrength, "radiance", 0, 1e6,
         "Radiance of the internal glow at its centre (0: none)."},
        {"storm.glow_radius_m", &Scene::stormGlowRadiusM, "m", 1, 1e6,
         "Radius of the glow's sphere of potential energy."},
        {"storm.glow_altitude_m", &Scene::stormGlowAltitudeM, "m", 0, 100000,
         "Altitude of the glow's centre, above the storm centre."},
        {"storm.motion_vectors", &Scene::stormMotionVectors, "bool", 0, 0,
         "The temporal reprojection follows the vortex rings (the talk's motion vectors); "
         "false reprojects with the wind scroll only, for comparison."},
        {"storm.ring_jitter", &Scene::stormRingJitter, "bool", 0, 0,
         "The vortex's ring overlaps as on PS4: one ring's noise is read, picked at random per "
         "sample with the overlap's blend as the outer ring's chance (the temporal "
         "reconstruction averages the picks), instead of both rings read and blended. The low "
         "tier sets it."},
        {"storm.cirrus", &Scene::stormCirrus, "-", 0, 1,
         "Coverage of the cirrus the storm's anvil sheds downwind, a patch of streaks along the "
         "wind in the high layer (at high_clouds.altitude_m, which must then lie above "
         "clouds.top_m), up to 2 storm radii downwind of the centre; it fades with the storm's "
         "blend. 0: none."},
        {"storm.cycle", &Scene::stormCycle, "bool", 0, 0,
         "The weather controller drives the storm from time_s: each cycle it picks one of "
         "storm.cycle_sites locations (from the seed), builds the storm there, holds it, "
         "dissipates it and stays calm; storm.blend is then the peak blend and storm.x_m/z_m "
         "are unused."},
        {"storm.cycle_sites", &Scene::stormCycleSites, "-", 1, 64,
         "Locations the controller picks from, placed in the weather map from the seed."},
        {"storm.cycle_build_s", &Scene::stormCycleBuildS, "s", 1, 1e6,
         "Build-up time: the blend rises from 0 to storm.blend."},
        {"storm.cycle_hold_s", &Scene::stormCycleHoldS, "s", 0, 1e6,
         "Time the storm holds at full blend."},
        {"storm.cycle_dissipate_s", &Scene::stormCycleDissipateS, "s", 1, 1e6,
         "Dissipation time: the blend falls back to 0."},
        {"storm.cycle_calm_s", &Scene::stormCycleCalmS, "s", 0, 1e6,
         "Calm time between one storm's end and the next one's build-up."},
        {"storm.lightning", &Scene::stormLightning, "bool", 0, 0,
         "Lightning while the storm holds (the controller's hold phase, or a constant storm): "
         "episodes of intra-cloud flashes of growing intensity, then 1 or 2 ground discharges "
         "with a bolt; all timings and positions from the seed."},
        {"storm.lightning_colour", &Scene::stormLightningColour, "linear RGB", 0, 1e6,
         "Colour of the flashes (the bolt's core is whiter)."},
        {"storm.lightning_strength", &Scene::stormLightningStrength, "radiance", 0, 1e6,
         "Emitted radiance of a flash at its peak, at the flash's centre (the sun's "
         "irradiance is about 9): 8 lights a daylit storm's foot without washing out its "
         "structure; at night, against moonlit cloud, far less is needed."},
        {"storm.lightning_radius_m", &Scene::stormLightningRadiusM, "m", 10, 1e5,
         "Radius of a flash's glow (its potential falls as (1 - d / radius)^12)."},
        {"storm.lightning_interval_s", &Scene::stormLightningIntervalS, "s", 1, 3600,
         "Time between flashes (each starts up to half of it late, from the seed); at least 1 s "
         "so a flash's mask is built over the frames before it."},
        {"storm.lightning_intra_flashes", &Scene::stormLightningIntraFlashes, "-", 1, 32,
         "Intra-cloud flashes in an episode, before its ground discharges."},
        {"storm.lightning_external", &Scene::stormLightningExternal, "-", 0, 1000,
         "Weight of a ground discharge's external flash (highlights on the storm's underside)."},
        {"storm.lightning_flash_mask", &Scene::stormLightningFlashMask, "bool", 0, 0,
         "Flash masks: the march writes the flash at unit intensity to its own channel, which "
         "the temporal reconstruction builds up before the flash and the resolve scales by the "
         "frame's intensity (false: the flash is marched into the radiance, for comparison). "
         "Off at render.cloud_resolution below 1."},
        {"storm.bolt_width_m", &Scene::stormBoltWidthM, "m", 0.1, 1000,
         "Width of a ground discharge's bright core."},
        {"lighting.phase_g", &Scene::phaseG, "-", -0.99, 0.99,
         "Eccentricity of the main Henyey-Greenstein lobe (GPU Pro 7 uses 0.2)."},
        {"lighting.silver_g", &Scene::silverG, "-", -0.99, 0.99,
         "Eccentricity of the forward silver-lining lobe."},
        {"lighting.silver_weight", &Scene::silverWeight, "-", 0, 1,
         "Weight of the silver-lining lobe in the two-lobe phase."},
        {"lighting.powder", &Scene::powder, "-", 0, 1,
         "Strength of the powder (dark edge) term; 0 is plain Beer's law."},
        {"lighting.scattering_octaves", &Scene::scatteringOctaves, "-", 1, 8,
         "Light octaves: 1 is the seeds' single scattering; more add Wrenninge's multiple-"
         "scattering approximation."},
        {"lighting.octave_factors", &Scene::octaveFactors, "-", 0, 1,
         "Per-octave factors [a, b, c] on energy, optical depth and eccentricity. The "
         "default [0.6, 0.3, 0.5] with 4 octaves is fitted to the path tracer "
         "(docs/QUALITY.md); Wrenninge's [0.5, 0.5, 0.5] is darker in thick cloud."},
        {"lighting.rain_absorption", &Scene::rainAbsorption, "-", 0, 100,
         "Extra light absorption at full precipitation (dark rain bases)."},
        {"lighting.light_samples", &Scene::lightSamples, "-", 1, 64,
         "Density samples in the cone toward the sun."},
        {"lighting.cone_length_m", &Scene::coneLengthM, "m", 10, 100000,
         "Length of the light-sample cone."},
        {"lighting.long_sample", &Scene::longSample, "bool", 0, 0,
         "Take one long-distance light sample for shadows of distant clouds."},
        {"lighting.long_sample_distance", &Scene::longSampleDistance, "cone lengths", 1, 100,
         "Distance of the long-distance sample."},
        {"lighting.cone_spread", &Scene::coneSpread, "-", 0, 10,
         "Sideways spread of the cone per sample, relative to the light step."},
        {"lighting.light_mip_bias", &Scene::lightMipBias, "mip levels", 0, 6,
         "Coarser noise mip for light samples."},
        {"lighting.ambient_top", &Scene::ambientTop, "linear RGB", 0, 1e6,
         "Ambient sky radiance reaching cloud tops."},
        {"lighting.ambient_bottom", &Scene::ambientBottom, "linear RGB", 0, 1e6,
         "Ambient radiance reaching cloud bases (ground bounce)."},
        {"lighting.ambient_strength", &Scene::ambientStrength, "-", 0, 100,
         "Multiplier on the ambient term."},
        {"lighting.phase", enumMember(&Scene::phaseFunction, {"two-lobe", "hg-draine"}), "-", 0, 0,
         "Phase function of the droplets: \"two-lobe\" (art-directable HG pair, the "
         "lighting.phase_g/silver_* keys) or \"hg-draine\" (Jendersie and d'Eon 2023 fit to "
         "Mie scattering for lighting.droplet_diameter_um). Used by the path tracer too."},
        {"lighting.droplet_diameter_um", &Scene::dropletDiameterUm, "um", 5, 50,
         "Droplet diameter of the HG+Draine phase function (cumulus: about 10-20)."},
        {"lighting.energy_conserving_steps", &Scene::energyConservingSteps, "bool", 0, 0,
         "Integrate each march step's light exactly (Hillaire 2015); false is the seeds' sum "
         "of source * extinction * step, which overshoots in thick steps."},
        {"terrain.enabled", &Scene::terrainEnabled, "bool", 0, 0,
         "A height field under the clouds (docs/ARCHITECTURE.md, terrain): ray-marched per "
         "pixel, it ends the cloud march and is lit by the sun through the air and the clouds' "
         "shadow, and by the sky. The camera must be above it."},
        {"terrain.file", &Scene::terrainFile, "path", 0, 0,
         "Height map: a 16-bit greyscale PNG (mapped from terrain.height_min_m to "
         "terrain.height_m) or a float EXR (Y, R or its only channel, metres), 2 to 8192 texels "
         "a side, top row north; empty generates ridged fractal mountains. Relative to the "
         "scene file."},
        {"terrain.extent_m", &Scene::terrainExtentM, "m", 1000, 1e6,
         "World size the height field covers along x (z in proportion to the map's rows); "
         "beyond it the ground is the flat planet."},
        {"terrain.offset_x_m", &Scene::terrainOffsetXM, "m", -1e7, 1e7,
         "World x of the height field's centre."},
        {"terrain.offset_z_m", &Scene::terrainOffsetZM, "m", -1e7, 1e7,
         "World z of the height field's centre."},
        {"terrain.height_m", &Scene::terrainHeightM, "m", 1, 20000,
         "Generated: the highest peak. PNG: the height of the value 65535."},
        {"terrain.height_min_m", &Scene::terrainHeightMinM, "m", 0, 20000,
         "PNG: the height of the value 0."},
        {"terrain.feature_size_m", &Scene::terrainFeatureSizeM, "m", 100, 1e6,
         "Generated: the wavelength of the largest ridges."},
        {"terrain.resolution", &Scene::terrainResolution, "texels", 64, 4096,
         "Generated: texels a side of the height field."},
        {"terrain.albedo", &Scene::terrainAlbedo, "-", 0, 1,
         "Lambertian albedo of gentle slopes (RGB)."},
        {"terrain.rock_albedo", &Scene::terrainRockAlbedo, "-", 0, 1,
         "Albedo of slopes steeper than about 35 degrees (RGB)."},
        {"terrain.snow_line_m", &Scene::terrainSnowLineM, "m", 0, 100000,
         "Gentle slopes above this altitude are snow (albedo 0.8)."},
        {"terrain.field_variation", &Scene::terrainFieldVariation, "-", 0, 1,
         "Fields: gentle slopes' albedo varies from field to field by up to this fraction, in "
         "brightness and in red (greener meadows, yellower crops), keeping its mean; it fades "
         "where a pixel spans several fields. 0 is one albedo everywhere."},
        {"terrain.field_size_m", &Scene::terrainFieldSizeM, "m", 10, 100000,
         "Side of a field (terrain.field_variation): a grid turned off the axes, its rows "
         "shifted at random."},
        {"terrain.max_steps", &Scene::terrainMaxSteps, "-", 8, 4096,
         "Cap on the steps of a ray's terrain march (sphere tracing with the field's steepest "
         "slope); a ray that runs out of steps misses the terrain."},
        {"cloud_shadow.enabled", &Scene::cloudShadowEnabled, "bool", 0, 0,
         "A shadow map of the clouds made each frame from their density (docs/ARCHITECTURE.md, "
         "cloud shadows): the ground and the terrain read it instead of two cheap density "
         "samples per pixel, and the light shafts read it. Made while the sun is above about "
         "1 degree."},
        {"cloud_shadow.resolution", &Scene::cloudShadowResolution, "texels", 16, 2048,
         "Texels a side of the shadow map."},
        {"cloud_shadow.extent_m", &Scene::cloudShadowExtentM, "m", 1000, 500000,
         "Side of the shadow map, on the ground plane around the camera (sun rays projected "
         "onto it); beyond it the ground falls back to the two-sample shadow and the air is lit."},
        {"cloud_shadow.steps", &Scene::cloudShadowSteps, "-", 1, 512,
         "Density samples along each shadow-map texel's sun ray through the cloud layer."},
        {"cloud_shadow.on_clouds", &Scene::cloudShadowOnClouds, "bool", 0, 0,
         "The clouds' own light reads the map beyond its cone (lighting.cone_length_m), in place "
         "of the long sample: the whole way to the sun, so a storm's far side and a cumulus in "
         "a bigger one's shadow are dark. Where the map does not reach, the long sample."},
        {"shafts.enabled", &Scene::shaftsEnabled, "bool", 0, 0,
         "Light shafts: the air in the clouds' shadow scatters no sunlight (needs "
         "cloud_shadow.enabled, and sky.model atmosphere with its aerial perspective; "
         "docs/ARCHITECTURE.md, light shafts)."},
        {"shafts.steps", &Scene::shaftsSteps, "-", 1, 1024,
         "Steps along each view ray at which the shadow map is read."},
        {"shafts.max_distance_m", &Scene::shaftsMaxDistanceM, "m", 100, 1e6,
         "How far along a view ray the shafts reach (no farther than the cloud layer's top)."},
        {"shafts.grid_factor", &Scene::shaftsGridFactor, "-", 1, 8,
         "Temporal frames: one shaft ray per N x N pixels, upsampled depth-aware (1: every "
         "pixel's own; stills always trace every pixel's). 4 costs 1/16 of the shafts."},
        {"pathtrace.ground_albedo", &Scene::groundAlbedo, "-", 0, 1,
         "Path tracer: Lambertian albedo of the ground; 0 makes the ground a black absorber "
         "that shows the sky.ground radiance, as the real-time renderer does. Unused where "
         "terrain.enabled: the path tracer's ground is then the terrain, at its albedos."},
        {"pathtrace.max_bounces", &Scene::pathMaxBounces, "-", 1, 100000,
         "Path tracer: a safety cap on scattering events per path; Russian roulette ends "
         "paths long before it in any realistic cloud (its bias is reported if reached)."},
        {"pathtrace.atmosphere", &Scene::pathAtmosphere, "bool", 0, 0,
         "Path tracer: trace the air as a medium too (Rayleigh, Mie and ozone of the atmosphere.* "
         "keys, each RGB channel a wavelength, about 3x the time) instead of lighting the clouds "
         "through the sky's tables; needs sky.model atmosphere."},
        {"march.zenith_steps", &Scene::zenithSteps, "-", 1, 4096,
         "View-ray steps for a ray pointing straight up or down."},
        {"march.horizon_steps", &Scene::horizonSteps, "-", 1, 4096,
         "View-ray steps for a ray along the horizon."},
        {"march.near_step_m", &Scene::nearStepM, "m", 0, 10000,
         "Flying in or near the clouds: the first 24 steps of a view ray's path through the "
         "cloud layer are no longer than this (where the layer's own step count would make them "
         "longer), so the cloud around the camera is sampled finely. 0 turns it off."},
        {"march.min_transmittance", &Scene::minTransmittance, "-", 0, 1,
         "The march stops when the transmittance falls below this, and the cloud is then "
         "opaque there (transmittance 0: the sun's disc does not shine through)."},
        {"march.coarse_step_factor", &Scene::coarseStepFactor, "fine steps", 1, 6,
         "Coarse/fine sampling: empty space is crossed this many fine steps at a time with "
         "cheap samples; 1 turns it off."},
        {"march.cheap_light_alpha", &Scene::cheapLightAlpha, "-", 0, 1,
         "Light samples become cheap (base shape only) once the view ray's opacity passes this; "
         "1 turns it off."},
        {"march.step_optimisation", &Scene::stepOptimisation, "-", 0, 8,
         "Todd's step optimisation: in empty space each coarse step grows by this gain times "
         "how far the base shape lies below the coverage threshold (0-1); steps that land in "
         "cloud step back. 0 turns it off."},
        {"march.empty_space_skipping", &Scene::emptySpaceSkipping, "bool", 0, 0,
         "Skip, without reading a texture, the stretches of a view ray that the weather map "
         "proves empty (a 32x32 grid of column tops over the map, the path tracer's bound); "
         "with march.coarse_step_factor 1 the image is exactly the unskipped march's."},
        {"march.noise_skipping", &Scene::noiseSkipping, "bool", 0, 0,
         "With march.empty_space_skipping, also pass over the samples where the base noise "
         "itself cannot make cloud at the column's coverage (a clearance field of the noise, "
         "made when a scene first asks for it); exact: the image is bit for bit the one "
         "without, with a quarter fewer samples in the default scene, but its lookups cost more "
         "than they save on lavapipe and the CPU backend. "
         "It skips outside the storm and without a data field, and no coarse steps under "
         "march.step_optimisation."},
        {"march.blue_noise", &Scene::blueNoise, "bool", 0, 0,
         "Offset each pixel's first step by a tileable 64x64 blue-noise map (void-and-cluster) "
         "plus a golden-ratio sequence per sample and frame, instead of a white-noise hash: the "
         "step noise becomes fine grain that averaging removes quickly."},
        {"march.distance_lod", &Scene::distanceLod, "bool", 0, 0,
         "Read coarser noise mips where a pixel covers more than a texel (distant clouds), "
         "instead of aliasing the detail into speckle."},
        {"march.max_distance_m", &Scene::maxDistanceM, "m", 100, 1e7,
         "Clouds beyond this distance are not marched."},
        {"march.horizon_fade", &Scene::horizonFade, "-", 0, 1,
         "Clouds fade out from this fraction of the maximum distance to it."},
    };
    return keys;
}

// Quality tiers after the Forbidden West PS4/PS5 table, as overlays of keys: applied through the
// key table (applyOverride), so a tier is validated and documented like any key.
struct Tier {
    const char* name;
    const char* description;
    std::vector<std::pair<const char*, const char*>> keys; // key, JSON value
};

const std::vector<Tier>& tiers() {
    static const std::vector<Tier> list = {
        {"low",
         "PS4: clouds marched at half resolution (a quarter of the pixels, upsampled; while the "
         "camera moves, the background behind them too), step optimisation, fewer steps, cheap "
         "light samples once the view is opaque, longer temporal accumulation.",
         {{"render.cloud_resolution", "0.5"},
          {"march.step_optimisation", "1"},
          {"lighting.light_samples", "6"},
          {"march.zenith_steps", "60"},
          {"march.horizon_steps", "90"},
          {"lighting.light_mip_bias", "1"},
          {"march.coarse_step_factor", "2"},
          {"march.cheap_light_alpha", "0.3"},
          {"render.temporal_accumulation", "16"},
          {"render.temporal", "true"},
          {"render.moving_background_reduced", "true"},
          {"storm.ring_jitter", "true"}}},
        {"high",
         "PS5: full resolution, 10 light samples at noise mip 0, 96-180 view steps; in "
         "sequences a quarter of the pixels marched a frame (still or moving), four rays a "
         "pixel for the background, and a moving camera's pixels gathered from the last 24 "
         "frames' marches.",
         {{"render.cloud_resolution", "1"},
          {"march.step_optimisation", "0"},
          {"lighting.light_samples", "10"},
          {"march.zenith_steps", "96"},
          {"march.horizon_steps", "180"},
          {"lighting.light_mip_bias", "0"},
          {"march.coarse_step_factor", "2"},
          {"march.cheap_light_alpha", "1"},
          {"render.temporal_accumulation", "8"},
          {"render.temporal", "true"},
          {"render.moving_block_2x2", "true"},
          {"render.still_block_2x2", "true"},
          {"render.background_samples", "4"},
          {"render.moving_gather_frames", "24"},
          {"storm.ring_jitter", "false"}}},
        {"reference",
         "Ground truth for the real-time path: every pixel every frame, every step a full "
         "sample, 256-512 steps, 4 samples per pixel.",
         {{"render.cloud_resolution", "1"},
          {"march.step_optimisation", "0"},
          {"lighting.light_samples", "10"},
          {"march.zenith_steps", "256"},
          {"march.horizon_steps", "512"},
          {"lighting.light_mip_bias", "0"},
          {"march.coarse_step_factor", "1"},
          {"march.cheap_light_alpha", "1"},
          {"render.samples_per_pixel", "4"},
          {"render.temporal", "false"},
          {"storm.ring_jitter", "false"}}},
    };
    return list;
}

const SceneKey* findKey(const std::string& key) {
    for (const SceneKey& k : sceneKeys())
        if (key == k.key)
            return &k;
    return nullptr;
}

std::string formatNumber(double v) {
    std::ostringstream s;
    s << std::setprecision(7) << v;
    return s.str();
}

// A user's text quoted in a message, cut so one hostile value cannot make the line unreadable.
std::string shortened(const std::string& text) {
    constexpr size_t kMax = 60;
    return text.size() <= kMax ? text : text.substr(0, kMax) + "...";
}

std::string rangeText(const SceneKey& k) {
    std::ostringstream text;
    if (k.member.index() == 0) // integers in full: a seed's maximum is 2147483647, not 2.1e9
        text << "[" << static_cast<long long>(k.min) << ", " << static_cast<long long>(k.max)
             << "]";
    else
        text << "[" << formatNumber(k.min) << ", " << formatNumber(k.max) << "]";
    return text.str();
}

// "a", "b" or "c"
std::string choicesText(const EnumMember& e) {
    std::string out;
    for (size_t i = 0; i < e.names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == e.names.size() ? " or " : ", ") + ("\"" + e.names[i] + "\"");
    return out;
}

std::string typeName(const Member& m) {
    switch (m.index()) {
    case 0:
        return "integer";
    case 1:
        return "number";
    case 2:
        return "boolean";
    case 3:
        return "string";
    case 4:
        return "array of 3 numbers";
    default:
        return "string: " + choicesText(std::get<5>(m));
    }
}

std::string jsonTypeName(const nlohmann::json& v) {
    if (v.is_array())
        return "an array of " + std::to_string(v.size());
    if (v.is_boolean())
        return "a boolean";
    if (v.is_number())
        return "a number";
    if (v.is_string())
        return "a string";
    if (v.is_object())
        return "an object";
    return "null";
}

double checkedNumber(const nlohmann::json& v, const SceneKey& k, const std::string& where) {
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < k.min || x > k.max)
        throw Error(where + ": " + k.key + " = " + formatNumber(x) + " is out of range " +
                    rangeText(k));
    return x;
}

// Set one key from a JSON value, checking type and range. `where` prefixes messages.
void assignKey(Scene& scene, const SceneKey& k, const nlohmann::json& v, const std::string& where) {
    auto wrongType = [&]() {
        return Error(where + ": " + k.key + " expects " + typeName(k.member) + ", got " +
                     jsonTypeName(v));
    };
    switch (k.member.index()) {
    case 0: {
        if (!v.is_number())
            throw wrongType();
        const double x = v.get<double>();
        if (x != std::floor(x))
            throw Error(where + ": " + k.key + " expects an integer, got " + formatNumber(x));
        scene.*std::get<0>(k.member) = static_cast<int>(checkedNumber(v, k, where));
        break;
    }
    case 1:
        if (!v.is_number())
            throw wrongType();
        scene.*std::get<1>(k.member) = static_cast<float>(checkedNumber(v, k, where));
        break;
    case 2:
        if (!v.is_boolean())
            throw wrongType();
        scene.*std::get<2>(k.member) = v.get<bool>();
        break;
    case 3:
        if (!v.is_string())
            throw wrongType();
        scene.*std::get<3>(k.member) = v.get<std::string>();
        break;
    case 5: {
        const EnumMember& e = std::get<5>(k.member);
        const std::string text = v.is_string() ? v.get<std::string>() : v.dump();
        for (size_t i = 0; i < e.names.size(); ++i)
            if (text == e.names[i]) {
                e.set(scene, static_cast<int>(i));
                return;
            }
        throw Error(where + ": " + k.key + " '" + text + "': expected " + choicesText(e));
    }
    default: {
        if (!v.is_array() || v.size() != 3)
            throw wrongType();
        glm::vec3 out;
        for (int i = 0; i < 3; ++i) {
            if (!v[i].is_number())
                throw wrongType();
            out[i] = static_cast<float>(checkedNumber(v[i], k, where));
        }
        scene.*std::get<4>(k.member) = out;
        break;
    }
    }
}

void applyJsonObject(Scene& scene, const nlohmann::json& object, const std::string& prefix,
                     const std::string& source) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
        if (it.value().is_object()) {
            applyJsonObject(scene, it.value(), key, source);
            continue;
        }
        const SceneKey* k = findKey(key);
        if (!k)
            throw Error(source + ": unknown key '" + shortened(key) + "' (see docs/SCENE.md)");
        assignKey(scene, *k, it.value(), source);
    }
}

// A scene is sections of keys whose values are numbers, strings or short arrays: nothing real
// nests deeper than a few levels, and a hostile file nested thousands deep must not reach the
// recursive parts of the JSON library (or the stack).
constexpr int kMaxSceneNesting = 16;

// Tracks the key path while nlohmann parses, to refuse duplicate keys (which the library would
// silently resolve, one of them winning) and runaway nesting, and to name the key a bad number
// belongs to.
class SceneJsonChecker {
public:
    explicit SceneJsonChecker(const std::string& source) : source_(source) {}

    bool operator()(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (depth > kMaxSceneNesting)
            throw Error(source_ + ": nested deeper than " + std::to_string(kMaxSceneNesting) +
                        " levels" +
                        (lastKey_.empty() ? "" : " under '" + shortened(lastKey_) + "'") +
                        "; a scene is sections of keys (see docs/SCENE.md)");
        if (event == Event::object_start) {
            objects_.push_back({lastKey_, {}});
        } else if (event == Event::object_end && !objects_.empty()) {
            objects_.pop_back();
        } else if (event == Event::key && !objects_.empty()) {
            Object& object = objects_.back();
            const std::string key = parsed.get<std::string>();
            lastKey_ = object.path.empty() ? key : object.path + "." + key;
            if (!object.keys.insert(key).second)
                throw Error(source_ + ": duplicate key '" + shortened(lastKey_) +
                            "' (each key may appear once)");
        }
        return true;
    }

    const std::string& lastKey() const { return lastKey_; }

private:
    struct Object {
        std::string path;
        std::set<std::string> keys;
    };
    std::string source_;
    std::vector<Object> objects_;
    std::string lastKey_;
};

// Parses scene JSON with the checks above; every failure names the source (and the key where
// one is known).
nlohmann::json parseSceneJson(const std::string& jsonText, const std::string& source) {
    SceneJsonChecker checker(source);
    try {
        return nlohmann::json::parse(jsonText, std::ref(checker));
    } catch (const nlohmann::json::parse_error& e) {
        std::string what = e.what();
        const auto pos = what.find("parse error");
        throw Error(source +
                    ": malformed JSON: " + (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const nlohmann::json::out_of_range&) {
        // The only out_of_range of parsing: a number beyond the range of a double (1e999).
        throw Error(source + ": a number too large for a double" +
                    (checker.lastKey().empty() ? "" : " at or after '" + checker.lastKey() + "'") +
                    "; expected a finite number");
    } catch (const nlohmann::json::exception& e) {
        throw Error(source + ": invalid JSON: " + e.what());
    }
}

std::string defaultText(const SceneKey& k) {
    const Scene d;
    switch (k.member.index()) {
    case 0:
        return std::to_string(d.*std::get<0>(k.member));
    case 1:
        return formatNumber(d.*std::get<1>(k.member));
    case 2:
        return d.*std::get<2>(k.member) ? "true" : "false";
    case 3: {
        const std::string s = d.*std::get<3>(k.member);
        return s.empty() ? "\"\"" : "\"" + s + "\"";
    }
    case 4: {
        const glm::vec3 v = d.*std::get<4>(k.member);
        return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
    }
    default: {
        const EnumMember& e = std::get<5>(k.member);
        return "\"" + e.names[static_cast<size_t>(e.get(d))] + "\"";
    }
    }
}

} // namespace

Scene parseScene(const std::string& jsonText, const std::string& source, const Scene& base) {
    const nlohmann::json root = parseSceneJson(jsonText, source);
    if (!root.is_object())
        throw Error(source + ": expected a JSON object at the top level, got " +
                    jsonTypeName(root));
    Scene scene = base;
    applyJsonObject(scene, root, "", source);
    validateScene(scene, source);
    return scene;
}

Scene loadScene(const std::string& path) {
    return loadScene(path, Scene{});
}

Scene loadScene(const std::string& path, const Scene& defaults) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(path + ": is a directory; expected a scene JSON file or a preset name");
    Scene scene = parseScene(io::readJsonInputFile(path, "scene file"), path, defaults);
    scene.baseDirectory = std::filesystem::path(path).parent_path().string();
    return scene;
}

void applyOverride(Scene& scene, const std::string& assignment, const std::string& where) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(where + " '" + shortened(assignment) + "': expected key=value");
    const std::string key = assignment.substr(0, eq);
    const std::string valueText = assignment.substr(eq + 1);
    const SceneKey* k = findKey(key);
    if (!k)
        throw Error(where + ": unknown key '" + shortened(key) + "' (see docs/SCENE.md)");
    SceneJsonChecker checker(where + ": " + key);
    nlohmann::json value;
    try {
        value = nlohmann::json::parse(valueText, std::ref(checker));
    } catch (const nlohmann::json::parse_error&) {
        value = valueText; // a bare word is a string
    } catch (const nlohmann::json::out_of_range&) {
        throw Error(where + ": " + key + " = " + shortened(valueText) +
                    " is too large for a double; expected a finite number");
    }
    assignKey(scene, *k, value, where);
}

void validateScene(const Scene& s, const std::string& source) {
    if (s.cloudTopM <= s.cloudBottomM + 10.0f)
        throw Error(source + ": clouds.top_m (" + formatNumber(s.cloudTopM) +
                    ") must be at least 10 m above clouds.bottom_m (" +
                    formatNumber(s.cloudBottomM) + ")");
    if (s.cameraPosition.y <= 0.0f)
        throw Error(source + ": camera.position altitude (y = " + formatNumber(s.cameraPosition.y) +
                    ") must be above the ground (> 0)");
    if (s.terrainEnabled && s.terrainFile.ends_with(".png") &&
        s.terrainHeightM <= s.terrainHeightMinM)
        throw Error(source + ": terrain.height_m (" + formatNumber(s.terrainHeightM) +
                    ") must be above terrain.height_min_m (" + formatNumber(s.terrainHeightMinM) +
                    ")");
    if (s.shaftsEnabled && !s.cloudShadowEnabled)
        throw Error(source + ": shafts.enabled needs cloud_shadow.enabled (the shafts read the "
                             "clouds' shadow map)");
    if (s.horizonSteps < 1 || s.zenithSteps < 1)
        throw Error(source + ": march steps must be at least 1");
    if (s.stormBlend > 0.0f && s.stormRadiusM > 0.5f * s.weatherExtentM)
        throw Error(source + ": storm.radius_m (" + formatNumber(s.stormRadiusM) +
                    ") must be at most half of weather.extent_m (" +
                    formatNumber(s.weatherExtentM) + "): the storm wraps with the weather map");
    if (s.stormBlend > 0.0f && !s.stormCycle &&
        (std::abs(s.stormXM - s.weatherOffsetXM) > 0.5f * s.weatherExtentM ||
         std::abs(s.stormZM - s.weatherOffsetZM) > 0.5f * s.weatherExtentM))
        throw Error(source + ": storm.x_m, storm.z_m (" + formatNumber(s.stormXM) + ", " +
                    formatNumber(s.stormZM) + ") must lie inside the weather map (" +
                    formatNumber(s.weatherExtentM) + " m square about weather.offset_x_m/z_m)");
    if (s.stormLightning && s.stormCycle && s.stormCycleHoldS < s.stormLightningIntervalS)
        throw Error(source + ": storm.cycle_hold_s (" + formatNumber(s.stormCycleHoldS) +
                    ") must be at least storm.lightning_interval_s (" +
                    formatNumber(s.stormLightningIntervalS) +
                    ") with storm.lightning on: the lightning fires while the storm holds");
    if (s.mieExtinction < s.mieScattering)
        throw Error(source + ": atmosphere.mie_extinction (" + formatNumber(s.mieExtinction) +
                    ") must be at least atmosphere.mie_scattering (" +
                    formatNumber(s.mieScattering) + "): extinction is scattering plus absorption");
    if (s.stormBlend > 0.0f && s.stormCirrus > 0.0f && s.highCloudAltitudeM <= s.cloudTopM)
        throw Error(source + ": high_clouds.altitude_m (" + formatNumber(s.highCloudAltitudeM) +
                    ") must be above clouds.top_m (" + formatNumber(s.cloudTopM) +
                    ") when storm.cirrus is above 0: the storm's cirrus is drawn in the high "
                    "layer, behind the clouds (or set storm.cirrus to 0)");
    if (s.highCloudCoverage > 0.0f && s.highCloudAltitudeM <= s.cloudTopM)
        throw Error(source + ": high_clouds.altitude_m (" + formatNumber(s.highCloudAltitudeM) +
                    ") must be above clouds.top_m (" + formatNumber(s.cloudTopM) +
                    ") when high_clouds.coverage is above 0: the layer is drawn behind the clouds");
}

std::string sceneSettingsText(const Scene& scene) {
    // Numbers as exact bits (hex float), so any change is a different text.
    auto exact = [](float v) {
        char text[32];
        std::snprintf(text, sizeof text, "%a", static_cast<double>(v));
        return std::string(text);
    };
    std::ostringstream out;
    for (const SceneKey& k : sceneKeys()) {
        out << k.key << '=';
        switch (k.member.index()) {
        case 0:
            out << scene.*std::get<0>(k.member);
            break;
        case 1:
            out << exact(scene.*std::get<1>(k.member));
            break;
        case 2:
            out << (scene.*std::get<2>(k.member) ? "true" : "false");
            break;
        case 3:
            out << nlohmann::json(scene.*std::get<3>(k.member)).dump();
            break;
        case 4: {
            const glm::vec3 v = scene.*std::get<4>(k.member);
            out << exact(v.x) << ',' << exact(v.y) << ',' << exact(v.z);
            break;
        }
        default: {
            const EnumMember& e = std::get<5>(k.member);
            out << e.names.at(static_cast<size_t>(e.get(scene)));
        }
        }
        out << '\n';
    }
    return out.str();
}

namespace {

nlohmann::json keyValue(const Scene& scene, const SceneKey& k) {
    switch (k.member.index()) {
    case 0:
        return scene.*std::get<0>(k.member);
    case 1: // as the double the float is, which reads back to the same float
        return static_cast<double>(scene.*std::get<1>(k.member));
    case 2:
        return scene.*std::get<2>(k.member);
    case 3:
        return scene.*std::get<3>(k.member);
    case 4: {
        const glm::vec3 v = scene.*std::get<4>(k.member);
        return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
    }
    default: {
        const EnumMember& e = std::get<5>(k.member);
        return e.names.at(static_cast<size_t>(e.get(scene)));
    }
    }
}

} // namespace

const std::vector<SceneKeyInfo>& sceneKeyInfos() {
    static const std::vector<SceneKeyInfo> infos = [] {
        std::vector<SceneKeyInfo> out;
        for (const SceneKey& k : sceneKeys()) {
            SceneKeyInfo info;
            info.key = k.key;
            info.type = static_cast<SceneKeyType>(k.member.index());
            info.unit = k.unit;
            info.min = k.min;
            info.max = k.max;
            if (k.member.index() == 5)
                info.choices = std::get<5>(k.member).names;
            info.doc = k.description;
            out.push_back(std::move(info));
        }
        return out;
    }();
    return infos;
}

std::string sceneKeyValue(const Scene& scene, const std::string& key) {
    const SceneKey* k = findKey(key);
    if (!k)
        throw Error("unknown scene key '" + shortened(key) + "' (see docs/SCENE.md)");
    return keyValue(scene, *k).dump();
}

std::string sceneJson(const Scene& scene) {
    const Scene defaults;
    nlohmann::ordered_json root = nlohmann::ordered_json::object();
    for (const SceneKey& k : sceneKeys()) {
        const nlohmann::json value = keyValue(scene, k);
        if (value == keyValue(defaults, k))
            continue;
        nlohmann::ordered_json* node = &root;
        std::string rest = k.key;
        for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1))
            node = &(*node)[rest.substr(0, dot)];
        (*node)[rest] = value;
    }
    return root.dump(2) + "\n";
}

std::string sceneDocumentationMarkdown() {
    std::ostringstream md;
    md << "# Scene reference\n\n"
       << "<!-- Generated by `cloudscape scene-doc` from the key table in src/io/scene.cpp; "
          "a test keeps this file equal to that output. Do not edit by hand. -->\n\n"
       << "A scene is a JSON object of nested objects whose leaves are the keys below, e.g.\n"
       << "`{\"weather\": {\"coverage\": 0.3}, \"sun\": {\"elevation_deg\": 5}}`. Every key is "
          "optional;\nmissing keys take their defaults. The defaults are the fair-weather "
          "cumulus preset's clouds, sun\nand air over flat ground; that preset, which a "
          "command renders when given no scene, adds\ncirrus and a landscape (terrain, the "
          "clouds' shadow map, a camera on a hill).\nOn the command line, `--set key=value` "
          "overrides any key, e.g. "
          "`--set weather.coverage=0.3`\nor `--set sun.irradiance=[12,10,8]`. Unknown keys, "
          "wrong types and out-of-range values\nare errors that name the key and the allowed "
          "range.\n\n"
       << "Coordinates: x east, y up (altitude above the ground at the origin), z north; the "
          "planet's\ncentre is at (0, -radius, 0). Radiance and irradiance are linear RGB in "
          "arbitrary but\nconsistent units.\n\n"
       << "| key | type | unit | default | range | meaning |\n"
       << "|---|---|---|---|---|---|\n";
    for (const SceneKey& k : sceneKeys()) {
        const bool ranged = k.member.index() == 0 || k.member.index() == 1 || k.member.index() == 4;
        md << "| `" << k.key << "` | " << typeName(k.member) << " | " << k.unit << " | `"
           << defaultText(k) << "` | " << (ranged ? rangeText(k) : "-") << " | " << k.description
           << " |\n";
    }
    md << "\nCross-key rules: `clouds.top_m` must be at least 10 m above `clouds.bottom_m`; the "
          "camera's\naltitude (`camera.position` y) must be above 0; "
          "`atmosphere.mie_extinction` must be at least\n`atmosphere.mie_scattering`; "
          "`high_clouds.altitude_m` must be above `clouds.top_m` when\n"
          "`high_clouds.coverage` is above 0.\n";
    md << "\n## Quality tiers\n\n`--tier NAME` applies one of these overlays of keys before any "
          "`--set`, through the same\ntable (so a tier is validated like a scene file).\n\n"
       << "| tier | keys | meaning |\n|---|---|---|\n";
    for (const Tier& t : tiers()) {
        md << "| `" << t.name << "` | ";
        for (size_t i = 0; i < t.keys.size(); ++i)
            md << (i ? ", " : "") << "`" << t.keys[i].first << "=" << t.keys[i].second << "`";
        md << " | " << t.description << " |\n";
    }
    md << keyframeDocumentationMarkdown();
    return md.str();
}

void applyTier(Scene& scene, const std::string& tier) {
    for (const Tier& t : tiers())
        if (tier == t.name) {
            for (const auto& [key, value] : t.keys)
                applyOverride(scene, std::string(key) + "=" + value, "--tier " + tier);
            return;
        }
    std::string known;
    for (size_t i = 0; i < tiers().size(); ++i)
        known += std::string(i == 0                    ? ""
                             : i + 1 == tiers().size() ? " or "
                                                       : ", ") +
                 tiers()[i].name;
    throw Error("--tier '" + tier + "': expected " + known);
}

const std::vector<std::string>& tierNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const Tier& t : tiers())
            out.push_back(t.name);
        return out;
    }();
    return names;
}

const Scene& defaultScene() {
    static const Scene scene;
    return scene;
}

KeyRange sceneKeyRange(const std::string& key) {
    const SceneKey* k = findKey(key);
    if (!k || !(k->member.index() == 0 || k->member.index() == 1 || k->member.index() == 4))
        throw Error("'" + key + "' is not a numeric scene key");
    return {k->min, k->max};
}

namespace io {

std::optional<SceneKeyKind> sceneKeyKind(const std::string& key) {
    const SceneKey* k = findKey(key);
    if (!k)
        return std::nullopt;
    switch (k->member.index()) {
    case 0:
        return SceneKeyKind::Integer;
    case 1:
        return SceneKeyKind::Number;
    case 2:
        return SceneKeyKind::Boolean;
    case 3:
        return SceneKeyKind::String;
    case 4:
        return SceneKeyKind::Vector3;
    default:
        return SceneKeyKind::Choice;
    }
}

void assignSceneKey(Scene& scene, const std::string& key, const nlohmann::json& value,
                    const std::string& where) {
    const SceneKey* k = findKey(key);
    if (!k)
        throw Error(where + ": unknown key '" + shortened(key) + "' (see docs/SCENE.md)");
    assignKey(scene, *k, value, where);
}

std::string readJsonInputFile(const std::string& path, const std::string& kind) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(path + ": is a directory; expected a " + kind);
    constexpr std::uintmax_t kMaxBytes = 16u << 20; // scenes and keyframes are kilobytes
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > kMaxBytes)
        throw Error(path + ": " + std::to_string(bytes) + " bytes is too large for a " + kind +
                    " (at most " + std::to_string(kMaxBytes) + ")");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(path + ": cannot open " + kind);
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw Error(path + ": cannot read " + kind);
    return text.str();
}

nlohmann::json parseCheckedJson(const std::string& text, const std::string& source) {
    return parseSceneJson(text, source);
}

std::string shortenedForMessage(const std::string& text) {
    return shortened(text);
}

std::string numberForMessage(double value) {
    return formatNumber(value);
}

std::string jsonTypeForMessage(const nlohmann::json& value) {
    return jsonTypeName(value);
}

} // namespace io

std::string presetDirectory() {
    return std::string(CLOUDSCAPE_SOURCE_DIR) + "/scenes";
}

std::string resolveScenePath(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    if (fs::exists(nameOrPath))
        return nameOrPath;
    const fs::path preset = fs::path(presetDirectory()) / (nameOrPath + ".json");
    if (nameOrPath.find('/') == std::string::npos && fs::exists(preset))
        return preset.string();
    throw Error(nameOrPath + ": no such scene file or preset (presets are in " + presetDirectory() +
                ")");
}

} // namespace cloudscape
