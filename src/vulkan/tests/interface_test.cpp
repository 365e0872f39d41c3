// The host/device interface (src/model/interface.glsl.h) against the compiled shaders: every
// binding a shader declares must be in its pass's table with the same descriptor kind (and the
// reverse), push-constant blocks and the records in storage buffers must have the C++ layout, and
// the parameter blocks the C++ offsets. Reads the SPIR-V words the backend loads; needs no device.
#include "model/features.glsl.h"
#include "model/interface.glsl.h"
#include "model/params.glsl.h"
#include "vulkan/tests/spirv_reflection.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace cm = cloudscape::model;
using cloudscape::testing::SpirvModule;

namespace {

const uint32_t kRenderClouds[] = {
#include "shaders/render_clouds.spv.inc"
};
const uint32_t kTemporalResolve[] = {
#include "shaders/temporal_resolve.spv.inc"
};
const uint32_t kUpsampleClouds[] = {
#include "shaders/upsample_clouds.spv.inc"
};
const uint32_t kCloudShadow[] = {
#include "shaders/cloud_shadow.spv.inc"
};
const uint32_t kAtmosphereTables[] = {
#include "shaders/atmosphere_tables.spv.inc"
};
const uint32_t kAtmosphereKernels[] = {
#include "shaders/atmosphere_kernels.spv.inc"
};
const uint32_t kModelKernels[] = {
#include "shaders/model_kernels.spv.inc"
};
const uint32_t kModelChecks[] = {
#include "shaders/model_checks.spv.inc"
};

SpirvModule moduleOf(const uint32_t* words, size_t bytes) {
    return SpirvModule(words, bytes / sizeof(uint32_t));
}

// Every compiled shader by name; modelPass marks the model's passes, which the backend
// specialises for a scene's features (the rest are tables and test kernels).
struct NamedShader {
    const char* name;
    SpirvModule module;
    bool modelPass;
};

std::vector<NamedShader> allShaders() {
    std::vector<NamedShader> shaders;
    shaders.push_back({"render_clouds", moduleOf(kRenderClouds, sizeof kRenderClouds), true});
    shaders.push_back(
        {"temporal_resolve", moduleOf(kTemporalResolve, sizeof kTemporalResolve), true});
    shaders.push_back({"upsample_clouds", moduleOf(kUpsampleClouds, sizeof kUpsampleClouds), true});
    shaders.push_back({"cloud_shadow", moduleOf(kCloudShadow, sizeof kCloudShadow), true});
    shaders.push_back(
        {"atmosphere_tables", moduleOf(kAtmosphereTables, sizeof kAtmosphereTables), false});
    shaders.push_back(
        {"atmosphere_kernels", moduleOf(kAtmosphereKernels, sizeof kAtmosphereKernels), false});
    shaders.push_back({"model_kernels", moduleOf(kModelKernels, sizeof kModelKernels), false});
    shaders.push_back({"model_checks", moduleOf(kModelChecks, sizeof kModelChecks), false});
    return shaders;
}

// Differences between a shader's descriptor bindings and a pass table, one line each; empty
// when they agree.
std::string bindingDifferences(const SpirvModule& shader, const cm::BindingSpec* table, int count) {
    std::ostringstream out;
    std::vector<bool> seen(static_cast<size_t>(count), false);
    for (const SpirvModule::Binding& b : shader.bindings()) {
        if (b.set != 0) {
            out << "binding " << b.binding << " is in set " << b.set << "\n";
            continue;
        }
        if (static_cast<int>(b.binding) >= count) {
            out << "binding " << b.binding << " is not in the table\n";
            continue;
        }
        seen[b.binding] = true;
        if (b.kind != table[b.binding].kind)
            out << "binding " << b.binding << " (" << table[b.binding].name
                << ") has another descriptor kind in the shader\n";
    }
    for (int i = 0; i < count; ++i)
        if (!seen[static_cast<size_t>(i)])
            out << "binding " << i << " (" << table[i].name << ") is not used by the shader\n";
    return out.str();
}

// The struct a buffer binding holds: the element of a runtime array (with its stride), or the
// block's only member.
struct BufferContent {
    uint32_t type = 0;
    uint32_t stride = 0; // 0: not an array
};
BufferContent contentOf(const SpirvModule& shader, int binding) {
    const auto b = shader.binding(0, static_cast<uint32_t>(binding));
    EXPECT_TRUE(b.has_value()) << "binding " << binding;
    if (!b)
        return {};
    const std::vector<uint32_t>& members = shader.members(b->blockType);
    EXPECT_EQ(members.size(), 1u) << "binding " << binding << ": one member per block";
    if (const auto array = shader.runtimeArray(members[0]))
        return {array->first, array->second};
    return {members[0], 0};
}

// A struct layout with no implicit padding, all of whose members are 4-byte scalars, vectors of
// them or such structs, is the C++ layout of the same declaration (C++ pads none of those), so
// one shared declaration plus this check and the size check proves std140/std430 = C++.
std::string paddingOf(const SpirvModule& shader, uint32_t type, const std::string& where) {
    std::ostringstream out;
    uint32_t end = 0;
    const std::vector<uint32_t> offsets = shader.memberOffsets(type);
    for (size_t m = 0; m < offsets.size(); ++m) {
        if (offsets[m] != end)
            out << where << " member " << m << " at offset " << offsets[m] << ", expected " << end
                << "\n";
        const uint32_t member = shader.members(type)[m];
        if (shader.isStruct(member))
            out << paddingOf(shader, member, where + "." + std::to_string(m));
        end = offsets[m] + shader.sizeOf(member);
    }
    return out.str();
}

template <class T> void expectRecords(const SpirvModule& shader, int binding) {
    const BufferContent c = contentOf(shader, binding);
    EXPECT_EQ(c.stride, sizeof(T)) << "binding " << binding;
    EXPECT_EQ(shader.sizeOf(c.type), sizeof(T)) << "binding " << binding;
    if (shader.isStruct(c.type)) {
        EXPECT_EQ(paddingOf(shader, c.type, "binding " + std::to_string(binding)), "");
    }
}

template <class T> void expectBlock(const SpirvModule& shader, int binding) {
    const BufferContent c = contentOf(shader, binding);
    EXPECT_EQ(c.stride, 0u) << "binding " << binding;
    EXPECT_EQ(shader.sizeOf(c.type), sizeof(T)) << "binding " << binding;
    EXPECT_EQ(paddingOf(shader, c.type, "binding " + std::to_string(binding)), "");
}

// A texel-buffer binding (bindingDifferences checks it has the table's kind). The records are
// whole RGBA32F rows (static_asserts in the model headers) and the host's views of them have that
// format, which a storage texel buffer must declare; a uniform one takes the view's (the
// terrain's R32F included).
void expectTexelBuffer(const SpirvModule& shader, int binding) {
    const auto b = shader.binding(0, static_cast<uint32_t>(binding));
    ASSERT_TRUE(b.has_value()) << "binding " << binding;
    if (b->kind == cm::DescriptorKind::StorageTexelBuffer) {
        EXPECT_EQ(shader.imageFormat(b->blockType), SpirvModule::kImageFormatRgba32f)
            << "binding " << binding;
    } else {
        EXPECT_EQ(b->kind, cm::DescriptorKind::UniformTexelBuffer) << "binding " << binding;
    }
}

template <class Push>
void expectPushBlock(const SpirvModule& shader, const cm::PassInterface& pass) {
    const uint32_t block = shader.pushConstantBlock();
    ASSERT_NE(block, 0u) << pass.shader;
    ASSERT_EQ(shader.members(block).size(), 1u) << pass.shader;
    EXPECT_EQ(shader.sizeOf(block), pass.pushConstantBytes) << pass.shader;
    EXPECT_EQ(sizeof(Push), pass.pushConstantBytes) << pass.shader;
    EXPECT_EQ(paddingOf(shader, block, pass.shader), "");
}

} // namespace

