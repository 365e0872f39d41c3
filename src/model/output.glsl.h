// What becomes of the radiance at the end: clouds composited over their background, and the one
// tone mapping from linear HDR to display values (PNG output, the display-luminance metrics).
#ifndef CLOUDSCAPE_MODEL_OUTPUT_GLSL_H
#define CLOUDSCAPE_MODEL_OUTPUT_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Clouds in front of the sky, premultiplied: colour = cloud + transmittance * background.
inline vec3 compositeOver(vec3 cloudRadiance, float transmittance, vec3 background) {
    return cloudRadiance + background * transmittance;
}

// ACES filmic curve (Narkowicz's fit) on exposed linear radiance, then the sRGB transfer
// function: the one place where HDR becomes display values.
inline float linearToSrgb(float x) {
    x = saturate(x);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}

inline vec3 toneMap(vec3 radiance, float exposure) {
    vec3 x = radiance * exposure;
    vec3 mapped = (x * (x * 2.51f + vec3(0.03f))) / (x * (x * 2.43f + vec3(0.59f)) + vec3(0.14f));
    return vec3(linearToSrgb(mapped.x), linearToSrgb(mapped.y), linearToSrgb(mapped.z));
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
