// Height maps from files: a 16-bit greyscale PNG (the usual export of terrain tools) mapped to a
// height range, or a float EXR in metres. Every refusal is one line naming the file.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/terrain.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace cloudscape {
namespace {

constexpr float kMaxTerrainHeightM = 20000.0f;

void checkSide(const std::string& path, int width, int height) {
    if (width < kMinHeightMapSide || height < kMinHeightMapSide || width > kMaxHeightMapSide ||
        height > kMaxHeightMapSide)
        throw Error(path + ": height map is " + std::to_string(width) + "x" +
                    std::to_string(height) + " texels; expected " +
                    std::to_string(kMinHeightMapSide) + " to " + std::to_string(kMaxHeightMapSide) +
                    " on a side");
}

// Row 0 of an image is its top, the field's far (largest z) edge seen from above with x east and
// z north: flip so the field's row 0 is its smallest z.
HeightField fromImageRows(const std::vector<float>& values, int width, int height) {
    HeightField f;
    f.width = width;
    f.height = height;
    f.heights.resize(values.size());
    for (int row = 0; row < height; ++row)
        std::copy_n(values.begin() + size_t(row) * width, width,
                    f.heights.begin() + size_t(height - 1 - row) * width);
    return f;
}

HeightField loadPngHeights(const std::string& path, float minM, float maxM) {
    int width = 0, height = 0, channels = 0;
    const std::vector<uint16_t> data = readPng16(path, width, height, channels);
    checkSide(path, width, height);
    if (channels > 2)
        throw Error(path + ": a " + std::to_string(channels) +
                    "-channel PNG; expected a greyscale height map (1 channel, or 2 with alpha)");
    std::vector<float> values(size_t(width) * height);
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = minM + (maxM - minM) * (float(data[i * channels]) / 65535.0f);
    return fromImageRows(values, width, height);
}

HeightField loadExrHeights(const std::string& path) {
    const ExrImage image = readExr(path);
    checkSide(path, image.width, image.height);
    const std::vector<float>* channel = nullptr;
    for (const char* name : {"Y", "R"})
        for (size_t i = 0; i < image.names.size() && !channel; ++i)
            if (image.names[i] == name)
                channel = &image.channels[i];
    if (!channel && image.names.size() == 1)
        channel = &image.channels[0];
    if (!channel)
        throw Error(path + ": height map EXR has no Y or R channel (and more than one channel)");
    for (size_t i = 0; i < channel->size(); ++i) {
        const float h = (*channel)[i];
        if (!std::isfinite(h) || h < 0.0f || h > kMaxTerrainHeightM)
            throw Error(path + ": height map texel (" + std::to_string(i % image.width) + ", " +
                        std::to_string(i / image.width) + ") is " + std::to_string(h) +
                        "; expected a finite height in metres from 0 to 20000");
    }
    return fromImageRows(*channel, image.width, image.height);
}

} // namespace

HeightField loadHeightMap(const std::string& path, float minM, float maxM) {
    if (!std::filesystem::is_regular_file(path))
        throw Error(path + ": cannot read height map: no such file");
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".exr" || ext == ".EXR")
        return loadExrHeights(path);
    if (ext == ".png" || ext == ".PNG")
        return loadPngHeights(path, minM, maxM);
    throw Error(path + ": height map must be a 16-bit PNG (.png) or a float EXR (.exr)");
}

} // namespace cloudscape
