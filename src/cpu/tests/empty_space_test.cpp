// Empty-space skipping (model/cloud_bound.glsl.h, march.glsl.h): the grid of column tops must
// bound the density everywhere, including the storm and its anvil; the march that skips must be
// exactly the unskipped one when every step is a full sample, and within a stated transmittance
// error of it as shipped (coarse/fine), over presets with the storm, terrain, the high layer and
// thin cloud; and it must take fewer texture-reading samples.
#include <cloudscape/noise.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "core/cloud_top_grid.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_cloud_shadow.h"
#include "cpu/cpu_model.h"
#include "model/cloud_bound.glsl.h"
#include "model/cloud_shadow.glsl.h"
#include "model/march.glsl.h"
#include "model/noise_clearance.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using cloudscape::RenderResult;
using cloudscape::Scene;
using cloudscape::SceneResources;
namespace cm = cloudscape::model;

namespace {

const cloudscape::NoiseTextures& smallNoise() {
    static const cloudscape::NoiseTextures noise = [] {
        cloudscape::NoiseTextures n;
        n.base = cloudscape::generateBaseNoise(1, 32);
        n.detail = cloudscape::generateDetailNoise(1, 16);
        n.curl = cloudscape::generateCurlNoise(1, 32);
        return n;
    }();
    return noise;
}

Scene preset(const std::string& name) {
    Scene s = cloudscape::loadScene(cloudscape::resolveScenePath(name));
    s.width = 64;
    s.height = 36;
    return s;
}

SceneResources resourcesFor(const Scene& s) {
    SceneResources r;
    r.noise = smallNoise();
    r.weather = cloudscape::prepareWeather(s);
    cloudscape::prepareDataField(s, r);
    return r;
}

// The textures a density evaluation reads, bound to a thread by the tests that evaluate it.
cloudscape::cpu::TextureSet texturesOf(const SceneResources& r) {
    cloudscape::cpu::TextureSet set;
    set.baseNoise = &r.noise.base;
    set.detailNoise = &r.noise.detail;
    set.curlNoise = &r.noise.curl;
    set.weatherMap = &r.weather;
    set.noiseClearance = r.noise.baseClearance.empty() ? nullptr : r.noise.baseClearance.data();
    return set;
}

// Presets that exercise every part of the bound: plain cumulus, thin stratus, the storm (raised
// coverage and type, the anvil at the layer top), a camera above and inside the layer.
const std::vector<std::string>& presets() {
    static const std::vector<std::string> names = {
        "fair-weather-cumulus", "overcast-stratus", "broken-stratocumulus", "superstorm",
        "under-the-storm",      "above-the-deck",   "inside-cloud"};
    return names;
}

} // namespace

