// A moving camera's pixel made from the marches themselves (render.moving_gather_frames): the
// marches of the last frames that land near the pixel, each moved to where its own cloud
// distance (and the clouds' motion since) puts it in this frame, averaged with a Gaussian of
// their distance to the pixel's centre. The resolve otherwise resamples the last frame's image,
// and each resampling softens it: a moving pixel could average no more than two marches before
// the blur cost more than the grain it removed (TURNING_ACCUMULATION). Gathered, every march is
// placed once, at its own sub-pixel point, so 24 frames of a quarter of the pixels give a pixel
// about six marches (docs/PERFORMANCE.md, "A moving camera gathers its last frames' marches").
#ifndef CLOUDSCAPE_MODEL_SAMPLE_GATHER_GLSL_H
#define CLOUDSCAPE_MODEL_SAMPLE_GATHER_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "features.glsl.h"
#include "interface.glsl.h"
#include "params.glsl.h"
#include "temporal_frame.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The most frames a ring keeps (the key's upper bound; the shaders' array of their parameters).
CONST_INT GATHER_MAX_FRAMES = 32;
// The Gaussian's standard deviation in pixels, for the 2x2 block (six marches a pixel in 24
// frames) and the 4x4 (one in 16): narrower where the marches are denser. High tier, frames
// 20-28 of the slow pan against the reference tier, gathering 16 frames: 0.3 0.970-0.971, 0.4
// 0.968-0.969, 0.5 0.962-0.963, 0.6 0.954-0.955 (24 frames at 0.3: 0.972-0.973); against 16
// samples a pixel 0.3 and 0.4 agree to 0.001. Default tier's 4x4, fast pan against 16 samples:
// 0.4 0.922-0.929, 0.6 0.924-0.935, 0.8 0.917-0.931.
CONST_FLOAT GATHER_SIGMA_SMALL_BLOCK = 0.3f;
CONST_FLOAT GATHER_SIGMA = 0.6f;
// Per frame of age, while the camera translates, the log of a march's weight falls by this: an
// older march's place depends on its one distance for more of the camera's travel (fly-forward,
// high tier: 0.962-0.966 -> 0.964-0.967; a turning camera places every march exactly and keeps
// them all at full weight).
CONST_FLOAT GATHER_AGE_FALLOFF = 0.1f;
// Below this total weight (no march within about two sigmas) the pixel is resolved as before.
CONST_FLOAT GATHER_MIN_WEIGHT = 0.05f;

// Reads the backend provides: the parameters of the frame held at a ring position, and that
// frame's march of a block (its index in the frame's block grid, row by row).
FrameParams gatherFrame(int position);
CloudTexel gatherTexel(int position, int blockIndex);
// An entering block's k-th extra march (0 to ENTERING_MARCHES - 1) at a slot of the entering
// ring (enteringSlot).
CloudTexel gatherEnteringTexel(int slot, int blockIndex, int k);

// Blocks a ring position holds room for at an image size: the 2x2 grid's, the larger.
inline int gatherSlotBlocks(ivec2 size) {
    ivec2 blocks = temporalBlockCount(size, TEMPORAL_SMALL_BLOCK);
    return blocks.x * blocks.y;
}

// The ring position of the frame `age` frames before frame F (F's own: age 0).
inline int gatherPosition(IN(FrameParams) F, int age) {
    int n = max(F.gatherFrames, 1);
    return ((F.sequenceFrame - age) % n + n) % n;
}

// A turning camera's entering edge: what the previous frame did not show has no earlier marches,
// so its first frames were made of a quarter of the pixels' marches (or their bilinear blend),
// and the last eighth of a fast pan's image scored 0.93 against 0.97 for the rest. A 2x2 block
// whose centre was outside the previous image (blockEntering) marches its other three pixels
// too, kept beside the block's record for ENTERING_FRAMES frames (the entering ring; the
// record's weight says how many): a new region starts with every pixel marched. High tier, fast
// pan, frames 20-28 against the reference tier: kept 2 frames +0.002, 4 +0.003, 8 +0.004
// (docs/PERFORMANCE.md, "The entering edge of a turning camera").
CONST_INT ENTERING_MARCHES = 3;
CONST_INT ENTERING_FRAMES = 4;

