#pragma once
// The clouds as a participating medium for the path tracer: extinction from the shared model's
// density function (the very code the real-time march samples), over a majorant grid that is an
// upper bound by construction, not by sampling.
//
// Why the bound holds: model/cloud_bound.glsl.h (columnCloudBound), over the texels a cell's
// bilinear footprint touches.
#include "model/density.glsl.h"
#include "model/params.glsl.h"
#include "model/phase.glsl.h"
#include "model/shell.glsl.h"
#include "pathtrace/tracking.h"

#include <cloudscape/texture.h>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace cloudscape::pathtrace {

class CloudMedium {
public:
    // The textures must be bound to every thread that calls sigmaT (cpu::ScopedTextureBinding).
    CloudMedium(const model::CloudParams& params, glm::vec3 cameraPosition,
                const Texture2D& weather);

    float sigmaT(glm::vec3 p) const;
    // The radiance the medium emits per unit of optical depth at p (the storm's glow and
    // lightning's flash, model::stormEmissionLit): the emission coefficient is sigmaT(p) times
    // it. Zero without a storm glow or lightning. See integrator.h for how paths collect it.
    glm::vec3 emission(glm::vec3 p) const;
    bool emits() const { return emits_; }
    // Whether the storm's glow or a flash can emit anything (else emission is zero everywhere,
    // and is not evaluated).
    static bool emitsLight(const model::CloudParams& params);
    float albedo() const { return params_.albedo; }
    model::PhaseFunction phase() const { return phase_; }

    // Majorant of a column cell (extinction, 1/m) and the altitude above which it is empty.
    struct Cell {
        float sigmaMax = 0.0f;
        float topAltitude = 0.0f;
    };
    const Cell& cell(int ix, int iz) const {
        return cells_[static_cast<size_t>(wrap(iz, cellsZ_)) * cellsX_ + wrap(ix, cellsX_)];
    }
    // The cell containing world (x, z), unwrapped index.
    glm::ivec2 cellIndexAt(float x, float z) const;
    float cellSizeMetres() const { return cellTexels_ * texelMetres_; }

    // Calls visit(t0, t1, sigmaMax) for consecutive pieces of the ray in [0, tMax] (front to
    // back) where the medium may be non-zero, until visit returns true.
    template <class Visit>
    void forEachSegment(glm::vec3 origin, glm::vec3 dir, float tMax, Visit&& visit) const;

private:
    static int wrap(int i, int n) {
        const int m = i % n;
        return m < 0 ? m + n : m;
    }
    // Texel-space coordinate (continuous, unwrapped) of a world x or z, through the model's
    // weatherUv (each coordinate depends only on its own axis).
    float texelX(float x) const {
        return model::weatherUv(glm::vec2(x, 0.0f), params_).x * float(texelsX_) - 0.5f;
    }
    float texelZ(float z) const {
        return model::weatherUv(glm::vec2(0.0f, z), params_).y * float(texelsZ_) - 0.5f;
    }
    // Cell (cx, cz)'s column as a world rectangle (centre and half size in xz, m), widened by a
    // texel: what the storm's distance bound and the data field's maximum are taken over.
    void cellRectangle(int cx, int cz, glm::vec2& centre, glm::vec2& half) const;
    // Calls visitPiece(t0, t1, cell) over the 2D grid cells the ray crosses in [t0, t1].
    template <class VisitCell>
    bool walkCells(glm::vec3 origin, glm::vec3 dir, float t0, float t1,
                   VisitCell&& visitCell) const;

    model::CloudParams params_;
    model::PhaseFunction phase_;
    glm::vec3 camera_;
    int texelsX_ = 1;
    int texelsZ_ = 1;
    float texelMetres_ = 1.0f;
    int cellTexels_ = 1;
    int cellsX_ = 1;
    int cellsZ_ = 1;
    std::vector<Cell> cells_;
    bool emits_ = false;
};

template <class VisitCell>
bool CloudMedium::walkCells(glm::vec3 origin, glm::vec3 dir, float t0, float t1,
                            VisitCell&& visitCell) const {
    // Amanatides-Woo over cells of cellTexels_ texels, in texel coordinates.
    const float scaleX = float(texelsX_) / params_.weatherExtent;
    const float scaleZ = float(texelsZ_) / params_.weatherExtent;
    const float cx = texelX(origin.x + dir.x * t0) / float(cellTexels_);
    const float cz = texelZ(origin.z + dir.z * t0) / float(cellTexels_);
    int ix = static_cast<int>(std::floor(cx));
    int iz = static_cast<int>(std::floor(cz));
    const float dx = dir.x * scaleX / float(cellTexels_); // cells per metre along the ray
    const float dz = dir.z * scaleZ / float(cellTexels_);
    const int stepX = dx > 0.0f ? 1 : -1;
    const int stepZ = dz > 0.0f ? 1 : -1;
    const float inf = kInfinity;
    float nextX =
        dx != 0.0f ? t0 + ((dx > 0.0f ? float(ix + 1) - cx : cx - float(ix)) / std::abs(dx)) : inf;
    float nextZ =
        dz != 0.0f ? t0 + ((dz > 0.0f ? float(iz + 1) - cz : cz - float(iz)) / std::abs(dz)) : inf;
    const float deltaX = dx != 0.0f ? 1.0f / std::abs(dx) : inf;
    const float deltaZ = dz != 0.0f ? 1.0f / std::abs(dz) : inf;
    float t = t0;
    while (t < t1) {
        const float end = std::min(std::min(nextX, nextZ), t1);
        if (end > t && visitCell(t, end, cell(ix, iz)))
            return true;
        t = end;
        if (nextX <= nextZ) {
            ix += stepX;
            nextX += deltaX;
        } else {
            iz += stepZ;
            nextZ += deltaZ;
        }
    }
    return false;
}

template <class Visit>
void CloudMedium::forEachSegment(glm::vec3 origin, glm::vec3 dir, float tMax, Visit&& visit) const {
    const float radius = params_.planetRadius;
    const glm::vec4 spans =
        model::shellIntervals(origin, dir, radius, params_.layerBottom, params_.layerTop);
    const glm::vec3 centre = model::planetCentre(radius);
    for (int span = 0; span < 2; ++span) {
        float s0 = span == 0 ? spans.x : spans.z;
        float s1 = std::min(span == 0 ? spans.y : spans.w, tMax);
        if (!(s1 > s0))
            continue;
        const bool stop = walkCells(origin, dir, s0, s1, [&](float a, float b, const Cell& c) {
            if (c.sigmaMax <= 0.0f)
                return false;
            // Only the part of the piece below the cell's cloud top can hold cloud.
            const glm::vec2 top = model::raySphere(origin, dir, centre, radius + c.topAltitude);
            const float lo = std::max(a, top.x);
            const float hi = std::min(b, top.y);
            if (top.x == model::NO_HIT && top.y == model::NO_HIT)
                return false;
            if (hi > lo)
                return visit(lo, hi, c.sigmaMax);
            return false;
        });
        if (stop)
            return;
    }
}

} // namespace cloudscape::pathtrace
