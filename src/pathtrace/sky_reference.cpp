// The sky's ground truth: see sky_reference.h. Plumbing: the light transport is
// air_integrator.h's, the medium's coefficients the model's (atmosphere_medium.h).
#include "pathtrace/sky_reference.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cloudscape::pathtrace {
namespace {

constexpr uint64_t kBlock = 1024; // paths per parallel task (and per random stream)

} // namespace

SkyReferenceEstimate traceSkyReference(const model::SkyParams& sky, glm::vec3 position,
                                       glm::vec3 dir, uint64_t pathsPerChannel,
                                       const SkyReferenceOptions& options) {
    const SunLight sun = makeSunLight(sky);
    AirPathOptions air;
    air.limits.maxBounces = options.maxBounces;
    air.singleScattering = options.singleScattering;
    const glm::dvec3 centre(0.0, -double(sky.atmosphere.bottomRadius), 0.0);
    const glm::dvec3 start = glm::dvec3(position) - centre;
    const glm::dvec3 view = glm::normalize(glm::dvec3(dir));
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
        PathCounters counters;
        for (uint64_t i = block * kBlock; i < end; ++i) {
            const double x =
                traceRadianceInAir(NoClouds{}, medium, sun, start, view, random, air, counters);
            s.sum += x;
            s.squares += x * x;
        }
        s.truncated = counters.truncated;
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
