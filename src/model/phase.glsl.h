// Phase functions, normalised so that they integrate to 1 over the sphere (1/sr).
#ifndef CLOUDSCAPE_MODEL_PHASE_GLSL_H
#define CLOUDSCAPE_MODEL_PHASE_GLSL_H

#include "compat.glsl.h"
#include "interface.glsl.h"

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
    // 1 + g^2 - 2 g cos written as (1 - g)^2 + 2 g (1 - cos), which keeps its precision in
    // float for the very forward lobes of droplet phase functions (g near 1, cos near 1).
    float g2 = g * g;
    float denom = max((1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f - cosTheta), 1e-12f);
    return (1.0f - g2) / (4.0f * PI * denom * sqrt(denom));
}

// Two lobes for an art-directable silver lining (Forbidden West talk): a broad main lobe and a
// strong forward lobe, mixed by weight; stays normalised.
inline float twoLobePhase(float cosTheta, float gMain, float gSilver, float silverWeight) {
    return mix(henyeyGreenstein(cosTheta, gMain), henyeyGreenstein(cosTheta, gSilver),
               silverWeight);
}

// Draine's (2003) phase function, HG times (1 + alpha cos^2) renormalised: with alpha = 0 it is
// HG, and alpha > 0 adds the backward glory and sideways dip of Mie scattering by droplets.
inline float drainePhase(float cosTheta, float g, float alpha) {
    float g2 = g * g;
    float denom = max((1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f - cosTheta), 1e-12f);
    float shape = (1.0f + alpha * cosTheta * cosTheta) / (1.0f + alpha * (1.0f + 2.0f * g2) / 3.0f);
    return (1.0f - g2) * shape / (4.0f * PI * denom * sqrt(denom));
}

// Jendersie and d'Eon (2023), "An Approximate Mie Scattering Function for Fog and Cloud
// Rendering": Mie scattering by water droplets of diameter d (micrometres, fitted for 5-50) as
// a blend of HG and Draine lobes. Returns (g of the HG lobe, g of the Draine lobe, Draine alpha,
// weight of the Draine lobe).
inline vec4 hgDraineParameters(float diameterUm) {
    float d = clamp(diameterUm, 5.0f, 50.0f);
    float gHG = exp(-0.0990567f / (d - 1.67154f));
    float gD = exp(-2.20679f / (d + 3.91029f) - 0.428934f);
    float alpha = exp(3.62489f - 8.29288f / (d + 5.52825f));
    float wD = exp(-0.599085f / (d - 0.641583f) - 0.665888f);
    return vec4(gHG, gD, alpha, wD);
}

inline float hgDrainePhase(float cosTheta, vec4 params) {
    return mix(henyeyGreenstein(cosTheta, params.x), drainePhase(cosTheta, params.y, params.z),
               params.w);
}

// ---- Importance sampling: each returns the cosine of the scattering angle for uniform u in
// [0, 1), distributed exactly as the phase function (so a path's weight is unchanged by a
// scattering event). The azimuth is uniform and chosen by the caller.

// The closed-form inverse of the HG distribution of cos theta.
inline float sampleHenyeyGreensteinCos(float g, float u) {
    if (abs(g) < 1e-3f) {
        return 1.0f - 2.0f * u;
    }
    float g2 = g * g;
    float sq = (1.0f - g2) / (1.0f - g + 2.0f * g * u);
    return clamp((1.0f + g2 - sq * sq) / (2.0f * g), -1.0f, 1.0f);
}

// Antiderivative over s = 1 + g^2 - 2 g cos of the unnormalised Draine density
// (1 + alpha cos^2) s^(-3/2), with cos = (1 + g^2 - s) / (2 g) substituted.
inline float draineAntiderivative(float s, float g, float alpha) {
    float a = 1.0f + g * g;
    float rs = sqrt(s);
    float k = alpha / (4.0f * g * g);
    return -2.0f / rs + k * (-2.0f * a * a / rs - 4.0f * a * rs + (2.0f / 3.0f) * s * rs);
}

