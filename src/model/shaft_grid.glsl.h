// Light shafts on a coarser grid, for the temporal resolve (shafts.grid_factor N > 1): the shafts
// are low-frequency (the clouds' shadow seen through kilometres of air), so one shaft ray per
// N x N pixels, upsampled, holds nearly all of them at 1/N^2 of the cost, while the clouds
// themselves are marched at full resolution. What is not low-frequency is where a ray's shafts
// end or split: at a terrain or cloud silhouette the air behind changes in one pixel. So each
// cell keeps its ray's two parts (lightShaftsParts: in front of the first cloud, and behind it
// before the cloud's transmittance) with the two distances that decide them (the shafts' length,
// lightShaftsEnd, and the first cloud's distance within it), and a pixel blends the four cells
// around it bilinearly, each weighted by how close its distances are to the pixel's own
// (depth-aware); the pixel applies its own cloud transmittance to the part behind. The cells'
// step offsets are fixed per cell, like a pixel's, so a still view does not flicker.
//
// A cell sits on the pixel cell * N + N / 2 (clamped into the image), whose resolved cloud depth
// it uses. The grid is read through shaftTexel, a prototype like the texture reads: the CPU
// backend serves it from its buffer, temporal_resolve.comp from RESOLVE_SHAFTS.
#ifndef CLOUDSCAPE_MODEL_SHAFT_GRID_GLSL_H
#define CLOUDSCAPE_MODEL_SHAFT_GRID_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "interface.glsl.h"
#include "light_shafts.glsl.h"
#include "params.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// One cell of this frame's grid (inside shaftGridSize).
ShaftTexel shaftTexel(ivec2 cell);

// True when the temporal resolve takes its shafts from the grid.
inline bool shaftGridActive(IN(CloudParams) P) {
    return lightShaftsActive(P) && P.shafts.gridFactor > 1;
}

// Cells of the grid over an image of `size` pixels.
inline ivec2 shaftGridSize(ivec2 size, int factor) {
    return (size + ivec2(factor - 1)) / factor;
}

// The pixel a cell's shaft ray goes through.
inline ivec2 shaftGridPixel(ivec2 cell, ivec2 size, int factor) {
    return min(cell * factor + ivec2(factor / 2), size - ivec2(1));
}

// Where the shafts of a ray end (its length) and split (the first cloud within that length).
inline float shaftSplit(float cloudDepth, float end) {
    return cloudDepth == NO_HIT ? end : min(cloudDepth, end);
}

// A cell's record: its pixel's ray, that pixel's first cloud (cloudDepth, from the resolve) and
// geometry.
inline ShaftTexel shaftGridTexel(ivec2 cell, float cloudDepth, float geometryDepth,
                                 IN(FrameParams) F, IN(CloudParams) P) {
    ivec2 pixel = shaftGridPixel(cell, ivec2(F.width, F.height), P.shafts.gridFactor);
    vec3 dir = cameraRayDirection(F, float(pixel.x), float(pixel.y));
    float jitter = pixelRandom(uint(cell.x), uint(cell.y), 0u, uint(F.seed) ^ 0x5aa5u);
    ShaftLight parts =
        lightShaftsParts(F.cameraPosition, dir, cloudDepth, geometryDepth, jitter, P);
    float end = lightShaftsEnd(F.cameraPosition, dir, geometryDepth, P);
    ShaftTexel t;
    t.front = vec4(parts.front, end);
    t.behind = vec4(parts.behind, shaftSplit(cloudDepth, end));
    return t;
}

// How well a cell stands for a pixel whose shafts have length `end` and split at `split`: 1 when
// both distances agree, 1/2 when they differ by 10 % in all, toward 0 across a silhouette.
inline float shaftCellSimilarity(ShaftTexel t, float end, float split) {
    float d = abs(t.front.w - end) / max(end, 1.0f) + abs(t.behind.w - split) / max(split, 1.0f);
    float x = 10.0f * d;
    return 1.0f / (1.0f + x * x);
}

