// Temporal reconstruction (Horizon Zero Dawn, GPU Pro 7 notes and the Forbidden West talk): each
// frame marches one pixel of every 4x4 block, in a fixed order that visits all 16 in 16 frames
// (while the camera moves, optionally one of every 2x2 block: temporalBlockFor);
// every other pixel is reprojected from the previous full-resolution result, moved with the
// camera and with the clouds' own wind drift using the stored cloud distance, and falls back to
// the block's fresh pixel where the history is invalid (off screen, disoccluded, no history).
// A moving camera may instead gather its last frames' marches (sample_gather.glsl.h).
#ifndef CLOUDSCAPE_MODEL_TEMPORAL_GLSL_H
#define CLOUDSCAPE_MODEL_TEMPORAL_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "interface.glsl.h"
#include "params.glsl.h"
#include "pixel.glsl.h"
#include "sample_gather.glsl.h"
#include "shaft_grid.glsl.h"
#include "shell.glsl.h"
#include "temporal_frame.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Reprojection offsets (pixels) beyond which history stops accumulating.
CONST_FLOAT ACCUMULATION_MOTION_LIMIT = 0.25f;
// Marches a moving pixel averages while the camera turns without translating and marches the
// small block (turningMarchCount).
CONST_INT TURNING_ACCUMULATION = 2;
// Motion (pixels) that depends on the distance, beyond which a translating camera's history is
// not trusted (reprojectedHistory).
CONST_FLOAT HISTORY_PARALLAX_LIMIT = 1.0f;

// Reads the backend provides for the resolve, as prototypes like the texture reads: one texel of
// the previous frame's result (a pixel inside the previous image) and this frame's march of a
// block (a block inside this frame's grid). Filtering and clamping are the model's, below.
CloudTexel historyTexel(ivec2 pixel);
CloudTexel freshTexel(ivec2 block);

// The pixel nearest to a fractional position, clamped to an image: round half up, computed from
// floor so that both languages agree exactly (GLSL's round() may round ties either way).
inline ivec2 nearestPixel(vec2 pixel, ivec2 size) {
    vec2 below = floor(pixel);
    vec2 r = below + step(vec2(0.5f, 0.5f), pixel - below);
    r = clamp(r, vec2(0.0f, 0.0f), vec2(float(size.x - 1), float(size.y - 1)));
    return ivec2(int(r.x), int(r.y));
}

// The history at a fractional pixel: premultiplied cloud and transmittance bilinearly, clamped at
// the image edge (size: the previous frame's).
inline vec4 historyCloud(vec2 pixel, ivec2 size) {
    vec2 p = clamp(pixel, vec2(0.0f, 0.0f), vec2(float(size.x - 1), float(size.y - 1)));
    ivec2 p0 = ivec2(int(p.x), int(p.y));
    ivec2 p1 = ivec2(min(p0.x + 1, size.x - 1), min(p0.y + 1, size.y - 1));
    vec2 a = p - vec2(float(p0.x), float(p0.y));
    vec4 top = mix(historyTexel(p0).cloud, historyTexel(ivec2(p1.x, p0.y)).cloud, a.x);
    vec4 bottom = mix(historyTexel(ivec2(p0.x, p1.y)).cloud, historyTexel(p1).cloud, a.x);
    return mix(top, bottom, a.y);
}

// The masked lightning flash channel of the history, bilinearly like the cloud (only read while
// there is lightning).
inline float historyFlash(vec2 pixel, ivec2 size) {
    vec2 p = clamp(pixel, vec2(0.0f, 0.0f), vec2(float(size.x - 1), float(size.y - 1)));
    ivec2 p0 = ivec2(int(p.x), int(p.y));
    ivec2 p1 = ivec2(min(p0.x + 1, size.x - 1), min(p0.y + 1, size.y - 1));
    vec2 a = p - vec2(float(p0.x), float(p0.y));
    float top = mix(historyTexel(p0).flash, historyTexel(ivec2(p1.x, p0.y)).flash, a.x);
    float bottom = mix(historyTexel(ivec2(p0.x, p1.y)).flash, historyTexel(p1).flash, a.x);
    return mix(top, bottom, a.y);
}

