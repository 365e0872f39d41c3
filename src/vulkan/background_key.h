#pragma once
// When a renderer's background buffers must be made again. Two levels (pixel.glsl.h):
// - the light (BackgroundLight per pixel: the terrain, ground or sky behind the clouds before the
//   clouds' shadows, and the geometry's depth), a pure function of the camera's rays, the
//   parameters it reads (the terrain's, the sky's and air's, the planet's radius, the march's far
//   end) and the terrain's and air's tables: a still camera keeps it through wind, coverage drags
//   and painting;
// - the background under this frame's clouds (BackgroundTexel: the light with the clouds' shadow
//   and the high layer applied), which also follows every cloud parameter and texture: a still
//   scene (the viewer between edits) keeps it too.
// A frame with a scene depth buffer makes both: the buffer's contents are not part of the keys.
// Plumbing only.
#include "model/params.glsl.h"
#include "core/kept_inputs.h"

#include <cstdint>
#include <cstring>

namespace cloudscape::vulkan {

// What cameraRayDirection reads of a FrameParams.
struct CameraRays {
    float position[3], forward[3], right[3], up[3];
    float tanHalfFov, aspect;
    int width, height;
    int backgroundSamples; // rays averaged per pixel
};

inline CameraRays cameraRaysOf(const model::FrameParams& f) {
    CameraRays c;
    std::memset(&c, 0, sizeof c);
    for (int i = 0; i < 3; ++i) {
        c.position[i] = f.cameraPosition[i];
        c.forward[i] = f.cameraForward[i];
        c.right[i] = f.cameraRight[i];
        c.up[i] = f.cameraUp[i];
    }
    c.tanHalfFov = f.tanHalfFov;
    c.aspect = f.aspect;
    c.width = f.width;
    c.height = f.height;
    c.backgroundSamples = f.backgroundSamples;
    return c;
}

class BackgroundKey {
public:
    // Whether this frame must make the light and whether it must apply the clouds to it (true
    // whenever the light was made). `pass` is the resolve's frame, `output` the upsample's (the
    // same at full resolution); lightTextures: ModelTextures::backgroundVersion(), allTextures:
    // contentVersion().
    struct Decision {
        bool makeLight = true;
        bool applyClouds = true;
    };
    Decision decide(const model::CloudParams& cloud, const model::FrameParams& pass,
                    const model::FrameParams& output, int features, uint64_t lightTextures,
                    uint64_t allTextures) {
        LightInputs light;
        std::memset(&light, 0, sizeof light);
        light.sky = cloud.sky;
        light.terrain = cloud.terrain;
        light.planetRadius = cloud.planetRadius;
        light.maxDistance = cloud.maxDistance;
        light.pass = cameraRaysOf(pass);
        light.output = cameraRaysOf(output);
        light.features = features;
        light.textures = lightTextures;
        CloudInputs clouds;
        std::memset(&clouds, 0, sizeof clouds);
        std::memcpy(&clouds.cloud, &cloud, sizeof cloud);
        clouds.textures = allTextures;
        Decision d;
        if (pass.hasSceneDepth != 0 || output.hasSceneDepth != 0) {
            invalidate();
            return d;
        }
        d.makeLight = light_.changed(light);
        d.applyClouds = clouds_.changed(clouds) || d.makeLight;
        return d;
    }
    // The buffers' contents are unknown (a new size, a failed submission).
    void invalidate() {
        light_.invalidate();
        clouds_.invalidate();
    }

private:
    struct LightInputs {
        model::SkyParams sky;
        model::TerrainParams terrain;
        float planetRadius;
        float maxDistance;
        CameraRays pass, output;
        int features;
        int pad;
        uint64_t textures;
    };
    struct CloudInputs { // with the light's key, everything the background reads
        model::CloudParams cloud;
        uint64_t textures;
    };
    KeptInputs<LightInputs> light_;
    KeptInputs<CloudInputs> clouds_;
};

} // namespace cloudscape::vulkan
