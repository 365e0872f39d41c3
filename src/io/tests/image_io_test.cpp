#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/texture_export.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

class IoTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cloudscape_io_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    size_t entries() const {
        return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), {}));
    }
    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    fs::path dir_;
};

} // namespace

TEST_F(IoTest, PngRoundTrip) {
    std::vector<uint8_t> rgba(5 * 3 * 4);
    for (size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = static_cast<uint8_t>(i * 7);
    cloudscape::writePng(path("a.png"), 5, 3, rgba);
    int w, h, c;
    EXPECT_EQ(cloudscape::readPng(path("a.png"), w, h, c), rgba);
    EXPECT_EQ(w, 5);
    EXPECT_EQ(h, 3);
    EXPECT_EQ(c, 4);
}

TEST_F(IoTest, ExrRoundTripWithLayers) {
    std::vector<float> a = {1.0f, -2.0f, 3.5f, 1e6f, 0.0f, 7.0f};
    std::vector<float> t = {0.25f, 0.5f, 0.75f, 1.0f, 0.0f, 0.125f};
    cloudscape::writeExr(path("a.exr"), 3, 2, {{"R", a.data()}, {"cloud.T", t.data()}});
    const cloudscape::ExrImage img = cloudscape::readExr(path("a.exr"));
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.channel("R"), a);
    EXPECT_EQ(img.channel("cloud.T"), t);
    EXPECT_THROW(img.channel("nope"), cloudscape::Error);
}

// The reader decodes a block of rows at a time (about 2^20 values): an image of several blocks,
// whose blocks end inside OpenEXR's 16-row chunks, comes back exactly.
TEST_F(IoTest, ExrOfManyReadBlocksRoundTripsExactly) {
    const int w = 1031, h = 1029; // 2 channels: 508 rows a block, the last one short
    std::vector<float> r(static_cast<size_t>(w) * h), z(r.size());
    for (size_t i = 0; i < r.size(); ++i) {
        r[i] = static_cast<float>(i) * 0.25f;
        z[i] = 1.0f / static_cast<float>(i + 1);
    }
    cloudscape::writeExr(path("big.exr"), w, h, {{"R", r.data()}, {"Z", z.data()}});
    const cloudscape::ExrImage img = cloudscape::readExr(path("big.exr"));
    ASSERT_EQ(img.width, w);
    ASSERT_EQ(img.height, h);
    EXPECT_EQ(img.channel("R"), r);
    EXPECT_EQ(img.channel("Z"), z);
}

TEST_F(IoTest, FailedWritesLeaveNothingAndKeepExistingFiles) {
    const std::string keep = path("keep.png");
    std::ofstream(keep) << "precious";
    // Invalid arguments are rejected before anything is touched.
    EXPECT_THROW(cloudscape::writePng(keep, 0, 3, {}), cloudscape::Error);
    EXPECT_THROW(cloudscape::writePng(keep, 2, 2, std::vector<uint8_t>(3)), cloudscape::Error);
    // A directory that does not exist, a parent that is a file, a target that is a directory.
    EXPECT_THROW(cloudscape::writePng(path("no/dir/x.png"), 1, 1, std::vector<uint8_t>(4)),
                 cloudscape::Error);
    EXPECT_THROW(cloudscape::writePng(keep + "/x.png", 1, 1, std::vector<uint8_t>(4)),
                 cloudscape::Error);
    fs::create_directories(path("adir"));
    EXPECT_THROW(cloudscape::writePng(path("adir"), 1, 1, std::vector<uint8_t>(4)),
                 cloudscape::Error);
    const std::vector<float> one(1, 0.0f);
    EXPECT_THROW(cloudscape::writeExr(path("no/dir/x.exr"), 1, 1, {{"R", one.data()}}),
                 cloudscape::Error);
    EXPECT_EQ(read(keep), "precious");
    EXPECT_EQ(entries(), 2u) << "no temporary files may be left behind";
}

TEST_F(IoTest, ErrorsNameThePath) {
    try {
        int w, h, c;
        cloudscape::readPng(path("missing.png"), w, h, c);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    }
    std::ofstream(path("text.png")) << "not a png";
    try {
        int w, h, c;
        cloudscape::readPng(path("text.png"), w, h, c);
        FAIL();
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("text.png"), std::string::npos);
    }
    EXPECT_THROW(cloudscape::readExr(path("text.png")), cloudscape::Error);
    EXPECT_THROW(cloudscape::checkOutputWritable(""), cloudscape::Error);
    EXPECT_NO_THROW(cloudscape::checkOutputWritable(path("new.png")));
    EXPECT_FALSE(fs::exists(path("new.png"))) << "the check must not create the file";
}

TEST_F(IoTest, TextureExportWritesAllForms) {
    cloudscape::Texture3D t;
    t.size = 4;
    t.mips.assign(1, std::vector<float>(4 * 4 * 4 * 4));
    for (size_t i = 0; i < t.mips[0].size(); ++i)
        t.mips[0][i] = static_cast<float>(i % 256) / 255.0f;
    cloudscape::exportTexture3D(t, 3, dir_.string(), "tex");
    for (const char* ext : {".png", ".raw", ".exr", ".json"})
        EXPECT_TRUE(fs::exists(path(std::string("tex") + ext))) << ext;
    const std::string raw = read(path("tex.raw"));
    ASSERT_EQ(raw.size(), 4u * 4u * 4u * 3u);
    for (size_t texel = 0; texel < 64; ++texel)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(static_cast<uint8_t>(raw[texel * 3 + c]), (texel * 4 + c) % 256);
    int w, h, c;
    cloudscape::readPng(path("tex.png"), w, h, c);
    EXPECT_EQ(w, 2 * 4); // 4 slices in a 2 x 2 atlas
    EXPECT_EQ(h, 2 * 4);
    EXPECT_EQ(c, 3);
    EXPECT_NE(read(path("tex.json")).find("\"depth\": 4"), std::string::npos);
    EXPECT_THROW(cloudscape::exportTexture3D(t, 3, path("missing"), "tex"), cloudscape::Error);
}
