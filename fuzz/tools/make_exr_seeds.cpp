// Writes the EXR seeds of the depth_exr and checkpoint corpora (committed under fuzz/corpus; run
// again only to change them): small images in every compression, pixel type and layout OpenEXR
// reads, so the fuzzer starts from each of the decoder's paths.
//   c++ -std=c++20 fuzz/tools/make_exr_seeds.cpp $(pkg-config --cflags --libs OpenEXR) \
//       -o /tmp/make_exr_seeds && /tmp/make_exr_seeds fuzz/corpus
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace {

struct Spec {
    std::string file;
    int width = 8, height = 8;
    int offsetX = 0, offsetY = 0; // data window origin
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    Imf::PixelType type = Imf::FLOAT;
    std::vector<std::string> channels{"R"};
    bool tiled = false;
    Imf::LevelMode levels = Imf::ONE_LEVEL;
    std::vector<std::pair<std::string, std::string>> attributes;
    float special = 0.0f; // written into pixel 0 when non-zero (NaN, inf, negative)
};

// One plane of values in the channel's pixel type: a ramp of depths in metres.
struct Plane {
    std::vector<float> f;
    std::vector<half> h;
    std::vector<unsigned> u;
};

void write(const std::filesystem::path& dir, const Spec& s) {
    const Imath::Box2i window({s.offsetX, s.offsetY},
                              {s.offsetX + s.width - 1, s.offsetY + s.height - 1});
    Imf::Header header(window, window);
    header.compression() = s.compression;
    for (const auto& [name, value] : s.attributes)
        header.insert(name, Imf::StringAttribute(value));
    const size_t n = static_cast<size_t>(s.width) * s.height;
    std::vector<Plane> planes(s.channels.size());
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < s.channels.size(); ++c) {
        header.channels().insert(s.channels[c], Imf::Channel(s.type));
        Plane& p = planes[c];
        p.f.resize(n);
        for (size_t i = 0; i < n; ++i)
            p.f[i] = 50.0f * static_cast<float>(i + c);
        if (s.special != 0.0f)
            p.f[0] = s.special;
        p.h.assign(p.f.begin(), p.f.end());
        for (float v : p.f)
            p.u.push_back(std::isfinite(v) && v > 0 ? static_cast<unsigned>(v) : 0u);
        char* base = s.type == Imf::FLOAT  ? reinterpret_cast<char*>(p.f.data())
                     : s.type == Imf::HALF ? reinterpret_cast<char*>(p.h.data())
                                           : reinterpret_cast<char*>(p.u.data());
        const size_t bytes = s.type == Imf::HALF ? 2 : 4;
        base -= (static_cast<ptrdiff_t>(s.offsetX) + static_cast<ptrdiff_t>(s.offsetY) * s.width) *
                static_cast<ptrdiff_t>(bytes);
        frame.insert(s.channels[c], Imf::Slice(s.type, base, bytes, bytes * s.width));
    }
    const std::string path = (dir / s.file).string();
    if (s.tiled) {
        header.setTileDescription(Imf::TileDescription(4, 4, s.levels));
        Imf::TiledOutputFile out(path.c_str(), header);
        out.setFrameBuffer(frame);
        for (int ly = 0; ly < out.numYLevels(); ++ly)
            for (int lx = 0; lx < out.numXLevels(); ++lx) {
                if (s.levels != Imf::RIPMAP_LEVELS && lx != ly)
                    continue;
                out.writeTiles(0, out.numXTiles(lx) - 1, 0, out.numYTiles(ly) - 1, lx, ly);
            }
    } else {
        Imf::OutputFile out(path.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(s.height);
    }
}

} // namespace

int main(int argc, char** argv) {
    const std::filesystem::path root = argc > 1 ? argv[1] : "fuzz/corpus";
    const auto depth = root / "depth_exr", checkpoint = root / "checkpoint";
    std::filesystem::create_directories(depth);
    std::filesystem::create_directories(checkpoint);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();

    using C = Imf::Compression;
    const std::pair<const char*, C> compressions[] = {
        {"none", Imf::NO_COMPRESSION}, {"rle", Imf::RLE_COMPRESSION},
        {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION},
        {"piz", Imf::PIZ_COMPRESSION},   {"pxr24", Imf::PXR24_COMPRESSION},
        {"b44", Imf::B44_COMPRESSION},   {"b44a", Imf::B44A_COMPRESSION},
        {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION}};
    for (const auto& [name, compression] : compressions) {
        Spec s;
        s.file = std::string("r_float_") + name + ".exr";
        s.compression = compression;
        write(depth, s);
        s.file = std::string("z_half_") + name + ".exr";
        s.type = Imf::HALF;
        s.channels = {"Z"};
        write(depth, s);
    }
    write(depth, {.file = "only_uint.exr", .width = 4, .height = 4, .type = Imf::UINT,
                  .channels = {"depth"}});
    write(depth, {.file = "nan_and_inf.exr", .special = nan});
    write(depth, {.file = "inf.exr", .special = inf});
    write(depth, {.file = "negative.exr", .special = -5.0f});
    write(depth, {.file = "offset_window.exr", .width = 5, .height = 3, .offsetX = -3,
                  .offsetY = 7});
    write(depth, {.file = "rgb_one_row.exr", .width = 16, .height = 1,
                  .channels = {"B", "G", "R"}});
    write(depth, {.file = "two_channels_no_r.exr", .channels = {"X", "Y"}});
    write(depth, {.file = "tiled.exr", .tiled = true});
    write(depth, {.file = "tiled_mipmap_half.exr", .compression = Imf::PIZ_COMPRESSION,
                  .type = Imf::HALF, .tiled = true, .levels = Imf::MIPMAP_LEVELS});
    write(depth, {.file = "tiled_ripmap.exr", .width = 6, .height = 5, .tiled = true,
                  .levels = Imf::RIPMAP_LEVELS});

    const std::vector<std::string> rgba{"A", "B", "G", "R"};
    auto estimate = [&](const char* file, std::string samples, std::string scene, int w = 4,
                        int h = 4, std::vector<std::string> channels = {"A", "B", "G", "R"}) {
        Spec s{.file = file, .width = w, .height = h, .channels = std::move(channels)};
        if (!samples.empty())
            s.attributes.emplace_back("cloudscape.samples", samples);
        if (!scene.empty())
            s.attributes.emplace_back("cloudscape.scene", scene);
        write(checkpoint, s);
    };
    estimate("valid_16spp.exr", "16", "fuzz");
    estimate("valid_1x1.exr", "1", "fuzz", 1, 1);
    estimate("samples_not_a_number.exr", "abc", "fuzz");
    estimate("samples_negative.exr", "-5", "fuzz");
    estimate("samples_too_large.exr", "18446744073709551616", "fuzz");
    estimate("samples_trailing_text.exr", "16x", "fuzz");
    estimate("no_samples.exr", "", "fuzz");
    estimate("other_scene.exr", "16", "another scene");
    estimate("no_blue.exr", "16", "fuzz", 4, 4, {"G", "R"});
    return 0;
}
