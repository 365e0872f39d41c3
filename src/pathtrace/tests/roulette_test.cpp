// Russian roulette must not bias the estimate: in a white furnace (albedo 1, radiance 1 arriving
// from every direction) the radiance is 1 everywhere, so with the fixed roulette applied from the
// very first event, not only after 64, every path faces it many times and any survival that is
// not compensated by the weight shows. (The validation tests' paths rarely reach event 64.)
#include "pathtrace/integrator.h"
#include "pathtrace/slab_medium.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pt = cloudscape::pathtrace;
namespace cm = cloudscape::model;

TEST(PathTraceRoulette, AWhiteFurnaceStaysWhiteWithRouletteFromTheFirstEvent) {
    pt::BoxMedium box;
    box.lower = glm::vec3(-1e5f, 0.0f, -1e5f);
    box.upper = glm::vec3(1e5f, 4.0f, 1e5f);
    box.phaseFunction = cm::makePhaseFunction(cm::PHASE_HG, glm::vec4(0.6f));
    auto white = [](glm::vec3, bool) { return glm::vec3(1.0f); };
    pt::PathLimits limits;
    limits.rouletteAfter = 0;
    const int n = 40000;
    double sum = 0.0, sumSq = 0.0;
    uint64_t collisions = 0;
    pt::Random random(pt::mixBits(77), 0);
    for (int i = 0; i < n; ++i) {
        pt::PathCounters counters;
        const double l = pt::traceRadiance(
                             box, pt::SunLight{}, pt::Ground{}, white, glm::vec3(0.0f, 2.0f, 0.0f),
                             glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), random, limits, counters)
                             .x;
        sum += l;
        sumSq += l * l;
        collisions += counters.collisions;
    }
    const double mean = sum / n;
    const double se = std::sqrt(std::max(sumSq / n - mean * mean, 0.0) / n);
    EXPECT_GT(static_cast<double>(collisions) / n, 3.0) << "paths must face the roulette often";
    EXPECT_LT(se, 0.01);
    EXPECT_NEAR(mean, 1.0, 4.0 * se + 1e-6);
}
