// The atmosphere around the clouds, after Hillaire 2020 ("A Scalable and Production Ready Sky and
// Atmosphere Rendering Technique"; constants from Bruneton 2017): Rayleigh and Mie scattering with
// exponential density profiles, ozone absorption in a tent, a spherical planet. Everything the
// clouds and the background need is read from lookup tables held in one buffer of vec4 texels
// (atmosphereLutTexel, supplied by each backend): the optical depth to the top of the atmosphere
// (256x64, for the transmittance), Hillaire's multiple-scattering transfer (32x32), the sky seen
// from the camera's altitude (192x108) and the ambient light of a point from above and from below
// (2 x 32x32), a second sky view lit by the moon, and the aerial-perspective volume (32x64x32, the
// air's light and transmittance up to a distance along a direction). The tables' texels are
// computed by the *LutTexel functions below, one texel per call, so the same code fills them on the
// host and in a compute pass (atmosphereTableTexel, at the end); all tables hold values per unit
// sun irradiance, so the sun's colour is a uniform.
//
// Positions are world positions (y up, the planet's centre at (0, -bottomRadius, 0), as the cloud
// shell's); a position's zenith is the direction from the centre.
#ifndef CLOUDSCAPE_MODEL_ATMOSPHERE_GLSL_H
#define CLOUDSCAPE_MODEL_ATMOSPHERE_GLSL_H

#include "compat.glsl.h"
#include "params.glsl.h"
#include "phase.glsl.h"