// Cloud distance and accumulated marches are not filtered: the nearest pixel's.
inline float historyDepth(vec2 pixel, ivec2 size) {
    return historyTexel(nearestPixel(pixel, size)).depth;
}
// The nearest cloud distance among the 3x3 history pixels around a pixel (NO_HIT if none has
// cloud): the first guess of the reprojection's distance. A cloud that grows into a pixel as the
// camera approaches (its edge moving outward) left that pixel's own history at the sky or ground
// behind; started from there the iteration found the background's consistent answer, and the
// cloud's outer edge was shown only where a march landed, a 4x4 stipple along every expanding
// edge. Started from the nearest cloud (the "closest depth" of temporal anti-aliasing) it finds
// the cloud where the cloud now is.
inline float nearestHistoryDepth(vec2 pixel, ivec2 size) {
    ivec2 centre = nearestPixel(pixel, size);
    float nearest = NO_HIT;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 p = clamp(centre + ivec2(dx, dy), ivec2(0, 0), size - ivec2(1, 1));
            float d = historyTexel(p).depth;
            if (d != NO_HIT && (nearest == NO_HIT || d < nearest)) {
                nearest = d;
            }
        }
    }
    return nearest;
}

inline float historyWeight(vec2 pixel, ivec2 size) {
    return historyTexel(nearestPixel(pixel, size)).weight;
}

// The four marched blocks around a pixel that the upsampled fallback blends (b0 to b1) and the
// bilinear weights between them (a), clamped to the image's blocks.
struct UpsampleFootprint {
    ivec2 b0;
    ivec2 b1;
    vec2 a;
};

inline UpsampleFootprint upsampleFootprint(ivec2 pixel, int frame, IN(FrameParams) F) {
    int side = frameBlock(F);
    ivec2 offset = blockOffsetForFrame(frame, side);
    ivec2 blocks = temporalBlockCount(ivec2(F.width, F.height), side);
    vec2 u = vec2(float(pixel.x - offset.x), float(pixel.y - offset.y)) / float(side);
    u = clamp(u, vec2(0.0f, 0.0f), vec2(float(blocks.x - 1), float(blocks.y - 1)));
    UpsampleFootprint f;
    f.b0 = ivec2(int(floor(u.x)), int(floor(u.y)));
    f.b1 = ivec2(min(f.b0.x + 1, blocks.x - 1), min(f.b0.y + 1, blocks.y - 1));
    f.a = u - vec2(float(f.b0.x), float(f.b0.y));
    return f;
}

// The fresh marches' flash channel at a pixel, bilinearly as upsampledFresh does the cloud.
inline float upsampledFreshFlash(ivec2 pixel, int frame, IN(FrameParams) F) {
    UpsampleFootprint f = upsampleFootprint(pixel, frame, F);
    ivec2 b0 = f.b0;
    ivec2 b1 = f.b1;
    vec2 a = f.a;
    float top = mix(freshTexel(b0).flash, freshTexel(ivec2(b1.x, b0.y)).flash, a.x);
    float bottom = mix(freshTexel(ivec2(b0.x, b1.y)).flash, freshTexel(b1).flash, a.x);
    return mix(top, bottom, a.y);
}