// Records the entering ring holds at an image size: ENTERING_MARCHES a block of the 2x2 grid, for
// ENTERING_FRAMES frames.
inline int enteringRingRecords(ivec2 size) {
    return gatherSlotBlocks(size) * ENTERING_MARCHES * ENTERING_FRAMES;
}

// The entering ring's slot of the frame `age` frames before frame F.
inline int enteringSlot(IN(FrameParams) F, int age) {
    return ((F.sequenceFrame - age) % ENTERING_FRAMES + ENTERING_FRAMES) % ENTERING_FRAMES;
}

// The k-th of 2x2 block b's pixels that frame F's march does not take (marchedPixel), in row
// order; at the image's right or bottom edge clamped inside it as marchedPixel is.
inline ivec2 enteringPixel(ivec2 b, int k, IN(FrameParams) F) {
    ivec2 o = blockOffsetForFrame(F.sequenceFrame, TEMPORAL_SMALL_BLOCK);
    int marched = o.y * TEMPORAL_SMALL_BLOCK + o.x;
    int i = k >= marched ? k + 1 : k;
    ivec2 p = b * TEMPORAL_SMALL_BLOCK + ivec2(i % TEMPORAL_SMALL_BLOCK, i / TEMPORAL_SMALL_BLOCK);
    return ivec2(min(p.x, F.width - 1), min(p.y, F.height - 1));
}

// Whether 2x2 block b of frame F shows what the previous frame did not: its centre, as far as
// the march reaches (a turning camera moves every distance alike), outside the previous image or
// behind its camera.
inline bool blockEntering(ivec2 b, IN(FrameParams) F, IN(FrameParams) previous, IN(CloudParams) P,
                          float dt) {
    vec2 centre = vec2(b * TEMPORAL_SMALL_BLOCK) + vec2(0.5f, 0.5f);
    bool visible = false;
    vec2 q = reprojectPixel(F, previous, P, centre.x, centre.y, NO_HIT, dt, visible);
    return !visible || q.x < -0.5f || q.y < -0.5f || q.x > float(previous.width) - 0.5f ||
           q.y > float(previous.height) - 0.5f;
}

// How many ring positions hold frames of frame F's sequence once F's marches are kept: one more
// than the previous frame's where the sequence continues with the same ring, else F's alone.
inline int gatherValidFor(IN(FrameParams) F, IN(FrameParams) previous, bool continues) {
    if (F.gatherFrames <= 0) {
        return 0;
    }
    bool sameRing = continues && previous.gatherFrames == F.gatherFrames;
    return sameRing ? min(previous.gatherValid + 1, F.gatherFrames) : 1;
}

// Whether frame F's pixels are gathered: a moving camera continuing a sequence, with a ring.
inline bool gatherActive(IN(FrameParams) F, IN(FrameParams) previous, bool haveHistory) {
    return haveHistory && F.gatherFrames > 0 && F.gatherValid > 1 && cameraMoved(F, previous);
}

// The resolve's FEATURE_GATHER for frame F: set exactly where gatherActive is, so a resolve
// built without it does what one with it would.
inline int gatherFeatureFor(IN(FrameParams) F, IN(FrameParams) previous, bool haveHistory) {
    return gatherActive(F, previous, haveHistory) ? FEATURE_GATHER : 0;
}

// The extra marches of block b in frame F (ENTERING_MARCHES or 0): an entering block's while the
// frame gathers with the small block (gatherActive is the caller's `gathering`).
inline int enteringMarchCount(ivec2 b, IN(FrameParams) F, IN(FrameParams) previous,
                              IN(CloudParams) P, float dt, bool gathering) {
    bool small = F.temporalBlock == TEMPORAL_SMALL_BLOCK;
    return gathering && small && blockEntering(b, F, previous, P, dt) ? ENTERING_MARCHES : 0;
}

