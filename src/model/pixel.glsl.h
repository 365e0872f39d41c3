// Everything one output pixel needs, for both backends: samplesPerPixel jittered marches (the
// first through the pixel centre, the rest offset within it), each composited over the sky, and
// averaged. All randomness is a hash of (pixel, sample, seed), so the image is deterministic.
#ifndef CLOUDSCAPE_MODEL_PIXEL_GLSL_H
#define CLOUDSCAPE_MODEL_PIXEL_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "march.glsl.h"
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
    int lightSamples;
};

inline PixelResult renderPixel(uint x, uint y, IN(FrameParams) F, IN(CloudParams) P) {
    PixelResult r;
    r.cloudRadiance = vec3(0.0f, 0.0f, 0.0f);
    r.transmittance = 0.0f;
    r.composite = vec3(0.0f, 0.0f, 0.0f);
    r.depth = NO_HIT;
    r.densitySamples = 0;
    r.lightSamples = 0;
    int spp = max(F.sampling.x, 1);
    uint seed = uint(F.size.w);
    vec3 origin = vec3(F.cameraPosition.x, F.cameraPosition.y, F.cameraPosition.z);
    float pixelAngle = 2.0f * F.cameraForward.w / float(F.size.y);
    for (int s = 0; s < spp; ++s) {
        uint sampleIndex = uint(F.size.z * spp + s);
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
        float jitter = pixelRandom(x, y, sampleIndex, seed);
        MarchResult m = marchClouds(origin, dir, jitter, pixelAngle, P);
        r.densitySamples += m.densitySamples;
        r.lightSamples += m.lightSamples;
        r.cloudRadiance += m.radiance;
        r.transmittance += m.transmittance;
        if (m.depth != NO_HIT && (r.depth == NO_HIT || m.depth < r.depth)) {
            r.depth = m.depth;
        }
        r.composite += compositeOver(m.radiance, m.transmittance, skyRadiance(dir, P));
    }
    float inv = 1.0f / float(spp);
    r.cloudRadiance *= inv;
    r.transmittance *= inv;
    r.composite *= inv;
    return r;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
