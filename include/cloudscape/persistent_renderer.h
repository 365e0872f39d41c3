#pragma once
// A renderer that stays alive, for anything that renders more than once (the command-line tool's
// render, render --frames and bench; a viewer): created once for a backend and device, it keeps
// the context, the pipelines, the textures and the temporal history, and regenerates only what a
// change of scene touches. On the Vulkan backend the images stay on the device and only what is
// asked for is read back.
#include <cloudscape/backend.h>
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cloudscape {

// What renderFrame may change from one frame to the next without touching the scene.
struct Camera {
    glm::vec3 position{0.0f, 2.0f, 0.0f}; // metres, y up
    float headingDeg = 0.0f;
    float pitchDeg = 12.0f;
    float fovDeg = 60.0f;
};
Camera cameraOf(const Scene& scene);
Scene withCamera(Scene scene, const Camera& camera, float timeS);

// What an update regenerated (everything else a scene change touches is a uniform).
struct UpdateReport {
    bool noise = false;          // a new seed: the noise textures, generated and uploaded
    bool weather = false;        // a weather generator key or weather.image: the map, uploaded
    bool depth = false;          // render.depth_file or the image size: the depth buffer reloaded
    bool atmosphere = false;     // the sun's elevation, the camera's altitude or an atmosphere key:
                                 // its lookup tables remade (on the Vulkan device, or on the host
                                 // and uploaded)
    bool terrain = false;        // a terrain key that shapes the height field: remade, uploaded
    bool dataField = false;      // a data field key or weather.field_image: remade on the host (it
                                 // reaches the device in the parameter block, no texture)
    bool noiseClearance = false; // march.noise_skipping turned on: the base noise's clearance
                                 // field made, and the noise uploaded again with it
    double seconds = 0.0;        // the whole update, host and device
};

// A rectangle of texels of one level of the weather map: columns [x, x + width), rows
// [y, y + height), inside the level.
struct TexelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};
// The texels of `level` that level-0 texels inside `rects` feed (a texel i of level l averages
// level l - 1's 2i and 2i + 1, so its footprint is i >> l), as rectangles that do not overlap:
// footprints that meet are merged into the rectangle around both.
std::vector<TexelRect> weatherFootprint(const std::vector<TexelRect>& rects, const Texture2D& map,
                                        int level);

class Renderer {
public:
    // Prepares the scene's resources and opens the backend (Auto picks as renderScene does, and
    // `notice` says why when it falls back to the CPU). The atmosphere's tables are made once
    // the backend is open: by the Vulkan backend on its device (SceneResources::
    // atmosphereOnDevice), else on the host. Throws cloudscape::Error.
    Renderer(const Scene& scene, const BackendOptions& options, std::string* notice = nullptr);
    // Over resources the caller prepared for `scene` (they are moved in); tables they lack, or
    // made for another scene, are made as above.
    Renderer(const Scene& scene, SceneResources resources, const BackendOptions& options,
             std::string* notice = nullptr);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Makes `scene` current, regenerating only what its changes touch (see UpdateReport); the
    // render calls below do it themselves, so calling it is only needed to measure or report.
    UpdateReport update(const Scene& scene);

    // Replaces the weather map with an edited one of the same extent (the viewer's brush): its
    // coverage distribution is taken anew and the map uploaded; the scene keys are untouched, so
    // a later change of a weather generator key (or weather.image) makes the map again.
    void replaceWeatherMap(Texture2D map);
    // Edits the weather map in place (the viewer's brush and its undo): `edit` may change the
    // texels of each level inside weatherFootprint(rects, map, level) and nothing else; `rects`
    // (level 0, inside the map) must not overlap. Only those texels reach the device: copied
    // into the image the passes sample, which stays (no re-upload, no descriptor rewritten). The
    // map's coverage distribution and empty-space maxima are updated where the texels changed.
    // Throws cloudscape::Error naming a rectangle outside the map.
    void editWeatherMap(const std::vector<TexelRect>& rects,
                        const std::function<void(Texture2D&)>& edit);
    // Counts the weather maps made or replaced whole (a weather key, weather.image, a reload,
    // replaceWeatherMap), not editWeatherMap's edits: what a painter's cached copy is for.
    uint64_t weatherMapVersion() const { return weatherVersion_; }
    // Replaces the data field's regions (the viewer's brush on its channels): the next render
    // reads them from the parameter block, nothing is uploaded; a later change of a data-field
    // key (or weather.field_image) makes the field again. Throws cloudscape::Error unless it
    // holds DATA_FIELD_GRID^2 regions.
    void replaceDataField(std::vector<glm::vec4> field);
    // Counts the data fields made from the scene (its keys, a reload), not replaceDataField's.
    uint64_t dataFieldVersion() const { return dataFieldVersion_; }
    // The weather map as the device holds it, every level's RGBA8 texels back to back from level
    // 0 (read back for checking that edits reached it); empty on the CPU backend.
    std::vector<uint8_t> deviceWeatherMap() const;

