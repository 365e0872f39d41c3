// Everything one output pixel needs, for both backends: samplesPerPixel jittered marches (the
// first through the pixel centre, the rest offset within it), each composited over the sky, and
// averaged. All randomness is a hash of (pixel, sample, seed) or a read of the fixed blue-noise
// map, so the image is deterministic.
#ifndef CLOUDSCAPE_MODEL_PIXEL_GLSL_H
#define CLOUDSCAPE_MODEL_PIXEL_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "features.glsl.h"
#include "ground.glsl.h"
#include "high_clouds.glsl.h"
#include "light_shafts.glsl.h"
#include "lightning.glsl.h"
#include "march.glsl.h"
#include "output.glsl.h"
#include "params.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

struct PixelResult {
    vec3 cloudRadiance;  // premultiplied, averaged over the samples
    float transmittance; // averaged
    vec3 composite;      // clouds over the sky
    float depth;         // nearest first-cloud distance of the samples; NO_HIT if none
    int densitySamples;
    int cloudSamples; // density samples that found cloud
    int emptySkips;   // empty-space skips (march.glsl.h)
    int lightSamples;
    float flash; // the masked lightning flash at unit intensity, averaged (lightning.glsl.h)
};

// What the clouds are composited over, before the high-altitude layer: the terrain where it is
// the nearest geometry; opaque scene geometry from the depth buffer (nearer than
// march.max_distance_m and than the terrain) drawn flat in the ground colour, since the renderer
// does not shade it (an engine composites the cloud layer over its own scene); with the
// atmosphere, the lit planet surface where the ray meets it; otherwise the sky. G is
// sceneGeometryAlong's for this ray (or the depth buffer alone with the terrain's distance).
struct SeenBackground {
    vec3 radiance;
    float distance;      // NO_HIT for the sky
    bool groundFallback; // shaded by the clouds beyond the shadow map (ground.glsl.h)
};

// The opaque geometry along a camera ray: `depth` the nearest (the depth buffer's or the
// terrain's; P.maxDistance or beyond for none), `terrain` the terrain's own distance (NO_HIT for
// none). Made once per ray and handed on, so a pixel marches the terrain once (the composite
// needs to know which of the two `depth` is).
struct SceneGeometry {
    float depth;
    float terrain;
};

inline SceneGeometry geometryWithTerrain(vec3 origin, vec3 dir, float geometryDepth,
                                         IN(CloudParams) P) {
    SceneGeometry g;
    g.depth = geometryDepth;
    g.terrain = terrainHitDistance(origin, dir, P);
    return g;
}

// What lies behind the clouds before this frame's clouds shade it: base + beam * (the clouds'
// beam share at the surface) + diffuse * (their diffuse share), ground.glsl.h's SurfaceLight
// seen from the camera; the sky and flat depth-buffer geometry are all base. Nothing in it moves
// with the clouds (or the high layer, applied after): only the camera's rays, the sun, the
// terrain and the air change it, so the Vulkan temporal renderer keeps it per pixel (its
// background pass) while those stay, and applies each frame's clouds (backgroundUnderClouds).
// Where the composite is not compiled (the reduced resolve) only the depth is made.
struct BackgroundLight {
    vec4 base;    // rgb; a: the distance of what is seen (NO_HIT: the sky)
    vec4 beam;    // rgb; a: the geometry depth (SceneGeometry.depth)
    vec4 diffuse; // rgb; a: the distance of the surface the clouds shade (terrain, ground), or 0
};
CONST_INT BACKGROUND_LIGHT_ROWS = 3; // texels of a kept record (interface.glsl.h)