TEST(Interface, MarchShaderMatchesItsTable) {
    const SpirvModule shader = moduleOf(kRenderClouds, sizeof kRenderClouds);
    EXPECT_EQ(bindingDifferences(shader, cm::MARCH_BINDINGS, cm::MARCH_BINDING_COUNT), "");
    expectPushBlock<cm::MarchPush>(shader, cm::MARCH_PASS);
    expectBlock<cm::CloudParams>(shader, cm::MARCH_CLOUD_PARAMS);
    expectBlock<cm::FrameParams>(shader, cm::MARCH_FRAME_PARAMS);
    expectRecords<float>(shader, cm::MARCH_SCENE_DEPTH);
    for (int b : {cm::MARCH_OUT_CLOUD, cm::MARCH_OUT_COMPOSITE, cm::MARCH_ATMOSPHERE,
                  cm::MARCH_TERRAIN, cm::MARCH_CLOUD_SHADOW, cm::MARCH_NOISE_CLEARANCE})
        expectTexelBuffer(shader, b);
    expectBlock<cm::FrameCounters>(shader, cm::MARCH_COUNTERS);
}

TEST(Interface, ResolveShaderMatchesItsTable) {
    const SpirvModule shader = moduleOf(kTemporalResolve, sizeof kTemporalResolve);
    EXPECT_EQ(bindingDifferences(shader, cm::RESOLVE_BINDINGS, cm::RESOLVE_BINDING_COUNT), "");
    expectPushBlock<cm::ResolvePush>(shader, cm::RESOLVE_PASS);
    expectBlock<cm::CloudParams>(shader, cm::RESOLVE_CLOUD_PARAMS);
    expectBlock<cm::FrameParams>(shader, cm::RESOLVE_FRAME_PARAMS);
    expectBlock<cm::FrameParams>(shader, cm::RESOLVE_PREVIOUS_FRAME);
    for (int b : {cm::RESOLVE_HISTORY, cm::RESOLVE_FRESH, cm::RESOLVE_OUT_HISTORY,
                  cm::RESOLVE_OUT_COMPOSITE, cm::RESOLVE_ATMOSPHERE, cm::RESOLVE_TERRAIN,
                  cm::RESOLVE_CLOUD_SHADOW, cm::RESOLVE_BACKGROUND, cm::RESOLVE_BACKGROUND_SEEN,
                  cm::RESOLVE_SHAFTS})
        expectTexelBuffer(shader, b);
    expectRecords<float>(shader, cm::RESOLVE_SCENE_DEPTH);
    expectBlock<cm::FrameCounters>(shader, cm::RESOLVE_COUNTERS);
}

