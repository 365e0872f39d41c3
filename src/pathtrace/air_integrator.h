#pragma once
// The volumetric path integrator with the air: radiance in one RGB channel arriving at a point
// through the atmosphere (atmosphere_medium.h) and, optionally, a cloud medium inside it (the
// sky reference has none; `pathtrace.atmosphere` cloud renders have the clouds). Two media
// overlap: the free flight in their sum is the nearer of two independent delta-tracked
// collisions (the sum's transmittance is the product of theirs), and a shadow ray's
// transmittance is the product of their two estimates. Otherwise as integrator.h: a scattering
// event samples the collided medium's phase function exactly (Rayleigh or Cornette-Shanks for
// the air, in proportion to their coefficients; the clouds' own phase), the sun is sampled in its
// disc at every vertex, and a Lambertian ground at the atmosphere's ground albedo reflects. The
// sun's light is the disc's above the atmosphere: the air on the way is traced, not tabled.
// Nothing lies beyond the top of the atmosphere; camera rays that leave it through the sun's disc
// see the disc (limb-darkened as the model's), when the caller asks for it. Clouds that emit (the
// storm's glow, lightning) add their emission at every cloud collision, as integrator.h derives.
#include "model/phase.glsl.h"
#include "model/sky.glsl.h"
#include "pathtrace/atmosphere_medium.h"
#include "pathtrace/integrator.h"
#include "pathtrace/random.h"
#include "pathtrace/tracking.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace cloudscape::pathtrace {

// The cosine of a Rayleigh scattering angle for u uniform in [0, 1): the exact inverse of its
// CDF (mu^3 + 3 mu = 8 u - 4, solved by Cardano's formula).
inline float sampleRayleighCos(float u) {
    const double b = 8.0 * double(u) - 4.0;
    const double root = std::sqrt(b * b / 4.0 + 1.0);
    return static_cast<float>(std::cbrt(b / 2.0 + root) + std::cbrt(b / 2.0 - root));
}

// No clouds: the medium of a sky alone.
struct NoClouds {
    template <class Visit> void forEachSegment(glm::vec3, glm::vec3, float, Visit&&) const {}
    float sigmaT(glm::vec3) const { return 0.0f; }
    float albedo() const { return 1.0f; }
    model::PhaseFunction phase() const {
        return model::makePhaseFunction(model::PHASE_HG, glm::vec4(0.0f));
    }
};

struct AirPathOptions {
    PathLimits limits;
    bool singleScattering = false; // only the sun's light scattered (or reflected) once
    // The sun's disc for camera rays that leave the atmosphere through it (null: not counted).
    const model::SkyParams* discSky = nullptr;
    // A surface with a terrain (integrator.h's Ground with hasTerrain()): the ground is the
    // terrain, at its albedos, and it shadows; null (or no terrain): the sphere at the
    // atmosphere's ground albedo.
    const Ground* terrain = nullptr;
};

