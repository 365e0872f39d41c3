#include "core/model_params.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace cloudscape {

glm::vec3 directionFromAngles(float headingDeg, float elevationDeg) {
    const float h = glm::radians(headingDeg);
    const float e = glm::radians(elevationDeg);
    return {std::sin(h) * std::cos(e), std::sin(e), std::cos(h) * std::cos(e)};
}

model::CloudParams makeCloudParams(const Scene& s) {
    model::CloudParams p{};
    p.planet = {s.planetRadiusM, s.cloudBottomM, s.cloudTopM, s.weatherExtentM};
    p.noiseScale = {s.baseNoisePeriodM, s.detailNoisePeriodM, s.curlPeriodM, s.curlStrengthM};
    p.wind = glm::vec4(directionFromAngles(s.windHeadingDeg, 0.0f), s.windSpeedMps);
    p.animation = {s.timeS, s.windShearM, s.detailSpeedRatio, s.updraft};
    p.shape = {s.erosion, 0.0f, s.extinctionPerM, s.albedo};
    p.weatherOrigin = {s.weatherOffsetXM, s.weatherOffsetZM, 1.0f, 0.0f};
    p.sunDirection = glm::vec4(directionFromAngles(s.sunHeadingDeg, s.sunElevationDeg),
                               glm::radians(s.sunAngularDiameterDeg) * 0.5f);
    p.sunIrradiance = glm::vec4(s.sunIrradiance, 0.0f);
    p.ambientTop = glm::vec4(s.ambientTop, s.ambientStrength);
    p.ambientBottom = glm::vec4(s.ambientBottom, 0.0f);
    p.phase = {s.phaseG, s.silverG, s.silverWeight, s.powder};
    p.lighting = {s.rainAbsorption, s.coneLengthM, s.longSampleDistance, s.coneSpread};
    p.march = {static_cast<float>(s.zenithSteps), static_cast<float>(s.horizonSteps),
               s.minTransmittance, s.maxDistanceM};
    p.skyZenith = glm::vec4(s.skyZenith, 0.0f);
    p.skyHorizon = glm::vec4(s.skyHorizon, s.horizonFade);
    p.ground = glm::vec4(s.ground, 0.0f);
    p.multipleScattering = glm::vec4(s.octaveFactors, 0.0f);
    // Texel sizes of the generated noise (128^3 base, 32^3 detail) in metres, as log2.
    p.distanceLod = {std::log2(s.baseNoisePeriodM / 128.0f),
                     std::log2(s.detailNoisePeriodM / 32.0f), s.distanceLod ? 1.0f : 0.0f, 0.0f};
    p.optimisation = {static_cast<float>(s.coarseStepFactor), s.cheapLightAlpha,
                      s.stepOptimisation, s.blueNoise ? 1.0f : 0.0f};
    p.counts = {s.lightSamples, s.longSample ? 1 : 0, s.lightMipBias, s.scatteringOctaves};
    p.lightingModel = {static_cast<float>(s.phaseFunction == "hg-draine" ? model::PHASE_HG_DRAINE
                                                                          : model::PHASE_TWO_LOBE),
                       s.dropletDiameterUm, s.energyConservingSteps ? 1.0f : 0.0f, 0.0f};
    return p;
}

model::FrameParams makeFrameParams(const Scene& s, int frameIndex) {
    model::FrameParams f{};
    const glm::vec3 forward = directionFromAngles(s.cameraHeadingDeg, s.cameraPitchDeg);
    const glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    // x east, y up, z north is a left-handed frame (as in Unity): facing north, east is on the
    // right, which is up x forward here.
    const glm::vec3 right = glm::normalize(glm::cross(worldUp, forward));
    const glm::vec3 up = glm::cross(forward, right);
    f.cameraPosition = glm::vec4(s.cameraPosition, 0.0f);
    f.cameraForward = glm::vec4(forward, std::tan(glm::radians(s.cameraFovDeg) * 0.5f));
    f.cameraRight = glm::vec4(right, static_cast<float>(s.width) / static_cast<float>(s.height));
    f.cameraUp = glm::vec4(up, s.exposure);
    f.size = {s.width, s.height, frameIndex, s.seed};
    // sampling.z (a scene depth buffer is bound) is set by the backend that binds one.
    f.sampling = {s.samplesPerPixel, s.temporalAccumulation, 0, 0};
    return f;
}

} // namespace cloudscape
