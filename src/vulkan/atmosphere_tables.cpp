#include "vulkan/atmosphere_tables.h"

#include "vulkan/frame_io.h"
#include "vulkan/march_pass.h"
#include "vulkan/submit.h"

#include <cstring>

namespace cloudscape::vulkan {
namespace {

const uint32_t kAtmosphereTablesSpirv[] = {
#include "shaders/atmosphere_tables.spv.inc"
};

// A timestamp before the first table and after each.
constexpr uint32_t kQueries = model::ATMOSPHERE_TABLE_COUNT + 1;

} // namespace

AtmosphereTables::AtmosphereTables(Context& ctx, const Buffer& tables)
    : ctx_(ctx), tables_(tables),
      pass_(ctx, model::TABLES_PASS, kAtmosphereTablesSpirv, sizeof kAtmosphereTablesSpirv, 1),
      resources_(ctx) {
    params_ =
        &resources_.hostBuffer(sizeof(model::SkyParams), vk::BufferUsageFlagBits::eStorageBuffer);
    set_ = pass_.allocateSet();
    DescriptorWriter(model::TABLES_PASS, set_)
        .buffer(model::TABLES_SKY_PARAMS, *params_)
        .buffer(model::TABLES_ATMOSPHERE, tables_)
        .commit(ctx_.device);
    queries_ = ctx_.device.createQueryPoolUnique({{}, vk::QueryType::eTimestamp, kQueries});
}

void AtmosphereTables::fill(const model::SkyParams& sky) {
    ctx_.device.waitIdle(); // nothing may still read the tables overwritten below
    std::memcpy(params_->mapped, &sky, sizeof sky);
    submitAndWait(ctx_, [&](vk::CommandBuffer cmd) { record(cmd); });
    const std::vector<double> ms = timestampsMs(ctx_, *queries_, kQueries);
    gpuMs_ = ms.empty() ? -1.0 : ms.back();
    for (size_t t = 0; t < tableMs_.size(); ++t)
        tableMs_[t] = ms.empty() ? -1.0 : ms[t + 1] - ms[t];
}

void AtmosphereTables::record(vk::CommandBuffer cmd) const {
    const bool timed = ctx_.timestampValidBits > 0;
    cmd.resetQueryPool(*queries_, 0, kQueries);
    if (timed)
        cmd.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *queries_, 0);
    pass_.bind(cmd, set_);
    for (int table = 0; table < model::ATMOSPHERE_TABLE_COUNT; ++table) {
        // Every table, the moon's too: its texels are zero while the moon is off, which
        // overwrites a previous night's.
        const glm::ivec3 layout = model::atmosphereTableLayout(table);
        pass_.push(cmd, model::TablesPush{table, 0, 0, 0});
        dispatchImage(cmd, layout.y, layout.z);
        // The next table reads this one; after the last, the renders that read them all.
        shaderWritesToShader(cmd);
        if (timed)
            cmd.writeTimestamp(vk::PipelineStageFlagBits::eComputeShader, *queries_,
                               static_cast<uint32_t>(table + 1));
    }
    shaderWritesToHost(cmd);
}

std::vector<glm::vec4> AtmosphereTables::texels() const {
    // Host memory may be non-coherent: invalidate before reading.
    ctx_.device.invalidateMappedMemoryRanges(
        vk::MappedMemoryRange(tables_.memory, 0, VK_WHOLE_SIZE));
    std::vector<glm::vec4> out(static_cast<size_t>(model::ATMOSPHERE_LUT_TEXELS));
    std::memcpy(out.data(), tables_.mapped, out.size() * sizeof(glm::vec4));
    return out;
}

} // namespace cloudscape::vulkan
