// GPU category: the shared model functions through their GLSL compilation (model_kernels.comp on
// the Vulkan device) agree with the same functions compiled as C++.
#include "model/lighting.glsl.h"
#include "model/phase.glsl.h"
#include "model/profiles.glsl.h"
#include "model/shell.glsl.h"
#include "model/weather.glsl.h"
#include "vulkan/kernel_runner.h"

#include <gtest/gtest.h>

#include <random>

namespace cm = cloudscape::model;

namespace {

const uint32_t kKernels[] = {
#include "shaders/model_kernels.spv.inc"
};

// Relative-or-absolute closeness: GPUs may use fast exp/pow/sqrt (a few ulp).
void expectClose(float gpu, float cpu, const char* what, size_t i) {
    const float tolerance = 1e-4f + 1e-4f * std::abs(cpu);
    EXPECT_NEAR(gpu, cpu, tolerance) << what << " at input " << i;
}

} // namespace

TEST(VulkanKernels, SharedFunctionsAgreeWithTheCpp) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const size_t n = 256;
    std::vector<glm::vec4> inputs(n);
    for (glm::vec4& v : inputs)
        // Braces: drawn left to right (a call's arguments have no order).
        v = glm::vec4{u(rng), u(rng), u(rng), u(rng)};
    const auto run = cloudscape::vulkan::runKernel(
        kKernels, sizeof kKernels, {inputs, std::vector<glm::vec4>(n * 3)}, (n + 63) / 64, true);
    ASSERT_TRUE(run.validationMessages.empty()) << run.validationMessages.front();
    const std::vector<glm::vec4>& out = run.buffers[1];
    for (size_t i = 0; i < n; ++i) {
        const glm::vec4 v = inputs[i];
        const float cosTheta = v.x * 2.0f - 1.0f;
        const float g = v.y * 1.8f - 0.9f;
        expectClose(out[i * 3].x, cm::henyeyGreenstein(cosTheta, g), "henyeyGreenstein", i);
        expectClose(out[i * 3].y, cm::remap(v.x, v.y, v.z + 1.0f, -1.0f, 2.0f), "remap", i);
        expectClose(out[i * 3].z, cm::verticalProfile(v.z, v.w), "verticalProfile", i);
        expectClose(out[i * 3].w, cm::beerPowder(v.w * 3.0f, cosTheta, v.y), "beerPowder", i);
        const glm::vec3 origin(0.0f, v.z * 12000.0f + 1.0f, 0.0f);
        const glm::vec3 dir = glm::normalize(glm::vec3(v.x - 0.5f, v.y - 0.5f, 0.3f));
        const glm::vec4 shell = cm::shellIntervals(origin, dir, 6371000.0f, 1500.0f, 8000.0f);
        for (int c = 0; c < 4; ++c) {
            // Distances of up to ~300 km in float: a few metres of rounding either way.
            EXPECT_NEAR(out[i * 3 + 1][c], shell[c], 2.0f + 1e-5f * std::abs(shell[c]))
                << "shellIntervals at input " << i << " component " << c;
        }
        const glm::vec3 rule = cm::applyPrecipitationRule(glm::vec3(v.x, v.y, v.z));
        expectClose(out[i * 3 + 2].x, rule.x, "applyPrecipitationRule", i);
        expectClose(out[i * 3 + 2].z, rule.z, "applyPrecipitationRule", i);
        expectClose(out[i * 3 + 2].w, cm::twoLobePhase(cosTheta, 0.2f, 0.85f, v.w), "twoLobe", i);
    }
}
