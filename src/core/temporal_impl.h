#pragma once
// The backends' side of TemporalRenderer: each backend implements Impl (the CPU one in
// src/cpu/cpu_temporal.cpp, the Vulkan one in src/vulkan/vulkan_temporal.cpp); the public class
// forwards to it. Both run the model's src/model/temporal.glsl.h.
#include <cloudscape/temporal.h>

#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace cloudscape {

class TemporalRenderer::Impl {
public:
    virtual ~Impl() = default;
    virtual RenderResult renderFrame(const Scene& scene, int frameIndex,
                                     Readback readback = Readback::All) = 0;
    virtual TemporalState saveState() const = 0;
    virtual void restoreState(const TemporalState& state) = 0; // already checked
    virtual std::string backendName() const = 0;
    // Vulkan: the device buffer (VkBuffer as an integer, and its size) holding the last frame's
    // composite, vec4 per pixel; zeros on the CPU.
    virtual std::pair<uint64_t, uint64_t> deviceComposite() const { return {0, 0}; }
    // The clouds' shadow map the last frame read (cloud_shadow.glsl.h records, row-major);
    // empty while it is off.
    virtual std::vector<glm::vec4> lastCloudShadowMap() const = 0;
    // The resources' textures (noise, weather map) changed in place (the persistent Renderer's
    // updates and edits): what was made from them is stale.
    virtual void texturesChanged() = 0;
    // The last frame's sources and sample counts (empty before the first frame).
    virtual TemporalDebugImage debugImage() const = 0;
    Breakdown breakdown; // of the last frame
};

// The image of per-pixel CloudTexel.debug codes (texelDebugCode), width x height.
TemporalDebugImage temporalDebugImageOf(const float* codes, int width, int height);

// Throws cloudscape::Error unless the state's arrays match its size and its frame parameters
// are a FrameParams (src/core/temporal_state.cpp).
void checkTemporalState(const TemporalState& state);

std::unique_ptr<TemporalRenderer::Impl> makeCpuTemporal(const SceneResources& resources);
// Throws cloudscape::Error when the Vulkan device cannot be opened.
std::unique_ptr<TemporalRenderer::Impl> makeVulkanTemporal(const SceneResources& resources,
                                                           const BackendOptions& options);

} // namespace cloudscape
