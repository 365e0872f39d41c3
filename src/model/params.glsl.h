// The parameters the model reads, declared once for GLSL and C++. Everything is packed in vec4
// and ivec4 members so the std140 and std430 layouts equal the C++ layout; the C++ side checks
// the sizes. Units are physical: metres, seconds, 1/m, linear radiance.
#ifndef CLOUDSCAPE_MODEL_PARAMS_GLSL_H
#define CLOUDSCAPE_MODEL_PARAMS_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Per-scene cloud model and lighting parameters.
struct CloudParams {
    vec4 planet;        // x planet radius, y cloud layer bottom altitude, z top altitude (m),
                        // w weather map extent (m, the map wraps beyond it)
    vec4 noiseScale;    // x base noise period, y detail noise period, z curl noise period (m),
                        // w curl distortion amplitude (m)
    vec4 wind;          // xyz unit wind direction (horizontal), w wind speed (m/s)
    vec4 animation;     // x time (s), y cloud-top shear offset (m), z detail-noise speed ratio,
                        // w upward drift as a fraction of the wind speed
    vec4 shape;         // x detail erosion strength, y unused, z extinction at density 1
                        // (1/m), w single-scattering albedo
    vec4 weatherOrigin; // xy world xz (m) of the weather map's centre, z coverage multiplier,
                        // w type offset (added to the map's type, then clamped)
    vec4 sunDirection;  // xyz unit vector toward the sun, w angular radius of the disc (rad)
    vec4 sunIrradiance; // rgb sun irradiance at the top of the clouds (linear), w unused
    vec4 ambientTop;    // rgb sky radiance lighting cloud tops (linear), w ambient strength
    vec4 ambientBottom; // rgb radiance from below (ground bounce) lighting cloud bases
    vec4 phase;         // x g of the main HG lobe, y g of the silver-lining lobe, z weight of
                        // the silver-lining lobe, w powder strength (0 off, 1 full)
    vec4 lighting;      // x rain absorption gain, y light cone length (m), z long-distance
                        // sample distance as a multiple of the cone length, w cone spread
    vec4 march;         // x steps at the zenith, y steps at the horizon, z transmittance at
                        // which the march stops, w maximum march distance (m)
    vec4 skyZenith;     // rgb placeholder sky radiance at the zenith
    vec4 skyHorizon;    // rgb placeholder sky radiance at the horizon, w horizon fade start as
                        // a fraction of the maximum march distance
    vec4 ground;        // rgb ground radiance below the horizon, w unused
    vec4 multipleScattering; // Wrenninge octave factors: x energy a, y optical depth b,
                             // z eccentricity c (per octave)
    vec4 optimisation;       // x coarse step factor (1 = every step full), y view alpha above
                             // which light samples are cheap (>= 1 = never), z step
                             // optimisation gain (0 = off), w blue-noise start offset (1 on)
    vec4 distanceLod;        // x log2 of a base-noise texel (m), y of a detail texel,
                             // z distance LOD on (1) or off (0), w unused
    ivec4 counts;            // x light cone samples, y long-distance sample on (1) or off (0),
                  // z noise mip bias for light samples, w scattering octaves (1 = single)
    vec4 lightingModel; // x phase function kind (PHASE_TWO_LOBE or PHASE_HG_DRAINE of
                        // phase.glsl.h), y droplet diameter for HG+Draine (micrometres),
                        // z step integration: 1 energy-conserving (Hillaire 2015), 0 the
                        // seeds' sum of source * extinction * step, w unused
};

// Per-frame camera and output parameters.
struct FrameParams {
    vec4 cameraPosition; // xyz world position (m; y is altitude above the ground), w unused
    vec4 cameraForward;  // xyz unit view direction, w tan(vertical fov / 2)
    vec4 cameraRight;    // xyz unit right vector, w aspect ratio (width / height)
    vec4 cameraUp;       // xyz unit up vector, w exposure multiplier
    ivec4 size;          // x width, y height (pixels), z frame index, w seed for jitter
    ivec4 sampling;      // x samples per pixel, y temporal accumulation cap (marches),
                         // z scene depth buffer bound (1) or not (0), w unused
};

#ifdef __cplusplus
static_assert(sizeof(CloudParams) == 21 * 16, "CloudParams must match the GLSL layout");
static_assert(sizeof(FrameParams) == 6 * 16, "FrameParams must match the GLSL layout");
#endif

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
