// The cloud density sampler of GPU Pro 7 4.3.4 and the Forbidden West talk: base shape from the
// Perlin-Worley noise dilated by a Worley FBM, shaped by the vertical profile, grown by coverage,
// then eroded by curl-distorted high-frequency Worley noise (wispy at the bottom, billowy at the
// top), with wind shear over height and animation that moves base and detail at different
// speeds. Density is dimensionless in [0, 1]; extinction = density * P.extinction (1/m).
#ifndef CLOUDSCAPE_MODEL_DENSITY_GLSL_H
#define CLOUDSCAPE_MODEL_DENSITY_GLSL_H

#include "camera.glsl.h"
#include "compat.glsl.h"
#include "data_field.glsl.h"
#include "params.glsl.h"
#include "profiles.glsl.h"
#include "sampling.glsl.h"
#include "shell.glsl.h"
#include "storm.glsl.h"
#include "weather.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// How far below 0 the coverage threshold reaches at coverage 1 (see baseCloudDensity).
CONST_FLOAT COVERAGE_OVERSHOOT = 0.15f;

// Normalised height of a point in the cloud layer, clamped to [0, 1].
inline float heightFractionAt(vec3 p, IN(CloudParams) P) {
    float altitude = altitudeOf(p, P.planetRadius);
    return saturate((altitude - P.layerBottom) / (P.layerTop - P.layerBottom));
}

// Where a world position reads the weather map: the map is laid flat over xz, centred on
// P.weatherOrigin, and wraps every P.weatherExtent metres.
inline vec2 weatherUv(vec2 xz, IN(CloudParams) P) {
    return (xz - P.weatherOrigin) / P.weatherExtent + vec2(0.5f, 0.5f);
}

// Weather (coverage, precipitation, type) at a world position, with the scene's coverage and
// type offset and the precipitation rule applied (weather.glsl.h); no storm.
inline vec3 weatherAt(vec3 p, IN(CloudParams) P) {
    vec4 texel = sampleWeatherMap(weatherUv(vec2(p.x, p.z), P));
    return weatherFromTexel(texel, P.coverageBias, P.typeOffset);
}

// Everything a density evaluation needs about its position, computed once per sample.
struct DensityContext {
    vec3 position;        // world position (m)
    float heightFraction; // in the region's layer (data_field.glsl.h: regionHeightFraction)
    vec3 weather;         // coverage, precipitation, type (rule applied, storm stencil applied)
    float bottomType;     // the data field's, or the storm's where larger
    float anvilCoverage;  // coverage of the flipped (anvil) profile: the field's or the storm's
    float anvil;          // weight of the anvil's lift: the field's coverage or the storm's mask
    StormSample storm;    // the superstorm at this position (storm.glsl.h)
};

// The data field with the storm's stencil composited in (each channel the larger of the two):
// the storm relaxes the bottom, spreads the anvil and raises the base over its foot.
inline DensityContext densityContextAt(vec3 p, IN(CloudParams) P) {
    DensityContext ctx;
    ctx.position = p;
    ctx.storm = stormSampleAt(p, P);
    vec4 field = dataFieldAt(vec2(p.x, p.z), P);
    ctx.bottomType = max(field.x, ctx.storm.bottomType);
    ctx.anvilCoverage = max(field.y, ctx.storm.anvil * P.stormCoverage);
    ctx.anvil = max(field.y, ctx.storm.anvil);
    float minHeight = max(field.z, ctx.storm.baseRise);
    ctx.heightFraction = regionHeightFraction(heightFractionAt(p, P), minHeight, field.w);
    ctx.weather = stormWeather(weatherAt(p, P), ctx.storm.footR, P);
    return ctx;
}

// The wind, written once for every reader (both noise lookups here, the temporal reprojection's
// cloudMotion): the field drifts with the wind and slightly upward, so that clouds seem to grow,
// windTravel metres in a time; tops lean downwind by the shear.
inline vec3 cloudDriftDirection(IN(CloudParams) P) {
    return P.windDirection + vec3(0.0f, P.updraft, 0.0f);
}

inline float windTravel(float seconds, IN(CloudParams) P) {
    return seconds * P.windSpeed;
}

// A noise lookup position: p sheared by height and moved back by the drift of `travel` metres.
inline vec3 windShifted(vec3 p, float heightFraction, float travel, IN(CloudParams) P) {
    return p + P.windDirection * (heightFraction * P.windShear) - cloudDriftDirection(P) * travel;
}

