#pragma once
// Test support shared by the CPU and GPU test binaries: a small view from under a superstorm
// with lightning on (the under-the-storm preset's storm), and the start of its first flash.
#include <cloudscape/scene.h>

#include "core/lightning.h"

namespace cloudscape::testing {

inline Scene underALightningStorm() {
    Scene s;
    s.width = 48;
    s.height = 28;
    s.cloudTopM = 12000.0f;
    s.highCloudAltitudeM = 13000.0f; // the storm's cirrus lies above the clouds (validateScene)
    s.weatherExtentM = 150000.0f;
    s.coverage = 0.1f;
    s.stormBlend = 1.0f;
    s.stormZM = 3000.0f;
    s.stormRadiusM = 19000.0f;
    s.stormGlowStrength = 6.0f;
    s.stormLightDensityScale = 8.0f;
    s.cameraPitchDeg = 35.0f;
    s.stormLightning = true;
    // A flash that outshines the daylit storm (the default, 8, is tuned for looks), so the tests
    // measure the flash and not the noise around it.
    s.stormLightningStrength = 300.0f;
    return s;
}

// The start (s) of the first flash after 1 s, searched in 5 ms steps over two minutes; -1 if
// there is none.
inline float firstFlashStart(const Scene& s) {
    for (float t = 1.0f; t < 120.0f; t += 0.005f) {
        const LightningState l = lightningStateAt(s, t);
        if (l.peak > 0.0f)
            return l.startS;
    }
    return -1.0f;
}

} // namespace cloudscape::testing
