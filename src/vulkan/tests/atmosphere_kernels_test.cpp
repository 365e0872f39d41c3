// The atmosphere's per-texel functions compiled as GLSL against the host's tables they fill (the
// C++ build of the same header): every table, texels spread over it, on the device.
#include <cloudscape/scene.h>

#include "core/atmosphere_luts.h"
#include "core/model_params.h"
#include "model/atmosphere.glsl.h"
#include "vulkan/kernel_runner.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace cm = cloudscape::model;

namespace {

const uint32_t kKernels[] = {
#include "shaders/atmosphere_kernels.spv.inc"
};

struct Table {
    int kind, offset, width, height;
};

} // namespace

TEST(VulkanAtmosphere, TheTexelFunctionsMatchTheHostTables) {
    for (float elevation : {35.0f, 3.0f, -3.0f}) {
        cloudscape::Scene s;
        s.sunElevationDeg = elevation;
        const cm::SkyParams sky = cloudscape::makeSkyParams(s);
        const std::vector<glm::vec4> tables = cloudscape::computeAtmosphereLuts(sky);
        std::vector<glm::vec4> params(sizeof(cm::AtmosphereParams) / 16 + 1);
        std::memcpy(params.data(), &sky.atmosphere, sizeof(cm::AtmosphereParams));
        params.back() = glm::vec4(sky.sunDirection, sky.sunAngularRadius);

        const Table kinds[] = {
            {0, cm::TRANSMITTANCE_LUT_OFFSET, cm::TRANSMITTANCE_LUT_WIDTH,
             cm::TRANSMITTANCE_LUT_HEIGHT},
            {1, cm::MULTISCATTER_LUT_OFFSET, cm::MULTISCATTER_LUT_SIZE, cm::MULTISCATTER_LUT_SIZE},
            {2, cm::SKYVIEW_LUT_OFFSET, cm::SKYVIEW_LUT_WIDTH, cm::SKYVIEW_LUT_HEIGHT},
            {3, cm::AMBIENT_ABOVE_LUT_OFFSET, cm::AMBIENT_LUT_SIZE, cm::AMBIENT_LUT_SIZE},
            {4, cm::AMBIENT_BELOW_LUT_OFFSET, cm::AMBIENT_LUT_SIZE, cm::AMBIENT_LUT_SIZE}};
        std::mt19937 rng(11);
        std::vector<glm::vec4> queries;
        std::vector<glm::vec4> expected;
        for (const Table& t : kinds)
            for (int n = 0; n < 48; ++n) {
                const int x = std::uniform_int_distribution<int>(0, t.width - 1)(rng);
                const int y = std::uniform_int_distribution<int>(0, t.height - 1)(rng);
                queries.emplace_back(float(t.kind), float(x), float(y), 0.0f);
                expected.push_back(tables[static_cast<size_t>(t.offset + y * t.width + x)]);
            }
        const auto groups = static_cast<uint32_t>((queries.size() + 63) / 64);
        const auto run = cloudscape::vulkan::runKernel(
            kKernels, sizeof kKernels,
            {params, tables, queries, std::vector<glm::vec4>(queries.size())}, groups, true);
        ASSERT_TRUE(run.validationMessages.empty()) << run.validationMessages.front();
        const std::vector<glm::vec4>& got = run.buffers[3];
        for (size_t i = 0; i < queries.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                // Float sums of up to 64 directions x 32 steps in another order and with the
                // device's exp/sqrt: agreement to 0.2 % of the value, or 1e-6 absolute where the
                // value is nearly zero (a clear-day sky is about 0.05 per unit irradiance).
                const double tolerance = 2e-3 * std::abs(expected[i][c]) + 1e-6;
                EXPECT_NEAR(got[i][c], expected[i][c], tolerance)
                    << "sun " << elevation << " table " << queries[i].x << " texel ("
                    << queries[i].y << ", " << queries[i].z << ") channel " << c;
            }
    }
}
