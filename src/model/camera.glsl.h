// Primary rays and per-pixel random numbers.
#ifndef CLOUDSCAPE_MODEL_CAMERA_GLSL_H
#define CLOUDSCAPE_MODEL_CAMERA_GLSL_H

#include "compat.glsl.h"
#include "params.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Unit view direction through the centre of pixel (x, y); y = 0 is the top row.
inline vec3 cameraRayDirection(IN(FrameParams) F, float x, float y) {
    float width = float(F.width);
    float height = float(F.height);
    float tanHalf = F.tanHalfFov;
    float sx = (2.0f * (x + 0.5f) / width - 1.0f) * tanHalf * F.aspect;
    float sy = (1.0f - 2.0f * (y + 0.5f) / height) * tanHalf;
    vec3 forward = F.cameraForward;
    vec3 right = F.cameraRight;
    vec3 up = F.cameraUp;
    return normalize(forward + right * sx + up * sy);
}

// An integer hash with good avalanche (xorshift-multiply), identical in both languages.
inline uint hashUint(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// A uniform number in [0, 1) for a pixel, frame and seed.
inline float pixelRandom(uint x, uint y, uint frame, uint seed) {
    uint h = hashUint(x + hashUint(y + hashUint(frame + hashUint(seed))));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
