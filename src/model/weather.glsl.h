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

// The weather map stores a coverage *field*, not coverage: a 16-bit value whose high byte is in
// the red channel and low byte in alpha. The decoding is linear, so filtering both channels
// filters the field. The scene's coverage (weather.coverage) is a bias on the field chosen on the
// host so that the map's mean coverage equals it (CoverageField in cloudscape/weather.h); it is a
// uniform, so changing it regenerates nothing, and it applies to a painted map (whose 8-bit
// coverage is stored with the low byte equal to the high byte, i.e. exactly) as to the
// procedural one.
CONST_FLOAT FIELD_HIGH_BYTE = 65280.0f / 65535.0f;
CONST_FLOAT FIELD_LOW_BYTE = 255.0f / 65535.0f;

inline float coverageField(vec4 texel) {
    return texel.x * FIELD_HIGH_BYTE + texel.w * FIELD_LOW_BYTE;
}

// "Rain clouds are always present where it is raining" (GPU Pro 7 4.3.3): as precipitation
// approaches 1 the type is biased to cumulonimbus and coverage to at least 0.7. The bias starts
// at precipitation 0.5 and is complete at 1, so painted maps blend smoothly. Idempotent.
// weather = (coverage, precipitation, type).
inline float precipitationType(float type, float precipitation) {
    return mix(type, TYPE_CUMULONIMBUS, smoothstep(0.5f, 1.0f, precipitation));
}

inline vec3 applyPrecipitationRule(vec3 weather) {
    float rain = smoothstep(0.5f, 1.0f, weather.y);
    float coverage = max(weather.x, 0.7f * rain);
    float type = mix(weather.z, TYPE_CUMULONIMBUS, rain);
    return vec3(coverage, weather.y, type);
}

// Weather (coverage, precipitation, type) from the map's raw values (coverage field,
// precipitation, type): the field shifted by the scene's coverage bias, the type by its offset,
// then the precipitation rule. Monotonic in every raw value, which the path tracer's majorant
// relies on; the one mapping every reader of the map uses.
inline vec3 weatherFromRaw(vec3 raw, float coverageBias, float typeOffset) {
    vec3 w = vec3(saturate(raw.x + coverageBias), raw.y, saturate(raw.z + typeOffset));
    return applyPrecipitationRule(w);
}

inline vec3 weatherFromTexel(vec4 texel, float coverageBias, float typeOffset) {
    return weatherFromRaw(vec3(coverageField(texel), texel.y, texel.z), coverageBias, typeOffset);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
