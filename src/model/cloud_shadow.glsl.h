// The clouds' shadow map (issue 12): one map of sun rays over the area around the camera, made
// each frame from the clouds' own density (cloudDensityAt, so it moves with the wind over
// time_s) and read by the ground, the terrain and the light shafts instead of marching the layer
// per pixel.
//
// The map is in sun space as an oblique projection on a grid of the world fixed by the map's
// texel size (extent / resolution): map texel (i, j) is the sun ray through the centre of world
// texel w = CloudShadowParams.firstTexel + (i, j) of the plane y = 0, the point (w + 0.5) * size.
// Every world point p lies on exactly one such ray, the one through p - sun * (p.y / sun.y), so
// the parameterisation is exact, curvature included (the layer is intersected as the sphere
// shell it is); a ground texel's footprint is stretched along the sun's heading as its shadow is.
// Each texel stores, after the Beer shadow maps of Hillaire / UE5, where along its ray the cloud
// lies and how much of it there is: x the distance from the plane to the lowest sample with
// cloud, y to the highest, z the optical depth of the whole crossing. A point's optical depth
// toward the sun is z where it lies below the cloud, 0 above it, and linear in between, so points
// between and inside clouds (light shafts, peaks in cloud) get partial shadow.
// A texel's record is a function of its world texel alone (and of the parameters other than
// where the map lies), and the buffer is toroidal (cloudShadowStorageIndex): as the map follows a
// moving camera each world texel stays where it is stored, so a renderer makes only the rows and
// columns the move brings in (src/vulkan/cloud_shadow_map.cpp) and the map it holds is the one a
// whole pass would make.
#ifndef CLOUDSCAPE_MODEL_CLOUD_SHADOW_GLSL_H
#define CLOUDSCAPE_MODEL_CLOUD_SHADOW_GLSL_H

#include "cloud_bound.glsl.h"
#include "compat.glsl.h"
#include "density.glsl.h"
#include "features.glsl.h"
#include "params.glsl.h"
#include "shell.glsl.h"
#include "sky.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// The clouds' mean cosine of scattering: water droplets in visible light (Hansen and Travis 1974,
// 0.85-0.87), the medium's own, not the lighting's artistic phase lobes.
CONST_FLOAT CLOUD_DROPLET_ASYMMETRY = 0.86f;

// The share of the sun's light (as a fraction of what the same point would get in the open) that
// a cloud of direct transmittance `direct` passes on downward as diffuse light: light scattered
// out of the beam but onward, toward the ground. Droplets scatter almost without absorbing, and
// mostly forward, so the ground under a thick cumulus still gets a colourless glow from the
// cloud's base. With the beam (exp(-tau)) alone, cloud shadows were lit by the blue sky only: too
// dark and too blue, "lakes" seen from altitude (the path tracer's shadowed ground was 15-16 %
// brighter in red and green, docs/QUALITY.md section 7).
// The total transmission of a conservative scattering slab in the two-stream approximation
// (Bohren 1987, "Multiple scattering of light and some of its observable consequences"):
// 1 / (1 + 3/4 (1 - g) tau), of which the beam is exp(-tau). A cumulus is no slab: light
// diffusing downward through a cloud about as tall as it is wide leaves through its base and the
// lower halves of its four sides, a third of it through the base (CLOUD_BASE_EXIT_SHARE); only
// that third falls in the shadow, the rest around it among sunlit ground. At tau 30 the shadow
// gets 0.08 of the sun this way (the slab's whole 0.24 made shadows far brighter than traced).
CONST_FLOAT CLOUD_BASE_EXIT_SHARE = 1.0f / 3.0f;

inline float cloudDiffuseShare(float direct) {
    float tau = -log(max(direct, 1e-30f));
    float total = 1.0f / (1.0f + 0.75f * (1.0f - CLOUD_DROPLET_ASYMMETRY) * tau);
    return CLOUD_BASE_EXIT_SHARE * max(total - direct, 0.0f);
}

// The sun's light below clouds of direct transmittance `direct`, as a share of the open sky's:
// the beam and the clouds' diffuse light.
inline float lightBelowClouds(float direct) {
    return direct + cloudDiffuseShare(direct);
}

// A texel of the map (the backend's buffer): CloudShadowParams.resolution^2 texels, stored
// row-major at cloudShadowStorageIndex.
vec4 cloudShadowTexel(int index);