// Noise mip level for a view sample whose pixel covers `footprint` metres, for a texture whose
// texels are 2^log2Texel metres: far clouds read filtered noise instead of aliasing it into
// speckle (the view steps there are far longer than a detail texel).
inline float distanceLod(float footprint, float log2Texel, IN(CloudParams) P) {
    if (P.distanceLod == 0 || footprint <= 0.0f) {
        return 0.0f;
    }
    return max(log2(footprint) - log2Texel, 0.0f);
}

// The base noise's low-frequency Worley FBM, from its G, B and A channels.
inline float baseNoiseFbm(vec4 lowFreq) {
    return lowFreq.y * 0.625f + lowFreq.z * 0.25f + lowFreq.w * 0.125f;
}

// Wind-sheared, animated position of the base noise.
inline vec3 animatedBasePosition(vec3 p, float heightFraction, IN(CloudParams) P) {
    return windShifted(p, heightFraction, windTravel(P.time, P), P);
}

// The base cloud shape with the profile and coverage applied ("cheap" / coarse sample), and how
// far the profiled shape lies below the coverage threshold: x density, y margin (> 0 only where
// x is 0; 1 where there is no coverage at all). The margin is what the step optimisation of the
// march reads: the base noise is smooth, so a sample far below the threshold has no cloud near.
inline float baseShapeAt(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    vec3 basePos = animatedBasePosition(ctx.position, ctx.heightFraction, P);
    vec4 lowFreq = sampleBaseNoise(basePos / P.baseNoisePeriod, lod);
    // Carve the Perlin-Worley shape with the low-frequency Worley FBM (GPU Pro 7 4.3.4: the
    // FBM's complement is the new minimum): billow centres, where the inverted Worley is high,
    // keep their density and detail appears at the edges.
    float lowFbm = baseNoiseFbm(lowFreq);
    return saturate(remap(lowFreq.x, 1.0f - lowFbm, 1.0f, 0.0f, 1.0f));
}

// The coverage threshold the profiled base shape must exceed for cloud (coveredShape): 1 at
// coverage 0, slightly below 0 at coverage 1. The shape is at most 1, so a profile at or below it
// has no cloud whatever the noise (baseCloudSample, coverageMargin, profileTopAbove).
inline float coverageThreshold(float coverage) {
    return 1.0f - coverage * (1.0f + COVERAGE_OVERSHOOT);
}

// Coverage erodes the profiled shape (clouds inflate as coverage grows) and scales it so that
// sparse clouds are also lighter (GPU Pro 7 4.3.4). The threshold runs from 1 at coverage 0 to
// slightly below 0 at coverage 1, so that full coverage is overcast: every point inside the
// profile has cloud, as the weather map's "percentage of cloud coverage" promises, rather than
// keeping the base noise's holes. x density, y margin below the threshold.
inline vec2 coveredShape(float baseShape, float profile, float coverage) {
    float threshold = coverageThreshold(coverage);
    float field = baseShape * profile;
    float shaped = saturate(remap(field, threshold, 1.0f, 0.0f, 1.0f));
    return vec2(shaped * coverage, max(threshold - field, 0.0f));
}

// How far a profile lies below its coverage threshold where no base shape (at most 1) can make
// cloud: the margin (>= 0), 1 with no coverage or no profile; negative where cloud is possible.
inline float coverageMargin(float profile, float coverage) {
    if (coverage <= 0.0f || profile <= 0.0f) {
        return 1.0f;
    }
    return coverageThreshold(coverage) - profile;
}

