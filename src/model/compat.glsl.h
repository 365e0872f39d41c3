// The single-source subset: this header lets the model headers compile both as GLSL (glslc)
// and as C++ (with GLM). Rules: float literals carry the f suffix; parameters use IN/OUT/INOUT;
// no swizzle assignment, no templates, plain structs; every texture read goes through a named
// sampling function supplied by the backend. See docs/ARCHITECTURE.md.
#ifndef CLOUDSCAPE_MODEL_COMPAT_GLSL_H
#define CLOUDSCAPE_MODEL_COMPAT_GLSL_H

#ifdef __cplusplus
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/integer.hpp>
#define IN(T) const T&
#define OUT(T) T&
#define INOUT(T) T&
#define CONST_FLOAT static constexpr float
#define CONST_INT static constexpr int
namespace cloudscape::model {
using namespace glm;
using uint = uint32_t;
inline float inversesqrt(float x) {
    return 1.0f / std::sqrt(x);
}
} // namespace cloudscape::model
#else
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define CONST_FLOAT const float
#define CONST_INT const int
// Model functions are written `inline` so C++ can include them from many translation units;
// GLSL has no such keyword (it is reserved), so it is defined away.
#define inline
#endif

#ifdef __cplusplus
namespace cloudscape::model {
#endif

CONST_FLOAT PI = 3.14159265358979f;

inline float saturate(float x) {
    return clamp(x, 0.0f, 1.0f);
}

// Map x from [oldMin, oldMax] to [newMin, newMax] (no clamping), as in GPU Pro 7 4.3.4. A
// degenerate source range maps everything to newMax rather than dividing by zero.
inline float remap(float x, float oldMin, float oldMax, float newMin, float newMax) {
    float range = oldMax - oldMin;
    if (abs(range) < 1e-7f) {
        return newMax;
    }
    return newMin + (x - oldMin) / range * (newMax - newMin);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
