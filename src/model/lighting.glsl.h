// Cloud lighting (GPU Pro 7 4.4 and 4.5.3, Forbidden West "light energy = direct + ambient"):
// Beer's law over a cone of light samples toward the sun plus one long-distance sample, a
// two-lobe Henyey-Greenstein phase, the powder (in-scattering probability) term, extra absorption
// from precipitation, and ambient sky light that grows with height and falls with depth.
#ifndef CLOUDSCAPE_MODEL_LIGHTING_GLSL_H
#define CLOUDSCAPE_MODEL_LIGHTING_GLSL_H

#include "cloud_shadow.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// Beer-Lambert transmittance of an optical depth.
inline float beerLambert(float opticalDepth) {
    return exp(-opticalDepth);
}

// Beer's-Powder (GPU Pro 7 4.4.4): 2 exp(-d) (1 - exp(-2d)) darkens the sun-facing surface
// where few photons have turned around. The effect is seen with the sun behind the viewer, so
// its strength fades to nothing as the view turns toward the sun (cosTheta -> 1); strength 0 is
// plain Beer's law.
inline float powderFactor(float opticalDepth, float cosTheta, float strength) {
    float powder = 2.0f * (1.0f - exp(-2.0f * opticalDepth));
    return mix(1.0f, powder, strength * saturate(0.5f - 0.5f * cosTheta));
}

inline float beerPowder(float opticalDepth, float cosTheta, float strength) {
    return beerLambert(opticalDepth) * powderFactor(opticalDepth, cosTheta, strength);
}

// A fixed kernel of six offsets in [-1, 1]^3 that spreads the light samples into a cone (the
// seed's "noise kernel"); a function rather than an array initialiser so both languages agree.
inline vec3 coneKernel(int i) {
    if (i == 0)
        return vec3(0.38f, -0.62f, 0.21f);
    if (i == 1)
        return vec3(-0.71f, 0.13f, -0.45f);
    if (i == 2)
        return vec3(0.27f, 0.55f, -0.79f);
    if (i == 3)
        return vec3(-0.18f, -0.36f, 0.88f);
    if (i == 4)
        return vec3(0.83f, 0.41f, 0.12f);
    return vec3(-0.52f, -0.84f, -0.33f);
}

struct LightSample {
    float opticalDepth; // toward the sun, with rain absorption applied
    int densitySamples; // texture-driven density evaluations taken
};

// Optical depth from p toward the clouds' light (the sun, or the moon at night:
// cloudLightDirection) through a cone of P.lightSamples samples (GPU Pro 7 4.5.3)
// plus the optical depth beyond the cone: from the clouds' shadow map (cloud_shadow.glsl.h) where
// it covers the cone's end and cloud_shadow.on_clouds is set, else, if enabled, one long-distance
// sample at P.longSampleDistance cone lengths for shadows from distant clouds. cheap selects
// base-only samples (used once the view ray is mostly opaque).
inline LightSample sunOpticalDepth(vec3 p, float precipitation, float lod, bool cheap,
                                   IN(CloudParams) P) {
    vec3 sunDir = cloudLightDirection(P.sky);
    int samples = P.lightSamples;
    float stepLength = P.coneLength / float(max(samples, 1));
    float spread = P.coneSpread * stepLength;
    float depth = 0.0f;
    LightSample result;
    result.densitySamples = 0;
    for (int i = 0; i < samples; ++i) {
        // Sample in the middle of each step, offset sideways by a growing amount.
        vec3 q =
            p + sunDir * (stepLength * (float(i) + 0.5f)) + coneKernel(i % 6) * (spread * float(i));
        // The storm's foot darkens: its light samples count denser (x 1 elsewhere, exactly).
        float d = cloudDensityAt(q, lod, cheap, P) * stormLightDensityScale(q, P);
        depth += extinctionOf(d, P) * stepLength;
        result.densitySamples += 1;
    }
    // Beyond the cone: the clouds' shadow map where it covers the cone's end (the whole rest of
    // the way to the sun, so a storm's or a big cumulus's far side is dark and one cloud shades
    // the next), else the long sample.
    bool mapped = false;
    if (P.cloudShadow.lightsClouds != 0) {
        vec3 q = p + sunDir * P.coneLength;
        depth += cloudShadowOpticalDepth(q, P, mapped) * stormLightDensityScale(q, P);
    }
    if (P.longSample != 0 && !mapped) {
        // The long sample stands for the stretch beyond the cone, weighted by one cone length
        // (a deliberate underestimate: one sample says little about a long path).
        vec3 q = p + sunDir * (P.coneLength * P.longSampleDistance);
        float d = cloudDensityAt(q, lod, true, P) * stormLightDensityScale(q, P);
        depth += extinctionOf(d, P) * P.coneLength;
        result.densitySamples += 1;
    }
    // Rain clouds absorb more: thicken the material seen by the light (GPU Pro 7 4.4.5).
    result.opticalDepth = depth * (1.0f + P.rainAbsorption * precipitation);
    return result;
}

