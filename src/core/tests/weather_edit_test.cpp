// Editing the weather map in place (Renderer::editWeatherMap, the viewer's brush): what is kept
// beside the map is brought up to date from the changed texels alone, and must equal what the
// whole edited map gives: the coverage distribution (CoverageField::replaceTexels) and the
// empty-space grid's cell maxima (refreshWeatherCells); the footprints a device copy writes
// never overlap and cover every texel a changed one feeds.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/weather.h>

#include "core/cloud_top_grid.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace cloudscape;

namespace {

Texture2D smallMap() {
    WeatherParams p;
    p.resolution = 64;
    return generateWeatherMap(p);
}

// Sets the level-0 texels of r to a coverage field of `code` (16 bits) and rain 1.
void fill(Texture2D& map, const TexelRect& r, int code) {
    for (int j = r.y; j < r.y + r.height; ++j)
        for (int i = r.x; i < r.x + r.width; ++i) {
            float* t = map.texel(0, i, j);
            t[0] = float(code >> 8) / 255.0f;
            t[3] = float(code & 255) / 255.0f;
            t[1] = 1.0f;
        }
}

std::vector<float> texelsOf(const Texture2D& map, const TexelRect& r) {
    std::vector<float> out;
    for (int j = r.y; j < r.y + r.height; ++j)
        out.insert(out.end(), map.texel(0, r.x, j), map.texel(0, r.x, j) + 4 * r.width);
    return out;
}

} // namespace

TEST(WeatherEdit, CoverageDistributionAfterAnEditIsTheEditedMaps) {
    Texture2D map = smallMap();
    CoverageField field(map);
    const TexelRect r{50, 3, 14, 20};
    const std::vector<float> before = texelsOf(map, r);
    fill(map, r, 60000);
    const std::vector<float> after = texelsOf(map, r);
    field.replaceTexels(before.data(), after.data(), before.size() / 4);
    const CoverageField fresh(map);
    for (float bias : {-0.7f, -0.2f, 0.0f, 0.13f, 0.5f})
        EXPECT_EQ(field.meanCoverage(bias), fresh.meanCoverage(bias)) << bias;
    EXPECT_EQ(field.biasFor(0.4f), fresh.biasFor(0.4f));
    EXPECT_NE(field.meanCoverage(0.0f), CoverageField(smallMap()).meanCoverage(0.0f))
        << "the edit changed the distribution";
}

TEST(WeatherEdit, CellMaximaAfterAnEditAreTheEditedMaps) {
    Texture2D map = smallMap();
    WeatherCellMaxima cells = weatherCellMaxima(map);
    // At the map's edge: the cells across the wrap read these texels too.
    const TexelRect r{0, 60, 5, 4};
    fill(map, r, 65535);
    EXPECT_FALSE(cells.isFor(map)) << "the probe sees the edit (the map's first texel)";
    refreshWeatherCells(cells, map, r.x, r.y, r.x + r.width, r.y + r.height);
    const WeatherCellMaxima fresh = weatherCellMaxima(map);
    EXPECT_TRUE(cells.isFor(map));
    ASSERT_EQ(cells.cells.size(), fresh.cells.size());
    EXPECT_EQ(cells.cells, fresh.cells);
    EXPECT_NE(cells.cells, weatherCellMaxima(smallMap()).cells);
}

TEST(WeatherEdit, FootprintsCoverTheirParentsAndNeverOverlap) {
    const Texture2D map = smallMap(); // 64^2, 7 levels
    // A brush across the wrapped corner: four rectangles at level 0.
    const std::vector<TexelRect> rects = {
        {60, 61, 4, 3}, {0, 61, 3, 3}, {60, 0, 4, 2}, {0, 0, 3, 2}};
    for (int l = 0; l < map.levelCount(); ++l) {
        const std::vector<TexelRect> f = weatherFootprint(rects, map, l);
        const int w = map.levelWidth(l), h = map.levelHeight(l);
        std::vector<int> covered(static_cast<size_t>(w) * h, 0);
        for (const TexelRect& r : f) {
            ASSERT_GE(r.x, 0);
            ASSERT_GE(r.y, 0);
            ASSERT_LE(r.x + r.width, w);
            ASSERT_LE(r.y + r.height, h);
            for (int j = r.y; j < r.y + r.height; ++j)
                for (int i = r.x; i < r.x + r.width; ++i)
                    ++covered[static_cast<size_t>(j) * w + i];
        }
        EXPECT_EQ(*std::max_element(covered.begin(), covered.end()), 1) << "level " << l;
        for (const TexelRect& r : rects) // every level-0 texel's ancestor is in the footprint
            for (int j = r.y; j < r.y + r.height; ++j)
                for (int i = r.x; i < r.x + r.width; ++i)
                    EXPECT_EQ(covered[static_cast<size_t>(j >> l) * w + (i >> l)], 1)
                        << "level " << l << " from " << i << ", " << j;
    }
    EXPECT_EQ(weatherFootprint(rects, map, 0).size(), 4u);
    EXPECT_EQ(weatherFootprint(rects, map, 6).size(), 1u); // the 1x1 level
}
