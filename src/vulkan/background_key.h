#pragma once
// When a renderer's background buffers (pixel.glsl.h's BackgroundTexel per pixel: the terrain,
// ground or sky behind the clouds, seen through the high layer, and the geometry's depth) must
// be filled again. The background is a pure function of the camera's rays, the parameters and
// the textures' contents, so a still camera over an unchanged scene (the viewer between edits)
// keeps it; any change of those fills it again. Plumbing only.
#include "model/params.glsl.h"

#include <cstdint>
#include <cstring>
#include <optional>

namespace cloudscape::vulkan {

class BackgroundKey {
public:
    // True when the buffers must be filled for a frame with these inputs; from then on they count
    // as holding it. `pass` is the resolve's frame, `output` the upsample's (the same when the
    // clouds are at full resolution). A frame with a scene depth buffer always fills: the
    // buffer's contents are not part of the key.
    bool needsFill(const model::CloudParams& cloud, const model::FrameParams& pass,
                   const model::FrameParams& output, int features, uint64_t texturesVersion) {
        Inputs now;
        std::memset(&now, 0, sizeof now); // padding included: the key is compared as bytes
        std::memcpy(&now.cloud, &cloud, sizeof cloud);
        now.pass = cameraOf(pass);
        now.output = cameraOf(output);
        now.features = features;
        now.texturesVersion = texturesVersion;
        const bool depthBuffer = pass.hasSceneDepth != 0 || output.hasSceneDepth != 0;
        if (!depthBuffer && holds_ && std::memcmp(&*holds_, &now, sizeof now) == 0)
            return false;
        holds_ = now;
        return true;
    }
    // The buffers' contents are unknown (a new size, a failed submission).
    void invalidate() { holds_.reset(); }

private:
    // What cameraRayDirection and the background read of a FrameParams.
    struct Camera {
        float position[3], forward[3], right[3], up[3];
        float tanHalfFov, aspect;
        int width, height;
    };
    static Camera cameraOf(const model::FrameParams& f) {
        Camera c{};
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
        return c;
    }
    struct Inputs {
        model::CloudParams cloud;
        Camera pass, output;
        int features;
        int pad;
        uint64_t texturesVersion;
    };
    std::optional<Inputs> holds_;
};

} // namespace cloudscape::vulkan