// The nearest cloud distance of the four marches upsampledFresh blends (NO_HIT if none saw
// cloud): the distance that goes with the blended cloud. The pixel's own block's distance would
// be NO_HIT wherever only a neighbour's march found cloud, and hideBehindGeometry then erased
// that cloud over terrain, frame after frame: a moving camera's cloud edges over the ground
// wore away until only the marched pixels showed them, a 4x4 stipple.
inline float upsampledFreshDepth(ivec2 pixel, int frame, IN(FrameParams) F) {
    UpsampleFootprint f = upsampleFootprint(pixel, frame, F);
    ivec2 b0 = f.b0;
    ivec2 b1 = f.b1;
    float d[4];
    d[0] = freshTexel(b0).depth;
    d[1] = freshTexel(ivec2(b1.x, b0.y)).depth;
    d[2] = freshTexel(ivec2(b0.x, b1.y)).depth;
    d[3] = freshTexel(b1).depth;
    float nearest = NO_HIT;
    for (int i = 0; i < 4; ++i) {
        if (d[i] != NO_HIT && (nearest == NO_HIT || d[i] < nearest)) {
            nearest = d[i];
        }
    }
    return nearest;
}

// This frame's marches upsampled to a pixel: bilinear between the four nearest marched pixels
// (which sit at block * side + this frame's offset), clamped to the image's blocks. Used where
// there is no history, so revealed areas are smooth rather than 4x4 blocks.
inline vec4 upsampledFresh(ivec2 pixel, int frame, IN(FrameParams) F) {
    UpsampleFootprint f = upsampleFootprint(pixel, frame, F);
    ivec2 b0 = f.b0;
    ivec2 b1 = f.b1;
    vec2 a = f.a;
    vec4 top = mix(freshTexel(b0).cloud, freshTexel(ivec2(b1.x, b0.y)).cloud, a.x);
    vec4 bottom = mix(freshTexel(ivec2(b0.x, b1.y)).cloud, freshTexel(b1).cloud, a.x);
    return mix(top, bottom, a.y);
}

// The record a block march keeps of a pixel's march (the fresh marches, the gather's rings):
// weight is the block's entering marches for the block's own march (sample_gather.glsl.h), 0
// for an entering march; debug the viewer's texelDebugCode.
inline CloudTexel marchRecord(IN(PixelResult) r, float weight, float debug) {
    CloudTexel t;
    t.cloud = vec4(r.cloudRadiance, r.transmittance);
    t.depth = r.depth;
    t.weight = weight;
    t.flash = r.flash;
    t.debug = debug;
    return t;
}

struct TemporalPixel {
    vec4 cloud;    // premultiplied radiance, transmittance
    float depth;   // NO_HIT where there is no cloud
    float weight;  // marches accumulated in this pixel, capped by F.temporalAccumulation
    int source;    // TEMPORAL_SOURCE_MARCHED, _REPROJECTED or _FALLBACK (interface.glsl.h)
    float flash;   // the masked lightning flash at unit intensity (lightning.glsl.h)
    float samples; // density samples of the block's march this frame (the debug views' heat map)
};

// How far the clamp box reaches from the marches' bilinear blend, in units of their weighted mean
// absolute deviation from it: room for detail the sparse marches missed (with a march of 0 and
// one of 1 halfway between them, the box spans [-0.25, 1.25]).
CONST_FLOAT HISTORY_CLAMP_REACH = 1.5f;

