// What a temporal frame marches and where things were: the blocks and their order, the camera's
// motion between frames and the block side and jitter cycle it chooses, and the projection of a
// world point (moved back by the clouds' own motion) into an earlier frame's image. Shared by the
// resolve (temporal.glsl.h) and the moving camera's gather of earlier marches
// (sample_gather.glsl.h).
#ifndef CLOUDSCAPE_MODEL_TEMPORAL_FRAME_GLSL_H
#define CLOUDSCAPE_MODEL_TEMPORAL_FRAME_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "params.glsl.h"
#include "storm.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_INT TEMPORAL_BLOCK = 4;
CONST_INT TEMPORAL_CYCLE = 16;
// The block of a frame whose camera moves, when the scene asks for it
// (render.moving_block_2x2), or whose camera is still (render.still_block_2x2): a quarter of the
// pixels marched a frame, so no pixel's history is older than 4 frames. A translating camera's
// history drifts by its reprojection's error every frame (a grazing ray's light comes from
// kilometres of depth, reprojected with one distance) and is refused where the parallax passes a
// pixel; 16 frames of drift broke far cloud tops into blocks and streaks, and the fallback of one
// march per 4x4 block blurred near ones.
CONST_INT TEMPORAL_SMALL_BLOCK = 2;

// The pixel of a 4x4 block marched in a frame: the order of a 4x4 Bayer matrix, so that
// consecutive frames land far apart and any 4 consecutive frames cover every 2x2 quadrant.
inline ivec2 bayerOffsetForFrame(int frame) {
    int k = frame % TEMPORAL_CYCLE;
    // Where index k sits in the Bayer matrix [0 12 3 15; 4 8 7 11; 1 13 2 14; 5 9 6 10]: the
    // bits of k, reversed and de-interleaved.
    int x = ((k >> 1) & 1) * 2 + ((k >> 3) & 1);
    int y = (((k >> 1) ^ k) & 1) * 2 + (((k >> 3) ^ (k >> 2)) & 1);
    return ivec2(x, y);
}

// The pixel of a block of side `block` (TEMPORAL_BLOCK or TEMPORAL_SMALL_BLOCK) marched in a
// frame. A 2x2 block takes the quadrant of the 4x4 order, which visits all four in any 4
// consecutive frames, so a camera that starts or stops moving keeps the same order.
inline ivec2 blockOffsetForFrame(int frame, int block) {
    ivec2 o = bayerOffsetForFrame(frame);
    return block == TEMPORAL_BLOCK ? o : ivec2(o.x / 2, o.y / 2);
}

// The block side of frame F (the host's choice, FrameParams.temporalBlock).
inline int frameBlock(IN(FrameParams) F) {
    return F.temporalBlock;
}

// Blocks of side `block` covering an image of size (x, y): partial blocks at the right and bottom
// edges count.
inline ivec2 temporalBlockCount(ivec2 size, int block) {
    return ivec2((size.x + block - 1) / block, (size.y + block - 1) / block);
}

inline bool renderedInFrame(ivec2 pixel, int frame, int block) {
    ivec2 o = blockOffsetForFrame(frame, block);
    return pixel.x % block == o.x && pixel.y % block == o.y;
}

// The pixel a block marches in a frame; a partial block at the right or bottom edge marches its
// nearest pixel inside the image instead.
inline ivec2 marchedPixel(ivec2 block, int frame, IN(FrameParams) F) {
    int side = frameBlock(F);
    ivec2 o = blockOffsetForFrame(frame, side);
    return ivec2(min(block.x * side + o.x, F.width - 1), min(block.y * side + o.y, F.height - 1));
}

// The inverse of cameraRayDirection: the (fractional) pixel at which a world point appears, with
// pixel centres at integers. visible is false behind the camera.
inline vec2 projectToPixel(IN(FrameParams) F, vec3 worldPos, OUT(bool) visible) {
    vec3 camera = F.cameraPosition;
    vec3 forward = F.cameraForward;
    vec3 right = F.cameraRight;
    vec3 up = F.cameraUp;
    vec3 v = worldPos - camera;
    float z = dot(v, forward);
    visible = z > 1e-3f;
    float safeZ = max(z, 1e-3f);
    float sx = dot(v, right) / safeZ / (F.tanHalfFov * F.aspect);
    float sy = dot(v, up) / safeZ / F.tanHalfFov;
    float px = (sx + 1.0f) * 0.5f * float(F.width) - 0.5f;
    float py = (1.0f - sy) * 0.5f * float(F.height) - 0.5f;
    return vec2(px, py);
}

// Whether the camera moved through space since the previous frame (turning alone shifts the
// image the same at every distance): the history's clamp and parallax limit act only then.
inline bool cameraTranslated(IN(FrameParams) F, IN(FrameParams) previous) {
    return F.cameraPosition != previous.cameraPosition;
}

// Whether the camera moved, turned or zoomed since the previous frame.
inline bool cameraMoved(IN(FrameParams) F, IN(FrameParams) previous) {
    return cameraTranslated(F, previous) || F.cameraForward != previous.cameraForward ||
           F.tanHalfFov != previous.tanHalfFov;
}

