// The host-memory estimate (src/core/memory_estimate.cpp) counts the clouds' shadow map: a
// 2048^2 map is 64 MiB, which a render at a small size would otherwise not account for.
#include <cloudscape/error.h>
#include <cloudscape/memory_estimate.h>

#include <gtest/gtest.h>

#include <string>

using cloudscape::RenderJob;
using cloudscape::Scene;

TEST(MemoryEstimate, CountsTheCloudShadowMap) {
    Scene s;
    s.width = 64;
    s.height = 36;
    const uint64_t without = cloudscape::estimateRenderMemory(s, RenderJob::Sequence).total();
    EXPECT_EQ(cloudscape::cloudShadowMapBytes(s), 0u) << "off by default";
    s.cloudShadowEnabled = true;
    s.cloudShadowResolution = 2048;
    EXPECT_EQ(cloudscape::cloudShadowMapBytes(s), 64ull << 20);
    EXPECT_EQ(cloudscape::estimateRenderMemory(s, RenderJob::Sequence).total(),
              without + (64ull << 20));
    EXPECT_EQ(cloudscape::estimateRenderMemory(s, RenderJob::PathTrace).shadowMapBytes, 0u)
        << "the path tracer traces its shadows";
    // Refused up front, naming the map, when only a little more than the rest is available.
    try {
        cloudscape::requireHostMemory(s, RenderJob::Sequence, without + (1u << 20));
        ADD_FAILURE() << "a render that cannot hold its shadow map was accepted";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("shadow map"), std::string::npos) << e.what();
    }
}