// p is relative to the planet's centre; the clouds' world frame has the centre at
// (0, -bottomRadius, 0).
template <class Clouds>
float traceRadianceInAir(const Clouds& clouds, const AtmosphereMedium& air, const SunLight& sun,
                         glm::dvec3 p, glm::dvec3 dir, Random& random,
                         const AirPathOptions& options, PathCounters& counters) {
    const int channel = air.channel();
    const float g = air.mieG();
    const model::PhaseFunction cloudPhase = clouds.phase();
    const glm::dvec3 centre(0.0, -air.bottomRadius(), 0.0);
    auto world = [&](glm::dvec3 q) { return glm::vec3(q + centre); };
    const Ground* terrain =
        options.terrain != nullptr && options.terrain->hasTerrain() ? options.terrain : nullptr;
    const float sunIrradiance = sun.radiance[channel] * sun.solidAngle();
    float radiance = 0.0f;
    float weight = 1.0f;
    bool direct = true;
    counters.paths += 1;

    // The sun's light at q along a direction sampled in its disc, times its irradiance.
    struct SunSample {
        glm::dvec3 direction;
        float light;
    };
    auto sunAt = [&](glm::dvec3 q) -> SunSample {
        const glm::dvec3 toSun = glm::normalize(glm::dvec3(sampleSunDirection(sun, random)));
        const AtmosphereMedium::Exit out = air.exit(q, toSun);
        if (out.ground)
            return {toSun, 0.0f};
        if (terrain != nullptr && terrain->intersect(world(q), glm::vec3(toSun)) < kInfinity)
            return {toSun, 0.0f};
        float t = estimateAtmosphereTransmittance(air, q, toSun, out.distance, random);
        if (t > 0.0f)
            t *= estimateTransmittance(clouds, world(q), glm::vec3(toSun), kInfinity, random);
        return {toSun, t * sunIrradiance};
    };

    for (int event = 0;; ++event) {
        AtmosphereMedium::Exit out = air.exit(p, dir);
        if (terrain != nullptr) { // the terrain, in the world frame, before the sphere or the top
            const float tTerrain = terrain->intersect(world(p), glm::vec3(dir));
            if (tTerrain < kInfinity && double(tTerrain) < out.distance)
                out = {double(tTerrain), true};
        }
        const double tAir = sampleAtmosphereCollision(air, p, dir, out.distance, random);
        const float tCloud = sampleCollision(clouds, world(p), glm::vec3(dir),
                                             out.ground ? float(out.distance) : kInfinity, random);
        const bool cloudHit = tCloud < kInfinity && (tAir < 0.0 || double(tCloud) < tAir);
        const bool airHit = !cloudHit && tAir >= 0.0;
        if (!cloudHit && !airHit && !out.ground) {
            // Into space.
            const model::SkyParams* disc = options.discSky;
            const glm::vec3 d(dir);
            if (direct && disc != nullptr && model::insideSunDisc(d, *disc))
                radiance += weight * sun.radiance[channel] * model::sunLimbDarkening(d, *disc);
            break;
        }
        if (event >= options.limits.maxBounces) {
            counters.truncated += 1;
            break;
        }
        if (cloudHit || airHit) {
            counters.collisions += 1;
            p += dir * (cloudHit ? double(tCloud) : tAir);
            float phase = 0.0f;
            float rayleighShare = 0.0f; // of the air's scattering
            const SunSample s = sunAt(p);
            const float cosTheta = float(glm::dot(dir, s.direction));
            if (cloudHit) {
                // The clouds' emission, collected at the collision (integrator.h says why).
                if constexpr (requires { clouds.emission(world(p)); })
                    radiance += weight * clouds.emission(world(p))[channel];
                weight *= clouds.albedo();
                phase = model::evaluatePhase(cloudPhase, cosTheta);
            } else {
                const AtmosphereMedium::Coefficients c = air.at(p);
                const float scattering = c.rayleigh + c.mie;
                if (scattering <= 0.0f || c.extinction <= 0.0f)
                    break;
                weight *= scattering / c.extinction; // the rest is absorbed (Mie, ozone)
                phase = (c.rayleigh * model::rayleighPhase(cosTheta) +
                         c.mie * model::miePhase(cosTheta, g)) /
                        scattering;
                rayleighShare = c.rayleigh / scattering;
            }
            radiance += weight * phase * s.light;
            if (options.singleScattering)
                break;
            float cosScatter;
            if (cloudHit) {
                // Two draws in one fixed order (as integrator.h): function arguments are
                // evaluated in an unspecified order, so gcc and clang would differ.
                const float u = random.uniform();
                const float uLobe = random.uniform();
                cosScatter = model::samplePhaseCos(cloudPhase, uLobe, u);
            } else {
                const bool rayleigh = random.uniform() < rayleighShare;
                const float u = random.uniform();
                // Cornette-Shanks is Draine's phase function with alpha = 1.
                cosScatter = rayleigh ? sampleRayleighCos(u) : model::sampleDraineCos(g, 1.0f, u);
            }
            const float phi = 2.0f * glm::pi<float>() * random.uniform();
            dir =
                glm::normalize(glm::dvec3(model::directionAround(glm::vec3(dir), cosScatter, phi)));
        } else {
            // The ground: Lambertian at the atmosphere's ground albedo, or the terrain's.
            glm::dvec3 n;
            if (terrain != nullptr) {
                const Ground::TerrainHit hit =
                    terrain->terrainAt(world(p + dir * out.distance), float(out.distance));
                n = glm::dvec3(hit.normal);
                p = glm::dvec3(hit.leave) - centre;
                weight *= hit.albedo[channel];
            } else {
                n = glm::normalize(p + dir * out.distance);
                p = n * (air.bottomRadius() + 0.05); // just above the surface, out of its shadow
                weight *= air.groundAlbedo();
            }
            const SunSample s = sunAt(p);
            const double cosine = glm::dot(n, s.direction);
            if (cosine > 0.0)
                radiance += weight * float(cosine / glm::pi<double>()) * s.light;
            if (options.singleScattering)
                break;
            dir = glm::normalize(glm::dvec3(sampleCosineDirection(glm::vec3(n), random)));
        }
        direct = false;
        // Russian roulette as integrator.h's.
        float survive = std::min(weight, 1.0f);
        if (event >= options.limits.rouletteAfter)
            survive *= 0.95f;
        if (survive < 1.0f) {
            if (random.uniform() >= survive)
                break;
            weight /= survive;
        }
    }
    return radiance;
}

} // namespace cloudscape::pathtrace
