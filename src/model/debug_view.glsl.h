// The viewer's debug views (apps/cloudscape/view_debug.cpp): what a pixel of each view shows, as
// display values in [0, 1] (drawn without the tone curve). Single-source like every per-pixel rule.
#ifndef CLOUDSCAPE_MODEL_DEBUG_VIEW_GLSL_H
#define CLOUDSCAPE_MODEL_DEBUG_VIEW_GLSL_H

#include "compat.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The cloud layer's transmittance: white where the sky shows through, black where the clouds
// are opaque.
inline vec3 debugTransmittance(float transmittance) {
    return vec3(saturate(transmittance));
}

// The distance to the first cloud on a log scale from 100 m (white) to `farM` (black); blue
// where the ray meets no cloud.
inline vec3 debugDepth(float metres, float farM) {
    if (!(metres < farM))
        return vec3(0.1f, 0.2f, 0.45f);
    float t = saturate(log(max(metres, 100.0f) / 100.0f) / log(max(farM, 101.0f) / 100.0f));
    return vec3(1.0f - t);
}

// The weather map as the renderer reads it (coverage bias and precipitation rule applied):
// coverage red, precipitation green, cloud type blue.
inline vec3 debugWeather(vec4 texel, float coverageBias) {
    return weatherFromTexel(texel, coverageBias, 0.0f);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
