// Image files crafted against the readers: each case was found by a fuzz harness (fuzz/,
// docs/RELIABILITY.md) and is refused now with a one-line cloudscape::Error naming the file,
// before any decoding or pixel allocation.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

class HostileFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cloudscape_hostile_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::vector<uint8_t>& bytes) const {
        const std::string p = (dir_ / name).string();
        std::ofstream(p, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        return p;
    }

    // The message of the cloudscape::Error readPng throws ("" if it does not throw).
    static std::string pngError(const std::string& path) {
        try {
            int w = 0, h = 0, c = 0;
            cloudscape::readPng(path, w, h, c);
        } catch (const cloudscape::Error& e) {
            return e.what();
        }
        return "";
    }

    fs::path dir_;
};

} // namespace

// fuzz_weather_png: 70 bytes whose IDAT chunk declares 0x7000000d bytes; stb_image allocated
// the declared 1.8 GB before finding the file too short (a 43 s timeout under ASan).
TEST_F(HostileFiles, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
    const std::string p =
        write("chunk.png",
              {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
               0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00,
               0x00, 0x1f, 0x15, 0xc4, 0x89, 0x70, 0x00, 0x00, 0x0d, 0x49, 0x44, 0x41, 0x54, 0x78,
               0xda, 0x63, 0x10, 0x50, 0x30, 0xf8, 0x0f, 0x00, 0x02, 0x04, 0x01, 0x60, 0x52, 0xe2,
               0xa9, 0x61, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82});
    const std::string e = pngError(p);
    EXPECT_NE(e.find("chunk.png"), std::string::npos) << e;
    EXPECT_NE(e.find("past the end of the file"), std::string::npos) << e;
}

// stbi_load decodes whatever format it recognises; a GIF named .png loaded as a weather map.
TEST_F(HostileFiles, OnlyPngIsReadAsPng) {
    const std::string p =
        write("gif.png", {0x47, 0x49, 0x46, 0x38, 0x39, 0x61, 0x01, 0x00, 0x01, 0x00, 0x80,
                          0x00, 0x00, 0xff, 0xff, 0xff, 0x00, 0x00, 0x00, 0x21, 0xf9, 0x04,
                          0x01, 0x00, 0x00, 0x00, 0x00, 0x2c, 0x00, 0x00, 0x00, 0x00, 0x01,
                          0x00, 0x01, 0x00, 0x00, 0x02, 0x02, 0x44, 0x01, 0x00, 0x3b});
    const std::string e = pngError(p);
    EXPECT_NE(e.find("gif.png"), std::string::npos) << e;
    EXPECT_NE(e.find("not a PNG"), std::string::npos) << e;
}

TEST_F(HostileFiles, PngLargerThanTheLimitIsRefusedBeforeDecoding) {
    const int wide = cloudscape::kMaxImageSide + 1;
    const std::string p = (dir_ / "wide.png").string();
    cloudscape::writePngChannels(p, wide, 1, 1, std::vector<uint8_t>(wide, 7));
    const std::string e = pngError(p);
    EXPECT_NE(e.find(std::to_string(wide) + "x1 pixels"), std::string::npos) << e;

    const std::string ok = (dir_ / "ok.png").string();
    cloudscape::writePngChannels(ok, wide - 1, 1, 1, std::vector<uint8_t>(wide - 1, 7));
    EXPECT_EQ(pngError(ok), "");
}

TEST_F(HostileFiles, TruncatedPngNamesWhereItEnds) {
    const std::string full = (dir_ / "full.png").string();
    cloudscape::writePngChannels(full, 4, 4, 3, std::vector<uint8_t>(48, 9));
    std::ifstream in(full, std::ios::binary);
    std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    bytes.resize(bytes.size() - 12); // without IEND
    const std::string e = pngError(write("cut.png", bytes));
    EXPECT_NE(e.find("cut.png"), std::string::npos) << e;
    EXPECT_NE(e.find("truncated"), std::string::npos) << e;
}