TEST(EmptySpace, ColumnTopsBoundTheDensityEverywhere) {
    // Random points over the whole map (every cell) and the whole layer: wherever the full
    // density is non-zero, the point lies below its cell's top. A bound that forgot the storm,
    // the anvil or the precipitation rule fails here.
    // The last case adds a data field: regions with raised bases, lowered tops, ragged bottoms
    // and a painted anvil (a bound that forgot the region's layer or the anvil channel fails).
    for (const std::string name :
         {"fair-weather-cumulus", "superstorm", "rain-storm", "fair-weather-cumulus+field"}) {
        const bool field = name.find("+field") != std::string::npos;
        Scene s = preset(field ? name.substr(0, name.find('+')) : name);
        if (field) {
            s.baseVariation = 0.4f;
            s.topVariation = 0.6f;
            s.bottomType = 0.5f;
        }
        SceneResources r = resourcesFor(s);
        if (field)
            for (int j = 10; j < 20; ++j)
                for (int i = 40; i < 52; ++i)
                    r.dataField[size_t(j) * cm::DATA_FIELD_GRID + i].y = 0.8f;
        const cm::CloudParams P = cloudscape::makeCloudParams(s, r);
        ASSERT_EQ(P.dataFieldEnabled, field ? 1 : 0) << name;
        ASSERT_EQ(P.emptySpaceSkipping, 1) << name;
        const cloudscape::cpu::TextureSet set = texturesOf(r);
        const cloudscape::cpu::ScopedTextureBinding bind(set);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> xz(-0.5f * P.weatherExtent, 0.5f * P.weatherExtent);
        std::uniform_real_distribution<float> alt(P.layerBottom, P.layerTop);
        int cloudy = 0;
        int emptyCells = 0;
        for (int i = 0; i < 200000; ++i) {
            const glm::vec2 w = glm::vec2(xz(rng), xz(rng)) + P.weatherOrigin;
            // A point at altitude a above the planet, over (x, z).
            const float a = alt(rng);
            const float y =
                std::sqrt((P.planetRadius + a) * (P.planetRadius + a) - w.x * w.x - w.y * w.y) -
                P.planetRadius;
            const glm::vec3 p(w.x, y, w.y);
            const float top = cm::cloudTopOf(cm::cloudTopCell(w, P), P);
            emptyCells += top == cm::CLOUD_TOP_EMPTY ? 1 : 0;
            if (cm::cloudDensityAt(p, 0.0f, false, P) <= 0.0f)
                continue;
            ++cloudy;
            const float altitude = cm::altitudeOf(p, P.planetRadius);
            ASSERT_LT(altitude, top) << name << " at " << p.x << "," << p.y << "," << p.z;
            ASSERT_LT(altitude, P.cloudTopMax) << name;
        }
        std::printf("%-22s %d cloudy points of 200000, %d in empty cells, highest top %.0f m\n",
                    name.c_str(), cloudy, emptyCells, P.cloudTopMax);
        EXPECT_GT(cloudy, 100) << name << ": the test must see cloud";
    }
}

TEST(EmptySpace, SkippingIsExactWhenEveryStepIsAFullSample) {
    for (const std::string& name : presets()) {
        Scene s = preset(name);
        s.coarseStepFactor = 1;
        s.stepOptimisation = 0.0f;
        const SceneResources r = resourcesFor(s);
        s.emptySpaceSkipping = false;
        const RenderResult plain = cloudscape::renderCpu(s, r);
        s.emptySpaceSkipping = true;
        const RenderResult skipped = cloudscape::renderCpu(s, r);
        EXPECT_EQ(plain.cloud, skipped.cloud) << name;
        EXPECT_EQ(plain.composite, skipped.composite) << name;
        EXPECT_LT(skipped.stats.densitySamples, plain.stats.densitySamples) << name;
        EXPECT_EQ(plain.stats.emptySkips, 0u);
        std::printf("%-22s density samples %llu -> %llu (%llu skips)\n", name.c_str(),
                    static_cast<unsigned long long>(plain.stats.densitySamples),
                    static_cast<unsigned long long>(skipped.stats.densitySamples),
                    static_cast<unsigned long long>(skipped.stats.emptySkips));
    }
}

TEST(EmptySpace, ShippedMarchKeepsTheTransmittance) {
    // As shipped (coarse/fine): a jump restarts the coarse lattice where it lands, so a cloud
    // thinner than a coarse step may be found or missed differently. The transmittance error
    // against the unskipped march over every pixel: mean under 0.002, worst pixel under 0.1
    // (a single pixel at a thin edge), and the skipping must not lose cloud on the whole: the
    // mean signed difference stays under 0.001 (figures in docs/PERFORMANCE.md).
    for (const std::string& name : presets()) {
        Scene s = preset(name);
        const SceneResources r = resourcesFor(s);
        s.emptySpaceSkipping = false;
        const RenderResult plain = cloudscape::renderCpu(s, r);
        s.emptySpaceSkipping = true;
        const RenderResult skipped = cloudscape::renderCpu(s, r);
        double sumAbs = 0.0, sumSigned = 0.0, worst = 0.0;
        const size_t pixels = plain.cloud.size() / 4;
        for (size_t i = 0; i < pixels; ++i) {
            const double d = double(skipped.cloud[4 * i + 3]) - double(plain.cloud[4 * i + 3]);
            sumAbs += std::abs(d);
            sumSigned += d;
            worst = std::max(worst, std::abs(d));
        }
        const double meanAbs = sumAbs / double(pixels);
        const double meanSigned = sumSigned / double(pixels);
        std::printf("%-22s transmittance error mean %.5f signed %+.5f worst %.4f; density samples "
                    "%llu -> %llu\n",
                    name.c_str(), meanAbs, meanSigned, worst,
                    static_cast<unsigned long long>(plain.stats.densitySamples),
                    static_cast<unsigned long long>(skipped.stats.densitySamples));
        EXPECT_LT(meanAbs, 0.002) << name;
        EXPECT_LT(std::abs(meanSigned), 0.001) << name;
        EXPECT_LT(worst, 0.1) << name;
        EXPECT_LE(skipped.stats.densitySamples, plain.stats.densitySamples) << name;
    }
}

