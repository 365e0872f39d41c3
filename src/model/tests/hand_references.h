#pragma once
// Expectations written out by hand from the sources the model follows, shared by the CPU tests
// and the GPU model checks (src/vulkan/tests/model_checks_test.cpp). Nothing here calls the model:
// each is the published formula or the scene keys' documented meaning, in double precision.
#include <cloudscape/scene.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace cloudscape::hand {

// Henyey-Greenstein, normalised over the sphere.
inline double hg(double cosTheta, double g) {
    return (1.0 - g * g) /
           (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// Beer's-Powder factor 2 (1 - e^-2d) (GPU Pro 7 4.4.4), faded from full strength with the sun
// behind the viewer (cos -1) to none looking into it (cos 1).
inline double powder(double depth, double cosTheta, double strength) {
    const double fade = std::clamp(0.5 - 0.5 * cosTheta, 0.0, 1.0);
    return 1.0 + (2.0 * (1.0 - std::exp(-2.0 * depth)) - 1.0) * strength * fade;
}

// Wrenninge's octaves over the two-lobe phase: sum over i of a^i phase(g c^i) e^(-depth b^i),
// times the powder factor. For scenes with lighting.phase = two-lobe.
inline double octaves(const Scene& s, double depth, double cosTheta) {
    double sum = 0.0;
    for (int i = 0; i < s.scatteringOctaves; ++i) {
        const double a = std::pow(s.octaveFactors.x, i);
        const double b = std::pow(s.octaveFactors.y, i);
        const double c = std::pow(s.octaveFactors.z, i);
        const double phase = (1.0 - s.silverWeight) * hg(cosTheta, s.phaseG * c) +
                             s.silverWeight * hg(cosTheta, s.silverG * c);
        sum += a * phase * std::exp(-depth * b);
    }
    return sum * powder(depth, cosTheta, s.powder);
}

// How far the cloud field moves in dt seconds: wind.speed_mps toward wind.heading_deg (clockwise
// from north, +z, toward east, +x), rising at wind.updraft times the speed.
inline glm::dvec3 windDrift(const Scene& s, double dt) {
    const double h = s.windHeadingDeg * std::numbers::pi / 180.0;
    return glm::dvec3(std::sin(h), s.updraft, std::cos(h)) * (double(s.windSpeedMps) * dt);
}

// A level pinhole camera looking north (+z): right is east (+x), up is +y. Pixel centres at
// integers, vertical field of view fovDeg.
struct NorthCamera {
    double width, height, tanHalfFov;
    glm::dvec3 position;

    explicit NorthCamera(const Scene& s)
        : width(s.width), height(s.height),
          tanHalfFov(std::tan(s.cameraFovDeg * std::numbers::pi / 360.0)),
          position(s.cameraPosition) {}

    glm::dvec3 ray(double x, double y) const {
        const double sx = ((x + 0.5) / width * 2.0 - 1.0) * tanHalfFov * (width / height);
        const double sy = (1.0 - (y + 0.5) / height * 2.0) * tanHalfFov;
        return glm::normalize(glm::dvec3(sx, sy, 1.0));
    }
    glm::dvec2 project(glm::dvec3 world) const {
        const glm::dvec3 v = world - position;
        const double sx = v.x / v.z / (tanHalfFov * width / height);
        const double sy = v.y / v.z / tanHalfFov;
        return {(sx + 1.0) * 0.5 * width - 0.5, (1.0 - sy) * 0.5 * height - 0.5};
    }
};

// The light cone of GPU Pro 7 4.5.3: sample i (0-based) of n sits stepPosition of the way along
// light step i toward the sun (we take the middle, 0.5), offset sideways by kernel[i mod 6]
// times the cone spread times the step length times i, so the cone widens away from the point;
// each weighs one step. The long-distance sample sits at longSampleDistance cone lengths and
// weighs one cone length.
struct ConeSample {
    glm::dvec3 position;
    double weight; // metres of path it stands for
    bool longSample;
};
template <class Kernel>
std::vector<ConeSample> coneSamples(const Scene& s, glm::dvec3 sun, glm::dvec3 p, Kernel kernel,
                                    double stepPosition = 0.5) {
    std::vector<ConeSample> out;
    const double step = s.coneLengthM / s.lightSamples;
    const double spread = s.coneSpread * step;
    for (int i = 0; i < s.lightSamples; ++i)
        out.push_back(
            {p + sun * (step * (i + stepPosition)) + glm::dvec3(kernel(i % 6)) * (spread * i), step,
             false});
    if (s.longSample)
        out.push_back({p + sun * (double(s.coneLengthM) * s.longSampleDistance),
                       double(s.coneLengthM), true});
    return out;
}

} // namespace cloudscape::hand