inline BackgroundLight backgroundLightOf(vec3 origin, vec3 dir, IN(SceneGeometry) G,
                                         IN(CloudParams) P) {
    BackgroundLight b;
    b.base = vec4(0.0f, 0.0f, 0.0f, NO_HIT);
    b.beam = vec4(0.0f, 0.0f, 0.0f, G.depth);
    b.diffuse = vec4(0.0f);
    if (!featureCompiled(FEATURE_COMPOSITE)) {
        return b;
    }
    float geometryDepth = G.depth;
    float terrain = G.terrain;
    bool depthBufferNearer = terrain == NO_HIT || geometryDepth < terrain * 0.9999f;
    if (geometryDepth < P.maxDistance && depthBufferNearer) {
        b.base = vec4(P.sky.ground, geometryDepth);
        return b;
    }
    float distance = terrain;
    if (terrain == NO_HIT && atmosphereOn(P.sky)) {
        distance = groundHitDistance(origin, dir, P);
    }
    if (distance == NO_HIT) {
        b.base = vec4(skyRadiance(dir, P.sky), NO_HIT);
        return b;
    }
    SurfaceLight l = terrain != NO_HIT ? terrainSeenLight(origin, dir, terrain, P)
                                       : groundSeenLight(origin, dir, distance, P);
    b.base = vec4(l.base, distance);
    b.beam.x = l.beam.x; // .w keeps the geometry depth
    b.beam.y = l.beam.y;
    b.beam.z = l.beam.z;
    b.diffuse = vec4(l.diffuse, distance);
    return b;
}

// The radiance of the background beyond the high layer under this frame's clouds.
inline SeenBackground backgroundUnderCloudsBeyond(IN(BackgroundLight) b, vec3 origin, vec3 dir,
                                                  IN(CloudParams) P) {
    SeenBackground r;
    r.radiance = vec3(b.base.x, b.base.y, b.base.z);
    r.distance = b.base.w;
    r.groundFallback = false;
    if (b.diffuse.w > 0.0f) {
        SunThroughClouds clouds = sunThroughCloudsAt(origin + dir * b.diffuse.w, P);
        r.radiance += vec3(b.beam.x, b.beam.y, b.beam.z) * clouds.beam +
                      vec3(b.diffuse.x, b.diffuse.y, b.diffuse.z) * clouds.diffuse;
        r.groundFallback = clouds.beyondMap;
    }
    return r;
}

inline SeenBackground backgroundBeyondHighClouds(vec3 origin, vec3 dir, IN(SceneGeometry) G,
                                                 IN(CloudParams) P) {
    return backgroundUnderCloudsBeyond(backgroundLightOf(origin, dir, G, P), origin, dir, P);
}

// The background seen through the high-altitude layer where the layer is nearer: from below
// only the sky lies beyond it, from above everything does.
inline vec3 backgroundRadiance(vec3 origin, vec3 dir, IN(SceneGeometry) G, IN(CloudParams) P) {
    SeenBackground b = backgroundBeyondHighClouds(origin, dir, G, P);
    return highCloudsOver(b.radiance, b.distance, origin, dir, P);
}

// The same for a geometry depth alone (the terrain marched here).
inline vec3 backgroundRadiance(vec3 origin, vec3 dir, float geometryDepth, IN(CloudParams) P) {
    return backgroundRadiance(origin, dir, geometryWithTerrain(origin, dir, geometryDepth, P), P);
}

// What a pixel sees behind its clouds this frame, with no part of the clouds' march in it: the
// background beyond the high-altitude layer (its light under this frame's cloud shadows) and its
// distance, that background seen through the layer where the layer is nearer, and the
// geometry's depth. Where the composite is not compiled (the reduced resolve) only the depth.
struct BackgroundTexel {
    vec4 beyond; // rgb: radiance beyond the high layer; a: its distance (NO_HIT for the sky)
    vec4 seen;   // rgb: that radiance through the high layer where nearer; a: geometry depth
};
CONST_INT BACKGROUND_TEXEL_ROWS = 2;
#ifdef __cplusplus
static_assert(sizeof(BackgroundLight) == BACKGROUND_LIGHT_ROWS * 16, "rows of 16 bytes");
static_assert(sizeof(BackgroundTexel) == BACKGROUND_TEXEL_ROWS * 16, "rows of 16 bytes");
#endif

