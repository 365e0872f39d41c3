// The terrain (src/model/terrain.glsl.h, ground.glsl.h) on the CPU backend: the generated and
// loaded height fields, the march's hits against hand-worked geometry, the cloud march ending at
// the terrain, its shading, and the refusals of bad height maps and of a camera below ground.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/renderer.h>
#include <cloudscape/terrain.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "core/resources.h"
#include "cpu/cpu_textures.h"
#include "model/ground.glsl.h"
#include "model/terrain.glsl.h"

#include "small_resources.h"
#include "terrain_fixtures.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>

using cloudscape::HeightField;
using cloudscape::Scene;
namespace cm = cloudscape::model;
namespace fs = std::filesystem;

namespace {

using cloudscape::test::BoundTerrain;
using cloudscape::test::fieldOf;
using cloudscape::test::smallResources;
using cloudscape::test::terrainScene;

// A 16-bit greyscale PNG written by hand (stb writes 8-bit only): stored (uncompressed) deflate
// blocks, with the chunks' CRCs and the zlib Adler-32.
void writePng16(const std::string& path, int w, int h, const std::vector<uint16_t>& grey) {
    auto crc = [](const std::vector<uint8_t>& bytes) {
        uint32_t c = 0xffffffffu;
        for (uint8_t b : bytes) {
            c ^= b;
            for (int k = 0; k < 8; ++k)
                c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
        }
        return c ^ 0xffffffffu;
    };
    auto be32 = [](std::vector<uint8_t>& out, uint32_t v) {
        for (int s = 24; s >= 0; s -= 8)
            out.push_back(uint8_t(v >> s));
    };
    std::vector<uint8_t> raw;
    for (int y = 0; y < h; ++y) {
        raw.push_back(0); // filter: none
        for (int x = 0; x < w; ++x) {
            raw.push_back(uint8_t(grey[size_t(y) * w + x] >> 8));
            raw.push_back(uint8_t(grey[size_t(y) * w + x] & 0xff));
        }
    }
    std::vector<uint8_t> z = {0x78, 0x01};
    for (size_t pos = 0; pos < raw.size();) {
        const size_t len = std::min<size_t>(65535, raw.size() - pos);
        z.push_back(pos + len == raw.size() ? 1 : 0);
        z.push_back(uint8_t(len & 0xff));
        z.push_back(uint8_t(len >> 8));
        z.push_back(uint8_t(~len & 0xff));
        z.push_back(uint8_t((~len >> 8) & 0xff));
        z.insert(z.end(), raw.begin() + pos, raw.begin() + pos + len);
        pos += len;
    }
    uint32_t a = 1, b = 0;
    for (uint8_t v : raw) {
        a = (a + v) % 65521u;
        b = (b + a) % 65521u;
    }
    be32(z, (b << 16) | a);
    std::vector<uint8_t> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto chunk = [&](const char* type, const std::vector<uint8_t>& data) {
        be32(file, uint32_t(data.size()));
        std::vector<uint8_t> typed(type, type + 4);
        typed.insert(typed.end(), data.begin(), data.end());
        file.insert(file.end(), typed.begin(), typed.end());
        be32(file, crc(typed));
    };
    std::vector<uint8_t> ihdr;
    be32(ihdr, uint32_t(w));
    be32(ihdr, uint32_t(h));
    ihdr.insert(ihdr.end(), {16, 0, 0, 0, 0});
    chunk("IHDR", ihdr);
    chunk("IDAT", z);
    chunk("IEND", {});
    cloudscape::writeFileAtomic(path, file.data(), file.size());
}

std::string tempPath(const std::string& name) {
    return (fs::temp_directory_path() / ("cloudscape_terrain_" + name)).string();
}

// The message of the cloudscape::Error that f throws ("" if none).
template <class F> std::string errorOf(F f) {
    try {
        f();
    } catch (const cloudscape::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Terrain, GeneratedFieldIsSeededAndReachesItsHeight) {
    cloudscape::TerrainGenerator g;
    g.resolution = 96;
    g.extentM = 30000.0f;
    g.heightM = 2000.0f;
    g.featureSizeM = 6000.0f;
    const HeightField a = cloudscape::generateTerrain(g);
    EXPECT_EQ(a.heights, cloudscape::generateTerrain(g).heights) << "deterministic";
    EXPECT_NEAR(a.maxHeightM, 2000.0f, 1e-2f) << "the highest peak is terrain.height_m";
    EXPECT_LT(a.heights[0], 1.0f) << "the edge fades to the flat planet";
    g.seed = 2;
    EXPECT_NE(a.heights, cloudscape::generateTerrain(g).heights) << "the seed matters";
    // Ridges: a real relief, with steep ground somewhere and no slope above the bound.
    EXPECT_GT(a.maxSlope, 0.3f);
    float mean = 0.0f;
    for (size_t i = 0; i < a.texelCount(); ++i)
        mean += a.heights[i] / float(a.texelCount());
    EXPECT_GT(mean, 50.0f);
    EXPECT_LT(mean, 1000.0f) << "valleys, not a plateau";
}

// The cell maxima the march skips by (terrain.glsl.h): each level-0 cell holds the highest texel
// on and inside its edges (so the bilinear surface over it stays below), each coarser cell the
// highest of its four, and the top level the field's highest texel; a field re-measured keeps
// one set of maxima.
TEST(Terrain, CellMaximaBoundTheFieldOverEachCell) {
    const int n = 37; // 36 spans: 9 level-0 cells a side, padded to a grid of 16
    HeightField f = fieldOf(n, 3700.0f, [](float x, float z) {
        return 500.0f + 400.0f * std::sin(x * 0.003f) * std::cos(z * 0.002f);
    });
    cloudscape::measureHeightField(f, 100.0f, 100.0f);
    const int spans = cm::TERRAIN_CELL_SPANS;
    ASSERT_EQ(f.cellGrid, 16);
    ASSERT_EQ(f.cellLevels, 5);
    // The levels hold 16^2 + 8^2 + 4^2 + 2^2 + 1 cells, the top one last.
    ASSERT_EQ(f.heights.size(), f.texelCount() + 341);
    ASSERT_EQ(cm::terrainCellLevelOffset(f.cellLevels, f.cellGrid), 341);
    ASSERT_EQ(cm::terrainCellLevelOffset(f.cellLevels - 1, f.cellGrid), 340);
    // The smallest field: one cell, one level.
    const HeightField two = fieldOf(2, 100.0f, [](float x, float) { return x > 0 ? 7.0f : 3.0f; });
    ASSERT_EQ(two.cellLevels, 1);
    ASSERT_EQ(two.heights.size(), two.texelCount() + 1);
    EXPECT_EQ(two.heights.back(), 7.0f);
    auto cell = [&](int level, int cx, int cz) {
        return f.heights[f.texelCount() + size_t(cm::terrainCellLevelOffset(level, f.cellGrid)) +
                         size_t(cz) * (f.cellGrid >> level) + cx];
    };
    for (int level = 0; level < f.cellLevels; ++level) {
        const int size = spans << level;
        for (int cz = 0; cz * size < n - 1; ++cz)
            for (int cx = 0; cx * size < n - 1; ++cx) {
                float highest = -1.0f;
                for (int z = cz * size; z <= std::min((cz + 1) * size, n - 1); ++z)
                    for (int x = cx * size; x <= std::min((cx + 1) * size, n - 1); ++x)
                        highest = std::max(highest, f.heights[size_t(z) * n + x]);
                EXPECT_EQ(cell(level, cx, cz), highest) << level << " " << cx << " " << cz;
            }
    }
    EXPECT_EQ(cell(f.cellLevels - 1, 0, 0), f.maxHeightM);
}

TEST(Terrain, MarchHitsAPlateauWhereGeometrySaysSo) {
    const Scene s = terrainScene(8000.0f);
    BoundTerrain t(s, fieldOf(32, 8000.0f, [](float, float) { return 1000.0f; }));
    // Straight down from 3000 m over the field's centre: 2000 m to the plateau.
    const float down = cm::terrainHitDistance(glm::vec3(0, 3000, 0), glm::vec3(0, -1, 0), t.params);
    EXPECT_NEAR(down, 2000.0f, 2.0f);
    // Level at 500 m from 10 km south, heading north: the plateau's southern edge, 6 km on
    // (between the edge texel's centre and the extent's edge; the field is flat to there).
    const float level =
        cm::terrainHitDistance(glm::vec3(0, 500, -10000), glm::vec3(0, 0, 1), t.params);
    EXPECT_NEAR(level, 6000.0f, 5.0f);
    // Above the plateau looking up, and beside it heading away: no hit.
    EXPECT_EQ(cm::terrainHitDistance(glm::vec3(0, 1500, 0), glm::vec3(0, 1, 0), t.params),
              cm::NO_HIT);
    EXPECT_EQ(cm::terrainHitDistance(glm::vec3(0, 500, -10000), glm::vec3(0, 0, -1), t.params),
              cm::NO_HIT);
    // Heading down outside the field: the flat planet beyond it, found analytically.
    const glm::vec3 dir = glm::normalize(glm::vec3(0.0f, -0.1f, -1.0f));
    const float ground = cm::terrainHitDistance(glm::vec3(0, 500, -10000), dir, t.params);
    ASSERT_GT(ground, 5000.0f);
    const glm::vec3 hit = glm::vec3(0, 500, -10000) + dir * ground;
    EXPECT_NEAR(cm::terrainAltitude(hit, t.params.planetRadius), 0.0f, 0.5f)
        << "the planet's surface (the ray falls 518 m in y: the planet curves away)";
}

TEST(Terrain, MarchFindsASlopeWithinItsTolerance) {
    // A ramp h = 0.5 (z + 4000) m: a level ray at 1200 m meets it where 0.5 (z + 4000) = 1200.
    const Scene s = terrainScene(8000.0f);
    BoundTerrain t(s, fieldOf(64, 8000.0f, [](float, float z) { return 0.5f * (z + 4000.0f); }));
    EXPECT_NEAR(t.field.maxSlope, 0.5f, 1e-3f);
    const float hit =
        cm::terrainHitDistance(glm::vec3(0, 1200, -3000), glm::vec3(0, 0, 1), t.params);
    EXPECT_NEAR(hit, 1400.0f, 4.0f);
}

TEST(Terrain, SunlitSlopesAreBrighterThanShadedOnesAndTheTerrainShadowsItself) {
    Scene s = terrainScene(8000.0f);
    s.sunElevationDeg = 20.0f;
    s.sunHeadingDeg = 0.0f;                      // the sun in the north (+z)
    s.skyModel = cloudscape::SkyModel::Gradient; // no clouds' shadow or air: the terrain alone
    s.coverage = 0.0f;
    // A ridge along x at z = 0, 1000 m high, slopes of 1:2.
    BoundTerrain t(s, fieldOf(128, 8000.0f, [](float, float z) {
                       return std::max(0.0f, 1000.0f - 0.5f * std::fabs(z));
                   }));
    auto radianceAt = [&](float z) {
        const float h = cm::terrainHeightAt(glm::vec2(0.0f, z), t.params.terrain);
        return cm::terrainRadiance(glm::vec3(0.0f, h, z), glm::vec3(0.0f, -1.0f, 0.0f), 1000.0f,
                                   t.params);
    };
    t.params.coverageBias = -10.0f;              // no cloud anywhere
    const glm::vec3 north = radianceAt(600.0f);  // faces the sun
    const glm::vec3 south = radianceAt(-600.0f); // faces away, 26.6 deg slope > 20 deg sun
    const glm::vec3 foot = radianceAt(-2100.0f); // flat ground in the ridge's shadow
    const glm::vec3 open = radianceAt(3500.0f);  // flat ground in the sun
    EXPECT_GT(north.y, 2.0f * south.y);
    EXPECT_GT(open.y, 2.0f * foot.y) << "the ridge's shadow falls on the ground behind it";
    EXPECT_NEAR(south.y / foot.y, (0.5f + 0.5f * 0.894f) / 1.0f, 0.05f)
        << "both in shadow: sky light only, in proportion to the sky each faces";
}

TEST(Terrain, TheCloudMarchEndsAtTheTerrain) {
    // The camera at the bottom of a pit whose walls rise above the cloud layer: every view ray
    // meets a wall or the pit's floor before the cloud shell, so no density sample is taken.
    Scene s = terrainScene(20000.0f);
    s.cameraPosition = {0.0f, 100.0f, 0.0f};
    s.cameraPitchDeg = 0.0f;
    s.coverage = 0.8f;
    // The walls are cliffs (slope ~40), so the sphere tracing's steps are short: enough of them.
    s.terrainMaxSteps = 4096;
    cloudscape::SceneResources r = smallResources(s);
    const cloudscape::RenderResult open = cloudscape::renderCpu(s, r);
    ASSERT_GT(open.stats.densitySamples, 0u);
    EXPECT_EQ(open.stats.densitySamples, cloudscape::renderCpu(s, r).stats.densitySamples);
    r.terrain = fieldOf(
        64, 20000.0f, [](float x, float z) { return std::hypot(x, z) < 2000.0f ? 0.0f : 9000.0f; });
    const cloudscape::RenderResult walled = cloudscape::renderCpu(s, r);
    EXPECT_EQ(walled.stats.densitySamples, 0u);
    for (size_t i = 3; i < walled.cloud.size(); i += 4)
        ASSERT_EQ(walled.cloud[i], 1.0f) << "no cloud in front of the wall";
    // The terrain is drawn: the composite differs from the open view's sky and clouds.
    EXPECT_NE(walled.composite, open.composite);
}

TEST(Terrain, HeightsAreBilinearBetweenTexelCentres) {
    // A 2x2 field over 2 km: texel centres at x, z = -500 and +500 m, heights a = 0, b = 100
    // (east), c = 200 (north), d = 400. At (-250, 250) the weights are 0.25 east and 0.75 north:
    // mix(mix(0, 100, 0.25), mix(200, 400, 0.25), 0.75) = 193.75, by hand.
    const BoundTerrain t(terrainScene(2000.0f), fieldOf(2, 2000.0f, [](float x, float z) {
                             return x < 0.0f ? (z < 0.0f ? 0.0f : 200.0f)
                                             : (z < 0.0f ? 100.0f : 400.0f);
                         }));
    EXPECT_NEAR(cm::terrainHeightAt(glm::vec2(-250.0f, 250.0f), t.params.terrain), 193.75f, 1e-3f);
    // At (250, -250), 0.75 east and 0.25 north: mix(75, 350, 0.25) = 143.75.
    EXPECT_NEAR(cm::terrainHeightAt(glm::vec2(250.0f, -250.0f), t.params.terrain), 143.75f, 1e-3f);
    EXPECT_NEAR(cm::terrainHeightAt(glm::vec2(500.0f, 500.0f), t.params.terrain), 400.0f, 1e-3f);
}

TEST(Terrain, TerrainOffChangesNothing) {
    Scene s = terrainScene(20000.0f);
    s.terrainEnabled = false;
    cloudscape::SceneResources r = smallResources(s);
    const cloudscape::RenderResult plain = cloudscape::renderCpu(s, r);
    r.terrain = fieldOf(16, 20000.0f, [](float, float) { return 500.0f; });
    const cloudscape::RenderResult withField = cloudscape::renderCpu(s, r);
    EXPECT_EQ(plain.composite, withField.composite) << "a field is ignored with the terrain off";
}

TEST(Terrain, ACameraBelowTheTerrainIsRefused) {
    Scene s = terrainScene(20000.0f);
    s.cameraPosition = {0.0f, 300.0f, 0.0f};
    cloudscape::SceneResources r = smallResources(s);
    r.terrain = fieldOf(16, 20000.0f, [](float, float) { return 500.0f; });
    const std::string message = errorOf([&] { cloudscape::renderCpu(s, r); });
    EXPECT_NE(message.find("camera.position [0.0, 300.0, 0.0] is below the terrain"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("500.0 m"), std::string::npos) << message;
    s.cameraPosition.y = 520.0f;
    EXPECT_EQ(errorOf([&] { cloudscape::renderCpu(s, r); }), "");
    // Outside the field the ground is the flat planet: 300 m is above it.
    s.cameraPosition = {30000.0f, 300.0f, 0.0f};
    EXPECT_EQ(errorOf([&] { cloudscape::renderCpu(s, r); }), "");
}

TEST(Terrain, TheViewersCameraIsLiftedOverTheTerrainNotRefused) {
    Scene s = terrainScene(20000.0f);
    s.cameraPosition = {100.0f, 300.0f, -200.0f};
    cloudscape::SceneResources r = smallResources(s);
    r.terrain = fieldOf(16, 20000.0f, [](float, float) { return 500.0f; });
    EXPECT_TRUE(cloudscape::liftCameraAboveTerrain(s, r, 3.0f));
    // Up the vertical (at 100 m from the origin the planet's vertical is y to 1e-5), to 503 m.
    EXPECT_NEAR(s.cameraPosition.x, 100.0f, 0.01f);
    EXPECT_NEAR(s.cameraPosition.y, 503.0f, 0.6f); // a float altitude on a planet: 0.5 m steps
    EXPECT_NEAR(s.cameraPosition.z, -200.0f, 0.01f);
    EXPECT_EQ(errorOf([&] { cloudscape::renderCpu(s, r); }), "") << "what render accepts";
    const glm::vec3 lifted = s.cameraPosition;
    EXPECT_FALSE(cloudscape::liftCameraAboveTerrain(s, r, 3.0f)) << "already clear";
    EXPECT_EQ(s.cameraPosition, lifted);
    s.terrainEnabled = false;
    s.cameraPosition.y = 300.0f;
    EXPECT_FALSE(cloudscape::liftCameraAboveTerrain(s, r, 3.0f)) << "no terrain, no lift";
}

TEST(Terrain, LoadsSixteenBitPngAndFloatExrHeightMaps) {
    const std::string png = tempPath("ok.png");
    // 4 x 3, value 65535 in the top-left corner (the field's north-west), 0 elsewhere.
    std::vector<uint16_t> grey(12, 0);
    grey[0] = 65535;
    grey[5] = 32768;
    writePng16(png, 4, 3, grey);
    const HeightField f = cloudscape::loadHeightMap(png, 100.0f, 1100.0f);
    ASSERT_EQ(f.width, 4);
    ASSERT_EQ(f.height, 3);
    EXPECT_FLOAT_EQ(f.heights[size_t(2) * 4 + 0], 1100.0f) << "top row is the far (north) row";
    EXPECT_NEAR(f.heights[size_t(1) * 4 + 1], 100.0f + 1000.0f * 32768.0f / 65535.0f, 1e-3f);
    EXPECT_FLOAT_EQ(f.heights[0], 100.0f);

    const std::string exr = tempPath("ok.exr");
    std::vector<float> metres = {0.0f, 10.0f, 20.0f, 30.0f};
    cloudscape::writeExr(exr, 2, 2, {{"Y", metres.data()}});
    const HeightField e = cloudscape::loadHeightMap(exr, 0.0f, 1.0f);
    EXPECT_EQ(e.heights, (std::vector<float>{20.0f, 30.0f, 0.0f, 10.0f}));
    fs::remove(png);
    fs::remove(exr);
}

TEST(Terrain, BadHeightMapsAreRefusedNamingTheFile) {
    const std::string missing = tempPath("missing.png");
    EXPECT_EQ(errorOf([&] { cloudscape::loadHeightMap(missing, 0, 1); }),
              missing + ": cannot read height map: no such file");

    const std::string eight = tempPath("eight.png");
    cloudscape::writePngChannels(eight, 4, 4, 1, std::vector<uint8_t>(16, 7));
    EXPECT_EQ(errorOf([&] { cloudscape::loadHeightMap(eight, 0, 1); }),
              eight + ": a 8-bit PNG; expected a 16-bit greyscale PNG");

    const std::string nan = tempPath("nan.exr");
    std::vector<float> values = {1.0f, std::numeric_limits<float>::quiet_NaN(), 2.0f, 3.0f};
    cloudscape::writeExr(nan, 2, 2, {{"Y", values.data()}});
    const std::string nanMessage = errorOf([&] { cloudscape::loadHeightMap(nan, 0, 1); });
    EXPECT_EQ(nanMessage.rfind(nan + ": height map texel (1, 0) is nan", 0), 0u) << nanMessage;

    const std::string wide = tempPath("wide.exr");
    std::vector<float> row(9000 * 2, 1.0f);
    cloudscape::writeExr(wide, 9000, 2, {{"Y", row.data()}});
    EXPECT_EQ(errorOf([&] { cloudscape::loadHeightMap(wide, 0, 1); }),
              wide + ": height map is 9000x2 texels; expected 2 to 8192 on a side");

    const std::string text = tempPath("heights.txt");
    cloudscape::writeFileAtomic(text, "1 2 3", 5);
    EXPECT_NE(errorOf([&] { cloudscape::loadHeightMap(text, 0, 1); }).find("16-bit PNG"),
              std::string::npos);
    for (const std::string& p : {eight, nan, wide, text})
        fs::remove(p);
}

TEST(Terrain, ARendererRemakesTheFieldOnlyWhenItsShapeChanges) {
    Scene s = terrainScene(20000.0f);
    s.terrainResolution = 64;
    s.cameraPosition = {0.0f, 4000.0f, 0.0f};
    cloudscape::BackendOptions cpu;
    cpu.choice = cloudscape::BackendChoice::Cpu;
    cloudscape::SceneResources r = smallResources(s);
    cloudscape::prepareTerrain(s, r);
    cloudscape::Renderer renderer(s, r, cpu);
    Scene moved = s;
    moved.terrainOffsetXM = 500.0f;
    moved.terrainAlbedo = glm::vec3(0.3f);
    EXPECT_FALSE(renderer.update(moved).terrain) << "offset and albedo are uniforms";
    moved.terrainHeightM = 1000.0f;
    EXPECT_TRUE(renderer.update(moved).terrain);
    // A camera moved below the terrain is refused by the update as by a one-shot render.
    cloudscape::SceneResources plateau = smallResources(s);
    plateau.terrain = fieldOf(16, 20000.0f, [](float, float) { return 500.0f; });
    cloudscape::Renderer flat(s, plateau, cpu);
    Scene low = s;
    low.cameraPosition.y = 300.0f;
    EXPECT_NE(errorOf([&] { flat.render(low); }).find("below the terrain"), std::string::npos);
}

TEST(Terrain, FieldsVaryTheAlbedoAboutItsMeanAndFadeWithTheFootprint) {
    cm::TerrainParams T{};
    T.fieldSize = 300.0f;
    T.fieldVariation = 0.4f;
    // Many fields: every factor inside its bounds, brightness and red each of mean 1.
    double sumBrightness = 0.0, sumRed = 0.0;
    int differsFromNeighbour = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
        const glm::vec2 xz(-600000.0f + 337.0f * float(i), 1700.0f * float(i % 37));
        const glm::vec3 f = cm::fieldAlbedoFactor(xz, 0.0f, T);
        ASSERT_EQ(f.y, f.z);
        ASSERT_GE(f.y, 0.6f);
        ASSERT_LE(f.y, 1.4f);
        const float red = f.x / f.y;
        ASSERT_GE(red, 0.6f - 1e-5f);
        ASSERT_LE(red, 1.4f + 1e-5f);
        sumBrightness += f.y;
        sumRed += red;
        // One metre away is (almost always) the same field; 5 fields away another one.
        const glm::vec3 near = cm::fieldAlbedoFactor(xz + glm::vec2(0.5f, 0.3f), 0.0f, T);
        const glm::vec3 far = cm::fieldAlbedoFactor(xz + glm::vec2(1500.0f, 0.0f), 0.0f, T);
        differsFromNeighbour += near != f ? 1 : 0;
        EXPECT_NE(far, f) << i;
    }
    // Uniform in 1 +- 0.4: a standard deviation of 0.23, so the mean of 4000 is within 0.011
    // of 1 at 3 sigma.
    EXPECT_NEAR(sumBrightness / n, 1.0, 0.011);
    EXPECT_NEAR(sumRed / n, 1.0, 0.011);
    EXPECT_LT(differsFromNeighbour, n / 50) << "fields are patches, not noise";

    // The fade: full up to half a field per pixel, none from a whole field per pixel.
    const glm::vec2 p(1234.0f, -5678.0f);
    const glm::vec3 sharp = cm::fieldAlbedoFactor(p, 0.4f * T.fieldSize, T);
    const glm::vec3 half = cm::fieldAlbedoFactor(p, 0.75f * T.fieldSize, T);
    EXPECT_EQ(sharp, cm::fieldAlbedoFactor(p, 0.0f, T));
    EXPECT_NE(sharp, glm::vec3(1.0f)) << "this field is not the mean: pick another point";
    EXPECT_NEAR(half.y - 1.0f, 0.5f * (sharp.y - 1.0f), 1e-5f);
    EXPECT_EQ(cm::fieldAlbedoFactor(p, T.fieldSize, T), glm::vec3(1.0f));
    // No variation: the plain albedo exactly.
    T.fieldVariation = 0.0f;
    EXPECT_EQ(cm::fieldAlbedoFactor(p, 0.0f, T), glm::vec3(1.0f));
    T.albedo = glm::vec3(0.07f, 0.1f, 0.045f);
    T.snowLine = 100000.0f;
    EXPECT_EQ(cm::terrainAlbedo(p, 100.0f, 1.0f, 0.0f, T), T.albedo);
}

// Over-relaxed sphere tracing (terrain.glsl.h), and the march the renderer uses (over-relaxed,
// skipping cells by their maxima), against plain sphere tracing (relaxation 1, no cells), over
// the camera rays of the presets with terrain, and the rays toward the sun from where they land
// (the ground's own shadow): the same hits and misses (but where plain tracing ran out of steps
// and called a miss), each hit as close to the surface as plain tracing's, in fewer steps.
TEST(Terrain, RelaxedTracingAndCellSkipsFindTheSameGroundInFewerSteps) {
    for (const char* name : {"fair-weather-cumulus", "mountains"}) {
        Scene s = cloudscape::loadScene(cloudscape::resolveScenePath(name));
        s.width = 160;
        s.height = 90;
        s.terrainResolution = 512;
        cloudscape::SceneResources r;
        cloudscape::prepareTerrain(s, r);
        BoundTerrain t(s, r.terrain);
        const cm::FrameParams frame = cloudscape::makeFrameParams(s);
        struct Variant {
            float relaxation;
            bool cells;
            long steps = 0, disagreements = 0;
            float worst = 0.0f; // |gap| at the hit over the tolerance
        };
        Variant plain{1.0f, false}, relaxed{cm::TERRAIN_RELAXATION, false},
            skipping{cm::TERRAIN_RELAXATION, true};
        long hits = 0, exhausted = 0;
        auto gapRatio = [&](glm::vec3 o, glm::vec3 d, float hit) {
            return std::abs(cm::terrainGap(o + d * hit, t.params)) /
                   (cm::TERRAIN_HIT_EPSILON + cm::TERRAIN_HIT_RELATIVE * hit);
        };
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const glm::vec3 dir = cm::cameraRayDirection(frame, float(x), float(y));
                for (int ray = 0; ray < 2; ++ray) {
                    glm::vec3 origin = s.cameraPosition, d = dir;
                    if (ray == 1) { // toward the sun from the camera ray's ground
                        const float ground = cm::terrainHitDistance(origin, dir, t.params);
                        if (ground == cm::NO_HIT)
                            continue;
                        origin = origin + dir * ground + glm::vec3(0.0f, 1.0f, 0.0f);
                        d = t.params.sky.sunDirection;
                    }
                    int n = 0;
                    const float reference = cm::terrainMarch(origin, d, t.params, 1.0f, false, n);
                    plain.steps += n;
                    const bool gaveUp = reference == cm::NO_HIT && n == t.params.terrain.maxSteps;
                    exhausted += gaveUp ? 1 : 0;
                    hits += !gaveUp && reference != cm::NO_HIT ? 1 : 0;
                    if (!gaveUp && reference != cm::NO_HIT)
                        plain.worst = std::max(plain.worst, gapRatio(origin, d, reference));
                    for (Variant* v : {&relaxed, &skipping}) {
                        const float hit =
                            cm::terrainMarch(origin, d, t.params, v->relaxation, v->cells, n);
                        v->steps += n;
                        if (gaveUp) // plain tracing gave up: not a miss it found
                            continue;
                        if ((reference == cm::NO_HIT) != (hit == cm::NO_HIT))
                            ++v->disagreements;
                        else if (hit != cm::NO_HIT)
                            v->worst = std::max(v->worst, gapRatio(origin, d, hit));
                    }
                }
            }
        std::printf("%-22s %ld hits, %ld rays plain tracing gave up on; steps plain %ld, relaxed "
                    "%ld (%.2fx), with cells %ld (%.2fx); disagreements %ld, %ld; worst |gap| "
                    "over the tolerance: plain %.3f, relaxed %.3f, with cells %.3f\n",
                    name, hits, exhausted, plain.steps, relaxed.steps,
                    double(relaxed.steps) / plain.steps, skipping.steps,
                    double(skipping.steps) / plain.steps, relaxed.disagreements,
                    skipping.disagreements, plain.worst, relaxed.worst, skipping.worst);
        EXPECT_GT(hits, 1000) << name;
        for (const Variant* v : {&relaxed, &skipping}) {
            EXPECT_LE(v->disagreements, hits / 1000) << name;
            EXPECT_LE(v->worst, std::max(plain.worst, 1.0f) * 1.001f) << name;
        }
        EXPECT_LT(relaxed.steps, 0.85 * plain.steps) << name;
        EXPECT_LT(skipping.steps, 0.85 * relaxed.steps) << name;
    }
}