// The history limited to a box around this frame's four marches around the pixel (the ones
// upsampledFresh blends): neighbourhood clamping as in temporal anti-aliasing, with the sparse
// marches as the neighbourhood. Reprojection moves the history to where its cloud went but cannot
// know what has appeared in front of it: flying into a cloud, the far sky and cloud of the
// history stayed "valid" while every march around it saw the white inside (fly-through SSIM 0.38
// there). The marches see it, so the history is held to what they see. The range of the 3x3
// blocks around the pixel's block (12x12 pixels) was the first neighbourhood; wherever any of
// nine marches saw cloud it let every history through, so a cloud edge retreating across the
// terrain left trails of stale cloud several blocks long (fly-forward 28.0 -> 29.0 dB against the
// reference; docs/PERFORMANCE.md). The box is centred on the marches' bilinear blend and reaches
// HISTORY_CLAMP_REACH times their weighted deviation from it, per channel, so it changes smoothly
// from pixel to pixel: the range of the four marches (the box before) is the same for every
// pixel between them, and history clamped to it showed as flat 4x4 squares. Applied where the
// camera has moved since the previous frame and historyInDoubt finds a reason.
inline vec4 clampToFreshNeighbourhood(vec4 history, ivec2 pixel, int frame, IN(FrameParams) F) {
    UpsampleFootprint f = upsampleFootprint(pixel, frame, F);
    vec4 c00 = freshTexel(f.b0).cloud;
    vec4 c10 = freshTexel(ivec2(f.b1.x, f.b0.y)).cloud;
    vec4 c01 = freshTexel(ivec2(f.b0.x, f.b1.y)).cloud;
    vec4 c11 = freshTexel(f.b1).cloud;
    float w00 = (1.0f - f.a.x) * (1.0f - f.a.y);
    float w10 = f.a.x * (1.0f - f.a.y);
    float w01 = (1.0f - f.a.x) * f.a.y;
    float w11 = f.a.x * f.a.y;
    vec4 centre = c00 * w00 + c10 * w10 + c01 * w01 + c11 * w11;
    vec4 spread = abs(c00 - centre) * w00 + abs(c10 - centre) * w10 + abs(c01 - centre) * w01 +
                  abs(c11 - centre) * w11;
    vec4 reach = spread * HISTORY_CLAMP_REACH;
    return clamp(history, centre - reach, centre + reach);
}

// Motion (pixels) that depends on the distance, beyond which a translating camera's history is
// held to this frame's marches (the drift its distance's error may bring). A pixel's history ages
// up to 15 frames between its marches, so a small drift adds up: at half a pixel the far cloud
// tops seen while climbing (the fly-through) drifted into vertical streaks.
CONST_FLOAT HISTORY_CLAMP_PARALLAX = 0.25f;

// Whether a translating camera's history may show what is no longer there, so that it is held to
// this frame's marches (clampToFreshNeighbourhood): where its image moves with its distance by
// more than HISTORY_CLAMP_PARALLAX (an error of that distance drifts it off its cloud), or where
// a march around the pixel sees cloud at a distance that would put the history more than that far
// from where it was taken (something new in front of it: flying into a cloud). Elsewhere, far
// cloud under a slow flight, nothing gives the history away, and marches 4 pixels apart cannot
// tell its detail from an error: held to their range, the detail between them was flattened into
// the squares of the 4x4 grid. `from`: where reprojectedHistory took the history; `nearest`:
// upsampledFreshDepth's, the nearest cloud of those marches.
inline bool historyInDoubt(ivec2 pixel, IN(FrameParams) F, IN(FrameParams) previous,
                           IN(CloudParams) P, float dt, vec2 from, float parallax, float nearest) {
    if (parallax > HISTORY_CLAMP_PARALLAX) {
        return true;
    }
    if (nearest == NO_HIT) {
        return false;
    }
    bool visible = false;
    vec2 there =
        reprojectPixel(F, previous, P, float(pixel.x), float(pixel.y), nearest, dt, visible);
    return !visible || length(there - from) > HISTORY_CLAMP_PARALLAX;
}

