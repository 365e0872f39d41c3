#pragma once
// The atmosphere as a participating medium for the path tracer, one colour channel at a time: the
// model's own Rayleigh, Mie and ozone coefficients (model::atmosphereAt, the same constants and
// keys as the real-time tables), in a spherical shell from the ground to the top of the
// atmosphere. The path tracer is RGB like the model: each of the three channels is a wavelength
// with its own coefficients, traced separately (a path carries one channel).
//
// Geometry is in double precision about the planet's centre: at planet scale a float position
// is only good to half a metre, which moves the Mie coefficient at the ground by 4e-4.
//
// Bounds: along a ray the exponential profiles are largest at the lowest altitude of a piece,
// which is its end nearest the planet's centre (or the ray's closest approach, if it falls
// inside the piece), and smallest at its highest end; the ozone tent is largest at the altitude
// of its peak, or at the end of the piece's altitude range nearest it, and smallest at one of
// the range's ends. The upper bound is delta tracking's majorant, the lower one residual ratio
// tracking's control. The ray is cut into at most kPieces pieces so that both stay tight where
// the density changes quickly.
#include "model/atmosphere.glsl.h"
#include "pathtrace/random.h"
#include "pathtrace/tracking.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace cloudscape::pathtrace {

// Counts of control values above sigma_t (which would bias residual ratio tracking); the tests
// check it stays zero.
inline std::atomic<uint64_t>& minorantViolations() {
    static std::atomic<uint64_t> count{0};
    return count;
}

class AtmosphereMedium {
public:
    AtmosphereMedium(const model::AtmosphereParams& atmosphere, int channel)
        : a_(atmosphere), channel_(channel) {}

    struct Coefficients {
        float rayleigh = 0.0f;   // scattering, 1/m
        float mie = 0.0f;        // scattering, 1/m
        float extinction = 0.0f; // 1/m, with Mie and ozone absorption
    };

    // At a point relative to the planet's centre.
    Coefficients at(glm::dvec3 p) const {
        const model::AtmosphereSample s = model::atmosphereAt(altitude(p), a_);
        return {s.rayleighScattering[channel_], s.mieScattering[channel_], s.extinction[channel_]};
    }
    float sigmaT(glm::dvec3 p) const { return at(p).extinction; }

    float altitude(glm::dvec3 p) const {
        return static_cast<float>(glm::length(p) - double(a_.bottomRadius));
    }
    double bottomRadius() const { return a_.bottomRadius; }
    double topRadius() const { return a_.topRadius; }
    float groundAlbedo() const { return a_.groundAlbedo[channel_]; }
    float mieG() const { return a_.mieG; }
    int channel() const { return channel_; }

    // Distance along a unit ray from p (inside the atmosphere) to where it leaves it, and whether
    // that is the ground.
    struct Exit {
        double distance = 0.0;
        bool ground = false;
    };
    Exit exit(glm::dvec3 p, glm::dvec3 dir) const {
        const double b = glm::dot(p, dir);
        const double pp = glm::dot(p, p);
        const double R = a_.bottomRadius;
        const double discGround = b * b - (pp - R * R);
        if (b < 0.0 && discGround > 0.0) {
            const double t = -b - std::sqrt(discGround);
            if (t > 0.0)
                return {t, true};
        }
        const double top = a_.topRadius;
        const double discTop = b * b - (pp - top * top);
        return {std::max(0.0, -b + std::sqrt(std::max(discTop, 0.0))), false};
    }

    // Bounds on sigma_t over the piece [t0, t1] of the ray from p along dir: below (the control
    // of residual ratio tracking) and above (the majorant).
    struct Bounds {
        float lower = 0.0f;
        float upper = 0.0f;
    };
    Bounds bounds(glm::dvec3 p, glm::dvec3 dir, double t0, double t1) const {
        const double closest = std::clamp(-glm::dot(p, dir), t0, t1);
        const double r0 = glm::length(p + dir * t0);
        const double r1 = glm::length(p + dir * t1);
        const double rLow = glm::length(p + dir * closest);
        const double R = a_.bottomRadius;
        // A metre of margin for the float altitudes sigmaT sees.
        const float low = static_cast<float>(std::max(rLow - R - 1.0, 0.0));
        const float high = static_cast<float>(std::max(r0, r1) - R + 1.0);
        // The tent is concave: largest at its peak (or the nearest end of the altitude range),
        // smallest at one of the range's ends.
        const float peak = std::clamp(a_.ozoneCentre, low, high);
        const float tentMax = tent(peak);
        const float tentMin = std::min(tent(low), tent(high));
        const float ozone = a_.ozoneAbsorption[channel_];
        Bounds b;
        b.upper = (exponentials(low) + ozone * tentMax) * 1.0001f;
        b.lower = (exponentials(high) + ozone * tentMin) * 0.9999f;
        return b;
    }