TEST(EmptySpace, TheShadowMapSkipsExactly) {
    // The shadow map's rays skip what the grid proves empty (nextShadowSample): the map must be
    // bit for bit the unskipped one, the skipping must have had something to skip (a share of
    // the rays' samples at provably empty points), and the map must really consult the grid (one
    // that calls everything empty makes an empty map), else the equality proves nothing.
    int mapsCompared = 0;
    for (const std::string name :
         {"fair-weather-cumulus", "superstorm", "mountains", "rain-storm", "overcast-stratus",
          "broken-stratocumulus", "fly-through", "storm-cycle"}) {
        Scene s = preset(name);
        s.cloudShadowEnabled = true;
        s.cloudShadowResolution = 64;
        const SceneResources r = resourcesFor(s);
        cm::CloudParams P = cloudscape::makeCloudParams(s, r);
        if (!cm::cloudShadowMapUsable(P))
            continue;
        const cloudscape::cpu::TextureSet set = texturesOf(r);
        ASSERT_EQ(P.emptySpaceSkipping, 1) << name;
        const std::vector<glm::vec4> skipped = cloudscape::cpu::computeCloudShadowMap(P, set);
        P.emptySpaceSkipping = 0;
        const std::vector<glm::vec4> plain = cloudscape::cpu::computeCloudShadowMap(P, set);
        ASSERT_EQ(plain.size(), skipped.size()) << name;
        EXPECT_TRUE(std::memcmp(plain.data(), skipped.data(), plain.size() * sizeof(glm::vec4)) ==
                    0)
            << name;
        cm::CloudParams nothing = P;
        for (glm::vec4& four : nothing.cloudTops)
            four = glm::vec4(cm::CLOUD_TOP_EMPTY);
        nothing.cloudTopMax = cm::CLOUD_TOP_EMPTY;
        EXPECT_EQ(cloudscape::cpu::computeCloudShadowMap(nothing, set), plain)
            << name << ": without skipping the grid is not read";
        nothing.emptySpaceSkipping = 1;
        for (const glm::vec4& t : cloudscape::cpu::computeCloudShadowMap(nothing, set))
            ASSERT_EQ(t, glm::vec4(0.0f)) << name << ": an empty grid must skip every sample";
        P.emptySpaceSkipping = 1;
        // Provably empty sample points along the rays of a row of texels, and cloud in the map.
        const cloudscape::cpu::ScopedTextureBinding bind(set);
        const glm::vec3 sun = cm::cloudLightDirection(P.sky);
        int points = 0;
        int empty = 0;
        for (int i = 0; i < P.cloudShadow.resolution; ++i) {
            const glm::vec3 o = cm::cloudShadowTexelOrigin(glm::ivec2(i, i), P.cloudShadow);
            const glm::vec4 spans =
                cm::shellIntervals(o, sun, P.planetRadius, P.layerBottom, P.layerTop);
            for (int k = 0; k < 16; ++k) {
                const glm::vec3 p = o + sun * (spans.x + (k + 0.5f) / 16.0f * (spans.y - spans.x));
                ++points;
                empty += cm::provablyEmptyDistance(p, sun, cm::altitudeOf(p, P.planetRadius), P) >
                                 0.0f
                             ? 1
                             : 0;
            }
        }
        float depth = 0.0f;
        for (const glm::vec4& t : skipped)
            depth += t.z;
        std::printf("%-22s shadow-map samples provably empty: %d of %d; total depth %.1f\n",
                    name.c_str(), empty, points, depth);
        EXPECT_GT(empty, points / 10) << name << ": the skipping must have something to skip";
        EXPECT_GT(depth, 0.0f) << name << ": the map must see cloud";
        ++mapsCompared;
    }
    EXPECT_GE(mapsCompared, 8);
}