// The point of pixel m its march went through in a frame of parameters Fk (renderPixel: the
// centre for sample 0, else a hashed point; the centre stands for several samples' mean).
inline vec2 marchedPoint(ivec2 m, IN(FrameParams) Fk) {
    int spp = max(Fk.samplesPerPixel, 1);
    uint sampleIndex = uint(Fk.frameIndex * spp);
    vec2 p = vec2(float(m.x), float(m.y));
    if (sampleIndex == 0u || spp > 1) {
        return p;
    }
    uint seed = uint(Fk.seed);
    float dx = pixelRandom(uint(m.x), uint(m.y), sampleIndex, seed ^ 0x51u) - 0.5f;
    float dy = pixelRandom(uint(m.x), uint(m.y), sampleIndex, seed ^ 0xa7u) - 0.5f;
    return p + vec2(dx, dy);
}

struct GatherSum {
    vec4 cloud;    // weighted premultiplied radiance and transmittance
    float flash;   // weighted flash
    float weight;  // total weight
    float weight2; // sum of squared weights (the marches' effective count)
    float depth;   // the cloud distance of the heaviest march
    float heaviest;
};

// Where a march lands in frame F: its point in frame Fk, at its cloud distance (or at
// `background` for a march that met no cloud), moved on by the clouds' motion over `age`
// seconds.
inline vec2 gatheredMarchPixel(ivec2 m, IN(FrameParams) Fk, float depth, float background,
                               float age, IN(FrameParams) F, IN(CloudParams) P, OUT(bool) visible) {
    vec2 point = marchedPoint(m, Fk);
    vec3 dir = cameraRayDirection(Fk, point.x, point.y);
    float distance = depth == NO_HIT ? background : depth;
    vec3 world = previousCloudPosition(Fk.cameraPosition + dir * distance, -age, P);
    return projectToPixel(F, world, visible);
}

// Adds march t of pixel m in the frame of parameters Fk (ageSeconds before F) to the sum for
// `pixel`.
inline void gatherMarch(INOUT(GatherSum) s, ivec2 m, IN(CloudTexel) t, IN(FrameParams) Fk,
                        float ageWeight, float ageSeconds, ivec2 pixel, IN(FrameParams) F,
                        IN(CloudParams) P, float background, float sigma) {
    bool visible = false;
    vec2 here = gatheredMarchPixel(m, Fk, t.depth, background, ageSeconds, F, P, visible);
    vec2 d = here - vec2(float(pixel.x), float(pixel.y));
    float w = visible ? ageWeight * exp(-dot(d, d) / (2.0f * sigma * sigma)) : 0.0f;
    s.cloud += t.cloud * w;
    s.flash += t.flash * w;
    s.weight += w;
    s.weight2 += w * w;
    if (w > s.heaviest) {
        s.heaviest = w;
        s.depth = t.depth;
    }
}

// Adds block b (of blocksX a row) of the frame at a ring position to the sum for `pixel`;
// returns its entering marches' count (kept in the record's weight).
inline float gatherBlock(INOUT(GatherSum) s, int position, ivec2 b, int blocksX, IN(FrameParams) Fk,
                         float ageWeight, float ageSeconds, ivec2 pixel, IN(FrameParams) F,
                         IN(CloudParams) P, float background, float sigma) {
    CloudTexel t = gatherTexel(position, b.y * blocksX + b.x);
    gatherMarch(s, marchedPixel(b, Fk.sequenceFrame, Fk), t, Fk, ageWeight, ageSeconds, pixel, F, P,
                background, sigma);
    return t.weight;
}

// The weights of a march of the frame `age` frames before F: its age's, while the camera
// translates (GATHER_AGE_FALLOFF), and the Gaussian's width for its block.
inline float gatherAgeWeight(int age, bool translating) {
    return translating ? exp(-GATHER_AGE_FALLOFF * float(age)) : 1.0f;
}
inline float gatherSigma(IN(FrameParams) Fk) {
    return Fk.temporalBlock == TEMPORAL_SMALL_BLOCK ? GATHER_SIGMA_SMALL_BLOCK : GATHER_SIGMA;
}