    // Calls visit(t0, t1, bounds) for the pieces of [0, tMax] front to back until it returns
    // true.
    template <class Visit>
    void forEachPiece(glm::dvec3 p, glm::dvec3 dir, double tMax, Visit&& visit) const {
        const double length = std::max(tMax / kPieces, kMinPieceMetres);
        for (double t0 = 0.0; t0 < tMax; t0 += length) {
            const double t1 = std::min(t0 + length, tMax);
            if (visit(t0, t1, bounds(p, dir, t0, t1)))
                return;
        }
    }

    static constexpr double kPieces = 64.0;
    static constexpr double kMinPieceMetres = 500.0;

private:
    float tent(float altitude) const {
        return std::max(0.0f, 1.0f - std::abs(altitude - a_.ozoneCentre) / a_.ozoneHalfWidth);
    }
    // Rayleigh scattering and Mie extinction, as model::atmosphereAt has them.
    float exponentials(float altitude) const {
        return a_.rayleighScattering[channel_] * std::exp(-altitude / a_.rayleighScaleHeight) +
               a_.mieExtinction * std::exp(-altitude / a_.mieScaleHeight);
    }

    model::AtmosphereParams a_;
    int channel_ = 0;
};

// Delta tracking: the distance to the first real collision along the ray in [0, tMax], or a
// negative value if there is none.
inline double sampleAtmosphereCollision(const AtmosphereMedium& medium, glm::dvec3 p,
                                        glm::dvec3 dir, double tMax, Random& random) {
    double hit = -1.0;
    medium.forEachPiece(p, dir, tMax, [&](double t0, double t1, AtmosphereMedium::Bounds b) {
        const float majorant = b.upper;
        double t = t0;
        while (true) {
            t -= std::log(1.0 - double(random.uniform())) / double(majorant);
            if (t >= t1)
                return false; // memoryless: continue in the next piece
            const float sigma = medium.sigmaT(p + dir * t);
            checkMajorant(sigma, majorant);
            if (random.uniform() * majorant < sigma) {
                hit = t;
                return true;
            }
        }
    });
    return hit;
}

// Residual ratio tracking (Novak et al. 2014): the transmittance along the ray over [0, tMax] as
// exp(-control optical depth), known exactly piece by piece, times ratio tracking of the residual
// sigma_t - control against majorant - control. Plain ratio tracking has a relative variance of
// about exp(tau) - 1 with a tight majorant (23 % per sample for the zenith in red); the residual's
// optical depth is a small part of tau, and its majorant is kResidualScale times the bound, which
// divides what is left of the variance by about that factor for as many more (cheap) tentative
// collisions. No Russian roulette: the control's part is exact, and a
// low sun's small transmittance is the answer, not a path to cut short.
constexpr double kResidualScale = 8.0;

inline float estimateAtmosphereTransmittance(const AtmosphereMedium& medium, glm::dvec3 p,
                                             glm::dvec3 dir, double tMax, Random& random) {
    double transmittance = 1.0;
    medium.forEachPiece(p, dir, tMax, [&](double t0, double t1, AtmosphereMedium::Bounds b) {
        transmittance *= std::exp(-double(b.lower) * (t1 - t0));
        const double residualMajorant = kResidualScale * (double(b.upper) - double(b.lower));
        if (residualMajorant > 0.0) {
            double t = t0;
            while (true) {
                t -= std::log(1.0 - double(random.uniform())) / residualMajorant;
                if (t >= t1)
                    break;
                const float sigma = medium.sigmaT(p + dir * t);
                checkMajorant(sigma, b.upper);
                if (sigma < b.lower)
                    minorantViolations().fetch_add(1, std::memory_order_relaxed);
                transmittance *=
                    std::clamp(1.0 - (double(sigma) - b.lower) / residualMajorant, 0.0, 1.0);
                if (transmittance <= 0.0)
                    return true;
            }
        }
        return false;
    });
    return static_cast<float>(transmittance);
}

} // namespace cloudscape::pathtrace
