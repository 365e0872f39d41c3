#pragma once
// The CPU backend's texture sampling: trilinear filtering with wrap addressing and linear
// interpolation between mip levels, matching Vulkan's textureLod on a REPEAT/LINEAR/LINEAR-mip
// sampler (texel centres at (i + 0.5) / n). The model's sample* functions read the textures bound
// to the calling thread, which is how one copy of the model code finds its resources on the CPU.
#include <cloudscape/texture.h>

#include <glm/glm.hpp>

#include "model/interface.glsl.h"

namespace cloudscape::cpu {

glm::vec4 sampleTexture(const Texture3D& texture, glm::vec3 uvw, float lod);
glm::vec4 sampleTexture(const Texture2D& texture, glm::vec2 uv, float lod);

struct TextureSet {
    const Texture3D* baseNoise = nullptr;
    const Texture3D* detailNoise = nullptr;
    const Texture2D* curlNoise = nullptr;
    const Texture2D* weatherMap = nullptr;
    // The scene depth buffer at the render's size (metres along each view ray), when the frame
    // has one (FrameParams.hasSceneDepth); the blue-noise map needs no binding (one per process).
    const float* sceneDepth = nullptr;
    int sceneDepthWidth = 0;
    // The atmosphere's tables (SceneResources::atmosphere), read when the sky has one.
    const glm::vec4* atmosphere = nullptr;
    // The high-altitude layer's texture (NoiseTextures::highClouds), read when its coverage > 0.
    const Texture2D* highClouds = nullptr;
    // The terrain's height field (SceneResources::terrain.heights), read when the terrain is on.
    const float* terrain = nullptr;
    // The clouds' shadow map of this frame (computeCloudShadowMap), read when it is on.
    const glm::vec4* cloudShadow = nullptr;
    // The light shafts' grid (shaft_grid.glsl.h, shaftCellsX cells a row), when a pass reads one.
    const model::ShaftTexel* shafts = nullptr;
    int shaftCellsX = 0;
    // The base noise's clearance field (NoiseTextures::baseClearance), read by the march where
    // CloudParams.noiseClearanceSize says it is there.
    const uint32_t* noiseClearance = nullptr;
};

// Binds a texture set to the current thread for the lifetime of the object (nestable).
class ScopedTextureBinding {
public:
    explicit ScopedTextureBinding(const TextureSet& textures);
    ~ScopedTextureBinding();
    ScopedTextureBinding(const ScopedTextureBinding&) = delete;
    ScopedTextureBinding& operator=(const ScopedTextureBinding&) = delete;

private:
    const TextureSet* previous_;
};

} // namespace cloudscape::cpu