TEST(Interface, UpsampleShaderMatchesItsTable) {
    const SpirvModule shader = moduleOf(kUpsampleClouds, sizeof kUpsampleClouds);
    EXPECT_EQ(bindingDifferences(shader, cm::UPSAMPLE_BINDINGS, cm::UPSAMPLE_BINDING_COUNT), "");
    expectPushBlock<cm::UpsamplePush>(shader, cm::UPSAMPLE_PASS);
    expectBlock<cm::CloudParams>(shader, cm::UPSAMPLE_CLOUD_PARAMS);
    expectBlock<cm::FrameParams>(shader, cm::UPSAMPLE_FRAME_PARAMS);
    expectRecords<float>(shader, cm::UPSAMPLE_SCENE_DEPTH);
    for (int b : {cm::UPSAMPLE_IN_CLOUD, cm::UPSAMPLE_OUT_CLOUD, cm::UPSAMPLE_OUT_COMPOSITE,
                  cm::UPSAMPLE_ATMOSPHERE, cm::UPSAMPLE_TERRAIN, cm::UPSAMPLE_CLOUD_SHADOW,
                  cm::UPSAMPLE_BACKGROUND, cm::UPSAMPLE_BACKGROUND_SEEN, cm::UPSAMPLE_SHAFTS})
        expectTexelBuffer(shader, b);
}

TEST(Interface, CloudShadowShaderMatchesItsTable) {
    const SpirvModule shader = moduleOf(kCloudShadow, sizeof kCloudShadow);
    EXPECT_EQ(bindingDifferences(shader, cm::SHADOW_BINDINGS, cm::SHADOW_BINDING_COUNT), "");
    expectPushBlock<cm::ShadowPush>(shader, cm::SHADOW_PASS);
    expectBlock<cm::CloudParams>(shader, cm::SHADOW_CLOUD_PARAMS);
    expectTexelBuffer(shader, cm::SHADOW_OUT_MAP);
}

