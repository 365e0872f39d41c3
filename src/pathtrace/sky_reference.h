#pragma once
// Ground truth for the sky: radiance along a direction through the atmosphere as a participating
// medium (atmosphere_medium.h), by volumetric path tracing (air_integrator.h without clouds), to
// measure the real-time sky tables against (docs/QUALITY.md, bench/bench_sky_reference.cpp).
// Each path carries one RGB channel
// (the model's three wavelengths); it scatters off Rayleigh (its phase sampled exactly) or Mie
// (Cornette-Shanks, the model's phase, sampled exactly through Draine's CDF with alpha = 1), in
// proportion to their scattering coefficients, and is absorbed by the rest of the extinction
// (Mie absorption, ozone) through its weight. At every scattering vertex and every bounce off the
// Lambertian ground (at the atmosphere's ground albedo) the sun is sampled within its disc and
// its light arrives through a ratio-tracked shadow ray: the atmosphere's transmittance and the
// planet's shadow (straight rays: no refraction, unlike the model's grazing correction). Nothing
// lies beyond the top of the atmosphere, and the sun's disc itself is not counted: the estimate
// is the sky without the disc, as skyBackground is.
#include "model/params.glsl.h"
#include "pathtrace/air_integrator.h"
#include "pathtrace/atmosphere_medium.h"
#include "pathtrace/integrator.h"
#include "pathtrace/random.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace cloudscape::pathtrace {

struct SkyReferenceOptions {
    int maxBounces = 512;          // scattering and ground events
    bool singleScattering = false; // only the sun's light scattered once (for closed forms)
    uint64_t seed = 1;
};

struct SkyReferenceEstimate {
    glm::dvec3 radiance{0.0};      // in the units of sky.sunIrradiance per steradian
    glm::dvec3 standardError{0.0}; // of the mean, per channel
    uint64_t pathsPerChannel = 0;
    uint64_t truncated = 0; // paths that reached maxBounces (the only bias)
};

// Radiance arriving at a world position (inside the atmosphere) from the direction -dir, i.e.
// seen looking along dir, for the sky's sun and atmosphere (sky.atmosphere; its `enabled` flag is
// not read), over pathsPerChannel paths per channel on all cores. Deterministic for a seed.
SkyReferenceEstimate traceSkyReference(const model::SkyParams& sky, glm::vec3 position,
                                       glm::vec3 dir, uint64_t pathsPerChannel,
                                       const SkyReferenceOptions& options = {});

} // namespace cloudscape::pathtrace
