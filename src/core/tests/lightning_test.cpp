// The lightning schedule (src/core/lightning.cpp): a flash is 3 or 4 strokes about 57 ms apart,
// each a sharp rise and decay, dark after ~0.35 s; episodes of intra-cloud flashes growing in
// intensity, then 1 or 2 ground discharges with a bolt from the cloud base to the ground; only
// while the storm holds; the same seed gives the same flashes, another seed other ones; between
// flashes the state already names the next flash's position (its mask is built before it).
#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include "core/lightning.h"
#include "core/model_params.h"
#include "io/tests/refused_override.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using cloudscape::LightningState;
using cloudscape::Scene;

namespace {

Scene stormWithLightning() {
    Scene s;
    s.stormBlend = 1.0f;
    s.stormXM = 2000.0f;
    s.stormZM = 20000.0f;
    s.stormRadiusM = 15000.0f;
    s.stormLightning = true;
    s.stormLightningIntervalS = 3.0f;
    s.stormLightningIntraFlashes = 4;
    return s;
}

// The flashes (start, ground, peak) over [0, seconds) sampled every 10 ms.
struct Flash {
    int index;
    float start;
    bool ground;
    float peak;
    int strokes;
};
std::vector<Flash> flashesOver(const Scene& s, float from, float seconds) {
    std::vector<Flash> out;
    for (float t = from; t < from + seconds; t += 0.01f) {
        const LightningState l = cloudscape::lightningStateAt(s, t);
        if (!l.active || l.peak <= 0.0f)
            continue;
        if (out.empty() || out.back().index != l.flash)
            out.push_back({l.flash, l.startS, l.ground, l.peak, l.strokes});
    }
    return out;
}

} // namespace

TEST(Lightning, AFlashIsThreeOrFourStrokes57MsApartEachASharpRiseAndDecay) {
    for (int strokes = 3; strokes <= 4; ++strokes) {
        std::vector<float> peaks;
        float previous = 0.0f;
        bool rising = true;
        float risingFrom = 0.0f;
        for (float x = 0.0f; x < 0.5f; x += 0.0005f) {
            const float v = cloudscape::flashIntensityAt(x, strokes, 12345);
            if (rising && v < previous) {
                peaks.push_back(x - 0.0005f);
                // A sharp rise: from the previous trough to the peak in under 10 ms.
                EXPECT_LT(x - risingFrom, 0.012f) << strokes << " strokes, peak at " << x;
                rising = false;
            } else if (!rising && v > previous) {
                rising = true;
                risingFrom = x - 0.0005f;
            }
            previous = v;
        }
        ASSERT_EQ(peaks.size(), static_cast<size_t>(strokes));
        for (size_t i = 1; i < peaks.size(); ++i)
            EXPECT_NEAR(peaks[i] - peaks[i - 1], 0.057f, 0.015f);
        // The flash lasts about a quarter of a second and is dark after kFlashLifeS.
        EXPECT_GT(cloudscape::flashIntensityAt(0.2f, strokes, 12345), 0.0f);
        EXPECT_LT(cloudscape::flashIntensityAt(cloudscape::kFlashLifeS, strokes, 12345), 0.01f);
        // Between strokes it decays well below its peaks (a flicker, not a steady glow).
        EXPECT_LT(cloudscape::flashIntensityAt(0.050f, strokes, 12345), 0.3f);
    }
}

TEST(Lightning, EpisodesGrowThenDischargeToTheGroundWithABolt) {
    const Scene s = stormWithLightning();
    const std::vector<Flash> flashes = flashesOver(s, 0.0f, 60.0f);
    ASSERT_GE(flashes.size(), 12u);
    int grounds = 0, intraRun = 0;
    float lastIntraPeak = 0.0f;
    for (size_t i = 0; i < flashes.size(); ++i) {
        const Flash& f = flashes[i];
        if (!f.ground) {
            // Intra-cloud flashes of an episode grow in intensity.
            if (intraRun > 0) {
                EXPECT_GT(f.peak, lastIntraPeak);
            }
            lastIntraPeak = f.peak;
            ++intraRun;
            EXPECT_LE(intraRun, 4);
            EXPECT_LT(f.peak, 1.0f);
        } else {
            EXPECT_EQ(f.peak, 1.0f);
            ++grounds;
            intraRun = 0;
        }
        EXPECT_TRUE(f.strokes == 3 || f.strokes == 4);
        if (i > 0) {
            EXPECT_GT(f.start - flashes[i - 1].start, 1.0f); // room for the next mask
        }
    }
    EXPECT_GT(grounds, 2);
    // A ground discharge's bolt runs from the cloud base down to the ground, near the storm.
    for (float t = 0.0f; t < 60.0f; t += 0.01f) {
        const LightningState l = cloudscape::lightningStateAt(s, t);
        if (!l.ground || l.intensity <= 0.0f)
            continue;
        const float baseAltitude =
            glm::length(l.boltTop - glm::vec3(0, -s.planetRadiusM, 0)) - s.planetRadiusM;
        const float groundAltitude =
            glm::length(l.boltBottom - glm::vec3(0, -s.planetRadiusM, 0)) - s.planetRadiusM;
        EXPECT_NEAR(baseAltitude, s.cloudBottomM, 1.0f);
        EXPECT_NEAR(groundAltitude, 0.0f, 1.0f);
        EXPECT_LT(glm::length(glm::vec2(l.boltTop.x - s.stormXM, l.boltTop.z - s.stormZM)),
                  0.31f * s.stormRadiusM);
        break;
    }
}