TEST(Interface, AtmosphereTablesShaderMatchesItsTable) {
    const SpirvModule shader = moduleOf(kAtmosphereTables, sizeof kAtmosphereTables);
    EXPECT_EQ(bindingDifferences(shader, cm::TABLES_BINDINGS, cm::TABLES_BINDING_COUNT), "");
    expectPushBlock<cm::TablesPush>(shader, cm::TABLES_PASS);
    expectBlock<cm::SkyParams>(shader, cm::TABLES_SKY_PARAMS);
    expectRecords<glm::vec4>(shader, cm::TABLES_ATMOSPHERE);
}

TEST(Interface, TheCheckCatchesADriftedTable) {
    // Two bindings of different kinds swapped in a copy of the table, and one left out: the
    // comparison the tests above rely on must report both.
    const SpirvModule shader = moduleOf(kRenderClouds, sizeof kRenderClouds);
    cm::BindingSpec drifted[cm::MARCH_BINDING_COUNT];
    std::copy(std::begin(cm::MARCH_BINDINGS), std::end(cm::MARCH_BINDINGS), drifted);
    std::swap(drifted[cm::MARCH_WEATHER_MAP].kind, drifted[cm::MARCH_SCENE_DEPTH].kind);
    const std::string swapped = bindingDifferences(shader, drifted, cm::MARCH_BINDING_COUNT);
    EXPECT_NE(swapped.find("binding 5"), std::string::npos) << swapped;
    EXPECT_NE(swapped.find("binding 7"), std::string::npos) << swapped;
    const std::string shorter =
        bindingDifferences(shader, cm::MARCH_BINDINGS, cm::MARCH_BINDING_COUNT - 1);
    EXPECT_NE(shorter.find("not in the table"), std::string::npos) << shorter;
}

// GLSL passes parameters by value: a model function given CloudParams works on a copy, and an
// array of it read at a computed index makes the copy a real local array, which llvmpipe keeps
// in scratch memory per invocation. CloudParams.cloudTops (256 vec4) read that way made the
// lavapipe march 7x slower (cloud_bound.glsl.h). No shader may hold a local array longer than
// a few elements.
TEST(Interface, NoShaderCopiesALargeArrayIntoLocals) {
    for (const NamedShader& shader : allShaders())
        EXPECT_LE(shader.module.largestLocalArray(), 16u) << shader.name;
}

TEST(Interface, TheLocalArrayCheckSeesAnArrayInALocalStruct) {
    // A hand-assembled module: a function-local struct { float; vec4[256]; }, as a by-value copy
    // of CloudParams became; the check must report its 256 elements.
    auto op = [](uint32_t code, std::vector<uint32_t> operands) {
        std::vector<uint32_t> words{static_cast<uint32_t>(operands.size() + 1) << 16 | code};
        words.insert(words.end(), operands.begin(), operands.end());
        return words;
    };
    std::vector<uint32_t> words{0x07230203u, 0x00010500u, 0u, 20u, 0u};
    for (const auto& i :
         {op(21, {1, 32, 0}), op(43, {1, 2, 256}), op(22, {3, 32}), op(23, {4, 3, 4}),
          op(28, {5, 4, 2}), op(30, {6, 3, 5}), op(32, {7, 7, 6}), op(59, {7, 8, 7})})
        words.insert(words.end(), i.begin(), i.end());
    EXPECT_EQ(SpirvModule(words.data(), words.size()).largestLocalArray(), 256u);
}

// The backend specialises the model's passes for a scene's features (compute_pass.cpp) through
// the constant id features.glsl.h names; a shader whose constant had another id would silently
// keep every feature (and its cost).
TEST(Interface, ModelPassesDeclareTheFeatureConstant) {
    for (const NamedShader& shader : allShaders()) {
        if (!shader.modelPass)
            continue;
        const std::vector<uint32_t> ids = shader.module.specIds();
        EXPECT_EQ(ids, std::vector<uint32_t>{uint32_t(cm::MODEL_FEATURES_CONSTANT_ID)})
            << shader.name;
    }
}
