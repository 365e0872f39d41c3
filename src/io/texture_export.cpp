#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/texture_export.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace cloudscape {
namespace {

const char* formatName(int channels) {
    switch (channels) {
    case 1:
        return "R8_UNORM";
    case 2:
        return "R8G8_UNORM";
    case 3:
        return "R8G8B8_UNORM";
    default:
        return "R8G8B8A8_UNORM";
    }
}

inline uint8_t toUnorm8(float v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// Level 0 of a w x h x d texture (RGBA float, x fastest) written in all four forms.
void exportLevel(const std::vector<float>& texels, int w, int h, int d, int channels,
                 const std::string& directory, const std::string& name, AtomicFileSet& files) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(directory))
        throw Error(directory + ": output directory does not exist");
    if (channels < 1 || channels > 4)
        throw Error(name + ": invalid channel count " + std::to_string(channels));
    const fs::path base = fs::path(directory) / name;
    const size_t count = static_cast<size_t>(w) * h * d;

    std::vector<uint8_t> raw(count * channels);
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c)
            raw[i * channels + c] = toUnorm8(texels[i * 4 + c]);

    // Atlas: slice z goes to column z % columns, row z / columns.
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(d))));
    const int rows = (d + columns - 1) / columns;
    const int aw = columns * w;
    const int ah = rows * h;
    std::vector<uint8_t> atlas(static_cast<size_t>(aw) * ah * channels, 0);
    std::vector<std::vector<float>> planes(channels,
                                           std::vector<float>(static_cast<size_t>(aw) * ah));
    for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t src = (static_cast<size_t>(z) * h + y) * w + x;
                const size_t dst =
                    static_cast<size_t>((z / columns) * h + y) * aw + (z % columns) * w + x;
                for (int c = 0; c < channels; ++c) {
                    atlas[dst * channels + c] = raw[src * channels + c];
                    planes[c][dst] = texels[src * 4 + c];
                }
            }

    files.write(base.string() + ".png",
                [&](const std::string& path) { writePngChannels(path, aw, ah, channels, atlas); });
    files.write(base.string() + ".raw",
                [&](const std::string& path) { writeFileAtomic(path, raw.data(), raw.size()); });
    static const char* names[] = {"R", "G", "B", "A"};
    std::vector<ExrChannel> exr;
    for (int c = 0; c < channels; ++c)
        exr.push_back({names[c], planes[c].data()});
    files.write(base.string() + ".exr",
                [&](const std::string& path) { writeExr(path, aw, ah, exr); });

    nlohmann::json meta = {
        {"name", name},
        {"width", w},
        {"height", h},
        {"depth", d},
        {"channels", channels},
        {"format", formatName(channels)},
        {"layout", d > 1 ? "x fastest, then y, then z" : "x fastest, then y"},
        {"atlas_columns", columns},
        {"atlas_rows", rows},
        {"tiling", "wraps on every axis"},
    };
    const std::string text = meta.dump(2) + "\n";
    files.write(base.string() + ".json",
                [&](const std::string& path) { writeFileAtomic(path, text.data(), text.size()); });
}

} // namespace

std::vector<std::string> textureExportFiles(const std::string& directory, const std::string& name) {
    const std::string base = (std::filesystem::path(directory) / name).string();
    return {base + ".png", base + ".raw", base + ".exr", base + ".json"};
}

void exportTexture3D(const Texture3D& texture, int channels, const std::string& directory,
                     const std::string& name, AtomicFileSet& files) {
    exportLevel(texture.mips.at(0), texture.size, texture.size, texture.size, channels, directory,
                name, files);
}

void exportTexture2D(const Texture2D& texture, int channels, const std::string& directory,
                     const std::string& name, AtomicFileSet& files) {
    exportLevel(texture.mips.at(0), texture.width, texture.height, 1, channels, directory, name,
                files);
}

void exportTexture3D(const Texture3D& texture, int channels, const std::string& directory,
                     const std::string& name) {
    AtomicFileSet files;
    exportTexture3D(texture, channels, directory, name, files);
    files.commit();
}

void exportTexture2D(const Texture2D& texture, int channels, const std::string& directory,
                     const std::string& name) {
    AtomicFileSet files;
    exportTexture2D(texture, channels, directory, name, files);
    files.commit();
}

} // namespace cloudscape