// Draine's CDF has a closed form but no simple inverse: bisection to float precision (24
// halvings of [-1, 1]) has no failure modes. The closed form divides by g^2 and cancels badly
// for small |g| (1e-3 CDF error at g = 0.05), so g is kept at or above 0.2 in magnitude; the
// HG+Draine fit only ever uses g between 0.5 and 0.63, where the CDF is good to 1e-6.
inline float sampleDraineCos(float g, float alpha, float u) {
    float gs = abs(g) < 0.2f ? (g < 0.0f ? -0.2f : 0.2f) : g;
    float fLow = draineAntiderivative((1.0f + gs) * (1.0f + gs), gs, alpha);  // cos = -1
    float fHigh = draineAntiderivative((1.0f - gs) * (1.0f - gs), gs, alpha); // cos = +1
    float lo = -1.0f;
    float hi = 1.0f;
    for (int i = 0; i < 24; ++i) {
        float mid = 0.5f * (lo + hi);
        float s = 1.0f + gs * gs - 2.0f * gs * mid;
        float cdf = (fLow - draineAntiderivative(s, gs, alpha)) / (fLow - fHigh);
        if (cdf < u) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5f * (lo + hi);
}

// A phase function chosen at run time: kind (PHASE_* of interface.glsl.h) selects the shape,
// params its parameters.

struct PhaseFunction {
    int kind;
    vec4 params;
};

inline PhaseFunction makePhaseFunction(int kind, vec4 params) {
    PhaseFunction f;
    f.kind = kind;
    f.params = params;
    return f;
}

inline float evaluatePhase(IN(PhaseFunction) f, float cosTheta) {
    if (f.kind == PHASE_HG) {
        return henyeyGreenstein(cosTheta, f.params.x);
    }
    if (f.kind == PHASE_TWO_LOBE) {
        return twoLobePhase(cosTheta, f.params.x, f.params.y, f.params.z);
    }
    if (f.kind == PHASE_HG_DRAINE) {
        return hgDrainePhase(cosTheta, f.params);
    }
    return isotropicPhase();
}

// A mixture is sampled by choosing a lobe with its weight (uLobe), then sampling that lobe (u).
inline float samplePhaseCos(IN(PhaseFunction) f, float uLobe, float u) {
    if (f.kind == PHASE_HG) {
        return sampleHenyeyGreensteinCos(f.params.x, u);
    }
    if (f.kind == PHASE_TWO_LOBE) {
        return sampleHenyeyGreensteinCos(uLobe < f.params.z ? f.params.y : f.params.x, u);
    }
    if (f.kind == PHASE_HG_DRAINE) {
        return uLobe < f.params.w ? sampleDraineCos(f.params.y, f.params.z, u)
                                  : sampleHenyeyGreensteinCos(f.params.x, u);
    }
    return 1.0f - 2.0f * u;
}

// The same phase function with every lobe's eccentricity scaled (Wrenninge's octaves).
inline PhaseFunction scaledEccentricity(IN(PhaseFunction) f, float scale) {
    PhaseFunction s = f;
    if (f.kind == PHASE_HG) {
        s.params.x = f.params.x * scale;
    } else if (f.kind == PHASE_TWO_LOBE) {
        s.params.x = f.params.x * scale;
        s.params.y = f.params.y * scale;
    } else if (f.kind == PHASE_HG_DRAINE) {
        s.params.x = f.params.x * scale;
        s.params.y = f.params.y * scale;
    }
    return s;
}

// A unit direction at angle acos(cosTheta) from dir, at azimuth phi around it (the basis of
// Duff et al. 2017, continuous everywhere except where it does not matter).
// With sinTheta given, for angles so small that sqrt(1 - cos^2) would lose it.
inline vec3 directionAroundSin(vec3 dir, float cosTheta, float sinTheta, float phi) {
    float sign = dir.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sign + dir.z);
    float b = dir.x * dir.y * a;
    vec3 t1 = vec3(1.0f + sign * dir.x * dir.x * a, sign * b, -sign * dir.x);
    vec3 t2 = vec3(b, sign + dir.y * dir.y * a, -dir.y);
    return normalize(t1 * (sinTheta * cos(phi)) + t2 * (sinTheta * sin(phi)) + dir * cosTheta);
}

inline vec3 directionAround(vec3 dir, float cosTheta, float phi) {
    return directionAroundSin(dir, cosTheta, sqrt(max(1.0f - cosTheta * cosTheta, 0.0f)), phi);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