// fuzz_weather_png: a PNG whose first IDAT chunk is empty made stb_image copy it to a null
// pointer (undefined behaviour; fuzz/regressions/weather_png/empty-first-idat.png). Empty IDAT
// chunks are dropped before decoding: the image is the same with or without them.
TEST_F(HostileFiles, EmptyIdatChunksDoNotChangeThePng) {
    const std::vector<uint8_t> rgb{10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120};
    const std::string plain = (dir_ / "plain.png").string();
    cloudscape::writePngChannels(plain, 2, 2, 3, rgb);
    std::ifstream in(plain, std::ios::binary);
    std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    const std::vector<uint8_t> emptyIdat{0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xaf, 0x06, 0x1e};
    const std::string idat = "IDAT", iend = "IEND";
    const auto firstIdat = std::search(bytes.begin(), bytes.end(), idat.begin(), idat.end()) - 4;
    bytes.insert(firstIdat, emptyIdat.begin(), emptyIdat.end());
    const auto end = std::search(bytes.begin(), bytes.end(), iend.begin(), iend.end()) - 4;
    bytes.insert(end, emptyIdat.begin(), emptyIdat.end());
    int w = 0, h = 0, c = 0;
    EXPECT_EQ(cloudscape::readPng(write("empty-idat.png", bytes), w, h, c), rgb);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(c, 3);
}