namespace {

// CloudParams over a 32 km weather map centred at the origin: 1 km cells, the cell (16, 16)
// covering x and z in [0, 1000] m. Every column empty unless a test raises one.
cm::CloudParams kilometreCells() {
    const Scene s = preset("fair-weather-cumulus");
    cm::CloudParams P = cloudscape::makeCloudParams(s, resourcesFor(s));
    P.weatherExtent = 32000.0f;
    P.weatherOrigin = glm::vec2(0.0f);
    for (glm::vec4& four : P.cloudTops)
        four = glm::vec4(cm::CLOUD_TOP_EMPTY);
    return P;
}

void setTop(cm::CloudParams& P, int x, int z, float top) {
    const int index = z * cm::CLOUD_TOP_GRID + x;
    P.cloudTops[index / 4][index % 4] = top;
    P.cloudTopMax = std::max(P.cloudTopMax, top);
}

} // namespace

TEST(EmptySpace, CellExitIsTheNearerSideWorkedByHand) {
    // From (100, 200) in the cell [0, 1000]^2: heading (0.6, 0.8) the ray reaches z = 1000 after
    // 800 / 0.8 = 1000 m, before x = 1000 (900 / 0.6 = 1500 m); heading (-0.8, -0.6) it reaches
    // x = 0 after 100 / 0.8 = 125 m, before z = 0 (200 / 0.6 = 333 m). Along an axis the other
    // side never comes.
    const cm::CloudParams P = kilometreCells();
    const glm::vec3 p(100.0f, 1500.0f, 200.0f);
    const glm::ivec2 cell(16, 16);
    ASSERT_EQ(cm::cloudTopCell(glm::vec2(p.x, p.z), P), cell);
    EXPECT_NEAR(cm::cloudTopCellExit(p, glm::vec3(0.6f, 0.0f, 0.8f), cell, P), 1000.0f, 0.01f);
    EXPECT_NEAR(cm::cloudTopCellExit(p, glm::vec3(-0.8f, 0.0f, -0.6f), cell, P), 125.0f, 0.01f);
    EXPECT_NEAR(cm::cloudTopCellExit(p, glm::vec3(1.0f, 0.0f, 0.0f), cell, P), 900.0f, 0.01f);
    EXPECT_NEAR(cm::cloudTopCellExit(p, glm::vec3(0.0f, 0.6f, -0.8f), cell, P), 250.0f, 0.01f);
    // A ray straight up never leaves the column sideways.
    EXPECT_GT(cm::cloudTopCellExit(p, glm::vec3(0.0f, 1.0f, 0.0f), cell, P), 1.0e30f);
}

TEST(EmptySpace, SkipStopsWhereTheRayEntersACloudyColumn) {
    // An empty column beside one whose clouds reach 3 km: a level ray at 1.5 km crossing from
    // the empty one into the cloudy one may skip only to the shared side (x = 1000), not past it.
    cm::CloudParams P = kilometreCells();
    P.cloudTopMax = cm::CLOUD_TOP_EMPTY;
    setTop(P, 17, 16, 3000.0f);
    const glm::vec3 p(100.0f, 1500.0f, 200.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, 0.0f, 0.1f));
    const float altitude = cm::altitudeOf(p, P.planetRadius);
    const float skip = cm::provablyEmptyDistance(p, dir, altitude, P);
    EXPECT_NEAR(skip, 900.0f / dir.x, 0.05f);
    const glm::vec3 landing = p + dir * skip;
    EXPECT_NEAR(landing.x, 1000.0f, 0.01f);
    // Just past the landing the column holds cloud at this altitude: nothing to skip.
    const glm::vec3 inside = landing + dir * 0.5f;
    EXPECT_EQ(cm::provablyEmptyDistance(inside, dir, cm::altitudeOf(inside, P.planetRadius), P),
              0.0f);
}

