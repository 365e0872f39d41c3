// Reduced-resolution clouds (render.cloud_resolution < 1, the low tier's half resolution) brought
// to an output pixel, for both backends: the premultiplied cloud layer of the pass bilinearly,
// where a tap whose first cloud lies at or behind this pixel's geometry counts as clear sky
// (depth-aware), the cloud distance from the nearest tap, then composited over the
// full-resolution background. The pass is read through passTexel, a prototype like the texture
// reads: the CPU backend serves it from the pass's RenderResult, upsample_clouds.comp from the
// pass's CloudTexel buffer on the device.
#ifndef CLOUDSCAPE_MODEL_UPSAMPLE_GLSL_H
#define CLOUDSCAPE_MODEL_UPSAMPLE_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "interface.glsl.h"
#include "output.glsl.h"
#include "params.glsl.h"
#include "pixel.glsl.h"
#include "shaft_grid.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// One pixel of the reduced-resolution pass (inside the pass's image).
CloudTexel passTexel(ivec2 pixel);
// The background the pass made for one of its pixels (backgroundTexelAt at the pass size), read
// only where the output's background is brought up from the pass (upsampledBackground).
BackgroundTexel passBackgroundTexel(ivec2 pixel);

// Where an output pixel falls in the pass: its four taps (x0, y0) .. (x1, y1), the fractions
// (ax, ay) between them and the taps' bilinear weights, in the order (x0, y0), (x1, y0),
// (x0, y1), (x1, y1); (u, v) the pixel's centre in pass pixel coordinates. Pixel centres: output
// x + 0.5 lands at pass coordinate (x + 0.5) * passWidth / width - 0.5.
struct PassFootprint {
    float u;
    float v;
    int x0;
    int y0;
    int x1;
    int y1;
    float ax;
    float ay;
    vec4 weights;
};

inline PassFootprint passFootprint(ivec2 pixel, ivec2 passSize, IN(FrameParams) F) {
    PassFootprint f;
    float sx = float(passSize.x) / float(F.width);
    float sy = float(passSize.y) / float(F.height);
    f.u = clamp((float(pixel.x) + 0.5f) * sx - 0.5f, 0.0f, float(passSize.x) - 1.0f);
    f.v = clamp((float(pixel.y) + 0.5f) * sy - 0.5f, 0.0f, float(passSize.y) - 1.0f);
    f.x0 = int(f.u);
    f.y0 = int(f.v);
    f.x1 = min(f.x0 + 1, passSize.x - 1);
    f.y1 = min(f.y0 + 1, passSize.y - 1);
    f.ax = f.u - float(f.x0);
    f.ay = f.v - float(f.y0);
    f.weights = vec4((1.0f - f.ax) * (1.0f - f.ay), f.ax * (1.0f - f.ay), (1.0f - f.ax) * f.ay,
                     f.ax * f.ay);
    return f;
}

// The tap nearest the pixel's centre.
inline ivec2 nearestTap(IN(PassFootprint) f) {
    return ivec2(f.ax < 0.5f ? f.x0 : f.x1, f.ay < 0.5f ? f.y0 : f.y1);
}

// An output pixel's background brought up from the pass's, as the clouds are: the radiances
// bilinearly, the distances (of what lies beyond the high layer, and the geometry's depth, which
// orders cloud and geometry in the composite) from the nearest tap, as the cloud's depth is. Used
// while the camera moves with render.moving_background_reduced: the background's terrain march
// and light then run for the pass's pixels only, instead of every output pixel every frame.
inline BackgroundTexel upsampledBackground(ivec2 pixel, ivec2 passSize, IN(FrameParams) F) {
    PassFootprint f = passFootprint(pixel, passSize, F);
    BackgroundTexel t00 = passBackgroundTexel(ivec2(f.x0, f.y0));
    BackgroundTexel t10 = passBackgroundTexel(ivec2(f.x1, f.y0));
    BackgroundTexel t01 = passBackgroundTexel(ivec2(f.x0, f.y1));
    BackgroundTexel t11 = passBackgroundTexel(ivec2(f.x1, f.y1));
    vec4 w = f.weights;
    BackgroundTexel nearest = passBackgroundTexel(nearestTap(f));
    BackgroundTexel t;
    t.beyond = t00.beyond * w.x + t10.beyond * w.y + t01.beyond * w.z + t11.beyond * w.w;
    t.seen = t00.seen * w.x + t10.seen * w.y + t01.seen * w.z + t11.seen * w.w;
    t.beyond.w = nearest.beyond.w;
    t.seen.w = nearest.seen.w;
    return t;
}