TEST(Lightning, TheSameSeedGivesTheSameFlashesAnotherSeedOthers) {
    Scene a = stormWithLightning();
    const std::vector<Flash> first = flashesOver(a, 0.0f, 40.0f);
    const std::vector<Flash> again = flashesOver(a, 0.0f, 40.0f);
    ASSERT_EQ(first.size(), again.size());
    for (size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i].start, again[i].start);
        EXPECT_EQ(first[i].strokes, again[i].strokes);
    }
    Scene b = a;
    b.seed = 7;
    const std::vector<Flash> other = flashesOver(b, 0.0f, 40.0f);
    int differentStarts = 0;
    for (size_t i = 0; i < std::min(first.size(), other.size()); ++i)
        differentStarts += std::abs(first[i].start - other[i].start) > 0.02f;
    EXPECT_GT(differentStarts, 3);
}

TEST(Lightning, BetweenFlashesTheStateNamesTheNextFlashSoItsMaskIsBuilt) {
    const Scene s = stormWithLightning();
    const std::vector<Flash> flashes = flashesOver(s, 0.0f, 20.0f);
    ASSERT_GE(flashes.size(), 3u);
    const Flash& next = flashes[1];
    // From the end of the flash before until this one starts, the position is already this one's
    // and the intensity is 0; then it lights up at the same position.
    const LightningState during = cloudscape::lightningStateAt(s, next.start + 0.002f);
    for (float t = flashes[0].start + cloudscape::kFlashLifeS + 0.01f; t < next.start; t += 0.05f) {
        const LightningState l = cloudscape::lightningStateAt(s, t);
        EXPECT_EQ(l.flash, next.index);
        EXPECT_EQ(l.intensity, 0.0f);
        EXPECT_EQ(l.position, during.position);
    }
    EXPECT_GT(during.intensity, 0.0f);
}

TEST(Lightning, OnlyWhileTheStormHoldsAndNothingWhenOff) {
    Scene s = stormWithLightning();
    s.stormCycle = true;
    s.stormCycleBuildS = 60.0f;
    s.stormCycleHoldS = 30.0f;
    s.stormCycleDissipateS = 60.0f;
    s.stormCycleCalmS = 30.0f;
    EXPECT_TRUE(flashesOver(s, 0.0f, 60.0f).empty());    // building
    EXPECT_FALSE(flashesOver(s, 60.0f, 30.0f).empty());  // holding
    EXPECT_TRUE(flashesOver(s, 90.0f, 90.0f).empty());   // dissipating, calm
    EXPECT_FALSE(flashesOver(s, 240.0f, 30.0f).empty()); // the next cycle's hold
    // No flash outlasts the hold.
    for (const Flash& f : flashesOver(s, 60.0f, 30.0f))
        EXPECT_LE(f.start + cloudscape::kFlashLifeS, 90.0f + 1e-3f);
    // Off: the model's lightning block stays zero.
    Scene off = stormWithLightning();
    off.stormLightning = false;
    off.timeS = 10.0f;
    const auto p = cloudscape::makeCloudParams(off, 0.0f);
    EXPECT_EQ(p.lightning.enabled, 0);
    EXPECT_EQ(p.lightning.flashIntensity, 0.0f);
    Scene on = stormWithLightning();
    on.timeS = 10.0f;
    EXPECT_EQ(cloudscape::makeCloudParams(on, 0.0f).lightning.enabled, 1);
}

TEST(Lightning, BadInputIsRefusedNamingTheKey) {
    const auto refuses = expectOverrideRefusedNaming;
    refuses("storm.lightning_interval_s=0.5", "storm.lightning_interval_s");
    refuses("storm.lightning_radius_m=-1", "storm.lightning_radius_m");
    refuses("storm.lightning_strength=nan", "storm.lightning_strength");
    refuses("storm.lightning_intra_flashes=0", "storm.lightning_intra_flashes");
    refuses("storm.lightning_colour=[1,-1,0]", "storm.lightning_colour");
    refuses("storm.bolt_width_m=0", "storm.bolt_width_m");
    refuses("storm.lightning=maybe", "storm.lightning");
    // A hold shorter than the flash interval does not fit a flash: refused naming both keys.
    Scene s = stormWithLightning();
    s.stormCycle = true;
    s.stormCycleHoldS = 2.0f;
    try {
        cloudscape::validateScene(s, "test");
        ADD_FAILURE() << "a hold shorter than the lightning interval was accepted";
    } catch (const cloudscape::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("storm.cycle_hold_s"), std::string::npos) << m;
        EXPECT_NE(m.find("storm.lightning_interval_s"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
}
