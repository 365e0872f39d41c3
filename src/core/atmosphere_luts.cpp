// Filling the atmosphere's tables on the host: see atmosphere_luts.h. Plumbing around the model's
// *LutTexel functions; no physics here.
#include "core/atmosphere_luts.h"

#include "core/model_params.h"
#include "cpu/cpu_textures.h"
#include "model/atmosphere.glsl.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <cstring>

namespace cloudscape {
namespace {

namespace m = model;

// Fills every texel of one table, each worker reading the tables filled so far through its own
// thread binding.
void fillTable(std::vector<glm::vec4>& texels, int table, const m::SkyParams& sky) {
    const glm::ivec3 layout = m::atmosphereTableLayout(table);
    cpu::TextureSet set;
    set.atmosphere = texels.data();
    tbb::parallel_for(0, layout.z, [&](int y) {
        cpu::ScopedTextureBinding bind(set);
        for (int x = 0; x < layout.y; ++x)
            texels[static_cast<size_t>(layout.x + y * layout.y + x)] =
                m::atmosphereTableTexel(table, glm::ivec2(x, y), sky);
    });
}

} // namespace

std::vector<glm::vec4> computeAtmosphereLuts(const m::SkyParams& sky) {
    std::vector<glm::vec4> t(static_cast<size_t>(m::ATMOSPHERE_LUT_TEXELS), glm::vec4(0.0f));
    // In the model's order, each table after those it reads. The moon's tables are zero while
    // the moon is off: the buffer already is, so they are not filled.
    for (int table = 0; table < m::ATMOSPHERE_TABLE_COUNT; ++table)
        if (!m::atmosphereTableIsMoons(table) || sky.moonEnabled != 0)
            fillTable(t, table, sky);
    return t;
}

std::vector<float> atmosphereLutInputs(const m::SkyParams& sky) {
    // The tables read the atmosphere block and, for the sky view and the ambient, the sun's
    // elevation and radius (never its irradiance: they are per unit irradiance); the moon's sky
    // view its elevation and radius while it is on.
    std::vector<float> inputs(sizeof(m::AtmosphereParams) / sizeof(float) + 2);
    std::memcpy(inputs.data(), &sky.atmosphere, sizeof(m::AtmosphereParams));
    inputs[inputs.size() - 2] = sky.sunDirection.y;
    inputs[inputs.size() - 1] = sky.sunAngularRadius;
    if (sky.moonEnabled != 0) {
        inputs.push_back(sky.moonDirection.y);
        inputs.push_back(sky.moonAngularRadius);
    }
    return inputs;
}

void prepareAtmosphere(const Scene& scene, SceneResources& r, const AtmosphereMaker& device) {
    const auto start = std::chrono::steady_clock::now();
    const m::SkyParams sky = makeSkyParams(scene);
    r.atmosphereOnDevice = false;
    if (sky.atmosphere.enabled == 0) {
        r.atmosphere.clear();
        r.atmosphereInputs.clear();
        r.atmosphereSkyViewRadius = 0.0f;
        return;
    }
    r.atmosphere = device ? device(sky) : computeAtmosphereLuts(sky);
    r.atmosphereOnDevice = static_cast<bool>(device);
    r.atmosphereInputs = atmosphereLutInputs(sky);
    r.atmosphereSkyViewRadius = sky.atmosphere.skyViewRadius;
    r.atmosphereSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool atmosphereChanged(const Scene& scene, const SceneResources& r) {
    const m::SkyParams sky = makeSkyParams(scene);
    if (sky.atmosphere.enabled == 0)
        return !r.atmosphere.empty();
    return r.atmosphere.empty() || atmosphereLutInputs(sky) != r.atmosphereInputs;
}

} // namespace cloudscape
