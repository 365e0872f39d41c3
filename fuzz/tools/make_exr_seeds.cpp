// Writes the EXR seeds of the depth_exr and checkpoint corpora (committed under fuzz/corpus; run
// again only to change them): small images in every compression, pixel type and layout OpenEXR
// reads, so the fuzzer starts from each of the decoder's paths.
//   c++ -std=c++20 fuzz/tools/make_exr_seeds.cpp $(pkg-config --cflags --libs OpenEXR) \
//       -o /tmp/make_exr_seeds && /tmp/make_exr_seeds fuzz/corpus
#include <OpenEXR/ImfBoxAttribute.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfDeepImageStateAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfEnvmapAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfKeyCodeAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfPreviewImageAttribute.h>
#include <OpenEXR/ImfRationalAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <OpenEXR/ImfTimeCodeAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

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
    float special = 0.0f;            // written into pixel 0 when non-zero (NaN, inf, negative)
    bool everyAttributeType = false; // one attribute of each type OpenEXR knows, and a preview
};

// An attribute of every type OpenEXR 3.1 reads, so the fuzzer starts from each of its readers
// (and the header walk, src/io/exr_header_check.cpp, is checked against what OpenEXR writes).
void insertEveryAttributeType(Imf::Header& h) {
    h.insert("a.box2f", Imf::Box2fAttribute(Imath::Box2f({0.5f, 1.5f}, {2.5f, 3.5f})));
    h.insert("a.box2i", Imf::Box2iAttribute(Imath::Box2i({1, 2}, {3, 4})));
    h.insert("a.chromaticities", Imf::ChromaticitiesAttribute(Imf::Chromaticities()));
    h.insert("a.deepImageState", Imf::DeepImageStateAttribute(Imf::DIS_TIDY));
    h.insert("a.double", Imf::DoubleAttribute(2.5));
    h.insert("a.envmap", Imf::EnvmapAttribute(Imf::ENVMAP_CUBE));
    h.insert("a.float", Imf::FloatAttribute(1.25f));
    h.insert("a.floatvector", Imf::FloatVectorAttribute({1.0f, 2.0f, 3.0f}));
    h.insert("a.int", Imf::IntAttribute(-7));
    h.insert("a.keycode", Imf::KeyCodeAttribute(Imf::KeyCode(1, 2, 3, 4, 5, 4, 64)));
    h.insert("a.m33d", Imf::M33dAttribute(Imath::M33d()));
    h.insert("a.m33f", Imf::M33fAttribute(Imath::M33f()));
    h.insert("a.m44d", Imf::M44dAttribute(Imath::M44d()));
    h.insert("a.m44f", Imf::M44fAttribute(Imath::M44f()));
    h.insert("a.rational", Imf::RationalAttribute(Imf::Rational(24000, 1001)));
    h.insert("a.stringvector", Imf::StringVectorAttribute({"one", "", "three"}));
    h.insert("a.timecode", Imf::TimeCodeAttribute(Imf::TimeCode(1, 2, 3, 4)));
    h.insert("a.v2d", Imf::V2dAttribute(Imath::V2d(1, 2)));
    h.insert("a.v2f", Imf::V2fAttribute(Imath::V2f(1, 2)));
    h.insert("a.v2i", Imf::V2iAttribute(Imath::V2i(1, 2)));
    h.insert("a.v3d", Imf::V3dAttribute(Imath::V3d(1, 2, 3)));
    h.insert("a.v3f", Imf::V3fAttribute(Imath::V3f(1, 2, 3)));
    h.insert("a.v3i", Imf::V3iAttribute(Imath::V3i(1, 2, 3)));
    std::vector<Imf::PreviewRgba> preview(3 * 2, Imf::PreviewRgba(10, 20, 30, 255));
    h.setPreviewImage(Imf::PreviewImage(3, 2, preview.data()));
}

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
    if (s.everyAttributeType)
        insertEveryAttributeType(header);
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
        {"none", Imf::NO_COMPRESSION},   {"rle", Imf::RLE_COMPRESSION},
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
    write(depth, {.file = "only_uint.exr",
                  .width = 4,
                  .height = 4,
                  .type = Imf::UINT,
                  .channels = {"depth"}});
    write(depth, {.file = "nan_and_inf.exr", .special = nan});
    write(depth, {.file = "inf.exr", .special = inf});
    write(depth, {.file = "negative.exr", .special = -5.0f});
    write(depth,
          {.file = "offset_window.exr", .width = 5, .height = 3, .offsetX = -3, .offsetY = 7});
    write(depth,
          {.file = "rgb_one_row.exr", .width = 16, .height = 1, .channels = {"B", "G", "R"}});
    write(depth, {.file = "two_channels_no_r.exr", .channels = {"X", "Y"}});
    write(depth, {.file = "tiled.exr", .tiled = true});
    write(depth, {.file = "tiled_mipmap_half.exr",
                  .compression = Imf::PIZ_COMPRESSION,
                  .type = Imf::HALF,
                  .tiled = true,
                  .levels = Imf::MIPMAP_LEVELS});
    write(depth, {.file = "tiled_ripmap.exr",
                  .width = 6,
                  .height = 5,
                  .tiled = true,
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
    write(depth, {.file = "every_attribute_type.exr", .everyAttributeType = true});
    write(checkpoint, {.file = "every_attribute_type.exr",
                       .channels = rgba,
                       .attributes = {{"cloudscape.samples", "16"}, {"cloudscape.scene", "fuzz"}},
                       .everyAttributeType = true});
    return 0;
}