// Within a storm, or where the data field relaxes the bottom or spreads an anvil: the normal
// profile (the product of the bottom gradient, by the bottom type, and the type's top gradient)
// and the flipped anvil profile, each with its own coverage over the same base shape (one texture
// read), combined by their maximum so the top spreads horizontally (the talk's flipped and
// combined vertical profile gradient). Over the storm's foot (and under any anvil, the field's
// superstorm coverage as the storm's) the base shape is raised toward 1, the talk's noises
// "blended to their maximum values at the center": at coverage 1 alone the thin parts of the
// shape would be eroded away and the mesocyclone would be a lace, not a mass.
inline vec2 splitProfileSample(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    float coverage = ctx.weather.x;
    float profile = splitVerticalProfile(ctx.heightFraction, ctx.weather.z, ctx.bottomType);
    float anvilCoverage = ctx.anvilCoverage;
    float anvil = anvilVerticalProfile(ctx.heightFraction);
    // Each part can make cloud only where its profile exceeds its coverage threshold (the shape,
    // lifted or not, is at most 1, as in baseCloudSample); a part that cannot keeps its margin,
    // the profile's (a lower bound of the shape's), and needs no noise.
    float normalMargin = coverageMargin(profile, coverage);
    float anvilMargin = coverageMargin(anvil, anvilCoverage);
    bool normal = normalMargin < 0.0f;
    bool top = anvilMargin < 0.0f;
    if (!normal && !top) {
        return vec2(0.0f, min(normalMargin, anvilMargin));
    }
    float baseShape = baseShapeAt(ctx, lod, P);
    vec2 result = vec2(0.0f, normal ? 1.0f : normalMargin);
    if (normal) {
        result = coveredShape(mix(baseShape, 1.0f, ctx.storm.lift), profile, coverage);
    }
    if (top) {
        float anvilShape = mix(baseShape, 1.0f, STORM_ANVIL_LIFT * ctx.anvil);
        vec2 spread = coveredShape(anvilShape, anvil, anvilCoverage);
        result = vec2(max(result.x, spread.x), min(result.y, spread.y));
    } else {
        result.y = min(result.y, anvilMargin);
    }
    return result;
}

inline vec2 baseCloudSample(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    if (ctx.storm.r < 1.0f || ctx.anvilCoverage > 0.0f || ctx.bottomType > 0.0f) {
        return splitProfileSample(ctx, lod, P);
    }
    float coverage = ctx.weather.x;
    if (coverage <= 0.0f) {
        return vec2(0.0f, 1.0f);
    }
    float threshold = coverageThreshold(coverage);
    float profile = verticalProfile(ctx.heightFraction, ctx.weather.z);
    if (profile <= 0.0f) {
        return vec2(0.0f, max(threshold, 0.0f));
    }
    // The base shape is at most 1, so where the profile itself stays at or below the coverage
    // threshold no noise can make cloud: the sample is empty without reading the 3D texture.
    // The margin is then a lower bound of the one the noise would give (the step optimisation
    // grows its steps a little less there).
    if (profile <= threshold) {
        return vec2(0.0f, threshold - profile);
    }
    return coveredShape(baseShapeAt(ctx, lod, P), profile, coverage);
}

inline float baseCloudDensity(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    return baseCloudSample(ctx, lod, P).x;
}

// Erode a base density with curl-distorted detail noise: inverted (wispy) near the bottom of
// the layer, billowy above.
// The detail noise's FBM at a (possibly vortex-turned) position.
inline float detailFbmAt(vec3 position, float heightFraction, float lod, IN(CloudParams) P) {
    // The detail noise drifts faster than the base (wind.detail_speed_ratio).
    vec3 detailPos =
        windShifted(position, heightFraction, windTravel(P.time, P) * P.detailSpeedRatio, P);
    vec2 curlUv = vec2(position.x, position.z) / P.curlNoisePeriod;
    vec4 curlRaw = sampleCurlNoise(curlUv);
    // R and G are the divergence-free flow in the texture plane (world x and z), B is vertical.
    vec3 curl = vec3(curlRaw.x, curlRaw.z, curlRaw.y) * 2.0f - vec3(1.0f, 1.0f, 1.0f);
    // Turbulence is strongest at the cloud bottom.
    detailPos = detailPos + curl * (P.curlStrength * (1.0f - heightFraction));
    vec4 highFreq = sampleDetailNoise(detailPos / P.detailNoisePeriod, lod);
    return highFreq.x * 0.625f + highFreq.y * 0.25f + highFreq.z * 0.125f;
}

