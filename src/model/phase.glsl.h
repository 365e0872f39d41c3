// Phase functions, normalised so that they integrate to 1 over the sphere (1/sr).
#ifndef CLOUDSCAPE_MODEL_PHASE_GLSL_H
#define CLOUDSCAPE_MODEL_PHASE_GLSL_H

#include "compat.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

inline float isotropicPhase() {
    return 1.0f / (4.0f * PI);
}

// Henyey-Greenstein: (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)), where cosTheta is the cosine
// of the scattering angle. For a view ray direction d and the direction toward the sun l this is
// dot(d, l): looking into the sun is forward scattering, cosTheta = 1. (The GPU Pro 7 listing
// multiplies by pi and misplaces the exponent; this is the correct form.)
inline float henyeyGreenstein(float cosTheta, float g) {
    float g2 = g * g;
    float denom = max(1.0f + g2 - 2.0f * g * cosTheta, 1e-6f);
    return (1.0f - g2) / (4.0f * PI * denom * sqrt(denom));
}

// Two lobes for an art-directable silver lining (Forbidden West talk): a broad main lobe and a
// strong forward lobe, mixed by weight; stays normalised.
inline float twoLobePhase(float cosTheta, float gMain, float gSilver, float silverWeight) {
    return mix(henyeyGreenstein(cosTheta, gMain), henyeyGreenstein(cosTheta, gSilver),
               silverWeight);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
