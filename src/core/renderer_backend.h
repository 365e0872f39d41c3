#pragma once
// A backend's side of the persistent Renderer: the CPU one (src/cpu/cpu_backend.cpp) renders
// from the resources in memory, the Vulkan one (src/vulkan/vulkan_backend.cpp) keeps a
// VulkanDevice with the textures and pipelines and its renderers' buffers and history.
#include <cloudscape/persistent_renderer.h>

#include "model/params.glsl.h"

#include <memory>
#include <vector>

namespace cloudscape {

class Renderer::Backend {
public:
    virtual ~Backend() = default;
    virtual RenderResult still(const Scene& scene, const ProgressCallback& progress,
                               Readback readback) = 0;
    virtual RenderResult frame(const Scene& scene, int frameIndex, Readback readback) = 0;
    // The resources' noise or weather map were regenerated (the depth buffer is read per render).
    virtual void texturesChanged(bool noise, bool weather) = 0;
    // The resources' weather map was edited inside `rects` (Renderer::editWeatherMap): only
    // their footprints at each level need to reach where renders read the map.
    virtual void weatherEdited(const std::vector<TexelRect>& rects) = 0;
    virtual std::vector<uint8_t> deviceWeatherMap() const { return {}; }
    // The resources' atmosphere tables were remade on the host (or emptied: the gradient sky).
    virtual void atmosphereChanged() = 0;
    // True when this backend makes the atmosphere's tables itself (makeAtmosphere) rather than
    // taking the host's (atmosphereChanged).
    virtual bool makesAtmosphere() const { return false; }
    // Makes the tables for `sky` where its renders read them and returns a copy for the host.
    virtual std::vector<glm::vec4> makeAtmosphere(const model::SkyParams&) { return {}; }
    // The resources' terrain height field was remade.
    virtual void terrainChanged() = 0;
    virtual TemporalRenderer::Breakdown breakdown() const = 0;
    // The temporal history, as TemporalRenderer::saveState/restoreState (already checked).
    virtual TemporalState saveState() const = 0;
    virtual void restoreState(const TemporalState& state) = 0;
    virtual std::string name() const = 0;
    virtual Renderer::DeviceImage deviceImage() const { return {}; }
    // The clouds' shadow map the last render or frame read (Renderer::cloudShadowMap).
    virtual std::vector<glm::vec4> cloudShadowMap() const = 0;
    // The last temporal frame's (Renderer::temporalDebug); empty after a still.
    virtual TemporalDebugImage temporalDebug() const = 0;
    virtual Renderer::DeviceHandles deviceHandles() const { return {}; }
};

// Backend choice Auto: true when a Vulkan device exists; otherwise `notice` says why not.
bool autoChoosesVulkan(std::string* notice);

// The resources must outlive the backend (the Renderer owns both).
std::unique_ptr<Renderer::Backend> makeCpuRendererBackend(const SceneResources& resources);
std::unique_ptr<Renderer::Backend> makeVulkanRendererBackend(const SceneResources& resources,
                                                             const BackendOptions& options);

} // namespace cloudscape
