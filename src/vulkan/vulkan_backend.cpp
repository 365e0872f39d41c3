// The Vulkan backend of the persistent Renderer: one VulkanDevice (context, pipelines, textures)
// for the renderer's life, a full-frame renderer and a temporal renderer on it, created when
// first used. A regenerated texture is re-uploaded alone. Plumbing only.
#include "core/renderer_backend.h"
#include "vulkan/vulkan_device.h"
#include "vulkan/vulkan_still.h"
#include "vulkan/vulkan_temporal.h"

namespace cloudscape {
namespace {

Renderer::DeviceHandles handlesOf(const vulkan::Context& c) {
    auto handle = [](auto h) { return reinterpret_cast<uint64_t>(h); };
    return {handle(static_cast<VkInstance>(c.instance)),
            handle(static_cast<VkPhysicalDevice>(c.physicalDevice)),
            handle(static_cast<VkDevice>(c.device)),
            handle(static_cast<VkQueue>(c.queue)),
            c.queueFamily,
            handle(static_cast<VkSurfaceKHR>(c.surface))};
}

class VulkanRendererBackend final : public Renderer::Backend {
public:
    VulkanRendererBackend(const SceneResources& resources, const BackendOptions& options)
        : resources_(resources),
          device_(std::make_shared<vulkan::VulkanDevice>(options, resources)) {}

    RenderResult still(const Scene& scene, const ProgressCallback& progress,
                       Readback readback) override {
        if (!still_)
            still_ = std::make_unique<vulkan::VulkanStill>(device_);
        RenderResult out = vulkan::translateVulkanErrors(
            "rendering", [&] { return still_->render(scene, resources_, progress, readback); });
        out.stats.validationMessages = device_->context().takeValidationMessages();
        const vulkan::Buffer* composite = still_->composite();
        lastImage_ = {reinterpret_cast<uint64_t>(static_cast<VkBuffer>(composite->buffer)),
                      composite->size, out.width, out.height};
        lastWasStill_ = true;
        return out;
    }
    RenderResult frame(const Scene& scene, int frameIndex, Readback readback) override {
        RenderResult out = temporal().renderFrame(scene, frameIndex, readback);
        lastImage_ = {temporal_->deviceComposite().first, temporal_->deviceComposite().second,
                      out.width, out.height};
        lastWasStill_ = false;
        return out;
    }
    TemporalDebugImage temporalDebug() const override {
        if (lastWasStill_ || !temporal_)
            return {};
        return temporal_->debugImage();
    }
    std::vector<glm::vec4> cloudShadowMap() const override {
        if (lastWasStill_)
            return still_ ? still_->cloudShadowMap() : std::vector<glm::vec4>{};
        return temporal_ ? temporal_->lastCloudShadowMap() : std::vector<glm::vec4>{};
    }
    void texturesChanged(bool noise, bool weather) override {
        vulkan::translateVulkanErrors("texture upload", [&] {
            if (noise)
                device_->textures().replaceNoise(resources_.noise);
            if (weather)
                device_->textures().replaceWeather(resources_.weather);
        });
    }
    void weatherEdited(const std::vector<TexelRect>& rects) override {
        vulkan::translateVulkanErrors("weather map edit", [&] {
            device_->textures().updateWeather(resources_.weather, rects);
        });
    }
    std::vector<uint8_t> deviceWeatherMap() const override {
        return vulkan::translateVulkanErrors("weather map read-back",
                                             [&] { return device_->textures().readWeather(); });
    }
    void terrainChanged() override {
        vulkan::translateVulkanErrors("terrain upload", [&] {
            device_->textures().replaceTerrain(resources_.terrain.heights);
        });
    }
    void atmosphereChanged() override {
        vulkan::translateVulkanErrors("atmosphere upload", [&] {
            device_->textures().replaceAtmosphere(resources_.atmosphere);
        });
    }
    bool makesAtmosphere() const override { return true; }
    std::vector<glm::vec4> makeAtmosphere(const model::SkyParams& sky) override {
        return vulkan::translateVulkanErrors("atmosphere tables", [&] {
            vulkan::AtmosphereTables& tables = device_->atmosphereTables();
            tables.fill(sky);
            return tables.texels();
        });
    }
    TemporalRenderer::Breakdown breakdown() const override {
        return temporal_ ? temporal_->breakdown : TemporalRenderer::Breakdown{};
    }
    TemporalState saveState() const override {
        return temporal_ ? temporal_->saveState() : TemporalState{};
    }
    void restoreState(const TemporalState& state) override { temporal().restoreState(state); }
    std::string name() const override { return "vulkan: " + device_->deviceName(); }
    Renderer::DeviceImage deviceImage() const override { return lastImage_; }
    Renderer::DeviceHandles deviceHandles() const override { return handlesOf(device_->context()); }

private:
    TemporalRenderer::Impl& temporal() {
        if (!temporal_)
            temporal_ = vulkan::makeTemporalOn(device_, resources_);
        return *temporal_;
    }

    const SceneResources& resources_;
    std::shared_ptr<vulkan::VulkanDevice> device_;
    std::unique_ptr<vulkan::VulkanStill> still_;
    std::unique_ptr<TemporalRenderer::Impl> temporal_;
    Renderer::DeviceImage lastImage_;
    bool lastWasStill_ = false;
};

} // namespace

std::unique_ptr<Renderer::Backend> makeVulkanRendererBackend(const SceneResources& resources,
                                                             const BackendOptions& options) {
    return std::make_unique<VulkanRendererBackend>(resources, options);
}

struct PresentationDevice::Impl {
    vulkan::Context context;
    explicit Impl(const BackendOptions& o)
        : context(o.device, o.validation, o.presentation.get()) {}
};

PresentationDevice::PresentationDevice(const BackendOptions& options)
    : impl_(std::make_unique<Impl>(options)) {}

PresentationDevice::~PresentationDevice() = default;

Renderer::DeviceHandles PresentationDevice::handles() const {
    return handlesOf(impl_->context);
}

std::vector<std::string> PresentationDevice::takeValidationMessages() {
    return impl_->context.takeValidationMessages();
}

} // namespace cloudscape