    // A still: every pixel marched, render.samples_per_pixel times.
    RenderResult render(const Scene& scene, const ProgressCallback& progress = {},
                        Readback readback = Readback::All);
    // Frame `frameIndex` of a temporal sequence (1/16 of the pixels a frame); the history is used
    // when the previous call was frame frameIndex - 1 at the same size.
    RenderResult renderFrame(const Scene& scene, int frameIndex, Readback readback = Readback::All);
    // The next frame of the sequence with only the camera and the clock changed.
    RenderResult renderFrame(const Camera& camera, float timeS,
                             Readback readback = Readback::Display);

    // The temporal history after the last frame, and continuing from one (as TemporalRenderer:
    // the next renderFrame(scene, state.frameIndex + 1) uses it). restoreState throws
    // cloudscape::Error for a state whose sizes do not agree.
    TemporalState saveState() const;
    void restoreState(const TemporalState& state);

    const Scene& scene() const { return scene_; }
    const SceneResources& resources() const { return resources_; }
    std::string backendName() const;
    TemporalRenderer::Breakdown lastBreakdown() const;

    // Where the last image is on the device (Vulkan; zero handles on the CPU backend): a
    // storage buffer (VkBuffer) of vec4 RGBA linear composite per pixel, row-major.
    struct DeviceImage {
        uint64_t buffer = 0;
        uint64_t bytes = 0;
        int width = 0;
        int height = 0;
    };
    DeviceImage deviceImage() const;

    // The clouds' shadow map the last render or frame read, for looking at (the viewer): the
    // records of src/model/cloud_shadow.glsl.h (lowest cloud, highest cloud, optical depth),
    // cloud_shadow.resolution^2 of them, row-major from the smallest z; empty when the map is
    // off or the sun too low for it. Read back from the device on Vulkan; made again by the
    // same rule on the CPU.
    std::vector<glm::vec4> cloudShadowMap() const;
    // What made each pixel of the last frame (TemporalDebugImage, at the cloud pass's size);
    // empty when the last call was a still.
    TemporalDebugImage temporalDebug() const;
    // The Vulkan objects the image lives on (zero on the CPU backend), for drawing it into a
    // window created through BackendOptions::presentation: VkInstance, VkPhysicalDevice,
    // VkDevice, VkQueue (the renderer's; it waits for its own work before returning, so a caller
    // on the same thread may submit to it) and the presentation VkSurfaceKHR.
    struct DeviceHandles {
        uint64_t instance = 0;
        uint64_t physicalDevice = 0;
        uint64_t device = 0;
        uint64_t queue = 0;
        uint32_t queueFamily = 0;
        uint64_t surface = 0;
    };
    DeviceHandles deviceHandles() const;

    // One backend's side (src/core/renderer_backend.h).
    class Backend;

private:
    // The atmosphere's tables for `scene`: by the backend on its device when it makes them,
    // otherwise on the host and uploaded.
    void remakeAtmosphere(const Scene& scene);

    Scene scene_;
    SceneResources resources_;
    std::unique_ptr<Backend> backend_;
    int lastFrame_ = -1;
    uint64_t weatherVersion_ = 0;
    uint64_t dataFieldVersion_ = 0;
    // What an update that threw had begun remaking (ResourceChanges: noise, weather, depth,
    // terrain, data field), so the next update makes it again for its own scene.
    struct Unsettled {
        bool noise = false, weather = false, depth = false, terrain = false, dataField = false;
    } unsettled_;
};

// A Vulkan device opened only to present into a window (BackendOptions::presentation; its
// device index and validation as for a renderer): what draws a CPU Renderer's frames, which
// have no device of their own (the viewer's --backend cpu). Throws cloudscape::Error as a
// Vulkan renderer's start would (no loader, no device that presents to the surface).
class PresentationDevice {
public:
    explicit PresentationDevice(const BackendOptions& options);
    ~PresentationDevice();
    PresentationDevice(const PresentationDevice&) = delete;
    PresentationDevice& operator=(const PresentationDevice&) = delete;
    Renderer::DeviceHandles handles() const;
    // The validation layers' messages since the last call (with BackendOptions::validation).
    std::vector<std::string> takeValidationMessages();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace cloudscape
