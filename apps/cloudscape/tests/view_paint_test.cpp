// The viewer's brush on the data field's channels (view_paint.h), on a CPU renderer without a
// window: a stroke changes its channel only inside the brush and the clouds with it, undo puts
// the regions back exactly, the saved PNG reloads (weather.field_image) to the same regions, and
// a field made anew from the scene's keys cannot be undone into.
#include "view_paint.h"

#include <cloudscape/backend.h>
#include <cloudscape/data_field.h>
#include <cloudscape/error.h>
#include <cloudscape/noise.h>
#include <cloudscape/persistent_renderer.h>

#include "core/resources.h"
#include "cpu/tests/small_resources.h"
#include "model/data_field.glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace {

using cloudscape::Scene;
using cloudscape::cli::BrushStroke;

cloudscape::Renderer cpuRenderer(const Scene& s) {
    cloudscape::BackendOptions cpu;
    cpu.choice = cloudscape::BackendChoice::Cpu;
    return cloudscape::Renderer(s, cloudscape::test::smallResources(s), cpu);
}

Scene smallScene() {
    Scene s;
    s.width = 48;
    s.height = 27;
    s.weatherResolution = 64;
    s.terrainEnabled = false;
    s.coverage = 0.0f; // no cloud but what the brush paints
    s.cameraPitchDeg = 60.0f;
    s.highCloudCoverage = 0.0f;
    return s;
}

// Distance (m) from region (i, j)'s centre to world (x, z), wrapped over the map.
float regionDistance(const Scene& s, int i, int j, float x, float z) {
    const int n = cloudscape::model::DATA_FIELD_GRID;
    const float e = s.weatherExtentM;
    float dx = s.weatherOffsetXM + ((i + 0.5f) / n - 0.5f) * e - x;
    float dz = s.weatherOffsetZM + ((j + 0.5f) / n - 0.5f) * e - z;
    dx -= e * std::round(dx / e);
    dz -= e * std::round(dz / e);
    return std::sqrt(dx * dx + dz * dz);
}

} // namespace

TEST(ViewPaint, AFieldStrokeChangesItsChannelInsideTheBrushAndUndoPutsItBack) {
    Scene s = smallScene();
    cloudscape::Renderer renderer = cpuRenderer(s);
    const cloudscape::RenderResult before = renderer.render(s);
    cloudscape::cli::WeatherPainter painter;
    BrushStroke stroke;
    stroke.channel = cloudscape::cli::brushChannel("anvil");
    stroke.xM = 0.0f;
    stroke.zM = 4000.0f;
    stroke.radiusM = 6000.0f;
    stroke.strength = 1.0f;
    painter.paint(renderer, s, stroke);
    const std::vector<glm::vec4>& field = renderer.resources().dataField;
    const int n = cloudscape::model::DATA_FIELD_GRID;
    int inside = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec4 v = field[size_t(j) * n + i];
            const float d = regionDistance(s, i, j, stroke.xM, stroke.zM);
            EXPECT_EQ(glm::vec3(v.x, v.z, v.w), glm::vec3(0.0f, 0.0f, 1.0f)) << i << "," << j;
            if (d >= stroke.radiusM) {
                EXPECT_EQ(v.y, 0.0f) << "painted outside the brush at " << i << "," << j;
            } else if (d < 0.5f * stroke.radiusM) {
                EXPECT_GT(v.y, 0.5f) << i << "," << j;
                ++inside;
            }
        }
    EXPECT_GT(inside, 4);
    // Anvil cloud appears where nothing was.
    const cloudscape::RenderResult painted = renderer.render(s);
    std::printf("in-cloud samples %llu -> %llu, density samples %llu\n",
                (unsigned long long)before.stats.cloudSamples,
                (unsigned long long)painted.stats.cloudSamples,
                (unsigned long long)painted.stats.densitySamples);
    EXPECT_NE(painted.cloud, before.cloud);
    ASSERT_TRUE(painter.undo(renderer, s));
    EXPECT_TRUE(cloudscape::isNeutralDataField(renderer.resources().dataField));
    EXPECT_EQ(renderer.render(s).cloud, before.cloud);
    EXPECT_FALSE(painter.undo(renderer, s)) << "nothing more to undo";
}

TEST(ViewPaint, ASavedFieldReloadsToTheSameRegionsAndANewFieldEndsTheUndo) {
    Scene s = smallScene();
    s.baseVariation = 0.2f; // a generated field under the strokes
    cloudscape::Renderer renderer = cpuRenderer(s);
    cloudscape::cli::WeatherPainter painter;
    BrushStroke stroke;
    stroke.channel = cloudscape::cli::brushChannel("max_height");
    stroke.radiusM = 9000.0f;
    stroke.strength = -0.6f;
    painter.paint(renderer, s, stroke);
    stroke.channel = cloudscape::cli::brushChannel("bottom_type");
    stroke.xM = 12000.0f;
    stroke.strength = 0.8f;
    painter.paint(renderer, s, stroke);
    EXPECT_EQ(painter.undoSteps(), 2u);

    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("cloudscape-paint-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string png = (dir / "field.png").string();
    cloudscape::cli::WeatherPainter::saveFieldImage(renderer.resources().dataField, png);
    EXPECT_EQ(cloudscape::loadDataFieldImage(png), renderer.resources().dataField);
    std::filesystem::remove_all(dir);

    // A data-field key remakes the field from the scene: the strokes were on another one.
    Scene other = s;
    other.baseVariation = 0.3f;
    EXPECT_TRUE(renderer.update(other).dataField);
    EXPECT_FALSE(painter.undo(renderer, other));
    EXPECT_THROW(cloudscape::cli::brushChannel("anvils"), cloudscape::Error);
}
