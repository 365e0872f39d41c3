// GPU category: the model's behaviour through its GLSL build (model_checks.comp on the Vulkan
// device), checked against expectations written out by hand (src/model/tests/hand_references.h),
// not against the C++ build: Wrenninge's octaves, the wind drift of the temporal reprojection
// and the light cone's sample positions. A model bug would pass the CPU/GPU parity tests; these
// fail on it.
#include <cloudscape/scene.h>

#include "core/model_params.h"
#include "model/lighting.glsl.h"
#include "model/tests/hand_references.h"
#include "vulkan/kernel_runner.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace cm = cloudscape::model;
using cloudscape::Scene;

namespace {

const uint32_t kChecks[] = {
#include "shaders/model_checks.spv.inc"
};

// A query: kind, then up to six arguments (see model_checks.comp).
struct Query {
    glm::vec4 first;
    glm::vec4 second{0.0f};
};

std::vector<glm::vec4> runChecks(const Scene& scene, const std::vector<Query>& queries) {
    // The shader's weather map is analytic: coverage bias 0 reads its field as it is.
    const cm::CloudParams cloud = cloudscape::makeCloudParams(scene, 0.0f);
    const cm::FrameParams frame = cloudscape::makeFrameParams(scene);
    static_assert(sizeof cloud % 16 == 0 && sizeof frame % 16 == 0);
    std::vector<glm::vec4> params((sizeof cloud + sizeof frame) / 16);
    std::memcpy(params.data(), &cloud, sizeof cloud);
    std::memcpy(params.data() + sizeof cloud / 16, &frame, sizeof frame);
    std::vector<glm::vec4> in;
    for (const Query& q : queries) {
        in.push_back(q.first);
        in.push_back(q.second);
    }
    const auto groups = static_cast<uint32_t>((queries.size() + 63) / 64);
    const auto run = cloudscape::vulkan::runKernel(
        kChecks, sizeof kChecks, {params, in, std::vector<glm::vec4>(queries.size())}, groups,
        true);
    EXPECT_TRUE(run.validationMessages.empty()) << run.validationMessages.front();
    return run.buffers[2];
}

} // namespace

TEST(VulkanModelChecks, OctavesAreWrenningesSumWrittenOut) {
    Scene shipped;
    shipped.phaseFunction = cloudscape::PhaseFunctionKind::TwoLobe;
    Scene other = shipped;
    other.scatteringOctaves = 3;
    other.octaveFactors = {0.45f, 0.7f, 0.2f};
    other.powder = 0.6f;
    for (const Scene* s : {&shipped, &other}) {
        std::vector<Query> queries;
        for (float depth : {0.0f, 0.3f, 2.0f, 7.0f, 25.0f})
            for (float cosTheta : {-1.0f, -0.4f, 0.0f, 0.5f, 0.95f, 1.0f})
                queries.push_back({{0.0f, depth, cosTheta, 0.0f}});
        const auto out = runChecks(*s, queries);
        for (size_t i = 0; i < queries.size(); ++i) {
            const double expected =
                cloudscape::hand::octaves(*s, queries[i].first.y, queries[i].first.z);
            EXPECT_NEAR(out[i].x, expected, 1e-4 * expected + 1e-8)
                << "depth " << queries[i].first.y << " cos " << queries[i].first.z;
        }
    }
}

TEST(VulkanModelChecks, WindDriftIsWrittenOutFromTheWindKeys) {
    Scene s;
    s.width = 640;
    s.height = 360;
    s.cameraPosition = {0.0f, 2000.0f, 0.0f};
    s.cameraHeadingDeg = 0.0f;
    s.cameraPitchDeg = 0.0f;
    const cloudscape::hand::NorthCamera camera(s);
    for (float heading : {90.0f, 0.0f, 225.0f}) {
        s.windHeadingDeg = heading;
        s.windSpeedMps = 20.0f;
        s.updraft = 0.15f;
        std::vector<Query> queries;
        std::vector<glm::dvec2> expected;
        for (int i = 0; i < 8; ++i) {
            const float x = 40.0f + 75.0f * i, y = 30.0f + 40.0f * i, depth = 3000.0f + 700.0f * i;
            const float dt = 2.0f + 3.0f * i;
            queries.push_back({{1.0f, x, y, depth}, {dt, 0.0f, 0.0f, 0.0f}});
            const glm::dvec3 now = camera.position + camera.ray(x, y) * double(depth);
            expected.push_back(camera.project(now - cloudscape::hand::windDrift(s, dt)));
        }
        const auto out = runChecks(s, queries);
        for (size_t i = 0; i < queries.size(); ++i) {
            EXPECT_EQ(out[i].z, 1.0f) << "visible";
            EXPECT_NEAR(out[i].x, expected[i].x, 0.03) << "heading " << heading << " query " << i;
            EXPECT_NEAR(out[i].y, expected[i].y, 0.03) << "heading " << heading << " query " << i;
        }
    }
}

TEST(VulkanModelChecks, LightConeSamplesSitAtStepMiddlesInAWideningCone) {
    // The shader's density field is analytic; the optical depth the light march gathers must
    // equal the sum of that field at the hand-written cone positions (each read on the GPU too).
    for (int samples : {6, 10}) {
        Scene s;
        s.lightSamples = samples;
        s.rainAbsorption = 2.0f;
        const cm::CloudParams P = cloudscape::makeCloudParams(s, 0.0f);
        const glm::dvec3 sun(glm::vec3(P.sky.sunDirection));
        std::mt19937 rng(samples);
        std::uniform_real_distribution<float> xz(-20000.0f, 20000.0f), alt(1600.0f, 5000.0f);
        std::vector<Query> queries;
        std::vector<std::vector<cloudscape::hand::ConeSample>> cones;
        const int points = 40;
        for (int n = 0; n < points; ++n) {
            // Braces: drawn left to right (a call's arguments have no order).
            const glm::vec3 p{xz(rng), alt(rng), xz(rng)};
            const float precipitation = n % 4 == 0 ? 0.5f : 0.0f, lod = n % 2 ? 1.0f : 0.0f;
            const float cheap = n % 3 == 0 ? 1.0f : 0.0f;
            queries.push_back({{2.0f, p.x, p.y, p.z}, {precipitation, lod, cheap, 0.0f}});
            cones.push_back(cloudscape::hand::coneSamples(s, sun, glm::dvec3(p), cm::coneKernel));
        }
        // Then the density at every hand position, with the cheapness the point asked for (the
        // long sample is always cheap).
        for (int n = 0; n < points; ++n)
            for (const auto& c : cones[n]) {
                const glm::vec3 q(c.position);
                const float cheap = n % 3 == 0 || c.longSample ? 1.0f : 0.0f;
                queries.push_back({{3.0f, q.x, q.y, q.z}, {n % 2 ? 1.0f : 0.0f, cheap, 0.f, 0.f}});
            }
        const auto out = runChecks(s, queries);
        size_t next = points;
        int lit = 0;
        for (int n = 0; n < points; ++n) {
            double depth = 0.0;
            for (const auto& c : cones[n])
                depth += s.extinctionPerM * out[next++].x * c.weight;
            depth *= 1.0 + s.rainAbsorption * (n % 4 == 0 ? 0.5 : 0.0);
            EXPECT_NEAR(out[n].x, depth, 1e-4 * depth + 1e-6) << samples << " samples, point " << n;
            EXPECT_EQ(out[n].y, static_cast<float>(samples + 1));
            lit += depth > 0.1;
        }
        EXPECT_GT(lit, points / 2);
    }
}