// The history at a fractional pixel through a Catmull-Rom filter, built from 9 bilinear reads
// (weights of the middle two taps folded into one bilinear position per axis). Sharper than one
// bilinear read, which matters because history is resampled every frame while a camera moves.
// The negative lobes can overshoot, so the result is clamped to valid radiance and
// transmittance.
inline vec4 historyCatmullRom(vec2 p, ivec2 size) {
    vec2 p1 = floor(p);
    vec2 f = p - p1;
    vec2 w0 = f * (vec2(-0.5f, -0.5f) + f * (vec2(1.0f, 1.0f) - 0.5f * f));
    vec2 w1 = vec2(1.0f, 1.0f) + f * f * (vec2(-2.5f, -2.5f) + 1.5f * f);
    vec2 w2 = f * (vec2(0.5f, 0.5f) + f * (vec2(2.0f, 2.0f) - 1.5f * f));
    vec2 w3 = f * f * (vec2(-0.5f, -0.5f) + 0.5f * f);
    vec2 w12 = w1 + w2;
    vec2 t0 = p1 - vec2(1.0f, 1.0f);
    vec2 t12 = p1 + w2 / w12;
    vec2 t3 = p1 + vec2(2.0f, 2.0f);
    vec4 sum = historyCloud(vec2(t0.x, t0.y), size) * (w0.x * w0.y) +
               historyCloud(vec2(t12.x, t0.y), size) * (w12.x * w0.y) +
               historyCloud(vec2(t3.x, t0.y), size) * (w3.x * w0.y) +
               historyCloud(vec2(t0.x, t12.y), size) * (w0.x * w12.y) +
               historyCloud(vec2(t12.x, t12.y), size) * (w12.x * w12.y) +
               historyCloud(vec2(t3.x, t12.y), size) * (w3.x * w12.y) +
               historyCloud(vec2(t0.x, t3.y), size) * (w0.x * w3.y) +
               historyCloud(vec2(t12.x, t3.y), size) * (w12.x * w3.y) +
               historyCloud(vec2(t3.x, t3.y), size) * (w3.x * w3.y);
    return vec4(max(sum.x, 0.0f), max(sum.y, 0.0f), max(sum.z, 0.0f), clamp(sum.w, 0.0f, 1.0f));
}

// The previous frame's value for this pixel, if it can be trusted. The cloud distance used to
// reproject is found by a short fixed-point iteration on the history's own depths (start from
// this pixel's old depth, reproject, read the depth there, reproject again); the history is
// accepted when it is on screen and that iteration is consistent to a pixel, which rejects
// disocclusions. A history without cloud (NO_HIT) is reprojected at the pixel's geometry
// (background: its distance, or P.maxDistance for sky): what that history showed was the ground
// behind it, and a climbing camera moves the ground across the image. Taken as infinitely far it
// stayed put, and cloud that had been in front of the ground was drawn where it had moved away.
inline bool reprojectedHistory(ivec2 pixel, IN(FrameParams) F, IN(FrameParams) previous,
                               IN(CloudParams) P, float dt, float background, float freshDepth,
                               OUT(vec4) cloud, OUT(float) depth, OUT(float) weight,
                               OUT(bool) still, OUT(float) flash, OUT(vec2) from,
                               OUT(float) parallax) {
    float x = float(pixel.x);
    float y = float(pixel.y);
    bool visible = false;
    ivec2 size = ivec2(previous.width, previous.height);
    depth = nearestHistoryDepth(vec2(x, y), size);
    if (freshDepth != NO_HIT && (depth == NO_HIT || freshDepth < depth)) {
        depth = freshDepth;
    }
    vec2 prev = vec2(x, y);
    for (int i = 0; i < 2; ++i) {
        prev =
            reprojectPixel(F, previous, P, x, y, depth == NO_HIT ? background : depth, dt, visible);
        depth = historyDepth(prev, size);
    }
    bool checkVisible = false;
    vec2 check = reprojectPixel(F, previous, P, x, y, depth == NO_HIT ? background : depth, dt,
                                checkVisible);
    bool onScreen = prev.x >= -0.5f && prev.y >= -0.5f && prev.x <= float(previous.width) - 0.5f &&
                    prev.y <= float(previous.height) - 0.5f;
    // The share of the pixel's motion that depends on the distance: where the history would be
    // if what it shows were at the march's far end. Under a translating camera a fraction of it
    // is an error of the distance, and each frame resamples the last frame's already warped
    // history, so history that moves by more than a pixel this way drifts off its cloud (near
    // cloud crossing the terrain smeared into blotches and trails in the fly-through). There the
    // upsampled marches, softer but in place, are the better answer.
    bool parallaxSmall = true;
    parallax = 0.0f;
    if (cameraTranslated(F, previous)) {
        bool farVisible = false;
        vec2 far = reprojectPixel(F, previous, P, x, y, P.maxDistance, dt, farVisible);
        parallax = length(far - prev);
        parallaxSmall = farVisible && parallax <= HISTORY_PARALLAX_LIMIT;
    }
    cloud = vec4(0.0f, 0.0f, 0.0f, 1.0f);
    weight = 0.0f;
    flash = 0.0f;
    from = prev;
    // Moving content: resampled history is blurred and may lag, so a new march replaces it;
    // only (nearly) still pixels keep accumulating.
    still = length(prev - vec2(x, y)) <= ACCUMULATION_MOTION_LIMIT;
    if (visible && checkVisible && onScreen && parallaxSmall && length(check - prev) < 1.0f) {
        // A still pixel reads its own history exactly; a moving one through Catmull-Rom.
        cloud = still ? historyCloud(prev, size) : historyCatmullRom(prev, size);
        weight = historyWeight(prev, size);
        // The flash mask is a smooth glow: bilinear whether the pixel moves or not.
        flash = lightningOn(P) ? historyFlash(prev, size) : 0.0f;
        // Weight 0: the pixel was itself a fallback (upsampled marches), not a march of its own.
        // A still pixel then falls back again, to this frame's marches. A moving one keeps it:
        // its count comes from the nearest pixel, which steps by whole pixels while the content
        // moves by fractions of one, so rejecting it would leave whole columns or rows of
        // fallback drifting across a pan (25 % of the pixels on the slow pan), and the upsampled
        // marches are blurrier than resampled history (issue 4: slow-pan SSIM 0.886 -> 0.932).
        return weight > 0.0f || !still;
    }
    return false;
}