namespace {

std::vector<uint8_t> bytesOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::string exrError(const std::string& path) {
    try {
        cloudscape::readExr(path);
    } catch (const cloudscape::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

// fuzz_depth_exr, fuzz_checkpoint: a header attribute declaring about 2 GB in a file of 1 KB;
// OpenEXR allocated the declared size before reading the value.
TEST_F(HostileFiles, ExrAttributeLongerThanTheFileIsRefusedBeforeOpening) {
    const std::string good = (dir_ / "good.exr").string();
    const std::vector<float> r(4, 1.0f);
    cloudscape::writeExr(good, 2, 2, {{"R", r.data()}}, {{"note", "hello"}});
    std::vector<uint8_t> bytes = bytesOf(good);
    const std::string key("note\0string\0", 12);
    const auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
    ASSERT_NE(at, bytes.end());
    const size_t size = static_cast<size_t>(at - bytes.begin()) + key.size();
    bytes[size] = 0xf0, bytes[size + 1] = 0xff, bytes[size + 2] = 0xff, bytes[size + 3] = 0x7f;
    const std::string e = exrError(write("attribute.exr", bytes));
    EXPECT_NE(e.find("attribute.exr"), std::string::npos) << e;
    EXPECT_NE(e.find("attribute 'note' (string) declares 2147483632 bytes, past the end of the "
                     "file"),
              std::string::npos)
        << e;
    EXPECT_EQ(exrError(good), "");
}

// A writer killed mid-file leaves the table of scanline-block offsets after the header as
// zeros: OpenEXR then calls the file incomplete, and it is refused before any pixel memory.
TEST_F(HostileFiles, IncompleteExrIsRefusedBeforeItsPixelsAreAllocated) {
    const std::string full = (dir_ / "full.exr").string();
    std::vector<float> r(64 * 64);
    for (size_t i = 0; i < r.size(); ++i)
        r[i] = static_cast<float>(i % 17) * 0.37f + static_cast<float>(i) * 1e-3f;
    cloudscape::writeExr(full, 64, 64, {{"R", r.data()}});
    const std::vector<uint8_t> bytes = bytesOf(full);
    // The header's last attribute is screenWindowWidth, a float, then its terminating 0; then
    // the table of 4 offsets (64 rows, 16 per ZIP block).
    const std::string last("screenWindowWidth\0float\0", 24);
    const auto at = std::search(bytes.begin(), bytes.end(), last.begin(), last.end());
    ASSERT_NE(at, bytes.end());
    const size_t table = static_cast<size_t>(at - bytes.begin()) + last.size() + 4 + 4 + 1;
    std::vector<uint8_t> zeroed = bytes;
    std::fill(zeroed.begin() + table, zeroed.begin() + table + 32, 0);
    const std::string e = exrError(write("zeroed.exr", zeroed));
    EXPECT_NE(e.find("zeroed.exr"), std::string::npos) << e;
    EXPECT_NE(e.find("pixels are missing"), std::string::npos) << e;
    // Cut inside the pixel data, OpenEXR finds it while reading.
    const std::string cut = exrError(write("cut.exr", {bytes.begin(), bytes.end() - 200}));
    EXPECT_NE(cut.find("cut.exr: cannot read EXR"), std::string::npos) << cut;
    EXPECT_NE(exrError(write("text.exr", {'h', 'e', 'l', 'l', 'o'})).find("not an OpenEXR file"),
              std::string::npos);
}

// A data window one pixel wider than the limit, patched into a small valid file.
TEST_F(HostileFiles, ExrLargerThanTheLimitIsRefused) {
    const std::string good = (dir_ / "good.exr").string();
    const std::vector<float> r(2, 0.5f);
    cloudscape::writeExr(good, 2, 1, {{"R", r.data()}});
    std::vector<uint8_t> bytes = bytesOf(good);
    const std::string key("dataWindow\0box2i\0", 17);
    const auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
    ASSERT_NE(at, bytes.end());
    const size_t maxX = static_cast<size_t>(at - bytes.begin()) + key.size() + 4 + 8;
    const uint32_t x = cloudscape::kMaxImageSide; // xMax inclusive: one more than the limit
    for (int b = 0; b < 4; ++b)
        bytes[maxX + b] = static_cast<uint8_t>(x >> (8 * b));
    const std::string e = exrError(write("wide.exr", bytes));
    EXPECT_NE(e.find("wide.exr: cannot read EXR"), std::string::npos) << e;
    EXPECT_NE(e.find("maximum width"), std::string::npos) << e;
}

namespace {

// The process's peak resident memory so far, in MiB.
long peakResidentMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;
}

} // namespace

// fuzz_checkpoint: an 865-byte file whose header claims 16384 x 16384 pixels of one channel (the
// 2^28 values the reader allows), its table of DWAB blocks pointing every block at one empty
// block. The reader allocated and cleared the 1 GiB the header claims (1.2 GB of memory and 15 s
// under ASan) before OpenEXR found the pixels missing; the planes now grow as blocks decode, and
// it fails at the first block, naming the file and the rows.
TEST_F(HostileFiles, ExrClaimingMorePixelsThanItHoldsFailsBeforeAllocatingThem) {
    const std::string source = std::string(CLOUDSCAPE_SOURCE_DIR) +
                               "/fuzz/regressions/checkpoint/header-claims-16384x16384-pixels.exr";
    const std::string p = write("claims.exr", bytesOf(source));
    ASSERT_EQ(fs::file_size(p), 865u);
    const long before = peakResidentMiB();
    const std::string e = exrError(p);
    EXPECT_LT(peakResidentMiB() - before, 256) << "the reader allocated what the header claims";
    EXPECT_EQ(e.find(p + ": cannot read EXR: rows 0 to "), 0u) << e;
    EXPECT_NE(e.find("of a 16384x16384 image"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

// fuzz_checkpoint: a channel list attribute that declares 73 bytes but holds an 80-byte list.
// OpenEXR reads a channel list to its end, not to its declared size, so it went on reading the
// header 7 bytes off the walk that had checked it, and took a string's size from the middle of
// another attribute: 1.9 GB, allocated and cleared. The walk now requires every attribute of a
// type OpenEXR knows to declare what its value takes.
TEST_F(HostileFiles, ExrAttributeWhoseSizeDisagreesWithItsTypeIsRefused) {
    const std::string source = std::string(CLOUDSCAPE_SOURCE_DIR) +
                               "/fuzz/regressions/checkpoint/chlist-size-shifts-the-header.exr";
    const std::string p = write("shifted.exr", bytesOf(source));
    const long before = peakResidentMiB();
    const std::string e = exrError(p);
    EXPECT_LT(peakResidentMiB() - before, 256) << "OpenEXR read a size from the wrong place";
    EXPECT_EQ(e, p + ": cannot read EXR: attribute 'channels~' (chlist) declares 73 bytes, not "
                     "what a chlist takes");
}

// The walk knows the size of every attribute type OpenEXR writes: a file with one of each and a
// preview image (fuzz/tools/make_exr_seeds.cpp) is read.
TEST_F(HostileFiles, ExrWithEveryAttributeTypeIsRead) {
    const std::string source =
        std::string(CLOUDSCAPE_SOURCE_DIR) + "/fuzz/corpus/depth_exr/every_attribute_type.exr";
    EXPECT_EQ(exrError(source), "");
    const cloudscape::ExrImage image = cloudscape::readExr(source);
    EXPECT_EQ(image.width, 8);
    EXPECT_EQ(image.channel("R").size(), 64u);
}