// This frame's background from its light: the clouds' shares at the surface, then the high
// layer where it is nearer.
// groundFallback: whether it took the ground's fallback shadow (what it sees is shaded by the
// clouds beyond the shadow map); a pass compiled without FEATURE_GROUND_FALLBACK lists such
// pixels for a pass of their own.
inline BackgroundTexel backgroundUnderClouds(IN(BackgroundLight) light, vec3 origin, vec3 dir,
                                             IN(CloudParams) P, OUT(bool) groundFallback) {
    BackgroundTexel t;
    t.beyond = vec4(0.0f, 0.0f, 0.0f, NO_HIT);
    t.seen = vec4(0.0f, 0.0f, 0.0f, light.beam.w);
    groundFallback = false;
    if (!featureCompiled(FEATURE_COMPOSITE)) {
        return t;
    }
    SeenBackground b = backgroundUnderCloudsBeyond(light, origin, dir, P);
    t.beyond = vec4(b.radiance, b.distance);
    t.seen = vec4(highCloudsOver(b.radiance, b.distance, origin, dir, P), light.beam.w);
    groundFallback = b.groundFallback;
    return t;
}

inline BackgroundTexel backgroundUnderClouds(IN(BackgroundLight) light, vec3 origin, vec3 dir,
                                             IN(CloudParams) P) {
    bool groundFallback = false;
    return backgroundUnderClouds(light, origin, dir, P, groundFallback);
}

inline BackgroundTexel backgroundOf(vec3 origin, vec3 dir, IN(SceneGeometry) G, IN(CloudParams) P) {
    return backgroundUnderClouds(backgroundLightOf(origin, dir, G, P), origin, dir, P);
}

// A cloud layer pixel over its background, seen through the air: the air in front of the cloud
// (aerial perspective at the cloud's first depth) dims and tints the cloud's light and adds its
// own where the cloud is opaque; where it is transparent the background already holds the air's
// light. The one composite of every pass (full frames, the temporal resolve, the upsample).
// Seen from above the high-altitude layer, the layer lies in front of the cloud as well.
inline vec3 compositeCloudOver(vec3 cloudRadiance, float transmittance, float cloudDepth, vec3 dir,
                               IN(BackgroundTexel) bg, IN(FrameParams) F, IN(CloudParams) P) {
    vec3 origin = F.cameraPosition;
    vec3 seen = vec3(bg.seen.x, bg.seen.y, bg.seen.z);
    if (cloudDepth == NO_HIT) {
        return compositeOver(cloudRadiance, transmittance, seen);
    }
    bool layerInFront =
        featureCompiled(FEATURE_ABOVE_HIGH_CLOUDS) && highCloudsBefore(cloudDepth, origin, dir, P);
    vec3 background = layerInFront ? vec3(bg.beyond.x, bg.beyond.y, bg.beyond.z) : seen;
    AirLight air = cameraAerialPerspective(dir, cloudDepth, P.sky);
    vec3 c = cloudRadiance * air.transmittance + air.inScattered * (1.0f - transmittance) +
             background * transmittance;
    return layerInFront ? highCloudsOver(c, cloudDepth, origin, dir, P) : c;
}

// The same over the background of geometry G along dir.
inline vec3 compositeCloud(vec3 cloudRadiance, float transmittance, float cloudDepth, vec3 dir,
                           IN(SceneGeometry) G, IN(FrameParams) F, IN(CloudParams) P) {
    return compositeCloudOver(cloudRadiance, transmittance, cloudDepth, dir,
                              backgroundOf(F.cameraPosition, dir, G, P), F, P);
}

// The same for a geometry depth alone (the terrain marched here).
inline vec3 compositeCloud(vec3 cloudRadiance, float transmittance, float cloudDepth, vec3 dir,
                           float geometryDepth, IN(FrameParams) F, IN(CloudParams) P) {
    return compositeCloud(cloudRadiance, transmittance, cloudDepth, dir,
                          geometryWithTerrain(F.cameraPosition, dir, geometryDepth, P), F, P);
}