// How many marches a pixel marched this frame averages with its reprojected history (weight: the
// history's). A still pixel: up to F.temporalAccumulation, its exact running mean. A moving one
// is replaced, as in Horizon, except where the camera turns (or zooms) without translating while
// it marches the small block
// (render.moving_block_2x2): the reprojection is exact without translation and the history at
// most 4 frames old, so averaging two marches halves the march's grain for the softening of one
// more resampling. High tier, 192x108, frames 24 and 28 against a 16-sample reference: fast pan
// SSIM 0.954 / 0.959 -> 0.963 / 0.966 (3 marches 0.961 / 0.965, 5 0.959 / 0.963: the resampled
// history's blur wins); a translating camera's history lags the clouds' parallax, and averaging
// it lost (fly-forward 0.938 -> 0.937 for parallax under a quarter pixel, 0.936 under one).
inline float marchCountFor(bool valid, bool still, float weight, int side, IN(FrameParams) F,
                           IN(FrameParams) previous) {
    float cap = float(max(F.temporalAccumulation, 1));
    if (!valid) {
        return 1.0f;
    }
    if (still) {
        return min(weight + 1.0f, cap);
    }
    bool turning =
        side == TEMPORAL_SMALL_BLOCK && cameraMoved(F, previous) && !cameraTranslated(F, previous);
    return turning ? min(weight + 1.0f, min(float(TURNING_ACCUMULATION), cap)) : 1.0f;
}

