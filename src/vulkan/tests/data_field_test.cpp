// GPU category: the data field (model/data_field.glsl.h) on the Vulkan backend against the CPU
// backend: the field reaches the device in the parameter block and both read it alike, in the
// full-frame march and in the temporal path (march, resolve, shadow map), under validation.
#include <cloudscape/backend.h>
#include <cloudscape/data_field.h>
#include <cloudscape/metrics.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include "core/resources.h"
#include "model/params.glsl.h"
#include "vulkan/tests/vulkan_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using cloudscape::testing::channels;
using cloudscape::testing::sharedResources;
using cloudscape::testing::vulkanWithValidation;

// The default scene looking up at regions with raised bases, lowered tops, ragged bottoms and a
// painted anvil block overhead.
cloudscape::Scene fieldScene() {
    cloudscape::Scene s;
    s.width = 64;
    s.height = 36;
    s.coverage = 0.55f;
    s.cameraPitchDeg = 25.0f;
    s.baseVariation = 0.3f;
    s.topVariation = 0.5f;
    s.bottomType = 0.6f;
    return s;
}

cloudscape::SceneResources fieldResources(const cloudscape::Scene& s) {
    cloudscape::SceneResources r = sharedResources();
    cloudscape::prepareDataField(s, r);
    const int n = cloudscape::model::DATA_FIELD_GRID;
    for (int j = n / 2; j < n / 2 + 4; ++j)
        for (int i = n / 2 - 2; i < n / 2 + 2; ++i)
            r.dataField[size_t(j) * n + i].y = 0.7f;
    return r;
}

double psnrOf(const std::vector<float>& a, const std::vector<float>& b) {
    return cloudscape::compareImages(channels(a, 0, 3), channels(b, 0, 3), 3).psnr;
}

} // namespace

TEST(VulkanDataField, AStillWithTheFieldMatchesTheCpuBackend) {
    const cloudscape::Scene s = fieldScene();
    const cloudscape::SceneResources r = fieldResources(s);
    const cloudscape::RenderResult cpu = cloudscape::renderCpu(s, r);
    const cloudscape::RenderResult gpu = cloudscape::renderVulkan(s, r, vulkanWithValidation());
    EXPECT_TRUE(gpu.stats.validationMessages.empty()) << gpu.stats.validationMessages.front();
    // The field must matter to the image, or the agreement proves nothing: the share of pixels
    // whose cloud transmittance it moves by more than 0.1.
    const cloudscape::RenderResult plain = cloudscape::renderCpu(s, sharedResources());
    size_t moved = 0;
    for (size_t i = 3; i < cpu.cloud.size(); i += 4)
        moved += std::abs(cpu.cloud[i] - plain.cloud[i]) > 0.1f ? 1 : 0;
    const double change = double(moved) / double(cpu.cloud.size() / 4);
    const double agreement = psnrOf(cpu.composite, gpu.composite);
    std::printf("data field: CPU/Vulkan composite PSNR %.1f dB; the field moves the "
                "transmittance of %.0f%% of the pixels\n",
                agreement, 100.0 * change);
    EXPECT_GT(agreement, 36.0);
    EXPECT_GT(change, 0.1);
}

TEST(VulkanDataField, TemporalFramesWithTheFieldMatchTheCpuBackend) {
    cloudscape::Scene s = fieldScene();
    s.temporal = true;
    s.cloudShadowEnabled = true;
    const cloudscape::SceneResources r = fieldResources(s);
    cloudscape::TemporalRenderer cpu(r);
    cloudscape::TemporalRenderer gpu(r, vulkanWithValidation());
    double worst = 1e9;
    for (int i = 0; i < 6; ++i) {
        const cloudscape::RenderResult a = cpu.renderFrame(s, i);
        const cloudscape::RenderResult b = gpu.renderFrame(s, i);
        EXPECT_TRUE(b.stats.validationMessages.empty()) << b.stats.validationMessages.front();
        worst = std::min(worst, psnrOf(a.composite, b.composite));
    }
    std::printf("data field, temporal with the shadow map: worst frame PSNR %.1f dB\n", worst);
    EXPECT_GT(worst, 34.0);
}
