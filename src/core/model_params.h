#pragma once
// Turning a validated Scene into the model's GPU-layout parameter blocks. Both backends upload
// exactly these structs.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include "model/params.glsl.h"
#include "model/phase.glsl.h"

namespace cloudscape {

// Unit vector for an azimuth (clockwise from north = +z toward east = +x) and an elevation.
glm::vec3 directionFromAngles(float headingDeg, float elevationDeg);

// 1 - cos r for an angle r (radians), as 2 sin^2(r / 2) in double: cos r of a sun-sized r rounds
// to within a few float steps of 1.
float oneMinusCosOf(float angle);

// The moon's brightness at a phase angle (degrees) relative to the full moon (Allen's law).
double moonPhaseBrightness(double phaseAngleDeg);

model::SkyParams makeSkyParams(const Scene& scene);
// The sky as makeCloudParams(scene, resources) sets it: the atmosphere and the moon on only with
// the resources' tables, and which of sun and moon lights the clouds.
model::SkyParams makeSkyParams(const Scene& scene, const SceneResources& resources);
// The cloud parameters of a scene over its resources: the weather map's coverage bias is chosen
// so that the map's mean coverage is weather.coverage (CoverageField; from the map itself when
// resources.weatherCoverage is empty).
model::CloudParams makeCloudParams(const Scene& scene, const SceneResources& resources);
// The atmosphere is on when the scene asks for it (sky.model) and the resources hold its tables.
// With a coverage bias chosen by the caller (a cached CoverageField, or tests of model functions
// that read no weather map), and the gradient sky (there are no atmosphere tables to read).
model::CloudParams makeCloudParams(const Scene& scene, float coverageBias);
// The terrain's parameters for a height field (off when the scene's terrain is, or it is empty).
model::TerrainParams makeTerrainParams(const Scene& scene, const HeightField& field);

// The shadow map's and the light shafts' parameters (cloud_shadow.*, shafts.*): the map is
// centred near the camera, so they change with it every frame; all zero (off) unless the scene
// asks for the map. Needs p.sky (the sun) set.
void setCloudShadowParams(model::CloudParams& p, const Scene& scene);
model::FrameParams makeFrameParams(const Scene& scene, int frameIndex = 0);

} // namespace cloudscape