// A uniform number in [0, 1) fixed to a 25 cm cell of the world, for the low tier's pick of a
// vortex ring: a march's jittered steps land in other cells each frame, so the temporal
// reconstruction averages the picks. Cells rather than the position's float bits, so both
// backends pick alike except within a thousandth of a cell of its edge.
inline float positionRandom(vec3 p) {
    ivec3 c = ivec3(floor(p * 4.0f));
    uint h = hashUint(uint(c.x) + hashUint(uint(c.y) + hashUint(uint(c.z))));
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

// The mesocyclone's vortex (the talk's nested rings): the detail noise is read at the position
// turned back by its ring's angle, so the noise turns with the ring; in a ring overlap both
// rings are sampled and blended, so no cut shows where one ring ends
// (or, with storm.ring_jitter, one of them is read, picked at random).
inline float vortexDetailFbmAt(vec3 position, IN(DensityContext) ctx, float lod,
                               IN(CloudParams) P) {
    vec2 ring = stormRing(ctx.storm.r);
    int n = int(ring.x);
    if (P.stormRingJitter != 0 && ring.y > 0.0f) {
        // PS4: in the overlap one ring is read, the outer one with the blend's chance, so the
        // expected noise is the blend at half the reads.
        n += positionRandom(position) < ring.y ? 1 : 0;
        ring.y = 0.0f;
    }
    vec3 inner = rotateAboutStorm(position, -stormRingAngle(n, ctx.storm.r, P), P);
    float fbm = detailFbmAt(inner, ctx.heightFraction, lod, P);
    if (ring.y > 0.0f) {
        vec3 outer = rotateAboutStorm(position, -stormRingAngle(n + 1, ctx.storm.r, P), P);
        fbm = mix(fbm, detailFbmAt(outer, ctx.heightFraction, lod, P), ring.y);
    }
    return fbm;
}

inline float vortexDetailFbm(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    return vortexDetailFbmAt(ctx.position, ctx, lod, P);
}

// The storm's detail noise: the vortex's, and in the anvil (the talk's "rotated/skewed noises")
// the same read at a position squeezed toward the storm centre along the wind and across it, so
// its features are stretched into the fibrous streaks of ice cloud spreading from the top. The
// squeeze also makes the 32^3 texture repeat less often across the anvil's flat underside, where
// a plane through the noise showed its tiling as a lattice of tufts. Blended in over the tenth of
// the layer below the anvil (two reads there only), so the foot below keeps its own noise.
inline float stormDetailFbm(IN(DensityContext) ctx, float lod, IN(CloudParams) P) {
    float anvilBase = 1.0f - anvilProfile().w;
    float w = ctx.storm.anvil * smoothstep(anvilBase - 0.1f, anvilBase, ctx.heightFraction);
    float fbm = w < 1.0f ? vortexDetailFbm(ctx, lod, P) : 0.0f;
    if (w > 0.0f) {
        vec2 offset = stormOffset(vec2(ctx.position.x, ctx.position.z), P);
        vec2 along = vec2(P.windDirection.x, P.windDirection.z);
        along = dot(along, along) > 0.0f ? normalize(along) : vec2(1.0f, 0.0f);
        vec2 across = vec2(-along.y, along.x);
        vec2 squeezed = along * (dot(offset, along) * STORM_ANVIL_SQUEEZE_ALONG) +
                        across * (dot(offset, across) * STORM_ANVIL_SQUEEZE_ACROSS);
        vec3 q = vec3(ctx.position.x + (squeezed.x - offset.x), ctx.position.y,
                      ctx.position.z + (squeezed.y - offset.y));
        fbm = mix(fbm, vortexDetailFbmAt(q, ctx, lod, P), w);
    }
    return fbm;
}

inline float erodeWithDetail(float baseDensity, IN(DensityContext) ctx, float lod,
                             IN(CloudParams) P) {
    float highFbm = ctx.storm.r < 1.0f ? stormDetailFbm(ctx, lod, P)
                                       : detailFbmAt(ctx.position, ctx.heightFraction, lod, P);
    // Wispy (inverted) noise near the bottom, billowy above; the bottom type stretches the wispy
    // band up a ragged underside, as under the mesocyclone (x / 1 is exact at bottom type 0).
    float wispyBand = 1.0f + 9.0f * ctx.bottomType;
    float modifier = mix(highFbm, 1.0f - highFbm, saturate(ctx.heightFraction * 10.0f / wispyBand));
    float threshold = modifier * P.erosion;
    // Erosion that reaches 1 removes everything (remap's degenerate range would return 1
    // instead, which would also break the path tracer's bound density <= coverage).
    if (threshold >= 1.0f - 1e-6f) {
        return 0.0f;
    }
    return saturate(remap(baseDensity, threshold, 1.0f, 0.0f, 1.0f));
}

// Cloud density in [0, 1] at a sample. cheap: base shape only (one 3D texture read);
// otherwise the full sample with erosion.
inline float cloudDensity(IN(DensityContext) ctx, float lod, bool cheap, IN(CloudParams) P) {
    float base = baseCloudDensity(ctx, lod, P);
    if (cheap || base <= 0.0f) {
        return base;
    }
    return erodeWithDetail(base, ctx, lod, P);
}

inline float cloudDensityAt(vec3 p, float lod, bool cheap, IN(CloudParams) P) {
    return cloudDensity(densityContextAt(p, P), lod, cheap, P);
}

// Extinction coefficient (1/m) of a density.
inline float extinctionOf(float density, IN(CloudParams) P) {
    return density * P.extinction;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
