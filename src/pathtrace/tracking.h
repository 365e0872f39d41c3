#pragma once
// Free-flight sampling and transmittance in a heterogeneous medium, the two unbiased estimators
// of Woodcock et al. (1965) and Novak et al. (2014):
//  - delta tracking samples the distance to a real collision: tentative collisions are drawn
//    against a majorant sigma_max >= sigma_t and accepted with probability sigma_t / sigma_max;
//  - ratio tracking estimates transmittance as the product of (1 - sigma_t / sigma_max) over the
//    tentative collisions, which has far less variance than counting survivals.
// A medium supplies piecewise-constant majorants along a ray (forEachSegment) and sigma_t at a
// point; both estimators are exact whatever the majorant, as long as it bounds sigma_t.
#include "pathtrace/random.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace cloudscape::pathtrace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Counts of majorant violations (sigma_t > sigma_max), which would bias both estimators; the
// media are built so that this stays zero, and the tests check it.
inline std::atomic<uint64_t>& majorantViolations() {
    static std::atomic<uint64_t> count{0};
    return count;
}

inline void checkMajorant(float sigma, float majorant) {
    if (sigma > majorant * 1.0001f)
        majorantViolations().fetch_add(1, std::memory_order_relaxed);
}

// Distance to the first real collision along origin + t dir for t < tMax, or kInfinity.
template <class Medium>
float sampleCollision(const Medium& medium, glm::vec3 origin, glm::vec3 dir, float tMax,
                      Random& random) {
    float hit = kInfinity;
    medium.forEachSegment(origin, dir, tMax, [&](float t0, float t1, float majorant) {
        if (majorant <= 0.0f)
            return false;
        float t = t0;
        while (true) {
            t -= std::log(1.0f - random.uniform()) / majorant;
            if (t >= t1)
                return false; // memoryless: continue in the next segment
            const float sigma = medium.sigmaT(origin + dir * t);
            checkMajorant(sigma, majorant);
            if (random.uniform() * majorant < sigma) {
                hit = t;
                return true;
            }
        }
    });
    return hit;
}

// Transmittance from origin to origin + tMax dir. Once the estimate falls below rouletteBelow,
// Russian roulette ends it early without bias (survivors are reweighted): right for shadow rays,
// where small transmittances matter little, but it adds variance, so estimating a small
// transmittance itself calls for rouletteBelow = 0.
template <class Medium>
float estimateTransmittance(const Medium& medium, glm::vec3 origin, glm::vec3 dir, float tMax,
                            Random& random, float rouletteBelow = 0.1f) {
    float transmittance = 1.0f;
    medium.forEachSegment(origin, dir, tMax, [&](float t0, float t1, float majorant) {
        if (majorant <= 0.0f)
            return false;
        float t = t0;
        while (true) {
            t -= std::log(1.0f - random.uniform()) / majorant;
            if (t >= t1)
                return false;
            const float sigma = medium.sigmaT(origin + dir * t);
            checkMajorant(sigma, majorant);
            transmittance *= std::max(1.0f - sigma / majorant, 0.0f);
            if (transmittance <= 0.0f)
                return true;
            if (transmittance < rouletteBelow) {
                if (random.uniform() < 0.5f) {
                    transmittance = 0.0f;
                    return true;
                }
                transmittance *= 2.0f;
            }
        }
    });
    return transmittance;
}

} // namespace cloudscape::pathtrace
