// The CPU backend of the persistent Renderer: renderCpu for stills and one CPU temporal renderer
// for sequences, both reading the Renderer's resources in memory. Plumbing only.
#include "core/model_params.h"
#include "core/pixel_store.h"
#include "core/renderer_backend.h"
#include "core/temporal_impl.h"
#include "cpu/cpu_cloud_shadow.h"

#include <optional>

namespace cloudscape {
namespace {

class CpuRendererBackend final : public Renderer::Backend {
public:
    explicit CpuRendererBackend(const SceneResources& resources)
        : resources_(resources), temporal_(makeCpuTemporal(resources)) {}

    RenderResult still(const Scene& scene, const ProgressCallback& progress,
                       Readback readback) override {
        RenderResult r = renderCpu(scene, resources_, progress);
        keepReadback(r, readback);
        last_ = scene;
        lastWasStill_ = true;
        return r;
    }
    RenderResult frame(const Scene& scene, int frameIndex, Readback readback) override {
        RenderResult r = temporal_->renderFrame(scene, frameIndex, readback);
        last_ = scene;
        lastWasStill_ = false;
        return r;
    }
    TemporalDebugImage temporalDebug() const override {
        return lastWasStill_ ? TemporalDebugImage{} : temporal_->debugImage();
    }
    // A frame's map is the one its renderer keeps; a still's is made again rather than kept
    // from the render (every texel is a pure function of the scene's parameters, and a map is
    // asked for far less often than stills are rendered).
    std::vector<glm::vec4> cloudShadowMap() const override {
        if (!last_)
            return {};
        if (!lastWasStill_)
            return temporal_->lastCloudShadowMap();
        cpu::TextureSet textures{&resources_.noise.base, &resources_.noise.detail,
                                 &resources_.noise.curl, &resources_.weather};
        const model::CloudParams cloud = makeCloudParams(*last_, resources_);
        return cpu::cloudShadowMapInRows(cpu::computeCloudShadowMap(cloud, textures),
                                         cloud.cloudShadow);
    }
    // Renders read the resources themselves; only the temporal renderer's kept shadow map was
    // made from them.
    void texturesChanged(bool, bool) override { temporal_->texturesChanged(); }
    void weatherEdited(const std::vector<TexelRect>&) override { temporal_->texturesChanged(); }
    void atmosphereChanged() override {} // likewise
    void terrainChanged() override {}    // likewise
    TemporalRenderer::Breakdown breakdown() const override { return temporal_->breakdown; }
    TemporalState saveState() const override { return temporal_->saveState(); }
    void restoreState(const TemporalState& state) override { temporal_->restoreState(state); }
    std::string name() const override { return "cpu"; }

private:
    const SceneResources& resources_;
    std::unique_ptr<TemporalRenderer::Impl> temporal_;
    std::optional<Scene> last_; // of the last render or frame
    bool lastWasStill_ = false;
};

} // namespace

std::unique_ptr<Renderer::Backend> makeCpuRendererBackend(const SceneResources& resources) {
    return std::make_unique<CpuRendererBackend>(resources);
}

} // namespace cloudscape
