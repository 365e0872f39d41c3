// Weather-map interpretation shared by the generators, the CPU backend and the shaders.
#ifndef CLOUDSCAPE_MODEL_WEATHER_GLSL_H
#define CLOUDSCAPE_MODEL_WEATHER_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Cloud type encoding of the weather map's blue channel.
CONST_FLOAT TYPE_STRATUS = 0.0f;
CONST_FLOAT TYPE_STRATOCUMULUS = 1.0f / 3.0f;
CONST_FLOAT TYPE_CUMULUS = 2.0f / 3.0f;
CONST_FLOAT TYPE_CUMULONIMBUS = 1.0f;

// "Rain clouds are always present where it is raining" (GPU Pro 7 4.3.3): as precipitation
// approaches 1 the type is biased to cumulonimbus and coverage to at least 0.7. The bias starts
// at precipitation 0.5 and is complete at 1, so painted maps blend smoothly. Idempotent.
// weather = (coverage, precipitation, type).
inline vec3 applyPrecipitationRule(vec3 weather) {
    float rain = smoothstep(0.5f, 1.0f, weather.y);
    float coverage = max(weather.x, 0.7f * rain);
    float type = mix(weather.z, TYPE_CUMULONIMBUS, rain);
    return vec3(coverage, weather.y, type);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