// The block side of frame F (FrameParams.temporalBlock, set by the host before the frame's
// passes): TEMPORAL_SMALL_BLOCK where a sequence continues and the scene asks for it, with a
// moving camera (render.moving_block_2x2) or a still one (render.still_block_2x2), else
// TEMPORAL_BLOCK. A moving camera gains (fast pan at the high tier, SSIM 0.915 -> 0.947): each
// resampling of the history softens it, and a pixel is marched afresh every 4 frames instead of
// 16. A still camera's history is exact and its marches accumulate: the small block averages 4
// of them a pixel after 16 frames instead of 1 (marchCycleFor gives each a new jitter).
inline int temporalBlockFor(IN(FrameParams) F, IN(FrameParams) previous, bool continues,
                            bool moving2x2, bool still2x2) {
    bool moved = cameraMoved(F, previous);
    return continues && (moved ? moving2x2 : still2x2) ? TEMPORAL_SMALL_BLOCK : TEMPORAL_BLOCK;
}

// The index (FrameParams.frameIndex) that seeds frame `frame`'s march jitter: its start offsets
// and the points of the pixels it marches through (renderPixel). It changes once per
// TEMPORAL_CYCLE, when every pixel of a 4x4 block has been marched once, so that within a cycle
// each pixel is marched exactly as the full-resolution render of that cycle would march it. A
// still camera marching the small block marches every pixel once in 4 frames: there it changes
// every 4 frames, or the 4 marches a pixel accumulates in a cycle would be one march 4 times.
// (A moving camera's small block keeps the cycle: its history is replaced, not averaged, and a
// jitter changing every 4 frames measured worse, fly-forward at the high tier 0.932 -> 0.926.)
inline int marchCycleFor(int frame, int block, bool moved) {
    bool stillSmall = block == TEMPORAL_SMALL_BLOCK && !moved;
    return stillSmall ? frame / (TEMPORAL_SMALL_BLOCK * TEMPORAL_SMALL_BLOCK)
                      : frame / TEMPORAL_CYCLE;
}

// What a temporal frame marches, decided once by the host before the frame's passes (both
// backends): its block side (temporalBlockFor) and its jitter's cycle (marchCycleFor).
struct FrameMarch {
    int block;
    int cycle;
};

inline FrameMarch frameMarchFor(int frame, IN(FrameParams) F, IN(FrameParams) previous,
                                bool continues, bool moving2x2, bool still2x2) {
    FrameMarch m;
    m.block = temporalBlockFor(F, previous, continues, moving2x2, still2x2);
    m.cycle = marchCycleFor(frame, m.block, cameraMoved(F, previous));
    return m;
}

// Whether frame F's output background is brought up from its reduced-resolution pass's
// (upsample.glsl.h's upsampledBackground) rather than made per output pixel: where the scene asks
// for it (render.moving_background_reduced) and a sequence continues with a moving camera, the
// frames in which the background is made anew anyway. A still camera gets (and a renderer keeps)
// the full-size background; so does a sequence's first frame, and a frame with a scene depth
// buffer (its geometry is per output pixel). Decided by the host before the frame's passes.
inline bool backgroundFromPass(IN(FrameParams) F, IN(FrameParams) previous, bool continues,
                               bool reduced, bool asked) {
    return asked && reduced && continues && F.hasSceneDepth == 0 && cameraMoved(F, previous);
}

// How far the cloud field has moved in dt seconds: the base noise's wind drift (density.glsl.h).
inline vec3 cloudMotion(IN(CloudParams) P, float dt) {
    return cloudDriftDirection(P) * windTravel(dt, P);
}

// Where the cloud at world position p was dt seconds ago: moved back by the wind scroll, and
// inside a storm turned back about its centre by the vortex rings' speed, the two blended by the
// mask pow(saturate(1 - d / r), 0.1) exactly as the Forbidden West talk's listing does (its
// rotation speed carries the blend factor; the ring speeds are the noise's, storm.glsl.h).
inline vec3 previousCloudPosition(vec3 p, float dt, IN(CloudParams) P) {
    vec3 scrolled = p - cloudMotion(P, dt);
    if (!stormActive(P) || P.stormMotionVectors == 0) {
        return scrolled;
    }
    float d = length(stormOffset(vec2(p.x, p.z), P));
    if (d >= P.stormRadius) {
        return scrolled;
    }
    float speed = stormAngularSpeed(d / P.stormRadius, P) * P.stormBlend;
    vec3 rotated = rotateAboutStorm(p, -speed * dt, P);
    float mask = pow(saturate(1.0f - d / P.stormRadius), STORM_MOTION_EXPONENT);
    return mix(scrolled, rotated, mask);
}

// Where the cloud seen through pixel (x, y) of frame F, at distance depth, was in the previous
// frame's image. Sky without cloud is reprojected as if at the march's maximum distance.
inline vec2 reprojectPixel(IN(FrameParams) F, IN(FrameParams) previous, IN(CloudParams) P, float x,
                           float y, float depth, float dt, OUT(bool) visible) {
    vec3 camera = F.cameraPosition;
    vec3 dir = cameraRayDirection(F, x, y);
    float distance = depth == NO_HIT ? P.maxDistance : depth;
    vec3 world = previousCloudPosition(camera + dir * distance, dt, P);
    return projectToPixel(previous, world, visible);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