// Where map texel (i, j) (row j at the j-th smallest z) is stored: at its world texel modulo the
// resolution, which the host's storage shift gives for the map's first texel.
inline int cloudShadowStorageIndex(ivec2 texel, IN(CloudShadowParams) C) {
    int n = C.resolution;
    int x = texel.x + C.storageShiftX;
    int z = texel.y + C.storageShiftZ;
    x = x >= n ? x - n : x;
    z = z >= n ? z - n : z;
    return z * n + x;
}

// The side (m) of a texel of the map on the plane y = 0.
inline float cloudShadowTexelSize(IN(CloudShadowParams) C) {
    return C.extent / float(C.resolution);
}

// Below this sine of the sun's elevation the map is not made (its rays would cross tens of
// kilometres of the plane per kilometre of altitude): the sun is then at the horizon, where the
// planet's shadow and the air already take its light.
CONST_FLOAT CLOUD_SHADOW_MIN_SUN_Y = 0.02f;

// The map's texels are made and read only when it is on and the sun is high enough for it.
inline bool cloudShadowMapUsable(IN(CloudParams) P) {
    return featureCompiled(FEATURE_CLOUD_SHADOW) && cloudShadowWanted(P) &&
           cloudLightDirection(P.sky).y >= CLOUD_SHADOW_MIN_SUN_Y;
}

// The point of the plane y = 0 where texel `texel`'s sun ray starts.
inline vec3 cloudShadowTexelOrigin(ivec2 texel, IN(CloudShadowParams) C) {
    vec2 xz = (vec2(texel + C.firstTexel) + vec2(0.5f)) * cloudShadowTexelSize(C);
    return vec3(xz.x, 0.0f, xz.y);
}

// The per-texel rule: C.steps density samples (full, with erosion) through the cloud layer along
// the texel's sun ray, at the noise mip the clouds' own light march reads
// (lighting.light_mip_bias), so the ground's shadow is the shadow the clouds cast on themselves.
// The samples are stratified, one per step at a phase that differs from texel to texel: Roberts'
// R2 sequence over the texel's place in the world (stable as the map follows the camera), which
// spreads neighbouring texels' phases evenly. With every texel at the steps' midpoints, every
// texel sampled the same altitudes, and at a low sun (`mountains`: 9 degrees, 860 m steps along
// the ray) a cloud's optical depth rose and fell with the phase of those samples against the
// cloud from texel to texel along the sun's heading: bold stripes of shadow 860 m apart across
// the sunlit slopes. With the phases spread the error is a fine texture the bilinear read
// softens, and against the path tracer the shadows are closer (docs/QUALITY.md section 7).
// Samples on one world lattice of planes across the sun (neighbours a few metres apart) were
// tried: smooth, but each error then covered kilometres (MS-SSIM 0.78 -> 0.71 against the path
// tracer).
// Moves step i of a shadow-map ray (origin o toward the light, samples at start + (i + phase) * dt)
// past the samples the weather's cloud-top grid proves empty (cloud_bound.glsl.h), which would
// all read zero density: the record is exactly the unskipped one's. False once the ray ends.
// A loop of its own, as the view march's nextSamplePosition: a SIMD machine that runs a loop body
// whole for every lane would otherwise read the noise for each skipped sample.
inline bool nextShadowSample(INOUT(int) i, int steps, vec3 o, vec3 sun, float start, float dt,
                             float phase, IN(CloudParams) P) {
    bool found = false;
    while (i < steps) {
        float s = start + (float(i) + phase) * dt;
        vec3 p = o + sun * s;
        float empty = skippableDistance(p, sun, P);
        if (empty <= 0.0f) {
            found = true;
            break;
        }
        float resume = s + empty;
        if (resume >= start + float(steps) * dt) {
            i = steps; // no sample left before the ray's end (empty may be 3e38: no int)
            break;
        }
        i = max(i + 1, int(ceil((resume - start) / dt - phase)));
    }
    return found;
}