// Ambient sky light reaching a point: radiance from below at the base blending to the sky above
// at the top, attenuated with depth into the cloud, which the base (coarse) density stands for
// (Forbidden West: ambient = pow(1 - coarse density, 0.5)).
inline vec3 ambientRadiance(vec3 p, float heightFraction, float baseDensity, IN(CloudParams) P) {
    float depthFactor = sqrt(saturate(1.0f - baseDensity));
    // Under a storm the ambient blends toward the storm's setting (x 1 elsewhere, exactly).
    float storm = stormAmbientFactor(p, heightFraction, P);
    return skyAmbientAt(p, heightFraction, P.sky) * (P.sky.ambientStrength * depthFactor * storm);
}

// The droplets' phase function as the scene chose it: the art-directable two-lobe HG of the
// Forbidden West talk, or the HG+Draine fit to Mie scattering for a droplet diameter.
inline PhaseFunction cloudPhaseFunction(IN(CloudParams) P) {
    if (P.phaseKind == PHASE_HG_DRAINE) {
        return makePhaseFunction(PHASE_HG_DRAINE, hgDraineParameters(P.dropletDiameter));
    }
    return makePhaseFunction(PHASE_TWO_LOBE, vec4(P.phaseG, P.silverG, P.silverWeight, 0.0f));
}

// Sun light scattered toward the eye at a point whose optical depth toward the sun is
// lightDepth, per unit irradiance. One octave is the seeds' single-scattering model: phase times
// Beer's-Powder. More octaves add Wrenninge's (2013) approximation of multiple scattering: octave
// i contributes a^i of the energy, sees the optical depth scaled by b^i (light that has scattered
// travels further) and a phase of eccentricity g c^i (it has lost direction), which lets the
// interiors of thick clouds glow instead of going black. Energy is conserved for a <= b.
// The octaves' phase values depend only on the angle to the sun, which is constant along a view
// ray: the march evaluates them once per ray (octavePhasesFor), not per octave per sample (the
// HG+Draine fit alone costs four exponentials). Up to 8 octaves (lighting.scattering_octaves).
struct OctavePhases {
    vec4 low;  // octaves 0-3
    vec4 high; // octaves 4-7
};

inline OctavePhases octavePhasesFor(float cosTheta, IN(CloudParams) P) {
    OctavePhases phases;
    phases.low = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    phases.high = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    PhaseFunction droplets = cloudPhaseFunction(P);
    float c = 1.0f;
    for (int i = 0; i < min(P.scatteringOctaves, 8); ++i) {
        float phase = evaluatePhase(scaledEccentricity(droplets, c), cosTheta);
        if (i < 4) {
            phases.low[i] = phase;
        } else {
            phases.high[i - 4] = phase;
        }
        c *= P.octaveFactors.z;
    }
    return phases;
}

inline float directScatteringWith(float lightDepth, float cosTheta, IN(OctavePhases) phases,
                                  IN(CloudParams) P) {
    float powder = powderFactor(lightDepth, cosTheta, P.powder);
    float sum = 0.0f;
    float a = 1.0f;
    float b = 1.0f;
    for (int i = 0; i < min(P.scatteringOctaves, 8); ++i) {
        float phase = i < 4 ? phases.low[i] : phases.high[i - 4];
        sum += a * phase * beerLambert(lightDepth * b);
        a *= P.octaveFactors.x;
        b *= P.octaveFactors.y;
    }
    return sum * powder;
}

inline float directScattering(float lightDepth, float cosTheta, IN(CloudParams) P) {
    return directScatteringWith(lightDepth, cosTheta, octavePhasesFor(cosTheta, P), P);
}

// Radiance scattered toward the eye per unit extinction (the source term divided by sigma_t),
// for a sample at p with the given light optical depth.
inline vec3 scatteredRadianceWith(vec3 p, float lightDepth, float cosTheta, IN(OctavePhases) phases,
                                  float heightFraction, float baseDensity, IN(CloudParams) P) {
    vec3 sun = cloudLightIrradianceAt(p, P.sky); // the sun, or the moon at night
    float direct = directScatteringWith(lightDepth, cosTheta, phases, P);
    vec3 ambient = ambientRadiance(p, heightFraction, baseDensity, P);
    return (sun * direct + ambient) * P.albedo;
}

inline vec3 scatteredRadiance(vec3 p, float lightDepth, float cosTheta, float heightFraction,
                              float baseDensity, IN(CloudParams) P) {
    return scatteredRadianceWith(p, lightDepth, cosTheta, octavePhasesFor(cosTheta, P),
                                 heightFraction, baseDensity, P);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