// One full-resolution pixel of frame `frame`. A pixel marched this frame is blended into its
// reprojected history with weight 1 / (accumulated marches + 1), capped at F.temporalAccumulation
// (1 is Horizon's plain replacement), so a still view averages its step noise away while moving
// content keeps a short memory. Other pixels take the reprojected history, or the block's fresh
// march where there is none (off screen, disoccluded, start of a sequence). While the camera moves
// with a ring of earlier marches (render.moving_gather_frames) every pixel is gathered from them
// instead (sample_gather.glsl.h), where any lands near it. geometryDepth: the pixel's opaque
// geometry (sceneGeometryDepth; P.maxDistance or more for none).
inline TemporalPixel resolveTemporalPixel(ivec2 pixel, int frame, IN(FrameParams) F,
                                          IN(FrameParams) previous, IN(CloudParams) P, float dt,
                                          bool haveHistory, float geometryDepth) {
    int side = frameBlock(F);
    CloudTexel marched = freshTexel(ivec2(pixel.x / side, pixel.y / side));
    float background = min(geometryDepth, P.maxDistance);
    TemporalPixel r;
    r.samples = texelDebugSamples(marched.debug);
    if (featureCompiled(FEATURE_GATHER) && gatherActive(F, previous, haveHistory)) {
        GatherSum g = gatherMarches(pixel, F, P, upsampledFreshDepth(pixel, frame, F), background,
                                    cameraTranslated(F, previous));
        if (g.weight > GATHER_MIN_WEIGHT) {
            r.cloud = g.cloud / g.weight;
            r.flash = g.flash / g.weight;
            r.depth = g.depth;
            // The marches' effective count: what a still camera's next marches average with.
            r.weight = min(g.weight * g.weight / g.weight2, float(max(F.temporalAccumulation, 1)));
            r.source = renderedInFrame(pixel, frame, side) ? TEMPORAL_SOURCE_MARCHED
                                                           : TEMPORAL_SOURCE_REPROJECTED;
            return r;
        }
    }
    vec4 fresh = marched.cloud;
    float freshDist = marched.depth;
    vec4 history = vec4(0.0f, 0.0f, 0.0f, 1.0f);
    float historyDist = NO_HIT;
    float weight = 0.0f;
    bool still = false;
    float historyFlashValue = 0.0f;
    vec2 from = vec2(0.0f, 0.0f);
    float parallax = 0.0f;
    bool valid = haveHistory &&
                 reprojectedHistory(pixel, F, previous, P, dt, background, freshDist, history,
                                    historyDist, weight, still, historyFlashValue, from, parallax);
    // Only a camera that moved can see something new in front of its history (a turning one
    // only shifts it, the wind-drift reprojection follows the clouds), and a still view must keep
    // accumulating the exact running mean of its marches: the clamp is for moving cameras.
    if (valid && F.historyClamp != 0 && cameraTranslated(F, previous)) {
        float nearest = upsampledFreshDepth(pixel, frame, F);
        if (historyInDoubt(pixel, F, previous, P, dt, from, parallax, nearest)) {
            vec4 clamped = clampToFreshNeighbourhood(history, pixel, frame, F);
            // Clamped far from what it was, the history's cloud is gone: its distance with it.
            if (abs(clamped.w - history.w) > 0.25f) {
                historyDist = nearest;
            }
            history = clamped;
        }
    }
    if (renderedInFrame(pixel, frame, side)) {
        float count = marchCountFor(valid, still, weight, side, F, previous);
        r.cloud = valid ? mix(history, fresh, 1.0f / count) : fresh;
        r.flash = valid ? mix(historyFlashValue, marched.flash, 1.0f / count) : marched.flash;
        r.depth = freshDist;
        r.weight = count;
        r.source = TEMPORAL_SOURCE_MARCHED;
        return r;
    }
    if (valid) {
        r.cloud = history;
        r.flash = historyFlashValue;
        r.depth = historyDist;
        r.weight = weight;
        r.source = TEMPORAL_SOURCE_REPROJECTED;
        return r;
    }
    r.cloud = upsampledFresh(pixel, frame, F);
    r.flash = lightningOn(P) ? upsampledFreshFlash(pixel, frame, F) : 0.0f;
    r.depth = upsampledFreshDepth(pixel, frame, F);
    r.weight = 0.0f;
    r.source = TEMPORAL_SOURCE_FALLBACK;
    return r;
}

// History and upsampled marches come from neighbouring pixels: they must not paint cloud over
// this pixel's nearer geometry (a pixel marched here never has any). geometryDepth at or beyond
// the maximum march distance means no geometry.
inline TemporalPixel hideBehindGeometry(TemporalPixel t, float geometryDepth, IN(CloudParams) P) {
    if (geometryDepth < P.maxDistance && cloudHiddenByGeometry(t.depth, geometryDepth)) {
        t.cloud = vec4(0.0f, 0.0f, 0.0f, 1.0f);
        t.flash = 0.0f;
        t.depth = NO_HIT;
    }
    return t;
}