#ifdef __cplusplus
namespace cloudscape::model {
#endif

// ---- The tables' layout in the buffer (texels, x fastest).
CONST_INT TRANSMITTANCE_LUT_WIDTH = 256; // optical depth; x: view zenith (Bruneton's mapping)
CONST_INT TRANSMITTANCE_LUT_HEIGHT = 64; // y: radius
CONST_INT MULTISCATTER_LUT_SIZE = 32;    // x: sun zenith cosine, y: altitude
CONST_INT SKYVIEW_LUT_WIDTH = 192;       // x: azimuth from the sun
CONST_INT SKYVIEW_LUT_HEIGHT = 108;      // y: view zenith, horizon in the middle
CONST_INT AMBIENT_LUT_SIZE = 32;         // x: sun zenith cosine, y: sqrt of altitude fraction
CONST_INT TRANSMITTANCE_LUT_OFFSET = 0;
CONST_INT MULTISCATTER_LUT_OFFSET = TRANSMITTANCE_LUT_WIDTH * TRANSMITTANCE_LUT_HEIGHT;
CONST_INT SKYVIEW_LUT_OFFSET =
    MULTISCATTER_LUT_OFFSET + MULTISCATTER_LUT_SIZE * MULTISCATTER_LUT_SIZE;
CONST_INT AMBIENT_ABOVE_LUT_OFFSET = SKYVIEW_LUT_OFFSET + SKYVIEW_LUT_WIDTH * SKYVIEW_LUT_HEIGHT;
CONST_INT AMBIENT_BELOW_LUT_OFFSET = AMBIENT_ABOVE_LUT_OFFSET + AMBIENT_LUT_SIZE * AMBIENT_LUT_SIZE;
// The sky seen from the camera lit by the moon (the sky-view table for the moon's elevation; zero
// while the moon is off). The other tables are indexed by the source's zenith cosine, so the moon
// reads them as the sun does.
CONST_INT MOON_SKYVIEW_LUT_OFFSET = AMBIENT_BELOW_LUT_OFFSET + AMBIENT_LUT_SIZE * AMBIENT_LUT_SIZE;
// The aerial-perspective volume (below): x the azimuth from the source and y the view zenith, as
// the sky view's; z the distance. The air's light for the sun, its transmittance, and the air's
// light for the moon (zero while the moon is off; the transmittance is the same for both).
CONST_INT AERIAL_LUT_WIDTH = 32;
CONST_INT AERIAL_LUT_HEIGHT = 64;
CONST_INT AERIAL_LUT_DEPTH = 32;
CONST_INT AERIAL_LUT_TEXELS = AERIAL_LUT_WIDTH * AERIAL_LUT_HEIGHT * AERIAL_LUT_DEPTH;
CONST_INT AERIAL_SCATTER_LUT_OFFSET =
    MOON_SKYVIEW_LUT_OFFSET + SKYVIEW_LUT_WIDTH * SKYVIEW_LUT_HEIGHT;
CONST_INT AERIAL_TRANSMITTANCE_LUT_OFFSET = AERIAL_SCATTER_LUT_OFFSET + AERIAL_LUT_TEXELS;
CONST_INT MOON_AERIAL_SCATTER_LUT_OFFSET = AERIAL_TRANSMITTANCE_LUT_OFFSET + AERIAL_LUT_TEXELS;
CONST_INT ATMOSPHERE_LUT_TEXELS = MOON_AERIAL_SCATTER_LUT_OFFSET + AERIAL_LUT_TEXELS;

// Integration steps of the table passes and of the per-pixel aerial perspective.
CONST_INT TRANSMITTANCE_STEPS = 128;
CONST_INT MULTISCATTER_STEPS = 20;
CONST_INT SKYVIEW_STEPS = 32;
CONST_INT AMBIENT_STEPS = 16;
CONST_INT AERIAL_PERSPECTIVE_STEPS = 8; // per call of the integral (not the volume)
CONST_INT AERIAL_LUT_STEPS = 16;        // per texel of the aerial-perspective volume

// A texel of the tables (the backend's buffer).
vec4 atmosphereLutTexel(int index);

// ---- The medium.

struct AtmosphereSample {
    vec3 rayleighScattering; // 1/m
    vec3 mieScattering;      // 1/m
    vec3 extinction;         // 1/m, everything (Rayleigh, Mie, ozone)
};

inline AtmosphereSample atmosphereAt(float altitude, IN(AtmosphereParams) A) {
    float h = max(altitude, 0.0f);
    float rayleigh = exp(-h / A.rayleighScaleHeight);
    float mie = exp(-h / A.mieScaleHeight);
    float ozone = max(0.0f, 1.0f - abs(h - A.ozoneCentre) / A.ozoneHalfWidth);
    AtmosphereSample s;
    s.rayleighScattering = A.rayleighScattering * rayleigh;
    s.mieScattering = vec3(A.mieScattering * mie);
    s.extinction = s.rayleighScattering + vec3(A.mieExtinction * mie) + A.ozoneAbsorption * ozone;
    return s;
}

inline float rayleighPhase(float cosTheta) {
    return 3.0f / (16.0f * PI) * (1.0f + cosTheta * cosTheta);
}

// Cornette-Shanks, the Mie phase Bruneton and Hillaire use.
inline float miePhase(float cosTheta, float g) {
    float g2 = g * g;
    float denom = 1.0f + g2 - 2.0f * g * cosTheta;
    return 3.0f / (8.0f * PI) * (1.0f - g2) * (1.0f + cosTheta * cosTheta) /
           ((2.0f + g2) * denom * sqrt(denom));
}

// ---- Geometry on a sphere of radius r about the planet's centre: a ray starts at radius r with
// the cosine mu of its zenith angle.

// r^2 - R^2 without the cancellation of two squares of 6.4e6 m.
inline float squareDifference(float r, float R) {
    return (r - R) * (r + R);
}

// Distance along the ray to the top of the atmosphere (the ray starts inside it).
inline float distanceToTop(float r, float mu, IN(AtmosphereParams) A) {
    float disc = r * r * (mu * mu - 1.0f) + A.topRadius * A.topRadius;
    return max(0.0f, -r * mu + sqrt(max(disc, 0.0f)));
}

// Distance along the ray to the ground, or -1 if it misses the planet.
inline float distanceToGround(float r, float mu, IN(AtmosphereParams) A) {
    float disc = r * r * (mu * mu - 1.0f) + A.bottomRadius * A.bottomRadius;
    if (mu >= 0.0f || disc < 0.0f) {
        return -1.0f;
    }
    return max(0.0f, -r * mu - sqrt(disc));
}

// The cosine of the zenith angle of the horizon seen from radius r (negative above the ground).
inline float horizonCosine(float r, IN(AtmosphereParams) A) {
    return -sqrt(max(squareDifference(r, A.bottomRadius), 0.0f)) / r;
}

// Radius and zenith cosine at distance t along a ray from (r, mu).
inline vec2 alongRay(float r, float mu, float t) {
    float rt = sqrt(max(r * r + t * t + 2.0f * r * mu * t, 0.0f));
    return vec2(rt, (r * mu + t) / rt);
}

// ---- Bilinear reads of a table: texel centres at (i + 0.5) / size, clamped at the edges, done
// here rather than by a sampler so both backends interpolate in full float precision alike.
inline vec4 lutBilinear(int offset, int width, int height, vec2 uv) {
    vec2 x = clamp(uv, vec2(0.0f), vec2(1.0f)) * vec2(float(width), float(height)) - 0.5f;
    x = clamp(x, vec2(0.0f), vec2(float(width - 1), float(height - 1)));
    ivec2 i0 = ivec2(floor(x));
    ivec2 i1 = min(i0 + ivec2(1), ivec2(width - 1, height - 1));
    vec2 f = x - vec2(i0);
    vec4 a = atmosphereLutTexel(offset + i0.y * width + i0.x);
    vec4 b = atmosphereLutTexel(offset + i0.y * width + i1.x);
    vec4 c = atmosphereLutTexel(offset + i1.y * width + i0.x);
    vec4 d = atmosphereLutTexel(offset + i1.y * width + i1.x);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

// ---- Transmittance table (Bruneton 2017's parameterisation): x the distance to the top between
// its least and greatest value for the radius, y the radius through the distance to the horizon.

inline vec2 transmittanceLutUv(float r, float mu, IN(AtmosphereParams) A) {
    float H = sqrt(squareDifference(A.topRadius, A.bottomRadius));
    float rho = sqrt(max(squareDifference(r, A.bottomRadius), 0.0f));
    float d = distanceToTop(r, mu, A);
    float dMin = A.topRadius - r;
    float dMax = rho + H;
    return vec2((d - dMin) / max(dMax - dMin, 1e-3f), rho / H);
}

// The inverse: (r, mu) of a texel's uv.
inline vec2 transmittanceLutRMu(vec2 uv, IN(AtmosphereParams) A) {
    float H = sqrt(squareDifference(A.topRadius, A.bottomRadius));
    float rho = H * uv.y;
    float r = sqrt(rho * rho + A.bottomRadius * A.bottomRadius);
    float dMin = A.topRadius - r;
    float dMax = rho + H;
    float d = dMin + uv.x * (dMax - dMin);
    float mu = d <= 0.0f ? 1.0f : (H * H - rho * rho - d * d) / (2.0f * r * d);
    return vec2(r, clamp(mu, -1.0f, 1.0f));
}

// Optical depth from (r, mu) to the top by the midpoint rule: the table's texels. The table holds
// optical depth rather than transmittance: it varies smoothly where transmittance falls
// exponentially (near the horizon), so bilinear reads of it stay accurate.
inline vec3 opticalDepthToTop(float r, float mu, IN(AtmosphereParams) A) {
    float dt = distanceToTop(r, mu, A) / float(TRANSMITTANCE_STEPS);
    vec3 depth = vec3(0.0f);
    for (int i = 0; i < TRANSMITTANCE_STEPS; ++i) {
        vec2 p = alongRay(r, mu, (float(i) + 0.5f) * dt);
        depth += atmosphereAt(p.x - A.bottomRadius, A).extinction * dt;
    }
    return depth;
}

inline vec4 transmittanceLutTexel(ivec2 texel, IN(AtmosphereParams) A) {
    vec2 uv = (vec2(texel) + 0.5f) /
              vec2(float(TRANSMITTANCE_LUT_WIDTH), float(TRANSMITTANCE_LUT_HEIGHT));
    vec2 rMu = transmittanceLutRMu(uv, A);
    return vec4(opticalDepthToTop(rMu.x, rMu.y, A), 1.0f);
}

// Transmittance to the top along a ray that does not meet the ground, from the table.
inline vec3 transmittanceToTop(float r, float mu, IN(AtmosphereParams) A) {
    vec4 depth = lutBilinear(TRANSMITTANCE_LUT_OFFSET, TRANSMITTANCE_LUT_WIDTH,
                             TRANSMITTANCE_LUT_HEIGHT, transmittanceLutUv(r, mu, A));
    return exp(-vec3(depth.x, depth.y, depth.z));
}

// Refraction bends a ray that grazes the ground by about 2 x 34 arcminutes (the standard
// horizontal refraction, once on the way down to the tangent point and once up again), so the
// sun stays visible that far below the geometric horizon: from 8 km about 4 degrees below the
// horizontal instead of 2.9. It is the only refraction in the model (the straight-ray tables
// take the grazing value there).
CONST_FLOAT GRAZING_REFRACTION = 0.0198f; // radians; as a change of cosine at the horizon

// The sun's light at radius r with sun zenith cosine muS, per unit irradiance above the
// atmosphere: the transmittance, times the part of the disc above the (refracted) horizon: the
// planet's shadow, which reaches the low clouds before the high ones after sunset.
inline vec3 sunTransmittance(float r, float muS, float sunAngularRadius, IN(AtmosphereParams) A) {
    float muHorizon = horizonCosine(r, A);
    float muShadow = muHorizon - GRAZING_REFRACTION;
    float halfWidth = max(sunAngularRadius, 1e-4f); // smoothstep needs distinct edges
    float visible = smoothstep(muShadow - halfWidth, muShadow + halfWidth, muS);
    if (visible <= 0.0f) {
        return vec3(0.0f);
    }
    return transmittanceToTop(r, max(muS, muHorizon), A) * visible;
}

// ---- Multiple scattering (Hillaire 2020, section 5.5.2): at a radius and sun zenith cosine, the
// second-order light L2 and the transfer f_ms of an isotropic medium, integrated over the sphere
// of directions; psi_ms = L2 / (1 - f_ms) is the isotropic radiance of all orders >= 2 per unit
// scattering coefficient, added along every ray as sigma_s * psi_ms.

// The sun axis of the multiple-scattering and ambient tables: denser through twilight, where
// their values fall by orders of magnitude within a few degrees, after Bruneton and Neyret 2008's
// mapping x = (1 - exp(-k (muS - min))) / (1 - exp(-k (1 - min))), with x = 0 and 1 on the first
// and last texels' centres (so the overhead sun is a texel, not a clamped edge). min = -0.4 (the
// sun 23.6 degrees down, past astronomical twilight, where the tables are dark at every altitude:
// lower suns read it), k = 1.5: with 32 texels one every 1.6 degrees at -9 and 2.1 at the
// horizon, against 3.6 with muS linear, and 0.16 in muS at the zenith, where the light changes
// slowly.
CONST_FLOAT SUN_AXIS_MIN_COSINE = -0.4f;
CONST_FLOAT SUN_AXIS_STRETCH = 1.5f;

inline float sunAxisU(float muS, int size) {
    float k = SUN_AXIS_STRETCH;
    float lowest = SUN_AXIS_MIN_COSINE;
    float x =
        (1.0f - exp(-k * (clamp(muS, lowest, 1.0f) - lowest))) / (1.0f - exp(-k * (1.0f - lowest)));
    return (0.5f + x * float(size - 1)) / float(size);
}

inline float sunAxisMuS(float u, int size) {
    float k = SUN_AXIS_STRETCH;
    float lowest = SUN_AXIS_MIN_COSINE;
    float x = clamp((u * float(size) - 0.5f) / float(size - 1), 0.0f, 1.0f);
    return lowest - log(1.0f - x * (1.0f - exp(-k * (1.0f - lowest)))) / k;
}

inline vec2 multiScatterLutRMuS(vec2 uv, IN(AtmosphereParams) A) {
    float r = A.bottomRadius + max(uv.y * (A.topRadius - A.bottomRadius), 1.0f);
    return vec2(r, sunAxisMuS(uv.x, MULTISCATTER_LUT_SIZE));
}

inline vec2 multiScatterLutUv(float r, float muS, IN(AtmosphereParams) A) {
    return vec2(sunAxisU(muS, MULTISCATTER_LUT_SIZE),
                (r - A.bottomRadius) / (A.topRadius - A.bottomRadius));
}

inline vec3 multipleScattering(float r, float muS, IN(AtmosphereParams) A) {
    vec4 t = lutBilinear(MULTISCATTER_LUT_OFFSET, MULTISCATTER_LUT_SIZE, MULTISCATTER_LUT_SIZE,
                         multiScatterLutUv(r, muS, A));
    return vec3(t.x, t.y, t.z);
}

// Where a ray from (r, mu) leaves the atmosphere or meets the ground: (length, 1 if ground).
inline vec2 rayExtent(float r, float mu, IN(AtmosphereParams) A) {
    float ground = distanceToGround(r, mu, A);
    if (ground >= 0.0f) {
        return vec2(ground, 1.0f);
    }
    return vec2(distanceToTop(r, mu, A), 0.0f);
}

struct ScatteredLight {
    vec3 radiance;      // in-scattered along the ray, per unit sun irradiance
    vec3 transmittance; // along the ray
    vec3 transfer;      // multiple-scattering table only: f_ms along the ray (isotropic)
};

// Light scattered toward the start of a ray from (r, viewDir) over [0, rayLength], through
// `steps` midpoint steps with the energy-conserving step integral (Hillaire 2015): single
// scattering of the sun with the Rayleigh and Mie phase functions (or isotropic with
// `isotropic`, for the multiple-scattering table), plus, unless `isotropic`, multiple scattering
// from the table; a ray that ends on the ground adds the sunlit ground (Lambertian).
inline ScatteredLight scatterAlongRay(float r, vec3 viewDir, vec3 sunDir, float rayLength,
                                      bool hitsGround, int steps, bool isotropic,
                                      float sunAngularRadius, IN(AtmosphereParams) A) {
    ScatteredLight s;
    s.radiance = vec3(0.0f);
    s.transmittance = vec3(1.0f);
    s.transfer = vec3(0.0f);
    float cosTheta = dot(viewDir, sunDir);
    float phaseR = isotropic ? 1.0f / (4.0f * PI) : rayleighPhase(cosTheta);
    float phaseM = isotropic ? 1.0f / (4.0f * PI) : miePhase(cosTheta, A.mieG);
    float dt = rayLength / float(max(steps, 1));
    vec3 origin = vec3(0.0f, r, 0.0f);
    for (int i = 0; i < steps; ++i) {
        vec3 p = origin + viewDir * ((float(i) + 0.5f) * dt);
        float rp = length(p);
        vec3 up = p / rp;
        // Air below the ground is taken as the ground's: only the aerial-perspective volume's
        // rows below the horizon reach there (past where their own ray meets the ground), and
        // they must continue smoothly for the rows near the horizon to interpolate.
        rp = max(rp, A.bottomRadius);
        float muS = dot(up, sunDir);
        AtmosphereSample m = atmosphereAt(rp - A.bottomRadius, A);
        vec3 sun = sunTransmittance(rp, muS, sunAngularRadius, A);
        vec3 scattering = m.rayleighScattering * phaseR + m.mieScattering * phaseM;
        vec3 source = scattering * sun;
        if (!isotropic) {
            source += (m.rayleighScattering + m.mieScattering) * multipleScattering(rp, muS, A);
        }
        vec3 stepT = exp(-m.extinction * dt);
        vec3 safe = max(m.extinction, vec3(1e-12f));
        vec3 integral = (vec3(1.0f) - stepT) / safe;
        s.radiance += s.transmittance * source * integral;
        s.transfer += s.transmittance * (m.rayleighScattering + m.mieScattering) * integral;
        s.transmittance *= stepT;
    }
    if (hitsGround) {
        vec3 p = origin + viewDir * rayLength;
        vec3 up = normalize(p);
        float muS = dot(up, sunDir);
        vec3 sun = sunTransmittance(A.bottomRadius, muS, sunAngularRadius, A);
        s.radiance += s.transmittance * sun * (max(muS, 0.0f) / PI) * A.groundAlbedo;
    }
    return s;
}

// The multiple-scattering table's texel: 64 directions uniform over the sphere.
inline vec4 multiScatterLutTexel(ivec2 texel, IN(AtmosphereParams) A) {
    vec2 uv = (vec2(texel) + 0.5f) / float(MULTISCATTER_LUT_SIZE);
    vec2 rMuS = multiScatterLutRMuS(uv, A);
    float r = rMuS.x;
    vec3 sunDir = vec3(sqrt(max(1.0f - rMuS.y * rMuS.y, 0.0f)), rMuS.y, 0.0f);
    vec3 secondOrder = vec3(0.0f);
    vec3 transfer = vec3(0.0f);
    const int n = 8;
    for (int i = 0; i < n; ++i) {
        float cosZenith = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
        float sinZenith = sqrt(max(1.0f - cosZenith * cosZenith, 0.0f));
        for (int j = 0; j < n; ++j) {
            float phi = 2.0f * PI * (float(j) + 0.5f) / float(n);
            vec3 dir = vec3(sinZenith * cos(phi), cosZenith, sinZenith * sin(phi));
            vec2 extent = rayExtent(r, cosZenith, A);
            ScatteredLight s = scatterAlongRay(r, dir, sunDir, extent.x, extent.y > 0.5f,
                                               MULTISCATTER_STEPS, true, 0.0f, A);
            secondOrder += s.radiance;
            transfer += s.transfer;
        }
    }
    float count = float(n * n);
    secondOrder /= count;
    // The integrals over the sphere with the isotropic phase 1/(4 pi): means over directions.
    transfer /= count;
    return vec4(secondOrder / (vec3(1.0f) - min(transfer, vec3(0.99f))), 1.0f);
}

// ---- The sky seen from the camera (Hillaire 2020, section 5.3): x the azimuth from the sun,
// denser near it; y the view zenith, the horizon at 0.5 and denser near it.

inline vec2 skyViewLutZenithAndCosAzimuth(vec2 uv, float r, IN(AtmosphereParams) A) {
    float cosBeta = sqrt(max(squareDifference(r, A.bottomRadius), 0.0f)) / r;
    float beta = acos(clamp(cosBeta, -1.0f, 1.0f));
    float zenithHorizon = PI - beta;
    float zenith;
    if (uv.y < 0.5f) {
        float c = 1.0f - 2.0f * uv.y;
        zenith = zenithHorizon * (1.0f - c * c);
    } else {
        float c = uv.y * 2.0f - 1.0f;
        zenith = zenithHorizon + beta * c * c;
    }
    float cosAzimuth = -((uv.x * uv.x) * 2.0f - 1.0f);
    return vec2(zenith, cosAzimuth);
}

inline vec2 skyViewLutUv(float r, float viewZenith, float cosAzimuth, IN(AtmosphereParams) A) {
    float cosBeta = sqrt(max(squareDifference(r, A.bottomRadius), 0.0f)) / r;
    float beta = acos(clamp(cosBeta, -1.0f, 1.0f));
    float zenithHorizon = PI - beta;
    float v;
    if (viewZenith < zenithHorizon) {
        float c = 1.0f - viewZenith / zenithHorizon;
        v = (1.0f - sqrt(max(c, 0.0f))) * 0.5f;
    } else {
        float c = (viewZenith - zenithHorizon) / max(beta, 1e-6f);
        v = sqrt(max(c, 0.0f)) * 0.5f + 0.5f;
    }
    float u = sqrt(max(-cosAzimuth * 0.5f + 0.5f, 0.0f));
    return vec2(u, v);
}

// The sky-view table is made for the camera's radius, A.skyViewRadius (the camera above the top
// of the atmosphere sees it from the top).
inline float skyViewRadius(IN(AtmosphereParams) A) {
    return min(A.skyViewRadius, A.topRadius - 1.0f);
}

// The view direction at a sky-view (u, v), in the frame where the source lies at azimuth 0
// (x toward it, z sideways); the aerial-perspective volume shares it.
inline vec3 skyViewDirection(vec2 uv, IN(AtmosphereParams) A) {
    vec2 za = skyViewLutZenithAndCosAzimuth(uv, skyViewRadius(A), A);
    float sinView = sin(za.x);
    float sinAzimuth = sqrt(max(1.0f - za.y * za.y, 0.0f));
    return vec3(sinView * za.y, cos(za.x), sinView * sinAzimuth);
}

// A source at zenith cosine muS in that frame.
inline vec3 sourceAtAzimuthZero(float muS) {
    return vec3(sqrt(max(1.0f - muS * muS, 0.0f)), muS, 0.0f);
}

inline vec4 skyViewLutTexel(ivec2 texel, vec3 sunDir, float sunAngularRadius,
                            IN(AtmosphereParams) A) {
    vec2 uv = (vec2(texel) + 0.5f) / vec2(float(SKYVIEW_LUT_WIDTH), float(SKYVIEW_LUT_HEIGHT));
    float r = skyViewRadius(A);
    vec3 dir = skyViewDirection(uv, A);
    vec2 extent = rayExtent(r, dir.y, A);
    ScatteredLight s = scatterAlongRay(r, dir, sourceAtAzimuthZero(sunDir.y), extent.x,
                                       extent.y > 0.5f, SKYVIEW_STEPS, false, sunAngularRadius, A);
    return vec4(s.radiance, 1.0f);
}

// ---- The aerial-perspective volume (Hillaire 2020, section 5.5, indexed by direction rather
// than by the camera's frustum): the light the air scatters toward the camera over a distance
// along a view direction, per unit source irradiance, and the air's transmittance over it, from
// the camera's altitude. Hillaire's volume follows the frustum and is remade every frame; this one
// holds every direction, like the sky-view table it shares its (azimuth, zenith) mapping with, so
// it is remade only with that table (the sun's elevation, the camera's altitude, an atmosphere
// key) and any pixel of any pass, reprojected or not, reads it. Slice z (0-based) lies at
// reach * ((z + 1) / depth)^2, denser near the camera where the air changes fastest; distance 0
// has no air. The reach is the longest path through the atmosphere from the camera's radius (a
// ray grazing the ground), so every distance along every ray lies within the volume.

inline float aerialLutReach(IN(AtmosphereParams) A) {
    float r = skyViewRadius(A);
    return sqrt(max(squareDifference(r, A.bottomRadius), 0.0f)) +
           sqrt(squareDifference(A.topRadius, A.bottomRadius));
}

// The continuous slice coordinate of a distance: -1 at 0, z at slice z's distance.
inline float aerialLutSlice(float distance, IN(AtmosphereParams) A) {
    return pow(max(distance, 0.0f) / aerialLutReach(A), 1.0f / 3.0f) * float(AERIAL_LUT_DEPTH) -
           1.0f;
}

inline float aerialLutSliceDistance(int slice, IN(AtmosphereParams) A) {
    float s = float(slice + 1) / float(AERIAL_LUT_DEPTH);
    return aerialLutReach(A) * s * s * s;
}

// A texel's view direction (in the frame where the source lies at azimuth 0) and distance.
inline vec4 aerialLutRay(ivec3 texel, IN(AtmosphereParams) A) {
    vec2 uv =
        (vec2(texel.x, texel.y) + 0.5f) / vec2(float(AERIAL_LUT_WIDTH), float(AERIAL_LUT_HEIGHT));
    vec3 dir = skyViewDirection(uv, A);
    float reach = distanceToTop(skyViewRadius(A), dir.y, A);
    return vec4(dir, min(aerialLutSliceDistance(texel.z, A), reach));
}

// The volume's transmittance texel: the extinction part of aerialLutTexel's integral alone
// (the same steps, so the same values), which reads no table.
inline vec3 aerialLutTransmittance(ivec3 texel, IN(AtmosphereParams) A) {
    vec4 ray = aerialLutRay(texel, A);
    vec3 origin = vec3(0.0f, skyViewRadius(A), 0.0f);
    float dt = ray.w / float(AERIAL_LUT_STEPS);
    vec3 transmittance = vec3(1.0f);
    for (int i = 0; i < AERIAL_LUT_STEPS; ++i) {
        vec3 p = origin + vec3(ray.x, ray.y, ray.z) * ((float(i) + 0.5f) * dt);
        float rp = max(length(p), A.bottomRadius); // as scatterAlongRay below the ground
        transmittance *= exp(-atmosphereAt(rp - A.bottomRadius, A).extinction * dt);
    }
    return transmittance;
}

// A texel of the volume for a source at sourceDir (its zenith cosine is what matters): the air's
// light (per unit irradiance) and its transmittance up to the slice's distance, or to where the
// ray leaves the atmosphere or meets the ground if that is nearer (the ground's own light is not
// the air's).
inline ScatteredLight aerialLutTexel(ivec3 texel, vec3 sourceDir, float sourceAngularRadius,
                                     IN(AtmosphereParams) A) {
    vec4 ray = aerialLutRay(texel, A);
    return scatterAlongRay(skyViewRadius(A), vec3(ray.x, ray.y, ray.z),
                           sourceAtAzimuthZero(sourceDir.y), ray.w, false, AERIAL_LUT_STEPS, false,
                           sourceAngularRadius, A);
}

// The volume at `offset` read at a direction's (u, v) and a continuous slice: bilinear in each of
// the two slices around it, linear between them; before the first slice, linear from `atZero`
// (the value at distance 0).
inline vec4 aerialLutRead(int offset, vec2 uv, float slice, vec4 atZero) {
    float z = clamp(slice, -1.0f, float(AERIAL_LUT_DEPTH - 1));
    int z0 = int(floor(z));
    float f = z - float(z0);
    int sliceTexels = AERIAL_LUT_WIDTH * AERIAL_LUT_HEIGHT;
    vec4 near =
        z0 < 0 ? atZero
               : lutBilinear(offset + z0 * sliceTexels, AERIAL_LUT_WIDTH, AERIAL_LUT_HEIGHT, uv);
    if (f <= 0.0f) {
        return near;
    }
    vec4 far = lutBilinear(offset + min(z0 + 1, AERIAL_LUT_DEPTH - 1) * sliceTexels,
                           AERIAL_LUT_WIDTH, AERIAL_LUT_HEIGHT, uv);
    return mix(near, far, f);
}

// ---- Ambient light of a point in the atmosphere (for the clouds): the mean radiance of the upper
// hemisphere (cosine-weighted, i.e. irradiance / pi) and of the lower one, per unit sun
// irradiance, at a radius and sun zenith cosine (sunAxisU). y is the square root of the altitude
// fraction, so the cloud layers (1-10 km) get a third of the rows.

inline vec2 ambientLutRMuS(vec2 uv, IN(AtmosphereParams) A) {
    float r = A.bottomRadius + max(uv.y * uv.y * (A.topRadius - A.bottomRadius), 1.0f);
    return vec2(r, sunAxisMuS(uv.x, AMBIENT_LUT_SIZE));
}

inline vec2 ambientLutUv(float r, float muS, IN(AtmosphereParams) A) {
    float f = clamp((r - A.bottomRadius) / (A.topRadius - A.bottomRadius), 0.0f, 1.0f);
    return vec2(sunAxisU(muS, AMBIENT_LUT_SIZE), sqrt(f));
}

inline vec4 ambientLutTexel(ivec2 texel, bool below, float sunAngularRadius,
                            IN(AtmosphereParams) A) {
    vec2 uv = (vec2(texel) + 0.5f) / float(AMBIENT_LUT_SIZE);
    vec2 rMuS = ambientLutRMuS(uv, A);
    float r = rMuS.x;
    vec3 sunDir = vec3(sqrt(max(1.0f - rMuS.y * rMuS.y, 0.0f)), rMuS.y, 0.0f);
    vec3 sum = vec3(0.0f);
    const int n = 8;
    for (int i = 0; i < n; ++i) {
        // Cosine-weighted: cos(zenith) = sqrt(u) over u uniform.
        float cosZenith = sqrt((float(i) + 0.5f) / float(n));
        float mu = below ? -cosZenith : cosZenith;
        float sinZenith = sqrt(max(1.0f - cosZenith * cosZenith, 0.0f));
        for (int j = 0; j < n; ++j) {
            float phi = 2.0f * PI * (float(j) + 0.5f) / float(n);
            vec3 dir = vec3(sinZenith * cos(phi), mu, sinZenith * sin(phi));
            vec2 extent = rayExtent(r, mu, A);
            ScatteredLight s = scatterAlongRay(r, dir, sunDir, extent.x, extent.y > 0.5f,
                                               AMBIENT_STEPS, false, sunAngularRadius, A);
            sum += s.radiance;
        }
    }
    return vec4(sum / float(n * n), 1.0f);
}

// ---- The tables as one list, in the order they are made: each reads only those before it
// (multiple scattering reads the transmittance; the sky views and the ambient read both). The
// host's fill (src/core/atmosphere_luts.cpp) and the device's (atmosphere_tables.comp) walk this
// list, so both make the same texels with the same functions.
CONST_INT ATMOSPHERE_TABLE_TRANSMITTANCE = 0;
CONST_INT ATMOSPHERE_TABLE_MULTISCATTER = 1;
CONST_INT ATMOSPHERE_TABLE_SKYVIEW = 2;
CONST_INT ATMOSPHERE_TABLE_AMBIENT_ABOVE = 3;
CONST_INT ATMOSPHERE_TABLE_AMBIENT_BELOW = 4;
CONST_INT ATMOSPHERE_TABLE_MOON_SKYVIEW = 5;
CONST_INT ATMOSPHERE_TABLE_AERIAL_SCATTER = 6; // the volume's slices stacked: y = z * height + y
CONST_INT ATMOSPHERE_TABLE_AERIAL_TRANSMITTANCE = 7;
CONST_INT ATMOSPHERE_TABLE_MOON_AERIAL_SCATTER = 8;
CONST_INT ATMOSPHERE_TABLE_COUNT = 9;

// The moon's tables: zero while the moon is off.
inline bool atmosphereTableIsMoons(int table) {
    return table == ATMOSPHERE_TABLE_MOON_SKYVIEW || table == ATMOSPHERE_TABLE_MOON_AERIAL_SCATTER;
}

// A table's first texel in the buffer (x), width (y) and height (z).
inline ivec3 atmosphereTableLayout(int table) {
    if (table == ATMOSPHERE_TABLE_TRANSMITTANCE) {
        return ivec3(TRANSMITTANCE_LUT_OFFSET, TRANSMITTANCE_LUT_WIDTH, TRANSMITTANCE_LUT_HEIGHT);
    }
    if (table == ATMOSPHERE_TABLE_MULTISCATTER) {
        return ivec3(MULTISCATTER_LUT_OFFSET, MULTISCATTER_LUT_SIZE, MULTISCATTER_LUT_SIZE);
    }
    if (table == ATMOSPHERE_TABLE_SKYVIEW) {
        return ivec3(SKYVIEW_LUT_OFFSET, SKYVIEW_LUT_WIDTH, SKYVIEW_LUT_HEIGHT);
    }
    if (table == ATMOSPHERE_TABLE_AMBIENT_ABOVE) {
        return ivec3(AMBIENT_ABOVE_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE);
    }
    if (table == ATMOSPHERE_TABLE_AMBIENT_BELOW) {
        return ivec3(AMBIENT_BELOW_LUT_OFFSET, AMBIENT_LUT_SIZE, AMBIENT_LUT_SIZE);
    }
    if (table == ATMOSPHERE_TABLE_MOON_SKYVIEW) {
        return ivec3(MOON_SKYVIEW_LUT_OFFSET, SKYVIEW_LUT_WIDTH, SKYVIEW_LUT_HEIGHT);
    }
    int offset = table == ATMOSPHERE_TABLE_AERIAL_SCATTER         ? AERIAL_SCATTER_LUT_OFFSET
                 : table == ATMOSPHERE_TABLE_AERIAL_TRANSMITTANCE ? AERIAL_TRANSMITTANCE_LUT_OFFSET
                                                                  : MOON_AERIAL_SCATTER_LUT_OFFSET;
    return ivec3(offset, AERIAL_LUT_WIDTH, AERIAL_LUT_HEIGHT * AERIAL_LUT_DEPTH);
}

// A texel of a table for the sky's atmosphere, sun and moon; the moon's sky view is zero while
// the moon is off (its readers skip it then, and zero keeps a day's buffer what it was).
inline vec4 atmosphereTableTexel(int table, ivec2 texel, IN(SkyParams) S) {
    if (table == ATMOSPHERE_TABLE_TRANSMITTANCE) {
        return transmittanceLutTexel(texel, S.atmosphere);
    }
    if (table == ATMOSPHERE_TABLE_MULTISCATTER) {
        return multiScatterLutTexel(texel, S.atmosphere);
    }
    if (table == ATMOSPHERE_TABLE_SKYVIEW) {
        return skyViewLutTexel(texel, S.sunDirection, S.sunAngularRadius, S.atmosphere);
    }
    if (table == ATMOSPHERE_TABLE_AMBIENT_ABOVE || table == ATMOSPHERE_TABLE_AMBIENT_BELOW) {
        return ambientLutTexel(texel, table == ATMOSPHERE_TABLE_AMBIENT_BELOW, S.sunAngularRadius,
                               S.atmosphere);
    }
    if (atmosphereTableIsMoons(table) && S.moonEnabled == 0) {
        return vec4(0.0f);
    }
    if (table == ATMOSPHERE_TABLE_MOON_SKYVIEW) {
        return skyViewLutTexel(texel, S.moonDirection, S.moonAngularRadius, S.atmosphere);
    }
    ivec3 volumeTexel = ivec3(texel.x, texel.y % AERIAL_LUT_HEIGHT, texel.y / AERIAL_LUT_HEIGHT);
    if (table == ATMOSPHERE_TABLE_AERIAL_TRANSMITTANCE) {
        return vec4(aerialLutTransmittance(volumeTexel, S.atmosphere), 1.0f);
    }
    bool moon = table == ATMOSPHERE_TABLE_MOON_AERIAL_SCATTER;
    ScatteredLight air =
        aerialLutTexel(volumeTexel, moon ? S.moonDirection : S.sunDirection,
                       moon ? S.moonAngularRadius : S.sunAngularRadius, S.atmosphere);
    return vec4(air.radiance, 1.0f);
}

#ifdef __cplusplus
} // namespace cloudscape::model
#endif

#endif
