// Density-height profiles per cloud type (GPU Pro 7 4.3.2) and their blend by the weather map's
// type, the "vertical profile gradient" of the Forbidden West talk. Heights are fractions of the
// cloud layer (0 = layer bottom, 1 = layer top); with the default 1.5-8 km layer, cumulonimbus
// fill the layer while stratus stay within its lowest ~600 m.
#ifndef CLOUDSCAPE_MODEL_PROFILES_GLSL_H
#define CLOUDSCAPE_MODEL_PROFILES_GLSL_H

#include "compat.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// A profile is (x) where density starts to rise, (y) where it is full, (z) where it starts to
// fall and (w) where it has reached zero, as height fractions. Flat bases rise quickly; tops fall
// slowly so the coverage remap rounds them into domes.
inline vec4 stratusProfile() {
    return vec4(0.0f, 0.015f, 0.05f, 0.09f);
}
inline vec4 stratocumulusProfile() {
    return vec4(0.0f, 0.03f, 0.12f, 0.24f);
}
inline vec4 cumulusProfile() {
    return vec4(0.0f, 0.04f, 0.22f, 0.48f);
}
inline vec4 cumulonimbusProfile() {
    return vec4(0.0f, 0.05f, 0.65f, 1.0f);
}

// Blend the profile shapes (not their outputs) so that an intermediate type is one cloud of an
// intermediate height rather than two stacked layers.
inline vec4 profileForType(float type) {
    float t = clamp(type, 0.0f, 1.0f) * 3.0f;
    if (t < 1.0f) {
        return mix(stratusProfile(), stratocumulusProfile(), t);
    }
    if (t < 2.0f) {
        return mix(stratocumulusProfile(), cumulusProfile(), t - 1.0f);
    }
    return mix(cumulusProfile(), cumulonimbusProfile(), t - 2.0f);
}

// Density multiplier in [0, 1] at a height fraction for a profile; zero outside (x, w).
inline float evaluateProfile(vec4 profile, float heightFraction) {
    if (heightFraction <= profile.x || heightFraction >= profile.w) {
        return 0.0f;
    }
    float rise = smoothstep(profile.x, profile.y, heightFraction);
    float fall = 1.0f - smoothstep(profile.z, profile.w, heightFraction);
    return rise * fall;
}

inline float verticalProfile(float heightFraction, float type) {
    return evaluateProfile(profileForType(type), heightFraction);
}

// How far (height fraction) the bottom gradient relaxes at bottom type 1.
CONST_FLOAT BOTTOM_RELAX = 0.3f;

// The Forbidden West talk's split profile: the product of a bottom gradient (the rise), relaxed
// by the bottom type so the underside thins out over a deeper band, and the top gradient (the
// fall) of the cloud type. Never above verticalProfile; equal to it at bottom type 0.
inline float splitVerticalProfile(float heightFraction, float type, float bottomType) {
    vec4 p = profileForType(type);
    float full = mix(p.y, min(p.y + BOTTOM_RELAX, p.z), bottomType);
    return evaluateProfile(vec4(p.x, full, p.z, p.w), heightFraction);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
