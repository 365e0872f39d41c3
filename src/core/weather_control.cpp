#include "core/weather_control.h"

#include "core/fnv1a.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cloudscape {
namespace {

// A uniform number in [0, 1) from the seed and two integers (no global state).
float hashUnit(int seed, int a, int b) {
    const int32_t words[3] = {seed, a, b};
    const uint64_t h = fnv1a(words, sizeof words);
    return static_cast<float>((h >> 40) & 0xFFFFFF) / 16777216.0f;
}

// The envelope over one cycle: 0 -> 1 over the build-up, 1 while holding, 1 -> 0 over the
// dissipation, 0 while calm; and its integral from the cycle's start.
void envelope(const Scene& s, float phase, float& value, float& integral) {
    const float b = s.stormCycleBuildS, h = s.stormCycleHoldS, d = s.stormCycleDissipateS;
    if (phase < b) {
        value = phase / b;
        integral = 0.5f * phase * phase / b;
    } else if (phase < b + h) {
        value = 1.0f;
        integral = 0.5f * b + (phase - b);
    } else if (phase < b + h + d) {
        const float x = phase - b - h;
        value = 1.0f - x / d;
        integral = 0.5f * b + h + x - 0.5f * x * x / d;
    } else {
        value = 0.0f;
        integral = 0.5f * b + h + 0.5f * d;
    }
}

} // namespace

float stormCyclePeriod(const Scene& s) {
    return s.stormCycleBuildS + s.stormCycleHoldS + s.stormCycleDissipateS + s.stormCycleCalmS;
}

glm::vec2 stormSite(const Scene& s, int i) {
    // Inside the map with the whole radius (validateScene keeps the radius under half the map).
    const float room = std::max(s.weatherExtentM - 2.0f * s.stormRadiusM, 0.0f);
    const glm::vec2 origin(s.weatherOffsetXM, s.weatherOffsetZM);
    return origin + glm::vec2(hashUnit(s.seed, i, 1) - 0.5f, hashUnit(s.seed, i, 2) - 0.5f) * room;
}

StormState stormStateAt(const Scene& s, float t) {
    StormState state;
    if (!s.stormCycle) {
        state.blend = s.stormBlend;
        state.spin = s.stormBlend * t;
        state.centre = {s.stormXM, s.stormZM};
        return state;
    }
    const double period = stormCyclePeriod(s);
    const double cycle = std::floor(static_cast<double>(t) / period);
    const float phase = static_cast<float>(static_cast<double>(t) - cycle * period);
    state.cycle = static_cast<int>(std::min(cycle, 2.0e9));
    state.phaseS = phase;
    const int sites = std::max(s.stormCycleSites, 1);
    state.site =
        std::min(static_cast<int>(hashUnit(s.seed, state.cycle, 0) * float(sites)), sites - 1);
    state.centre = stormSite(s, state.site);
    float value = 0.0f, integral = 0.0f;
    envelope(s, phase, value, integral);
    state.blend = s.stormBlend * value;
    state.spin = s.stormBlend * integral;
    return state;
}

} // namespace cloudscape