struct UpsampledPixel {
    CloudTexel cloud; // weight unused
    vec3 composite;
};

// A tap of the pass, seen from a pixel whose geometry lies at geometryDepth.
inline vec4 upsampleTap(ivec2 p, float geometryDepth) {
    CloudTexel t = passTexel(p);
    if (cloudHiddenByGeometry(t.depth, geometryDepth)) {
        return vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
    return t.cloud;
}

// The masked lightning flash of the same tap (0 where the tap is hidden).
inline float upsampleFlashTap(ivec2 p, float geometryDepth) {
    CloudTexel t = passTexel(p);
    return cloudHiddenByGeometry(t.depth, geometryDepth) ? 0.0f : t.flash;
}

// Output pixel `pixel` of frame F from a pass of passSize pixels covering the same view
// (passFootprint). bg is the pixel's backgroundTexelAt (made on the spot, or kept by a
// background pass), or its upsampledBackground while a moving camera asks for it. shaftGrid: the
// pass made the light shafts' grid over its image (a temporal frame with shafts.grid_factor > 1,
// shaft_grid.glsl.h), read here at the pixel's place in the pass instead of marching the
// pixel's own shafts at full size.
inline UpsampledPixel upsampleCloudPass(ivec2 pixel, ivec2 passSize, IN(FrameParams) F,
                                        IN(CloudParams) P, IN(BackgroundTexel) bg, bool shaftGrid) {
    float geometry = bg.seen.w;
    PassFootprint f = passFootprint(pixel, passSize, F);
    vec4 w = f.weights;
    vec4 sum = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    sum += upsampleTap(ivec2(f.x0, f.y0), geometry) * w.x;
    sum += upsampleTap(ivec2(f.x1, f.y0), geometry) * w.y;
    sum += upsampleTap(ivec2(f.x0, f.y1), geometry) * w.z;
    sum += upsampleTap(ivec2(f.x1, f.y1), geometry) * w.w;
    float flash = 0.0f;
    if (lightningOn(P)) {
        flash = upsampleFlashTap(ivec2(f.x0, f.y0), geometry) * w.x +
                upsampleFlashTap(ivec2(f.x1, f.y0), geometry) * w.y +
                upsampleFlashTap(ivec2(f.x0, f.y1), geometry) * w.z +
                upsampleFlashTap(ivec2(f.x1, f.y1), geometry) * w.w;
    }
    float cloudDepth = passTexel(nearestTap(f)).depth;
    if (cloudHiddenByGeometry(cloudDepth, geometry)) {
        cloudDepth = NO_HIT;
    }
    vec3 dir = cameraRayDirection(F, float(pixel.x), float(pixel.y));
    vec3 radiance = vec3(sum.x, sum.y, sum.z);
    UpsampledPixel r;
    r.cloud.cloud = sum;
    r.cloud.depth = cloudDepth;
    r.cloud.weight = 0.0f;
    r.cloud.flash = flash;
    r.cloud.debug = 0.0f;
    BackgroundTexel behind = bg;
    behind.seen.w = min(geometry, P.maxDistance);
    // One composite whichever way the shafts come (llvmpipe runs both sides of a branch).
    vec3 delta;
    if (shaftGrid && shaftGridActive(P)) {
        delta = shaftGridDeltaAt(vec2(f.u, f.v), passSize, cloudDepth, sum.w, geometry, dir, F, P);
    } else {
        delta = pixelShaftsDelta(pixel, 0u, sum.w, cloudDepth, dir, behind.seen.w, F, P);
    }
    r.composite = compositeWithShaftsDelta(radiance, sum.w, flash, cloudDepth, dir, behind,
                                           lightShaftsActive(P), delta, F, P);
    return r;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