// The running sums of the upsample.
struct ShaftBlend {
    vec3 front;
    vec3 behind;
    float weight;
    float bestSimilarity;
    ShaftTexel best;
};

inline void addShaftCell(INOUT(ShaftBlend) b, ivec2 cell, float bilinear, float end, float split) {
    ShaftTexel t = shaftTexel(cell);
    float similarity = shaftCellSimilarity(t, end, split);
    float w = bilinear * similarity;
    b.front += vec3(t.front.x, t.front.y, t.front.z) * w;
    b.behind += vec3(t.behind.x, t.behind.y, t.behind.z) * w;
    b.weight += w;
    if (similarity > b.bestSimilarity) {
        b.bestSimilarity = similarity;
        b.best = t;
    }
}

// The shafts' change (<= 0) at `pixel` from the grid: the four cells around it, bilinear and
// depth-aware; where none of them is like the pixel (all weights under 1e-4), the most similar.
// cloudDepth and transmittance are the pixel's own resolved cloud's; geometryDepth its geometry's.
// `at` is the pixel's place in the image the grid was made over (`image` pixels: the frame's own,
// or a reduced pass's, whose grid the upsample reads); dir, cloudDepth, transmittance and
// geometryDepth are the pixel's own.
inline vec3 shaftGridDeltaAt(vec2 at, ivec2 image, float cloudDepth, float transmittance,
                             float geometryDepth, vec3 dir, IN(FrameParams) F, IN(CloudParams) P) {
    int factor = P.shafts.gridFactor;
    ivec2 grid = shaftGridSize(image, factor);
    float centre = float(factor / 2); // the cells' pixels (shaftGridPixel)
    float u = clamp((at.x - centre) / float(factor), 0.0f, float(grid.x - 1));
    float v = clamp((at.y - centre) / float(factor), 0.0f, float(grid.y - 1));
    int x0 = int(u);
    int y0 = int(v);
    int x1 = min(x0 + 1, grid.x - 1);
    int y1 = min(y0 + 1, grid.y - 1);
    float ax = u - float(x0);
    float ay = v - float(y0);
    float end = lightShaftsEnd(F.cameraPosition, dir, geometryDepth, P);
    float split = shaftSplit(cloudDepth, end);
    ShaftBlend b;
    b.front = vec3(0.0f);
    b.behind = vec3(0.0f);
    b.weight = 0.0f;
    b.bestSimilarity = -1.0f;
    b.best.front = vec4(0.0f);
    b.best.behind = vec4(0.0f);
    addShaftCell(b, ivec2(x0, y0), (1.0f - ax) * (1.0f - ay), end, split);
    addShaftCell(b, ivec2(x1, y0), ax * (1.0f - ay), end, split);
    addShaftCell(b, ivec2(x0, y1), (1.0f - ax) * ay, end, split);
    addShaftCell(b, ivec2(x1, y1), ax * ay, end, split);
    vec3 front = vec3(b.best.front.x, b.best.front.y, b.best.front.z);
    vec3 behind = vec3(b.best.behind.x, b.best.behind.y, b.best.behind.z);
    if (b.weight >= 1e-4f) {
        front = b.front / b.weight;
        behind = b.behind / b.weight;
    }
    float throughCloud = cloudDepth == NO_HIT ? 1.0f : transmittance;
    return -(front + behind * throughCloud);
}

// The same for a pixel of the image the grid was made over.
inline vec3 shaftGridDelta(ivec2 pixel, float cloudDepth, float transmittance, float geometryDepth,
                           vec3 dir, IN(FrameParams) F, IN(CloudParams) P) {
    return shaftGridDeltaAt(vec2(pixel), ivec2(F.width, F.height), cloudDepth, transmittance,
                            geometryDepth, dir, F, P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
