#pragma once
// The volumetric path integrator: radiance arriving at a point from a direction, through a
// medium lit by a sun of finite angular size, an environment (sky) and optionally a Lambertian
// ground. Unbiased: delta tracking finds collisions, the phase function is importance-sampled
// (the path weight is unchanged by a scattering event), the sun is sampled at every vertex with a
// ratio-tracked shadow ray (next-event estimation), and Russian roulette ends paths whose weight
// has dropped. The same code renders clouds and the validation slabs, so the published tables
// test the code the pictures come from.
#include "core/model_params.h"
#include "model/ground.glsl.h"
#include "model/phase.glsl.h"
#include "model/sky.glsl.h"
#include "pathtrace/random.h"
#include "pathtrace/tracking.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cloudscape::pathtrace {

struct SunLight {
    bool enabled = false;
    glm::vec3 direction{0.0f, 1.0f, 0.0f}; // unit, toward the sun
    // 1 - cos(angular radius), kept apart because cos(r) of a sun-sized r rounds to within a
    // few float steps of 1 (a 0.05 degree sun would be 25% off).
    float oneMinusCosRadius = 0.0f;
    glm::vec3 radiance{0.0f}; // of the disc (per steradian), above any atmosphere
    float solidAngleSr = 0.0f;
    // With the atmosphere on, the disc's light at a point passes through it (the model's
    // sunTransmittance: reddening and the planet's shadow), as the real-time renderer's does.
    bool throughAtmosphere = false;
    model::SkyParams sky{};

    float solidAngle() const { return solidAngleSr; }
    glm::vec3 radianceAt(glm::vec3 p) const {
        if (!throughAtmosphere)
            return radiance;
        const glm::vec2 rMuS = model::atmospherePosition(p, sky);
        return radiance *
               model::sunTransmittance(rMuS.x, rMuS.y, sky.sunAngularRadius, sky.atmosphere);
    }
};

// The scene's sun as the model defines it (sky.glsl.h's sunSolidAngle and sunDiscRadiance), so
// the path tracer and the real-time renderer see one disc.
inline SunLight makeSunLight(const model::SkyParams& sky) {
    SunLight sun;
    sun.enabled = true;
    sun.direction = glm::normalize(sky.sunDirection);
    sun.oneMinusCosRadius = sky.sunOneMinusCos;
    sun.solidAngleSr = model::sunSolidAngle(sky);
    sun.radiance = model::sunDiscRadiance(sky);
    sun.throughAtmosphere = sky.atmosphere.enabled != 0;
    sun.sky = sky;
    return sun;
}

// The clouds' direct light as the real-time renderer chooses it (sky.glsl.h's
// cloudLightDirection): the sun, or at night the moon when it lights the layer more; the moon
// is then a disc of its own radius and irradiance (its phase is in the irradiance; the disc's
// shape is not sampled). Camera rays see both discs through model::skyRadiance.
inline SunLight makeCloudLight(const model::SkyParams& sky) {
    if (sky.moonLightsClouds == 0)
        return makeSunLight(sky);
    model::SkyParams moon = sky;
    moon.sunDirection = sky.moonDirection;
    moon.sunAngularRadius = sky.moonAngularRadius;
    moon.sunOneMinusCos = sky.moonOneMinusCos;
    moon.sunIrradiance = sky.moonIrradiance;
    return makeSunLight(moon);
}

// A sun of angular radius r (radians) that delivers `irradiance` on a surface facing it (the
// validation scenes).
inline SunLight makeSunLight(glm::vec3 direction, float angularRadius, glm::vec3 irradiance) {
    model::SkyParams sky{};
    sky.sunDirection = direction;
    sky.sunAngularRadius = angularRadius;
    sky.sunOneMinusCos = oneMinusCosOf(angularRadius);
    sky.sunIrradiance = irradiance;
    return makeSunLight(sky);
}

// The planet's surface, a sphere of the given radius centred at (0, -radius, 0). With albedo 0
// it is not a reflector: a path that reaches it ends with the environment's radiance in its
// direction (the real-time renderer's ground colour), and it blocks the sun.
//
// With a terrain (the scene's CloudParams with terrain.enabled; its height field bound to the
// calling thread, as the model's textures are) the surface is the terrain instead: the model's
// own height field and ray march (terrain.glsl.h's terrainHitDistance, which continues on the
// flat planet beyond the field), an opaque Lambertian reflector at the model's normal and albedos
// (ground.glsl.h's terrainSurfaceAt), and the terrain shadows what lies behind it. The sphere
// stays as a floor under it: the march gives up after terrain.max_steps (the real-time renderer
// then shows no terrain), and a path must not fall through the planet.
struct Ground {
    bool enabled = false;
    float radius = 0.0f;
    float albedo = 0.0f;
    const model::CloudParams* terrain = nullptr; // null, or terrain.enabled off: the sphere

