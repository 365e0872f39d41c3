// Terrain fixtures for the CPU tests: hand-made height fields, a scene with the terrain on, and
// the model's parameters with a field bound to the thread for the model's reads.
#pragma once

#include <cloudscape/scene.h>
#include <cloudscape/terrain.h>

#include "core/model_params.h"
#include "cpu/cpu_textures.h"
#include "small_resources.h"

#include <utility>

namespace cloudscape::test {

// A field of n x n texels over `extent` metres whose height is f(x, z) at texel centres
// (world metres from the field's centre).
template <class F> HeightField fieldOf(int n, float extent, F f) {
    HeightField h;
    h.width = h.height = n;
    h.heights.resize(size_t(n) * n);
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x)
            h.heights[size_t(z) * n + x] =
                f((x + 0.5f) / n * extent - 0.5f * extent, (z + 0.5f) / n * extent - 0.5f * extent);
    measureHeightField(h, extent / n, extent / n);
    return h;
}

// A scene with the terrain on over `extent` metres centred at the origin.
inline Scene terrainScene(float extent) {
    Scene s;
    s.width = 32;
    s.height = 20;
    s.weatherResolution = 64;
    s.terrainEnabled = true;
    s.terrainExtentM = extent;
    return s;
}

// The model's parameters for a scene and field, with the field bound to this thread.
struct BoundTerrain {
    HeightField field;
    model::CloudParams params;
    cpu::TextureSet set;
    cpu::ScopedTextureBinding binding;
    BoundTerrain(const Scene& s, HeightField f)
        : field(std::move(f)), params(makeParams(s, field)), set(textures(field)), binding(set) {}
    static model::CloudParams makeParams(const Scene& s, const HeightField& f) {
        model::CloudParams p = makeCloudParams(s, 0.0f);
        p.terrain = makeTerrainParams(s, f);
        return p;
    }
    // Small noise and a weather map too, for the clouds' shadow.
    static cpu::TextureSet textures(const HeightField& f) {
        static const SceneResources clouds = smallResources(terrainScene(1000.0f));
        cpu::TextureSet t{&clouds.noise.base, &clouds.noise.detail, &clouds.noise.curl,
                          &clouds.weather};
        t.terrain = f.heights.data();
        return t;
    }
};

} // namespace cloudscape::test
