#include "core/lightning.h"

#include "core/fnv1a.h"
#include "core/weather_control.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace cloudscape {
namespace {

// A uniform number in [0, 1) from the seed and three integers (no global state).
float unitHash(int seed, int a, int b, int c) {
    const int32_t words[5] = {seed, a, b, c, 0x4c696768}; // "Ligh": apart from other streams
    const uint64_t h = fnv1a(words, sizeof words);
    return static_cast<float>((h >> 40) & 0xFFFFFF) / 16777216.0f;
}

float strokePulse(float x) {
    if (x < 0.0f)
        return 0.0f;
    if (x < kStrokeRiseS)
        return x / kStrokeRiseS;
    return std::exp(-(x - kStrokeRiseS) / kStrokeDecayS);
}

// World position at altitude h (m) above the ground point below world xz (the planet's centre is
// at (0, -radius, 0)).
glm::vec3 atAltitude(const Scene& s, glm::vec2 xz, float h) {
    const glm::vec3 centre(0.0f, -s.planetRadiusM, 0.0f);
    const glm::vec3 up = glm::normalize(glm::vec3(xz.x, 0.0f, xz.y) - centre);
    return centre + up * (s.planetRadiusM + h);
}

// A point uniformly distributed in a disc of radius r about c, from two hashes.
glm::vec2 inDisc(glm::vec2 c, float r, float u, float v) {
    const float angle = 6.2831853f * u;
    return c + glm::vec2(std::cos(angle), std::sin(angle)) * (r * std::sqrt(v));
}

} // namespace

float flashIntensityAt(float x, int strokes, int key) {
    float sum = 0.0f;
    for (int j = 0; j < strokes; ++j) {
        const float amplitude = j == 0 ? 1.0f : 0.5f + 0.4f * unitHash(key, j, 1, 0);
        const float jitter = j == 0 ? 0.0f : 0.02f * (unitHash(key, j, 2, 0) - 0.5f);
        sum += amplitude * strokePulse(x - (float(j) * kStrokeSpacingS + jitter));
    }
    return std::min(sum, 1.0f);
}

LightningState lightningStateAt(const Scene& s, float t) {
    LightningState state;
    const StormState storm = stormStateAt(s, t);
    if (!s.stormLightning || storm.blend <= 0.0f)
        return state;
    // The storm's timeline: the hold phase of the controller's cycle, or all of time_s.
    float timeline = t;
    float holdEnd = 1e30f;
    if (s.stormCycle) {
        timeline = storm.phaseS - s.stormCycleBuildS;
        holdEnd = s.stormCycleHoldS;
        if (timeline < 0.0f || timeline >= holdEnd)
            return state;
    }
    const float interval = s.stormLightningIntervalS;
    const int slots = s.stormLightningIntraFlashes + 2; // intra-cloud flashes, then 2 ground slots
    auto startOf = [&](int k) {
        return float(k) * interval + 0.5f * interval * unitHash(s.seed, storm.cycle, k, 0);
    };
    int k = static_cast<int>(std::floor(timeline / interval));
    if (timeline >= startOf(k) + kFlashLifeS)
        ++k; // the current flash is over: the state names the next one (its mask is built)
    const float start = startOf(k);
    const int slot = k % slots;
    const int episode = k / slots;
    const bool twoGround = unitHash(s.seed, storm.cycle, episode, 1) < 0.5f;
    state.active = true;
    state.flash = k;
    state.ground = slot >= s.stormLightningIntraFlashes;
    // Intra-cloud flashes grow in intensity toward the ground discharge; the second ground slot
    // fires only in episodes of two; a flash that would outlast the hold does not fire.
    if (!state.ground)
        state.peak =
            0.3f + 0.5f * float(slot) / float(std::max(s.stormLightningIntraFlashes - 1, 1));
    else
        state.peak = slot == s.stormLightningIntraFlashes || twoGround ? 1.0f : 0.0f;
    if (start + kFlashLifeS > holdEnd)
        state.peak = 0.0f;
    state.startS = t + (start - timeline);
    state.strokes = unitHash(s.seed, storm.cycle, k, 2) < 0.5f ? 3 : 4;
    const int key = static_cast<int>(unitHash(s.seed, storm.cycle, k, 3) * 16777216.0f);
    state.intensity = state.peak > 0.0f
                          ? state.peak * flashIntensityAt(timeline - start, state.strokes, key)
                          : 0.0f;

    // Where: inside the mesocyclone's foot (0.3 storm radii), intra-cloud flashes about the glow's
    // altitude, ground discharges low in the cloud above the bolt.
    const glm::vec2 xz =
        inDisc(storm.centre, 0.3f * s.stormRadiusM, unitHash(s.seed, storm.cycle, k, 4),
               unitHash(s.seed, storm.cycle, k, 5));
    const float low = s.cloudBottomM + 300.0f, high = std::max(s.cloudTopM - 500.0f, low);
    if (!state.ground) {
        const float h =
            s.stormGlowAltitudeM + 2000.0f * (unitHash(s.seed, storm.cycle, k, 6) - 0.5f);
        state.position = atAltitude(s, xz, std::clamp(h, low, high));
        return state;
    }
    state.position = atAltitude(s, xz, std::min(s.cloudBottomM + 1000.0f, high));
    state.boltTop = atAltitude(s, xz, s.cloudBottomM);
    const glm::vec2 foot = inDisc(xz, 1500.0f, unitHash(s.seed, storm.cycle, k, 7),
                                  unitHash(s.seed, storm.cycle, k, 8));
    state.boltBottom = atAltitude(s, foot, 0.0f);
    state.boltSeed = static_cast<int>(unitHash(s.seed, storm.cycle, k, 9) * 16777216.0f);
    return state;
}

} // namespace cloudscape