// The composite with light shafts already evaluated (shafts: whether they are on; delta: their
// change, lightShaftsDelta's) and this frame's lightning: the masked flash channel lit at the
// frame's intensity, and a ground discharge's bolt (in front of the clouds or seen through
// them). With shafts off it is compositeCloud plus the lightning exactly.
inline vec3 compositeWithShaftsDelta(vec3 cloudRadiance, float transmittance, float flash,
                                     float cloudDepth, vec3 dir, IN(BackgroundTexel) bg,
                                     bool shafts, vec3 delta, IN(FrameParams) F,
                                     IN(CloudParams) P) {
    float geometryDepth = bg.seen.w;
    vec3 c = compositeCloudOver(withFlash(cloudRadiance, flash, P), transmittance, cloudDepth, dir,
                                bg, F, P);
    if (shafts) {
        c = max(c + delta, vec3(0.0f));
    }
    if (!lightningOn(P)) {
        return c;
    }
    float pixelAngle = 2.0f * F.tanHalfFov / float(F.height);
    return c + lightningBoltRadiance(F.cameraPosition, dir, pixelAngle, geometryDepth, cloudDepth,
                                     transmittance, P);
}

// The change the pixel's own light shafts (light_shafts.glsl.h) make along its ray; 0 when they
// are off. `sampleInFrame` picks the pixel's shaft offset (0 in the reconstruction passes, the
// sample within the frame in renderPixel).
inline vec3 pixelShaftsDelta(ivec2 pixel, uint sampleInFrame, float transmittance, float cloudDepth,
                             vec3 dir, float geometryDepth, IN(FrameParams) F, IN(CloudParams) P) {
    vec3 delta = vec3(0.0f);
    if (lightShaftsActive(P)) {
        float jitter =
            pixelRandom(uint(pixel.x), uint(pixel.y), sampleInFrame, uint(F.seed) ^ 0x5aa5u);
        delta = lightShaftsDelta(F.cameraPosition, dir, cloudDepth, transmittance, geometryDepth,
                                 jitter, P);
    }
    return delta;
}

// compositeWithShaftsDelta with the pixel's own light shafts: what every pass displays (the
// temporal resolve and the upsample may take the shafts from a coarser grid instead:
// shaft_grid.glsl.h).
inline vec3 compositeWithLightning(ivec2 pixel, uint sampleInFrame, vec3 cloudRadiance,
                                   float transmittance, float flash, float cloudDepth, vec3 dir,
                                   IN(BackgroundTexel) bg, IN(FrameParams) F, IN(CloudParams) P) {
    vec3 delta =
        pixelShaftsDelta(pixel, sampleInFrame, transmittance, cloudDepth, dir, bg.seen.w, F, P);
    return compositeWithShaftsDelta(cloudRadiance, transmittance, flash, cloudDepth, dir, bg,
                                    lightShaftsActive(P), delta, F, P);
}

// The distance (m) along a pixel's ray to the depth buffer's geometry, when the frame has one
// (beyond P.maxDistance, or +inf, is sky), else P.maxDistance (no geometry).
inline float depthBufferDistance(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P) {
    if (F.hasSceneDepth != 0) {
        return sampleSceneDepth(pixel);
    }
    return P.maxDistance;
}

// The distance along a camera ray through `pixel` (direction dir) to opaque geometry: the depth
// buffer's or the terrain's, whichever is nearer (depthBufferDistance's value without either).
inline SceneGeometry sceneGeometryAlong(ivec2 pixel, vec3 dir, IN(FrameParams) F,
                                        IN(CloudParams) P) {
    SceneGeometry g;
    float depth = depthBufferDistance(pixel, F, P);
    g.terrain = terrainHitDistance(F.cameraPosition, dir, P);
    g.depth = g.terrain != NO_HIT ? min(depth, g.terrain) : depth;
    return g;
}

inline float geometryDepthAlong(ivec2 pixel, vec3 dir, IN(FrameParams) F, IN(CloudParams) P) {
    return sceneGeometryAlong(pixel, dir, F, P).depth;
}

// sceneGeometryAlong for the ray through the pixel's centre.
inline SceneGeometry sceneGeometryAt(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P) {
    return sceneGeometryAlong(pixel, cameraRayDirection(F, float(pixel.x), float(pixel.y)), F, P);
}

// The background light of the ray through a point of the pixel (offset from its centre, in
// pixels).
inline BackgroundLight backgroundLightThrough(ivec2 pixel, vec2 offset, IN(FrameParams) F,
                                              IN(CloudParams) P) {
    vec3 dir = cameraRayDirection(F, float(pixel.x) + offset.x, float(pixel.y) + offset.y);
    return backgroundLightOf(F.cameraPosition, dir, sceneGeometryAlong(pixel, dir, F, P), P);
}

