#pragma once
// What a kept shadow map of the clouds makes again for a new frame, for both backends' plumbing
// (src/cpu/cpu_cloud_shadow.cpp, src/vulkan/cloud_shadow_map.cpp). A texel's record depends on
// the CloudParams bytes but for where the map lies, and the storage is toroidal
// (cloud_shadow.glsl.h: each world texel keeps its place in the buffer), so a map that only moved
// makes the rows and columns the move brings in, and one whose inputs stayed makes nothing.
#include "model/params.glsl.h"

#include <glm/vec2.hpp>

#include <cstdlib>

namespace cloudscape {

// Clears in `p` what only places the map (its first texel and storage shift) and what the map
// never reads (the sky-view table's radius: the camera's altitude), leaving every input a
// texel's record depends on, so a camera flying over the map keeps every texel it still covers.
// CloudParams is plain data written whole by makeCloudParams: equal bytes, equal records.
inline void clearCloudShadowPlacement(model::CloudParams& p) {
    p.cloudShadow.firstTexel = glm::ivec2(0);
    p.cloudShadow.storageShiftX = 0;
    p.cloudShadow.storageShiftZ = 0;
    p.sky.atmosphere.skyViewRadius = 0.0f;
}

// Texels [begin, end) of the map, in map coordinates.
struct CloudShadowRegion {
    glm::ivec2 begin{0};
    glm::ivec2 end{0};
    long long texels() const { return static_cast<long long>(end.x - begin.x) * (end.y - begin.y); }
};

// At most two regions, none empty.
struct CloudShadowRegions {
    CloudShadowRegion parts[2];
    int count = 0;
    void add(glm::ivec2 begin, glm::ivec2 end) {
        if (end.x > begin.x && end.y > begin.y)
            parts[count++] = {begin, end};
    }
};

// What a map of n^2 texels must make when it holds records of the same inputs (sameRecords)
// placed `move` texels (now's first texel minus the held one's) away: nothing for no move, the
// columns the move brings in (over all rows) and then the rows (over the other columns) for a
// move within the map, else the whole map.
inline CloudShadowRegions cloudShadowRegionsToMake(bool sameRecords, glm::ivec2 move, int n) {
    CloudShadowRegions r;
    if (sameRecords && move == glm::ivec2(0))
        return r;
    if (!sameRecords || std::abs(move.x) >= n || std::abs(move.y) >= n) {
        r.add({0, 0}, {n, n});
        return r;
    }
    const int x0 = move.x > 0 ? n - move.x : 0;
    const int x1 = move.x > 0 ? n : -move.x;
    const int keptX0 = move.x > 0 ? 0 : x1;
    const int keptX1 = move.x > 0 ? x0 : n;
    r.add({x0, 0}, {x1, n});
    const int y0 = move.y > 0 ? n - move.y : 0;
    const int y1 = move.y > 0 ? n : -move.y;
    r.add({keptX0, y0}, {keptX1, y1});
    return r;
}

} // namespace cloudscape
