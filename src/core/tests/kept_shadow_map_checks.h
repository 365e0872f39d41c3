#pragma once
// Test support shared by the CPU and GPU test binaries: what a sequence renderer's kept shadow
// map of the clouds must do (src/core/cloud_shadow_update.h), checked through the persistent
// Renderer whatever its backend.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include "core/model_params.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace cloudscape::testing {

// The renderer keeps its map while its inputs stay (the viewer's still scene): a frame of the
// same scene reuses it, and every change that moves the clouds' density makes it again: the
// wind's time, a weather key, an edit of the weather map in place, and the map's own
// resolution. A change that missed the map would leave stale shadows. `s` has the map on.
inline void expectTheMapMadeAgainOnlyWhenItsInputsChange(Renderer& renderer, Scene s) {
    int frame = 0;
    std::vector<glm::vec4> last;
    // Renders a frame; returns whether it made the map, and checks a made map is a new one and
    // a kept one the same.
    auto made = [&](const char* what) {
        const bool m = renderer.renderFrame(s, frame++).stats.shadowMapMade;
        const std::vector<glm::vec4> map = renderer.cloudShadowMap();
        if (!last.empty() && map.size() == last.size()) {
            const bool same = std::memcmp(map.data(), last.data(), map.size() * sizeof map[0]) == 0;
            EXPECT_EQ(same, !m) << what << ": a made map is new, a kept one unchanged";
        }
        last = map;
        return m;
    };
    EXPECT_TRUE(made("the first frame"));
    EXPECT_FALSE(made("the same scene"));
    EXPECT_FALSE(made("the same scene again"));
    s.timeS += 120.0f;
    EXPECT_TRUE(made("two minutes of wind"));
    EXPECT_FALSE(made("the same time"));
    s.coverage += 0.1f;
    EXPECT_TRUE(made("a weather key"));
    renderer.editWeatherMap({{0, 0, 32, 32}}, [](Texture2D& w) {
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                w.texel(0, x, y)[0] = 1.0f; // full coverage in a corner
    });
    EXPECT_TRUE(made("a painted weather map"));
    EXPECT_FALSE(made("the painted map kept"));
    s.cloudShadowResolution = 64;
    EXPECT_TRUE(made("another resolution"));
    s.cloudShadowEnabled = false;
    s.shaftsEnabled = false;
    EXPECT_FALSE(made("the map off"));
    EXPECT_TRUE(last.empty());
}

// A camera flying over the map with the wind's time held (the viewer): the renderer makes only
// the rows and columns each move brings in (the buffer is toroidal, cloud_shadow.glsl.h), and the
// map it holds is, bit for bit, wholeMapFor(scene): the map a whole pass makes for that camera,
// in map order. A move the storage got wrong would leave records of the old place, or in the
// wrong rows, behind.
inline void expectAFlyingCameraMakesOnlyTheTexelsItsMoveBringsIn(
    Renderer& flying, Scene s,
    const std::function<std::vector<glm::vec4>(const Scene&)>& wholeMapFor) {
    const int n = s.cloudShadowResolution;
    const float texel = s.cloudShadowExtentM / float(n);
    auto firstTexel = [&](const Scene& at) {
        return makeCloudParams(at, flying.resources()).cloudShadow.firstTexel;
    };
    int frame = 0;
    glm::ivec2 held = firstTexel(s);
    EXPECT_EQ(flying.renderFrame(s, frame++).stats.shadowMapTexelsMade, int64_t(n) * n);
    // Moves in texels: under one, along each axis both ways, diagonal, and past the map.
    const glm::vec2 moves[] = {{0.3f, 0.0f}, {3.0f, 0.0f},   {0.0f, -2.0f}, {-5.0f, 4.0f},
                               {7.0f, 9.0f}, {-1.0f, -1.0f}, {150.0f, 0.0f}};
    for (glm::vec2 move : moves) {
        s.cameraPosition.x += move.x * texel;
        s.cameraPosition.z += move.y * texel;
        const glm::ivec2 now = firstTexel(s);
        const glm::ivec2 d = glm::abs(now - held);
        held = now;
        const int64_t expected =
            d.x >= n || d.y >= n ? int64_t(n) * n : int64_t(n) * d.x + int64_t(n - d.x) * d.y;
        const RenderResult a = flying.renderFrame(s, frame++);
        EXPECT_EQ(a.stats.shadowMapTexelsMade, expected) << move.x << ", " << move.y;
        EXPECT_EQ(a.stats.shadowMapMade, expected > 0);
        const std::vector<glm::vec4> got = flying.cloudShadowMap();
        const std::vector<glm::vec4> want = wholeMapFor(s);
        ASSERT_EQ(got.size(), want.size());
        size_t differ = 0, cloudy = 0;
        for (size_t i = 0; i < got.size(); ++i) {
            differ += std::memcmp(&got[i], &want[i], sizeof got[i]) != 0 ? 1 : 0;
            cloudy += want[i].z > 0.0f ? 1 : 0;
        }
        EXPECT_EQ(differ, 0u) << "after a move of " << move.x << ", " << move.y << " texels";
        EXPECT_GT(cloudy, got.size() / 10) << "the map holds cloud";
    }
}

} // namespace cloudscape::testing
