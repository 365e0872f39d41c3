#pragma once
// The parts of prepareResources (include/cloudscape/renderer.h), for a persistent Renderer that
// regenerates only what a scene change touches.
#include <cloudscape/renderer.h>

namespace cloudscape {

// All of prepareResources but the atmosphere's tables, for a Renderer: its backend makes those
// once it is open (on its device, or asks the host to).
SceneResources prepareResourcesWithoutAtmosphere(const Scene& scene);
// The noise textures, with the base noise's clearance field only where the scene asks for it
// (wantsNoiseClearance).
void prepareNoise(const Scene& scene, SceneResources& resources);
// Whether the scene's march reads the clearance field (march.noise_skipping, which only acts
// with march.empty_space_skipping).
bool wantsNoiseClearance(const Scene& scene);
// Makes the clearance field of resources' base noise if the scene wants it and it is missing
// (a scene that turned march.noise_skipping on); true when it did.
bool prepareNoiseClearance(const Scene& scene, SceneResources& resources);
// The weather map and its coverage-field distribution.
void prepareWeather(const Scene& scene, SceneResources& resources);
// The data field's regions (weather.field_image, or the generator's weather.* keys).
void prepareDataField(const Scene& scene, SceneResources& resources);
void prepareDepth(const Scene& scene, SceneResources& resources);
// The terrain's height field, generated or loaded (empty when terrain.enabled is false).
void prepareTerrain(const Scene& scene, SceneResources& resources);
// The light's horizon over the terrain (appendLightHorizon) for the light that shines on the
// clouds now (the sun, or the moon when it outshines it: after the atmosphere's tables), unless
// the field already holds it; true when it was (re)made.
bool prepareTerrainLight(const Scene& scene, SceneResources& resources);
// Throws cloudscape::Error when the scene's camera is not above its terrain.
void checkCameraAboveTerrain(const Scene& scene, const SceneResources& resources);
// Raises the scene's camera along the planet's vertical until it is clearanceM above the terrain
// under it (the viewer's camera: flown into a hill, it walks over it instead of ending the
// session); true when it moved the camera.
bool liftCameraAboveTerrain(Scene& scene, const SceneResources& resources, float clearanceM);

// Which resources a change from `before` to `after` invalidates. Everything a scene holds that is
// not listed here (coverage included) reaches the model as a uniform.
struct ResourceChanges {
    bool noise = false;     // seed
    bool weather = false;   // the procedural generator's keys and seed, or weather.image
    bool dataField = false; // its generator's keys and seed, or weather.field_image
    bool depth = false;     // render.depth_file, or the size it must match
    bool terrain = false;   // a terrain key that shapes the height field (not its offset/albedo)
};
ResourceChanges resourceChanges(const Scene& before, const Scene& after);

} // namespace cloudscape