    bool hasTerrain() const { return terrain != nullptr && terrain->terrain.enabled != 0; }

    // Distance along a unit ray to the surface (from outside), or kInfinity.
    float intersect(glm::vec3 origin, glm::vec3 dir) const {
        const float sphere = intersectSphere(origin, dir);
        if (!hasTerrain())
            return sphere;
        const float t = model::terrainHitDistance(origin, dir, *terrain);
        return t == model::NO_HIT ? sphere : std::min(t, sphere);
    }
    glm::vec3 normalAt(glm::vec3 p) const {
        return glm::normalize(p - glm::vec3(0.0f, -radius, 0.0f));
    }

    // The terrain where a ray reached it at distance t: where a path leaving the surface starts
    // (terrainLeaveLift above the surface along the vertical: the march's hit lies within its
    // tolerance above or below it, and a bisected hit below it), the normal and the albedo.
    struct TerrainHit {
        glm::vec3 leave;
        glm::vec3 normal;
        glm::vec3 albedo;
    };
    TerrainHit terrainAt(glm::vec3 p, float t) const {
        // t = 0: a point, not a pixel (each path lands on one field).
        const model::TerrainSurface s = model::terrainSurfaceAt(p, glm::vec3(0.0f), 0.0f, *terrain);
        const float gap = model::terrainGap(p, *terrain);
        return {p + s.up * (model::terrainLeaveLift(t) - gap), s.normal, s.albedo};
    }

private:
    float intersectSphere(glm::vec3 origin, glm::vec3 dir) const {
        if (!enabled)
            return kInfinity;
        const glm::vec3 oc = origin - glm::vec3(0.0f, -radius, 0.0f);
        const double b = glm::dot(oc, dir);
        // |oc|^2 - r^2 in a form that keeps the altitude's precision at planet scale.
        const double altitude = glm::length(glm::dvec3(oc)) - radius;
        const double c = altitude * (glm::length(glm::dvec3(oc)) + radius);
        const double disc = b * b - c;
        if (disc < 0.0 || c < 0.0)
            return kInfinity;
        const double t = -b - std::sqrt(disc);
        return t > 0.0 ? static_cast<float>(t) : kInfinity;
    }
};

struct PathLimits {
    int maxBounces = 1024; // scattering and surface events
    // After this many events, paths also face a fixed roulette (survival 0.95) so that the
    // expected length of a path that never loses weight (albedo 1) stays bounded.
    int rouletteAfter = 64;
};

struct PathCounters {
    uint64_t paths = 0;
    uint64_t collisions = 0; // real scattering events
    uint64_t truncated = 0;  // paths that reached maxBounces (the only bias)
};

// Uniform direction inside the sun's cone.
inline glm::vec3 sampleSunDirection(const SunLight& sun, Random& random) {
    // x = 1 - cos theta is uniform in [0, 1 - cos r]; sin theta from x keeps its precision.
    const float x = random.uniform() * sun.oneMinusCosRadius;
    return model::directionAroundSin(sun.direction, 1.0f - x, std::sqrt(x * (2.0f - x)),
                                     2.0f * glm::pi<float>() * random.uniform());
}

// Cosine-weighted direction about a normal.
inline glm::vec3 sampleCosineDirection(glm::vec3 normal, Random& random) {
    const float cosTheta = std::sqrt(random.uniform());
    return model::directionAround(normal, cosTheta, 2.0f * glm::pi<float>() * random.uniform());
}

