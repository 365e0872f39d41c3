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

// Output pixel `pixel` of frame F from a pass of passSize pixels covering the same view. Pixel
// centres: output x + 0.5 lands at pass coordinate (x + 0.5) * passWidth / width - 0.5. bg is
// the pixel's backgroundTexelAt (made on the spot, or kept by a background pass). shaftGrid: the
// pass made the light shafts' grid over its image (a temporal frame with shafts.grid_factor > 1,
// shaft_grid.glsl.h), read here at the pixel's place in the pass instead of marching the
// pixel's own shafts at full size.
inline UpsampledPixel upsampleCloudPass(ivec2 pixel, ivec2 passSize, IN(FrameParams) F,
                                        IN(CloudParams) P, IN(BackgroundTexel) bg, bool shaftGrid) {
    float geometry = bg.seen.w;
    float sx = float(passSize.x) / float(F.width);
    float sy = float(passSize.y) / float(F.height);
    float u = clamp((float(pixel.x) + 0.5f) * sx - 0.5f, 0.0f, float(passSize.x) - 1.0f);
    float v = clamp((float(pixel.y) + 0.5f) * sy - 0.5f, 0.0f, float(passSize.y) - 1.0f);
    int x0 = int(u);
    int y0 = int(v);
    int x1 = min(x0 + 1, passSize.x - 1);
    int y1 = min(y0 + 1, passSize.y - 1);
    float ax = u - float(x0);
    float ay = v - float(y0);
    vec4 sum = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    sum += upsampleTap(ivec2(x0, y0), geometry) * ((1.0f - ax) * (1.0f - ay));
    sum += upsampleTap(ivec2(x1, y0), geometry) * (ax * (1.0f - ay));
    sum += upsampleTap(ivec2(x0, y1), geometry) * ((1.0f - ax) * ay);
    sum += upsampleTap(ivec2(x1, y1), geometry) * (ax * ay);
    float flash = 0.0f;
    if (lightningOn(P)) {
        flash = upsampleFlashTap(ivec2(x0, y0), geometry) * ((1.0f - ax) * (1.0f - ay)) +
                upsampleFlashTap(ivec2(x1, y0), geometry) * (ax * (1.0f - ay)) +
                upsampleFlashTap(ivec2(x0, y1), geometry) * ((1.0f - ax) * ay) +
                upsampleFlashTap(ivec2(x1, y1), geometry) * (ax * ay);
    }
    ivec2 nearest = ivec2(ax < 0.5f ? x0 : x1, ay < 0.5f ? y0 : y1);
    float cloudDepth = passTexel(nearest).depth;
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
        delta = shaftGridDeltaAt(vec2(u, v), passSize, cloudDepth, sum.w, geometry, dir, F, P);
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