// The per-cell maxima of the weather map are made once with the map (weatherCellMaxima) rather
// than every frame: the grid filled from them is the grid filled from the map, bit for bit, and
// maxima made from another map are not used.
TEST(EmptySpace, TheCachedCellMaximaGiveTheSameGridAndAreNotUsedForAnotherMap) {
    // Presets whose weather varies over the map (superstorm's is clear but for the storm, so
    // another seed gives it the same grid); under-the-storm adds the storm's stencil.
    for (const std::string name : {"fair-weather-cumulus", "under-the-storm"}) {
        const Scene s = preset(name);
        const SceneResources r = resourcesFor(s);
        cm::CloudParams fromMap = cloudscape::makeCloudParams(s, r);
        cm::CloudParams fromCells = fromMap;
        cloudscape::fillCloudTopGrid(fromMap, r.weather);
        const cloudscape::WeatherCellMaxima cells = cloudscape::weatherCellMaxima(r.weather);
        ASSERT_TRUE(cells.isFor(r.weather));
        cloudscape::fillCloudTopGrid(fromCells, r.weather, &cells);
        EXPECT_EQ(std::memcmp(fromMap.cloudTops, fromCells.cloudTops, sizeof fromMap.cloudTops), 0)
            << name;
        EXPECT_EQ(fromMap.cloudTopMax, fromCells.cloudTopMax) << name;

        // Another map (another seed): the maxima do not fit it and are made again.
        Scene other = s;
        other.seed += 1;
        const cloudscape::Texture2D otherMap = cloudscape::prepareWeather(other);
        EXPECT_FALSE(cells.isFor(otherMap));
        cm::CloudParams stale = fromMap, fresh = fromMap;
        cloudscape::fillCloudTopGrid(stale, otherMap, &cells);
        cloudscape::fillCloudTopGrid(fresh, otherMap);
        EXPECT_EQ(std::memcmp(stale.cloudTops, fresh.cloudTops, sizeof stale.cloudTops), 0);
        EXPECT_NE(std::memcmp(stale.cloudTops, fromMap.cloudTops, sizeof stale.cloudTops), 0)
            << "the other map has other columns";
        // The same texels edited in place (same address and size) are another map too.
        cloudscape::Texture2D edited = r.weather;
        const cloudscape::WeatherCellMaxima editedCells = cloudscape::weatherCellMaxima(edited);
        for (size_t i = 0; i < edited.mips[0].size(); i += 4)
            edited.mips[0][i] = 1.0f - edited.mips[0][i];
        EXPECT_FALSE(editedCells.isFor(edited));
    }
}

TEST(EmptySpace, NoiseSkippingIsExactAndTakesFewerSamples) {
    // march.noise_skipping passes over the samples the base noise's clearance field proves
    // empty (noise_clearance.glsl.h), as shipped (coarse/fine) and with every step a full
    // sample: the images must be bit for bit those without it, with fewer density samples
    // wherever the field was used (not in the storm, which reshapes the noise).
    // The shipped 128^3 base noise: on the small one every texel is 4 times larger while the
    // distance LOD is the shipped noise's, so a read's reach covers nearly every clearance.
    cloudscape::NoiseTextures noise = smallNoise();
    noise.base = cloudscape::generateBaseNoise(1, 128);
    noise.baseClearance = cloudscape::generateNoiseClearance(noise.base);
    int fewer = 0;
    for (const std::string& name : presets()) {
        for (int coarse : {0, 1}) {
            Scene s = preset(name);
            s.width = 96;
            s.height = 54;
            if (coarse == 1)
                s.coarseStepFactor = 1;
            SceneResources r = resourcesFor(s);
            r.noise = noise;
            s.noiseSkipping = false;
            const RenderResult plain = cloudscape::renderCpu(s, r);
            s.noiseSkipping = true;
            ASSERT_EQ(cloudscape::makeCloudParams(s, r).noiseClearanceSize, noise.base.size);
            const RenderResult skipped = cloudscape::renderCpu(s, r);
            EXPECT_EQ(plain.cloud, skipped.cloud) << name;
            EXPECT_EQ(plain.composite, skipped.composite) << name;
            EXPECT_LE(skipped.stats.densitySamples, plain.stats.densitySamples) << name;
            fewer += skipped.stats.densitySamples < plain.stats.densitySamples ? 1 : 0;
            std::printf("%-22s coarse %s: density samples %llu -> %llu\n", name.c_str(),
                        coarse == 1 ? "1" : "as shipped",
                        static_cast<unsigned long long>(plain.stats.densitySamples),
                        static_cast<unsigned long long>(skipped.stats.densitySamples));
        }
    }
    // Three presets leave the field a threshold to use, at both step factors: fair-weather
    // cumulus, broken stratocumulus and the deck from above (overcast coverage leaves none, the
    // storm reshapes the noise, and inside the cloud the rays find cloud first).
    EXPECT_GE(fewer, 6) << "the field must have skipped where the weather leaves it a level";
}