// Returns (lowest cloud, highest cloud, optical depth, 0); a texel without cloud is all zeros.
inline vec4 cloudShadowMapTexel(ivec2 texel, IN(CloudParams) P) {
    vec3 sun = cloudLightDirection(P.sky); // the sun, or the moon when it lights the clouds
    vec3 o = cloudShadowTexelOrigin(texel, P.cloudShadow);
    vec4 spans = shellIntervals(o, sun, P.planetRadius, P.layerBottom, P.layerTop);
    float crossing = spans.y - spans.x;
    if (crossing <= 0.0f) {
        return vec4(0.0f);
    }
    int steps = max(P.cloudShadow.steps, 1);
    float dt = crossing / float(steps);
    float lod = float(P.lightMipBias);
    float depth = 0.0f;
    float lowest = 0.0f;
    float highest = 0.0f;
    bool found = false;
    ivec2 worldTexel = texel + P.cloudShadow.firstTexel;
    float phase = fract(0.5f + float(worldTexel.x & 4095) * 0.7548776662f +
                        float(worldTexel.y & 4095) * 0.5698402910f);
    int i = 0;
    while (nextShadowSample(i, steps, o, sun, spans.x, dt, phase, P)) {
        float s = spans.x + (float(i) + phase) * dt;
        float density = cloudDensityAt(o + sun * s, lod, false, P);
        if (density > 0.0f) {
            if (!found) {
                lowest = spans.x + float(i) * dt; // the sample's stratum
                found = true;
            }
            highest = spans.x + float(i + 1) * dt;
            depth += extinctionOf(density, P) * dt;
        }
        i += 1;
    }
    return vec4(lowest, highest, depth, 0.0f);
}

// Optical depth toward the sun at distance s along a texel's ray (cloudShadowMapTexel's record).
inline float cloudShadowDepthAlong(vec4 record, float s) {
    float span = max(record.y - record.x, 1.0f);
    return record.z * saturate((record.y - s) / span);
}

// Optical depth at distance s along map texel `texel`'s ray.
inline float cloudShadowDepthAt(ivec2 texel, float s, IN(CloudShadowParams) C) {
    return cloudShadowDepthAlong(cloudShadowTexel(cloudShadowStorageIndex(texel, C)), s);
}

// The four map texels around p's sun ray and p's optical depth along each
// (cloudShadowDepthAlong): x (i0, j0), y (i1, j0), z (i0, j1), w (i1, j1), with the bilinear
// weights between them. False (and nothing written) where the ray misses the map or the map is
// unusable.
inline bool cloudShadowCorners(vec3 p, IN(CloudParams) P, OUT(vec4) depths, OUT(vec2) weights) {
    if (!cloudShadowMapUsable(P)) {
        return false;
    }
    vec3 sun = cloudLightDirection(P.sky); // the sun, or the moon when it lights the clouds
    float s = p.y / sun.y;
    vec2 xz = vec2(p.x - sun.x * s, p.z - sun.z * s);
    int n = P.cloudShadow.resolution;
    float size = cloudShadowTexelSize(P.cloudShadow);
    vec2 x = (xz - vec2(P.cloudShadow.firstTexel) * size) / size - vec2(0.5f);
    if (x.x < -0.5f || x.y < -0.5f || x.x > float(n) - 0.5f || x.y > float(n) - 0.5f) {
        return false;
    }
    x = clamp(x, vec2(0.0f), vec2(float(n - 1)));
    ivec2 i0 = ivec2(floor(x));
    ivec2 i1 = min(i0 + ivec2(1), ivec2(n - 1));
    weights = x - vec2(i0);
    depths = vec4(cloudShadowDepthAt(ivec2(i0.x, i0.y), s, P.cloudShadow),
                  cloudShadowDepthAt(ivec2(i1.x, i0.y), s, P.cloudShadow),
                  cloudShadowDepthAt(ivec2(i0.x, i1.y), s, P.cloudShadow),
                  cloudShadowDepthAt(ivec2(i1.x, i1.y), s, P.cloudShadow));
    return true;
}

inline float bilinearCorners(vec4 corners, vec2 weights) {
    return mix(mix(corners.x, corners.y, weights.x), mix(corners.z, corners.w, weights.x),
               weights.y);
}

// The clouds' transmittance toward the sun at p from the map, bilinear over the four nearest
// texels (each evaluated at p's own distance along its ray, then blended, so an edge between
// cloud and gap is a linear ramp a texel wide). `inside` is set false where p's ray misses the
// map (or the map is unusable), and 1 returned.
inline float cloudShadowFromMap(vec3 p, IN(CloudParams) P, OUT(bool) inside) {
    vec4 depths;
    vec2 weights;
    inside = cloudShadowCorners(p, P, depths, weights);
    return inside ? bilinearCorners(exp(-depths), weights) : 1.0f;
}

// The clouds' optical depth toward the sun from p from the map (bilinear in optical depth, which
// the light march sums), for the clouds' own light beyond its cone (lighting.glsl.h). `inside`
// as cloudShadowFromMap's; 0 returned outside.
inline float cloudShadowOpticalDepth(vec3 p, IN(CloudParams) P, OUT(bool) inside) {
    vec4 depths;
    vec2 weights;
    inside = cloudShadowCorners(p, P, depths, weights);
    return inside ? bilinearCorners(depths, weights) : 0.0f;
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
