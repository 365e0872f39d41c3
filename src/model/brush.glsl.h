// The weather brush (the viewer's painting, apps/cloudscape/view_paint.cpp): how far one stroke
// moves a weather-map texel toward full or none. Written in the single-source subset like every
// per-texel rule, although only the host paints today.
#ifndef CLOUDSCAPE_MODEL_BRUSH_GLSL_H
#define CLOUDSCAPE_MODEL_BRUSH_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The stroke's weight at `distanceM` from its centre: 1 there, falling smoothly ((1 - t^2)^2,
// t = distance / radius) to exactly 0 at the radius and beyond, so a stroke never touches a
// texel outside its circle.
inline float brushWeight(float distanceM, float radiusM) {
    if (!(distanceM < radiusM))
        return 0.0f;
    float t = distanceM / radiusM;
    float s = 1.0f - t * t;
    return s * s;
}

// A channel's value after a stroke: moved toward 1 (strength > 0) or 0 (strength < 0) by
// |strength| times the weight; strength in [-1, 1].
inline float paintedValue(float value, float strength, float weight) {
    float target = strength >= 0.0f ? 1.0f : 0.0f;
    float amount = clamp((strength >= 0.0f ? strength : -strength) * weight, 0.0f, 1.0f);
    return mix(value, target, amount);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