// What a backend stores for a resolved pixel: the next frame's history and the displayed colour.
struct ResolvedPixel {
    CloudTexel history;
    vec3 composite; // clouds over the background (sky or flat geometry)
    int source;     // TEMPORAL_SOURCE_*
};

// The resolve without its composite: resolveTemporalPixel and the scene geometry's occlusion of
// borrowed cloud (geometry: the pixel's geometry depth), what the history keeps. Alone it is the
// resolve of reduced-resolution clouds, whose upsample composites at full size.
inline ResolvedPixel resolveTemporal(ivec2 pixel, int frame, IN(FrameParams) F,
                                     IN(FrameParams) previous, IN(CloudParams) P, float dt,
                                     bool haveHistory, float geometry) {
    TemporalPixel t = hideBehindGeometry(
        resolveTemporalPixel(pixel, frame, F, previous, P, dt, haveHistory, geometry), geometry, P);
    ResolvedPixel r;
    r.history.cloud = t.cloud;
    r.history.depth = t.depth;
    r.history.weight = t.weight;
    r.history.flash = t.flash;
    r.history.debug = texelDebugCode(t.source, t.samples);
    r.source = t.source;
    r.composite = vec3(0.0f);
    return r;
}

// The whole per-pixel work of the resolve pass, for both backends: resolveTemporal and the
// composite over the background (its shafts the pixel's own, or from the shafts' grid when
// P.shafts.gridFactor > 1: resolveShaftCell first). bg is the pixel's backgroundTexelAt (made on
// the spot, or kept by a background pass).
inline ResolvedPixel resolveAndComposite(ivec2 pixel, int frame, IN(FrameParams) F,
                                         IN(FrameParams) previous, IN(CloudParams) P, float dt,
                                         bool haveHistory, IN(BackgroundTexel) bg) {
    float geometry = bg.seen.w;
    ResolvedPixel r = resolveTemporal(pixel, frame, F, previous, P, dt, haveHistory, geometry);
    if (!featureCompiled(FEATURE_COMPOSITE)) {
        return r; // reduced-resolution clouds: the upsample composites at full size
    }
    vec3 dir = cameraRayDirection(F, float(pixel.x), float(pixel.y));
    vec4 cloud = r.history.cloud;
    vec3 radiance = vec3(cloud.x, cloud.y, cloud.z);
    float depth = r.history.depth;
    float flash = r.history.flash;
    // One composite whichever way the shafts come (llvmpipe runs both sides of a branch).
    vec3 delta;
    if (shaftGridActive(P)) {
        delta = shaftGridDelta(pixel, depth, cloud.w, geometry, dir, F, P);
    } else {
        delta = pixelShaftsDelta(pixel, 0u, cloud.w, depth, dir, geometry, F, P);
    }
    r.composite = compositeWithShaftsDelta(radiance, cloud.w, flash, depth, dir, bg,
                                           lightShaftsActive(P), delta, F, P);
    return r;
}

// One cell of the light shafts' grid (shaft_grid.glsl.h), made before the resolve reads it: the
// cell's pixel resolved as resolveAndComposite resolves it (for its first cloud's distance), then
// its shaft ray.
inline ShaftTexel resolveShaftCell(ivec2 cell, int frame, IN(FrameParams) F,
                                   IN(FrameParams) previous, IN(CloudParams) P, float dt,
                                   bool haveHistory) {
    ivec2 pixel = shaftGridPixel(cell, ivec2(F.width, F.height), P.shafts.gridFactor);
    float geometry = sceneGeometryDepth(pixel, F, P);
    TemporalPixel t = hideBehindGeometry(
        resolveTemporalPixel(pixel, frame, F, previous, P, dt, haveHistory, geometry), geometry, P);
    return shaftGridTexel(cell, t.depth, geometry, F, P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