TEST(EmptySpace, EverySampleANoiseSkipPassesIsEmptyAndTheGridWouldSampleIt) {
    // Random points and directions in the layer (fair-weather cumulus and broken stratocumulus,
    // the shipped base noise): everywhere along the span noiseClearDistance allows, the base shape
    // at that distance's level of detail is zero, and the point lies in the same column, below
    // its top (where the plain march would sample, not take the grid's skip).
    cloudscape::NoiseTextures noise = smallNoise();
    noise.base = cloudscape::generateBaseNoise(1, 128);
    noise.baseClearance = cloudscape::generateNoiseClearance(noise.base);
    for (const std::string name : {"fair-weather-cumulus", "broken-stratocumulus"}) {
        Scene s = preset(name);
        s.noiseSkipping = true;
        SceneResources r = resourcesFor(s);
        r.noise = noise;
        const cm::CloudParams P = cloudscape::makeCloudParams(s, r);
        ASSERT_EQ(P.noiseClearanceSize, 128) << name;
        const cloudscape::cpu::TextureSet set = texturesOf(r);
        const cloudscape::cpu::ScopedTextureBinding bind(set);
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        const float pixelAngle = 0.0015f;
        int spans = 0, points = 0;
        for (int i = 0; i < 100000; ++i) {
            const glm::vec2 xz = (glm::vec2(unit(rng), unit(rng)) - 0.5f) * 20000.0f;
            const float a = P.layerBottom + unit(rng) * (P.layerTop - P.layerBottom);
            const glm::vec3 p(xz.x, a, xz.y); // near the origin, y is about the altitude
            const glm::vec3 dir = glm::normalize(
                glm::vec3(unit(rng) - 0.5f, 0.3f * (unit(rng) - 0.5f), unit(rng) - 0.5f));
            const float t = 500.0f + unit(rng) * 30000.0f;
            if (cm::skippableDistance(p, dir, P) > 0.0f)
                continue; // the grid skips here: the march never asks the field
            const float span = cm::noiseClearDistance(p, dir, t, pixelAngle, P);
            if (span <= 0.0f)
                continue;
            ++spans;
            const glm::ivec2 column = cm::cloudTopCell(glm::vec2(p.x, p.z), P);
            for (int k = 0; k <= 8; ++k) {
                const float along = span * float(k) / 8.0f;
                const glm::vec3 q = p + dir * along;
                const float lod = cm::distanceLod((t + along) * pixelAngle, P.log2BaseTexel, P);
                ASSERT_EQ(cm::baseCloudSample(cm::densityContextAt(q, P), lod, P).x, 0.0f)
                    << name << " at " << q.x << "," << q.y << "," << q.z;
                ASSERT_EQ(cm::cloudTopCell(glm::vec2(q.x, q.z), P), column) << name;
                ASSERT_EQ(cm::skippableDistance(q, dir, P), 0.0f) << name << ": below the top";
                ++points;
            }
        }
        std::printf("%-22s %d spans, %d points checked\n", name.c_str(), spans, points);
        EXPECT_GT(spans, 1000) << name;
    }
}
