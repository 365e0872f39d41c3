#pragma once
// Turning a validated Scene into the model's GPU-layout parameter blocks. Both backends upload
// exactly these structs.
#include <cloudscape/scene.h>

#include "model/params.glsl.h"
#include "model/phase.glsl.h"

namespace cloudscape {

// Unit vector for an azimuth (clockwise from north = +z toward east = +x) and an elevation.
glm::vec3 directionFromAngles(float headingDeg, float elevationDeg);

model::SkyParams makeSkyParams(const Scene& scene);
model::CloudParams makeCloudParams(const Scene& scene);
model::FrameParams makeFrameParams(const Scene& scene, int frameIndex = 0);

} // namespace cloudscape