// Where the k-th of n background rays crosses its pixel: a rank-1 lattice (the golden ratio's
// Fibonacci-like generator) shifted so that ray 0 goes through the centre. A shifted lattice is
// as even over the pixel as any, and the centre ray's depths are the pixel's (the clouds' march
// and every reconstruction rule use the centre's geometry).
inline vec2 backgroundRayOffset(int k, int n) {
    return vec2(fract(float(k) / float(n) + 0.5f) - 0.5f,
                fract(float(k) * 0.618034f + 0.5f) - 0.5f);
}

// The background light the reconstruction passes (the temporal resolve, the upsample) keep and
// composite over: F.backgroundSamples rays through the pixel averaged, so the terrain's edges and
// the horizon are anti-aliased as a still's samples are (temporal frames march the clouds
// through jittered points of the pixel but would see the background through its centre only).
// The light is linear in the rays' shares, so their average still takes each frame's clouds
// exactly where the clouds' shadow is the same across the pixel; the distance and depth are the
// centre ray's, and the clouds' shadow is looked up at the shaded surface's distance
// (diffuse.w: the centre's, or where only other rays meet the ground, theirs).
inline BackgroundLight backgroundLightAt(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P) {
    BackgroundLight centre = backgroundLightThrough(pixel, vec2(0.0f, 0.0f), F, P);
    int n = F.backgroundSamples;
    if (n <= 1 || !featureCompiled(FEATURE_COMPOSITE)) {
        return centre;
    }
    vec4 base = centre.base;
    vec4 beam = centre.beam;
    vec4 diffuse = centre.diffuse;
    for (int k = 1; k < n; ++k) {
        BackgroundLight b = backgroundLightThrough(pixel, backgroundRayOffset(k, n), F, P);
        base += vec4(b.base.x, b.base.y, b.base.z, 0.0f);
        beam += vec4(b.beam.x, b.beam.y, b.beam.z, 0.0f);
        diffuse += vec4(b.diffuse.x, b.diffuse.y, b.diffuse.z, 0.0f);
        if (diffuse.w == 0.0f) {
            diffuse.w = b.diffuse.w;
        }
    }
    float inv = 1.0f / float(n);
    centre.base = vec4(base.x * inv, base.y * inv, base.z * inv, centre.base.w);
    centre.beam = vec4(beam.x * inv, beam.y * inv, beam.z * inv, centre.beam.w);
    centre.diffuse = vec4(diffuse.x * inv, diffuse.y * inv, diffuse.z * inv, diffuse.w);
    return centre;
}

inline BackgroundTexel backgroundTexelFrom(IN(BackgroundLight) light, ivec2 pixel,
                                           IN(FrameParams) F, IN(CloudParams) P,
                                           OUT(bool) groundFallback) {
    vec3 dir = cameraRayDirection(F, float(pixel.x), float(pixel.y));
    return backgroundUnderClouds(light, F.cameraPosition, dir, P, groundFallback);
}

inline BackgroundTexel backgroundTexelFrom(IN(BackgroundLight) light, ivec2 pixel,
                                           IN(FrameParams) F, IN(CloudParams) P) {
    bool groundFallback = false;
    return backgroundTexelFrom(light, pixel, F, P, groundFallback);
}

inline BackgroundTexel backgroundTexelAt(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P) {
    return backgroundTexelFrom(backgroundLightAt(pixel, F, P), pixel, F, P);
}

inline float sceneGeometryDepth(ivec2 pixel, IN(FrameParams) F, IN(CloudParams) P) {
    return sceneGeometryAt(pixel, F, P).depth;
}

// Reconstruction passes (the upsample of reduced-resolution clouds, temporal reprojection)
// borrow cloud from neighbouring pixels: a borrowed value whose first cloud lies at or behind
// this pixel's geometry is hidden by it. A value without a cloud depth (NO_HIT) saw no cloud at
// its own pixel, so whatever it carries was blended in from elsewhere: hidden too.
inline bool cloudHiddenByGeometry(float cloudDepth, float geometryDepth) {
    return cloudDepth == NO_HIT || cloudDepth >= geometryDepth;
}