// Radiance arriving at origin from direction -dir (i.e. looking along dir). Medium provides
// forEachSegment, sigmaT(p), albedo() and phase() (a model::PhaseFunction); environment(dir,
// withSunDisc) is the radiance of whatever lies beyond along dir. The sun disc is seen directly
// only by the first segment: after a scattering event the sun is reached through next-event
// estimation alone, so it is never counted twice.
//
// An emitting medium also provides emission(p): radiance emitted per unit of optical depth, S_e.
// Why that quantity and how it is collected. The real-time march adds a sample's source (its
// scattered light plus the storm's glow and flash) times T (1 - exp(-sigma_t dt)), which as dt
// goes to 0 is T sigma_t S dt: the model's emission is a source function, and the radiative
// transfer equation it solves is
//     dL/ds = -sigma_t L + sigma_s (phase-weighted in-scattered L) + j,   j = sigma_t S_e
// (in the usual notation j = sigma_a L_e, i.e. L_e = S_e sigma_t / sigma_a; the clouds' albedo is
// close to 1, so sigma_a is nearly zero and S_e is the form that stays finite). Its emitted part
// along a ray is the integral over s of T(s) sigma_t(s) S_e(s). Delta tracking picks a real
// collision at s with probability density sigma_t(s) T(s) (whatever the majorant: null collisions
// only thin the tentative ones), so S_e at the collision is an unbiased estimate of that integral
// (the collision estimator). Every vertex of a path does the same for the radiance arriving at
// the previous one, so each collision adds the path weight as it arrives there (before the
// albedo of the event: emission is not scattered light) times S_e. The sun's shadow rays carry
// the sun alone; the emitted light reaches other vertices through the paths themselves.
template <class Medium, class Environment>
glm::vec3 traceRadiance(const Medium& medium, const SunLight& sun, const Ground& ground,
                        const Environment& environment, glm::vec3 origin, glm::vec3 dir,
                        Random& random, const PathLimits& limits, PathCounters& counters) {
    glm::vec3 radiance(0.0f);
    float weight = 1.0f;
    // The terrain's coloured albedos, kept apart from the scalar weight: 1 on paths that have
    // not met it, and x * 1 is x, so those add up to the same bits as before the terrain.
    glm::vec3 tint(1.0f);
    bool direct = true;
    const model::PhaseFunction phase = medium.phase();
    counters.paths += 1;

    // Sun light reaching p (scaled by the phase or BRDF term the caller applies).
    auto sunThrough = [&](glm::vec3 p, glm::vec3 toSun) {
        if (ground.intersect(p, toSun) < kInfinity)
            return 0.0f;
        return estimateTransmittance(medium, p, toSun, kInfinity, random);
    };

    for (int event = 0;; ++event) {
        const float tGround = ground.intersect(origin, dir);
        const float t = sampleCollision(medium, origin, dir, tGround, random);
        if (t == kInfinity && tGround == kInfinity) {
            radiance += tint * (weight * environment(dir, direct));
            break;
        }
        if (event >= limits.maxBounces) {
            counters.truncated += 1;
            break;
        }
        if (t < kInfinity) {
            // A real collision: scatter.
            counters.collisions += 1;
            const glm::vec3 p = origin + dir * t;
            if constexpr (requires { medium.emission(p); })
                radiance += tint * (weight * medium.emission(p)); // before albedo: see above
            weight *= medium.albedo();
            if (sun.enabled) {
                const glm::vec3 toSun = sampleSunDirection(sun, random);
                const float transmittance = sunThrough(p, toSun);
                if (transmittance > 0.0f) {
                    const float f = model::evaluatePhase(phase, glm::dot(dir, toSun));
                    radiance +=
                        tint * (weight * f * transmittance * sun.solidAngle() * sun.radianceAt(p));
                }
            }
            // One draw per statement: a call's arguments are evaluated in an unspecified order
            // (gcc and clang differ), which would make the image depend on the compiler. This
            // is the order the gcc build has always drawn them in: u first, then uLobe.
            const float u = random.uniform();
            const float uLobe = random.uniform();
            const float cosTheta = model::samplePhaseCos(phase, uLobe, u);
            dir = model::directionAround(dir, cosTheta, 2.0f * glm::pi<float>() * random.uniform());
            origin = p;
        } else {
            // The ground.
            const glm::vec3 p = origin + dir * tGround;
            glm::vec3 n;
            glm::vec3 lifted;
            if (ground.hasTerrain()) {
                // A Lambertian surface at the terrain's albedo: the sun's light through the
                // clouds' ratio-tracked transmittance and the terrain's own shadow below, the
                // sky's (and the clouds' and the terrain's) by the path that goes on.
                const Ground::TerrainHit hit = ground.terrainAt(p, tGround);
                n = hit.normal;
                lifted = hit.leave;
                tint *= hit.albedo;
            } else {
                if (ground.albedo <= 0.0f) {
                    radiance += tint * (weight * environment(dir, false));
                    break;
                }
                n = ground.normalAt(p);
                lifted = p + n * 0.05f; // off the surface, out of its shadow
                weight *= ground.albedo;
            }
            if (sun.enabled) {
                const glm::vec3 toSun = sampleSunDirection(sun, random);
                const float cosine = glm::dot(n, toSun);
                if (cosine > 0.0f) {
                    const float transmittance = sunThrough(lifted, toSun);
                    radiance += tint * (weight * (cosine / glm::pi<float>()) * transmittance *
                                        sun.solidAngle() * sun.radianceAt(lifted));
                }
            }
            dir = sampleCosineDirection(n, random);
            origin = lifted;
        }
        direct = false;

        // Russian roulette: survival in proportion to the weight (below 1), and a fixed one for
        // very long paths; survivors carry the lost share, so the estimate stays unbiased. The
        // terrain's tint is left out: at its albedo of about 0.1 it would end 9 paths in 10 and
        // multiply the rest by 10, and those paths carry the sky's and the clouds' light on the
        // terrain, which would then be mostly noise; its paths rarely bounce twice anyway.
        float survive = std::min(weight, 1.0f);
        if (event >= limits.rouletteAfter)
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
