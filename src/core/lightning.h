#pragma once
// The lightning system of the Forbidden West talk ("Lightning Effects"), on the host: while a
// storm holds (the weather controller's hold phase, or a constant storm), flashes fire one every
// storm.lightning_interval_s (jittered from the seed) in episodes: several intra-cloud flashes of
// growing intensity, then 1 or 2 ground discharges. A flash lasts about 0.25 s: 3 or 4 strokes
// about 57 ms apart (Uman, "Lightning"), each a sharp rise and an exponential decay. Everything
// follows from the seed and the storm's cycle, so the same scene gives the same flashes.
//
// Between flashes the state already names the next flash's position (intensity 0): the renderer
// builds that flash's mask over the frames before it (lightning.glsl.h).
#include <cloudscape/scene.h>

#include <glm/vec3.hpp>

namespace cloudscape {

constexpr float kStrokeSpacingS = 0.057f; // Uman: strokes of a flash about 57 ms apart
constexpr float kStrokeRiseS = 0.004f;    // a stroke's sharp rise
constexpr float kStrokeDecayS = 0.035f;   // and its decay's time constant
constexpr float kFlashLifeS = 0.35f;      // after this a flash is dark (4 strokes and their decay)

struct LightningState {
    bool active = false;        // a storm is holding and storm.lightning is on
    int flash = -1;             // index of the current (or next) flash on the storm's timeline
    bool ground = false;        // that flash is a ground discharge
    float startS = 0.0f;        // its start, on time_s's clock
    float peak = 0.0f;          // its peak intensity (intra-cloud flashes grow toward 1)
    int strokes = 0;            // 3 or 4
    glm::vec3 position{0.0f};   // world (m): the flash's centre
    float intensity = 0.0f;     // now (0 before and after the flash)
    glm::vec3 boltTop{0.0f};    // ground discharge: leaves the cloud base here
    glm::vec3 boltBottom{0.0f}; // and meets the ground here
    int boltSeed = 0;
};

// Intensity (0 .. 1 per stroke) of a flash of `strokes` strokes at time x (s) after its start;
// the strokes' amplitudes and small timing jitters follow from key.
float flashIntensityAt(float x, int strokes, int key);

// The lightning at time t (s) of a scene (inactive unless storm.lightning is on and the storm
// holds at t).
LightningState lightningStateAt(const Scene& scene, float t);

} // namespace cloudscape
