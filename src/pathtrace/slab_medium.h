#pragma once
// A homogeneous box of medium: with a large width it is the plane-parallel slab of the radiative
// transfer literature, which is how the path tracer is validated against published tables.
#include "model/phase.glsl.h"
#include "pathtrace/tracking.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace cloudscape::pathtrace {

struct BoxMedium {
    glm::vec3 lower{-1.0f};
    glm::vec3 upper{1.0f};
    float sigma = 1.0f; // extinction (1/m)
    float singleScatteringAlbedo = 1.0f;
    // Majorant reported to the trackers, as a multiple of sigma: 1 is exact; the tests use
    // more to exercise null collisions (each then has probability 1 - 1/scale).
    float majorantScale = 1.0f;
    model::PhaseFunction phaseFunction =
        model::makePhaseFunction(model::PHASE_ISOTROPIC, glm::vec4(0.0f));

    float sigmaT(glm::vec3) const { return sigma; }
    float albedo() const { return singleScatteringAlbedo; }
    model::PhaseFunction phase() const { return phaseFunction; }

    // The ray's interval inside the box (the slab test), clipped to [0, tMax].
    template <class Visit>
    void forEachSegment(glm::vec3 origin, glm::vec3 dir, float tMax, Visit&& visit) const {
        float t0 = 0.0f;
        float t1 = tMax;
        for (int axis = 0; axis < 3; ++axis) {
            if (dir[axis] == 0.0f) {
                if (origin[axis] < lower[axis] || origin[axis] > upper[axis])
                    return;
                continue;
            }
            const float inv = 1.0f / dir[axis];
            float a = (lower[axis] - origin[axis]) * inv;
            float b = (upper[axis] - origin[axis]) * inv;
            if (a > b)
                std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        if (t1 > t0)
            visit(t0, t1, sigma * majorantScale);
    }
};

} // namespace cloudscape::pathtrace
