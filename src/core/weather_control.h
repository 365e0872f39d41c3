#pragma once
// The weather controller of the Forbidden West talk ("Controlling Chaos"): every cycle it picks
// one of a set of locations, builds a storm there over a build-up time, holds it while it
// discharges, dissipates it and leaves the sky calm before the next cycle. Deterministic: the
// locations and the order they are visited in follow from the seed alone.
#include <cloudscape/scene.h>

#include <glm/vec2.hpp>

namespace cloudscape {

struct StormState {
    float blend = 0.0f;     // storm.blend times the cycle's envelope
    float spin = 0.0f;      // s: the integral of the blend since the storm began (vortex clock)
    glm::vec2 centre{0.0f}; // world xz (m)
    int cycle = 0;          // index of the cycle time_s falls in
    int site = 0;           // the location picked for it
    float phaseS = 0.0f;    // s since the cycle began (the controller's; 0 without it)
};

// Seconds of one cycle (build + hold + dissipate + calm).
float stormCyclePeriod(const Scene& scene);
// World xz of location i (0 <= i < storm.cycle_sites): inside the weather map, the whole storm
// radius within it.
glm::vec2 stormSite(const Scene& scene, int i);
// The storm at time t: the controller's when storm.cycle is on, otherwise the storm.* keys as
// they are (a constant blend: spin = blend * t).
StormState stormStateAt(const Scene& scene, float t);

} // namespace cloudscape
