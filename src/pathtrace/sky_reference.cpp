// The sky's ground truth: see sky_reference.h. Light transport only; the medium's coefficients
// are the model's (atmosphere_medium.h).
#include "pathtrace/sky_reference.h"

#include "model/atmosphere.glsl.h"
#include "model/phase.glsl.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cloudscape::pathtrace {
namespace {

glm::dvec3 toDouble(glm::vec3 v) {
    return glm::dvec3(v);
}

// The sun's light reaching p along toSun (unit), through the air, unless the planet is in the
// way.
float sunTransmittanceAt(const AtmosphereMedium& medium, glm::dvec3 p, glm::dvec3 toSun,
                         Random& random) {
    const AtmosphereMedium::Exit out = medium.exit(p, toSun);
    if (out.ground)
        return 0.0f;
    return estimateAtmosphereTransmittance(medium, p, toSun, out.distance, random);
}

// Sun light for a vertex: a direction within the disc, and the disc's radiance times its solid
// angle in this channel (the irradiance above the atmosphere).
struct SunSample {
    glm::dvec3 direction;
    float irradiance;
};

SunSample sampleSun(const SunLight& sun, int channel, Random& random) {
    return {glm::normalize(toDouble(sampleSunDirection(sun, random))),
            sun.radiance[channel] * sun.solidAngle()};
}

constexpr uint64_t kBlock = 1024; // paths per parallel task (and per random stream)

} // namespace

float traceSkyPath(const AtmosphereMedium& medium, const SunLight& sun, glm::dvec3 p,
                   glm::dvec3 dir, Random& random, const SkyReferenceOptions& options,
                   bool& truncated) {
    const int channel = medium.channel();
    const float g = medium.mieG();
    float radiance = 0.0f;
    float weight = 1.0f;
    truncated = false;
    for (int event = 0;; ++event) {
        const AtmosphereMedium::Exit out = medium.exit(p, dir);
        const double t = sampleAtmosphereCollision(medium, p, dir, out.distance, random);
        if (t < 0.0 && !out.ground)
            break; // into space: nothing beyond the atmosphere but the (uncounted) disc
        if (event >= options.maxBounces) {
            truncated = true;
            break;
        }
        if (t >= 0.0) {
            p += dir * t;
            const AtmosphereMedium::Coefficients c = medium.at(p);
            const float scattering = c.rayleigh + c.mie;
            if (scattering <= 0.0f || c.extinction <= 0.0f)
                break;
            weight *= scattering / c.extinction; // the rest is absorbed (Mie, ozone)
            const SunSample s = sampleSun(sun, channel, random);
            const float cosTheta = static_cast<float>(glm::dot(dir, s.direction));
            const float phase = (c.rayleigh * model::rayleighPhase(cosTheta) +
                                 c.mie * model::miePhase(cosTheta, g)) /
                                scattering;
            const float tSun = sunTransmittanceAt(medium, p, s.direction, random);
            radiance += weight * phase * tSun * s.irradiance;
            if (options.singleScattering)
                break;
            const bool rayleigh = random.uniform() * scattering < c.rayleigh;
            const float u = random.uniform();
            // Cornette-Shanks is Draine's phase function with alpha = 1.
            const float cosScatter =
                rayleigh ? sampleRayleighCos(u) : model::sampleDraineCos(g, 1.0f, u);
            const float phi = 2.0f * glm::pi<float>() * random.uniform();
            dir = glm::normalize(toDouble(model::directionAround(glm::vec3(dir), cosScatter, phi)));
        } else {
            // The ground: Lambertian at the atmosphere's ground albedo.
            p += dir * out.distance;
            const glm::dvec3 n = glm::normalize(p);
            p = n * (medium.bottomRadius() + 0.01); // just above the surface
            weight *= medium.groundAlbedo();
            const SunSample s = sampleSun(sun, channel, random);
            const double cosine = glm::dot(n, s.direction);
            if (cosine > 0.0) {
                const float tSun = sunTransmittanceAt(medium, p, s.direction, random);
                radiance += weight * float(cosine / glm::pi<double>()) * tSun * s.irradiance;
            }
            if (options.singleScattering)
                break;
            dir = glm::normalize(toDouble(sampleCosineDirection(glm::vec3(n), random)));
        }
        // Russian roulette on the weight (never above 1 here); survivors carry the lost share.
        if (weight < 1.0f) {
            if (random.uniform() >= weight)
                break;
            weight = 1.0f;
        }
    }
    return radiance;
}

SkyReferenceEstimate traceSkyReference(const model::SkyParams& sky, glm::vec3 position,
                                       glm::vec3 dir, uint64_t pathsPerChannel,
                                       const SkyReferenceOptions& options) {
    const SunLight sun = makeSunLight(sky);
    const glm::dvec3 centre(0.0, -double(sky.atmosphere.bottomRadius), 0.0);
    const glm::dvec3 start = toDouble(position) - centre;
    const glm::dvec3 view = glm::normalize(toDouble(dir));
    const uint64_t blocks = (pathsPerChannel + kBlock - 1) / kBlock;
    struct Sums {
        double sum = 0.0;
        double squares = 0.0;
        uint64_t truncated = 0;
    };
    std::vector<Sums> sums(static_cast<size_t>(blocks * 3));
    tbb::parallel_for(uint64_t(0), blocks * 3, [&](uint64_t task) {
        const int channel = static_cast<int>(task % 3);
        const uint64_t block = task / 3;
        const AtmosphereMedium medium(sky.atmosphere, channel);
        Random random(mixBits(options.seed) ^ mixBits(block), mixBits(task + 0x5c7));
        Sums& s = sums[task];
        const uint64_t end = std::min(pathsPerChannel, (block + 1) * kBlock);
        for (uint64_t i = block * kBlock; i < end; ++i) {
            bool truncated = false;
            const double x = traceSkyPath(medium, sun, start, view, random, options, truncated);
            s.sum += x;
            s.squares += x * x;
            s.truncated += truncated ? 1 : 0;
        }
    });
    SkyReferenceEstimate e;
    e.pathsPerChannel = pathsPerChannel;
    const double n = double(pathsPerChannel);
    for (int channel = 0; channel < 3; ++channel) {
        double sum = 0.0;
        double squares = 0.0;
        for (uint64_t block = 0; block < blocks; ++block) { // in order: deterministic
            sum += sums[block * 3 + channel].sum;
            squares += sums[block * 3 + channel].squares;
            e.truncated += sums[block * 3 + channel].truncated;
        }
        const double mean = sum / n;
        const double variance =
            std::max(squares / n - mean * mean, 0.0) * n / std::max(n - 1.0, 1.0);
        e.radiance[channel] = mean;
        e.standardError[channel] = std::sqrt(variance / n);
    }
    return e;
}

} // namespace cloudscape::pathtrace
