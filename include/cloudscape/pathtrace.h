#pragma once
// The ground truth: an unbiased volumetric path tracer over the same density field the real-time
// renderer marches (src/pathtrace). Delta tracking over a provably safe majorant grid, ratio
// tracking toward the sun, importance-sampled phase functions, multiple scattering ended by
// Russian roulette, the sky as environment light and an optional Lambertian ground. Progressive:
// an image accumulates samples pass by pass and can be continued later.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape {

struct PathTraceImage {
    int width = 0;
    int height = 0;
    uint64_t samplesPerPixel = 0;
    uint64_t stream = 0; // independent sample streams give independent estimates of one image
    // 3 per pixel: the running mean of the radiance samples (linear RGB), rounded to float after
    // every sample. That is exactly what the EXR output stores, so an image read back and
    // continued (`pathtrace --resume`) has the same bits as one rendered in one go.
    std::vector<float> mean;
};

struct PathTraceStats {
    uint64_t paths = 0;
    uint64_t collisions = 0;         // real scattering events
    uint64_t truncated = 0;          // paths cut at pathtrace.max_bounces (biased; should be 0)
    uint64_t majorantViolations = 0; // extinction above the majorant (would bias; must be 0)
    double seconds = 0.0;
};

// Adds `samples` samples per pixel to `image` (an empty image is allocated at the scene's size;
// a non-empty one must match it). Sample k of a pixel always draws the same random numbers and
// updates the float mean by the same rule, so continuing an image later, in any number of calls,
// gives bit for bit the result of rendering it in one go. progress receives the fraction of
// this call's work done.
PathTraceStats pathTrace(const Scene& scene, const SceneResources& resources, PathTraceImage& image,
                         int samples, const ProgressCallback& progress = {});

// A short hex fingerprint of everything a path-traced image depends on (model and camera
// parameters, weather map, seed, path tracer keys), so that a resumed render can check that it
// continues the same image.
std::string pathTraceFingerprint(const Scene& scene, const SceneResources& resources);

} // namespace cloudscape