// Adds the entering marches of block b of the frame `age` frames before F to the sum for `pixel`.
inline void gatherEntering(INOUT(GatherSum) s, int age, ivec2 b, ivec2 pixel, IN(FrameParams) F,
                           IN(CloudParams) P, float background, bool translating) {
    FrameParams Fk = gatherFrame(gatherPosition(F, age));
    float ageSeconds = F.sequenceTime - Fk.sequenceTime;
    int blocksX = temporalBlockCount(ivec2(Fk.width, Fk.height), Fk.temporalBlock).x;
    int slot = enteringSlot(F, age);
    for (int k = 0; k < ENTERING_MARCHES; ++k) {
        CloudTexel t = gatherEnteringTexel(slot, b.y * blocksX + b.x, k);
        gatherMarch(s, enteringPixel(b, k, Fk), t, Fk, gatherAgeWeight(age, translating),
                    ageSeconds, pixel, F, P, background, gatherSigma(Fk));
    }
}

// The gathered marches of the last F.gatherValid frames around pixel `pixel` of frame F. In
// each earlier frame it looks where this pixel's point at distance `estimate` (this frame's
// nearest march's cloud, or `background`) was, and weighs the 2x2 marched blocks around there by
// where their own distances put them now. translating: the camera moved through space (older
// marches count less, GATHER_AGE_FALLOFF).
inline GatherSum gatherMarches(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P, float estimate,
                               float background, bool translating) {
    GatherSum s;
    s.cloud = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    s.flash = 0.0f;
    s.weight = 0.0f;
    s.weight2 = 0.0f;
    s.depth = NO_HIT;
    s.heaviest = 0.0f;
    vec3 dir = cameraRayDirection(F, float(pixel.x), float(pixel.y));
    vec3 point = F.cameraPosition + dir * (estimate == NO_HIT ? background : estimate);
    int frames = min(F.gatherValid, GATHER_MAX_FRAMES);
    // The blocks of the newest ENTERING_FRAMES frames that kept entering marches (a bit a block:
    // 4 a frame), gathered after this loop: llvmpipe runs a branch's body for every lane and a
    // loop's at least once, so a body per block would cost every pixel the entering marches of
    // every block, one loop after it about one block's.
    uint entering = 0u;
    ivec2 origins[ENTERING_FRAMES];
    for (int age = 0; age < frames; ++age) {
        int position = gatherPosition(F, age);
        FrameParams Fk = gatherFrame(position);
        float ageSeconds = F.sequenceTime - Fk.sequenceTime;
        float ageWeight = gatherAgeWeight(age, translating);
        float sigma = gatherSigma(Fk);
        bool visible = false;
        vec2 q = projectToPixel(Fk, previousCloudPosition(point, ageSeconds, P), visible);
        int side = Fk.temporalBlock;
        ivec2 o = blockOffsetForFrame(Fk.sequenceFrame, side);
        ivec2 blocks = temporalBlockCount(ivec2(Fk.width, Fk.height), side);
        vec2 u = (q - vec2(float(o.x), float(o.y))) / float(side);
        ivec2 b0 = ivec2(int(floor(u.x)), int(floor(u.y)));
        if (age < ENTERING_FRAMES) {
            origins[age] = b0;
        }
        for (int dy = 0; dy <= 1; ++dy) {
            for (int dx = 0; dx <= 1; ++dx) {
                ivec2 b = b0 + ivec2(dx, dy);
                if (visible && b.x >= 0 && b.y >= 0 && b.x < blocks.x && b.y < blocks.y) {
                    float kept = gatherBlock(s, position, b, blocks.x, Fk, ageWeight, ageSeconds,
                                             pixel, F, P, background, sigma);
                    if (kept > 0.0f && age < ENTERING_FRAMES) {
                        entering |= 1u << uint(age * 4 + dy * 2 + dx);
                    }
                }
            }
        }
    }
    while (entering != 0u) {
        int bit = findLSB(entering);
        entering &= entering - 1u;
        int age = bit / 4;
        ivec2 b = origins[age] + ivec2(bit & 1, (bit >> 1) & 1);
        gatherEntering(s, age, b, pixel, F, P, background, translating);
    }
    return s;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
