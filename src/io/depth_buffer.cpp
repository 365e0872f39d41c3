// render.depth_file: the scene depth buffer the march stops at.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/renderer.h>

#include <cmath>
#include <filesystem>
#include <limits>

namespace cloudscape {

DepthBuffer loadDepthBuffer(const std::string& path, int width, int height) {
    const std::string what = "render.depth_file '" + path + "'";
    if (!std::filesystem::is_regular_file(path))
        throw Error(what + ": no such file");
    const ExrImage image = readExr(path);
    const std::vector<float>* channel = nullptr;
    for (const char* name : {"R", "Z"})
        for (size_t i = 0; i < image.names.size() && !channel; ++i)
            if (image.names[i] == name)
                channel = &image.channels[i];
    if (!channel && image.names.size() == 1)
        channel = &image.channels[0];
    if (!channel)
        throw Error(what +
                    ": expected an R or Z channel (or a single channel) of depths in metres");
    if (image.width != width || image.height != height)
        throw Error(what + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " pixels, but the render is " + std::to_string(width) + "x" +
                    std::to_string(height) + " (render.width x render.height)");
    DepthBuffer d;
    d.width = width;
    d.height = height;
    d.metres = *channel;
    for (size_t i = 0; i < d.metres.size(); ++i) {
        float& m = d.metres[i];
        if (std::isnan(m)) {
            m = std::numeric_limits<float>::infinity(); // no geometry
        } else if (m < 0.0f) {
            throw Error(what + ": negative depth " + std::to_string(m) + " at pixel (" +
                        std::to_string(i % static_cast<size_t>(width)) + ", " +
                        std::to_string(i / static_cast<size_t>(width)) + ")");
        }
    }
    return d;
}

} // namespace cloudscape
