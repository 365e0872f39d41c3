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

// Runs fill(x, y) for every texel of a table at `offset`, each worker reading the tables filled
// so far through its own thread binding.
template <typename Fill>
void fillTable(std::vector<glm::vec4>& texels, int offset, int width, int height, Fill fill) {
    cpu::TextureSet set;
    set.atmosphere = texels.data();
    tbb::parallel_for(0, height, [&](int y) {
        cpu::ScopedTextureBinding bind(set);
        for (int x = 0; x < width; ++x)
            texels[static_cast<size_t>(offset + y * width + x)] = fill(glm::ivec2(x, y));
    });
}

// The aerial-perspective volume for a source: its air light at `lightOffset` and, unless
// transmittanceOffset < 0, its transmittance there, one (slice, row) per task.
void fillAerialVolume(std::vector<glm::vec4>& texels, int lightOffset, int transmittanceOffset,
                      glm::vec3 sourceDir, float sourceRadius, const m::AtmosphereParams& a) {
    cpu::TextureSet set;
    set.atmosphere = texels.data();
    const int rows = m::AERIAL_LUT_DEPTH * m::AERIAL_LUT_HEIGHT;
    tbb::parallel_for(0, rows, [&](int row) {
        cpu::ScopedTextureBinding bind(set);
        const int z = row / m::AERIAL_LUT_HEIGHT, y = row % m::AERIAL_LUT_HEIGHT;
        for (int x = 0; x < m::AERIAL_LUT_WIDTH; ++x) {
            const m::ScatteredLight s =
                m::aerialLutTexel(glm::ivec3(x, y, z), sourceDir, sourceRadius, a);
            const size_t i = static_cast<size_t>(row * m::AERIAL_LUT_WIDTH + x);
            texels[static_cast<size_t>(lightOffset) + i] = glm::vec4(s.radiance, 1.0f);
            if (transmittanceOffset >= 0)
                texels[static_cast<size_t>(transmittanceOffset) + i] =
                    glm::vec4(s.transmittance, 1.0f);
        }
    });
}

} // namespace

std::vector<glm::vec4> computeAtmosphereLuts(const m::SkyParams& sky) {
    const m::AtmosphereParams& a = sky.atmosphere;
    std::vector<glm::vec4> t(static_cast<size_t>(m::ATMOSPHERE_LUT_TEXELS), glm::vec4(0.0f));
    fillTable(t, m::TRANSMITTANCE_LUT_OFFSET, m::TRANSMITTANCE_LUT_WIDTH,
              m::TRANSMITTANCE_LUT_HEIGHT,
              [&](glm::ivec2 texel) { return m::transmittanceLutTexel(texel, a); });
    fillTable(t, m::MULTISCATTER_LUT_OFFSET, m::MULTISCATTER_LUT_SIZE, m::MULTISCATTER_LUT_SIZE,
              [&](glm::ivec2 texel) { return m::multiScatterLutTexel(texel, a); });
    fillTable(t, m::SKYVIEW_LUT_OFFSET, m::SKYVIEW_LUT_WIDTH, m::SKYVIEW_LUT_HEIGHT,
              [&](glm::ivec2 texel) {
                  return m::skyViewLutTexel(texel, sky.sunDirection, sky.sunAngularRadius, a);
              });
    fillTable(t, m::AMBIENT_ABOVE_LUT_OFFSET, m::AMBIENT_LUT_SIZE, m::AMBIENT_LUT_SIZE,
              [&](glm::ivec2 texel) {
                  return m::ambientLutTexel(texel, false, sky.sunAngularRadius, a);
              });
    fillTable(
        t, m::AMBIENT_BELOW_LUT_OFFSET, m::AMBIENT_LUT_SIZE, m::AMBIENT_LUT_SIZE,
        [&](glm::ivec2 texel) { return m::ambientLutTexel(texel, true, sky.sunAngularRadius, a); });
    // The moon's sky view: the same texels for its direction (zero while it is off).
    if (sky.moonEnabled != 0)
        fillTable(t, m::MOON_SKYVIEW_LUT_OFFSET, m::SKYVIEW_LUT_WIDTH, m::SKYVIEW_LUT_HEIGHT,
                  [&](glm::ivec2 texel) {
                      return m::skyViewLutTexel(texel, sky.moonDirection, sky.moonAngularRadius, a);
                  });
    fillAerialVolume(t, m::AERIAL_SCATTER_LUT_OFFSET, m::AERIAL_TRANSMITTANCE_LUT_OFFSET,
                     sky.sunDirection, sky.sunAngularRadius, a);
    // The moon's air light (its transmittance is the sun's table's: the same air).
    if (sky.moonEnabled != 0)
        fillAerialVolume(t, m::MOON_AERIAL_SCATTER_LUT_OFFSET, -1, sky.moonDirection,
                         sky.moonAngularRadius, a);
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

void prepareAtmosphere(const Scene& scene, SceneResources& r) {
    const auto start = std::chrono::steady_clock::now();
    const m::SkyParams sky = makeSkyParams(scene);
    if (sky.atmosphere.enabled == 0) {
        r.atmosphere.clear();
        r.atmosphereInputs.clear();
        r.atmosphereSkyViewRadius = 0.0f;
        return;
    }
    r.atmosphere = computeAtmosphereLuts(sky);
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