// The march's start offset in [0, 1) for a pixel and sample. With blue noise on, the 64^2
// blue-noise map (shifted by the seed) gives neighbouring pixels well-separated offsets, so the
// step error is high-frequency grain rather than white-noise clumps; each later sample (or
// temporal cycle) adds the golden-ratio (Weyl) sequence to all of them, which keeps the pattern
// blue in every frame and spreads each pixel's offsets evenly over time, for the temporal
// filter and samples-per-pixel averaging to remove. Otherwise a hash (white noise).
inline float marchStartOffset(uint x, uint y, uint sampleIndex, uint seed, IN(CloudParams) P) {
    if (P.blueNoise == 0) {
        return pixelRandom(x, y, sampleIndex, seed);
    }
    uint shift = hashUint(seed ^ 0x9e3779b9u);
    ivec2 texel = ivec2(int((x + shift) & 0xffffu), int((y + (shift >> 16u)) & 0xffffu));
    // The map holds 256 equally populated levels k / 255; centre them in [0, 1).
    float rank = sampleBlueNoise(texel) * (255.0f / 256.0f) + (0.5f / 256.0f);
    float golden = float((sampleIndex * 2654435769u) >> 8u) * (1.0f / 16777216.0f);
    return fract(rank + golden);
}

inline PixelResult renderPixel(uint x, uint y, IN(FrameParams) F, IN(CloudParams) P) {
    PixelResult r;
    r.cloudRadiance = vec3(0.0f, 0.0f, 0.0f);
    r.transmittance = 0.0f;
    r.composite = vec3(0.0f, 0.0f, 0.0f);
    r.depth = NO_HIT;
    r.densitySamples = 0;
    r.cloudSamples = 0;
    r.emptySkips = 0;
    r.lightSamples = 0;
    r.flash = 0.0f;
    int spp = max(F.samplesPerPixel, 1);
    uint seed = uint(F.seed);
    vec3 origin = F.cameraPosition;
    float pixelAngle = 2.0f * F.tanHalfFov / float(F.height);
    for (int s = 0; s < spp; ++s) {
        uint sampleIndex = uint(F.frameIndex * spp + s);
        float dx = 0.0f;
        float dy = 0.0f;
        // The very first sample of a pixel goes through its centre; every later one (within
        // this frame, or in later temporal cycles) through a hashed point of the pixel, so
        // averaging samples also anti-aliases.
        if (sampleIndex > 0u) {
            dx = pixelRandom(x, y, sampleIndex, seed ^ 0x51u) - 0.5f;
            dy = pixelRandom(x, y, sampleIndex, seed ^ 0xa7u) - 0.5f;
        }
        vec3 dir = cameraRayDirection(F, float(x) + dx, float(y) + dy);
        // Opaque geometry (the depth buffer's, the terrain's) ends the march; a ray whose
        // geometry is nearer than the cloud shell is not marched at all.
        SceneGeometry geometry = sceneGeometryAlong(ivec2(int(x), int(y)), dir, F, P);
        float geometryDepth = geometry.depth;
        float jitter = marchStartOffset(x, y, sampleIndex, seed, P);
        MarchResult m = marchCloudsTo(origin, dir, jitter, pixelAngle, geometryDepth, P);
        r.densitySamples += m.densitySamples;
        r.cloudSamples += m.cloudSamples;
        r.emptySkips += m.emptySkips;
        r.lightSamples += m.lightSamples;
        r.cloudRadiance += m.radiance;
        r.transmittance += m.transmittance;
        r.flash += m.flash;
        if (m.depth != NO_HIT && (r.depth == NO_HIT || m.depth < r.depth)) {
            r.depth = m.depth;
        }
        if (featureCompiled(FEATURE_COMPOSITE)) {
            r.composite += compositeWithLightning(ivec2(int(x), int(y)), uint(s), m.radiance,
                                                  m.transmittance, m.flash, m.depth, dir,
                                                  backgroundOf(origin, dir, geometry, P), F, P);
        }
    }
    float inv = 1.0f / float(spp);
    r.cloudRadiance *= inv;
    r.transmittance *= inv;
    r.composite *= inv;
    r.flash *= inv;
    return r;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
