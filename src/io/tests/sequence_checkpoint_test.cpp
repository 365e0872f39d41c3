// The sequence checkpoint keeps the temporal state bit for bit, refuses what is not one, and its
// fingerprint changes with anything the frames depend on.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/keyframes.h>
#include <cloudscape/sequence_checkpoint.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace fs = std::filesystem;
using namespace cloudscape;

namespace {

class Checkpoint : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cloudscape_checkpoint_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// A state with awkward values: infinities (no cloud), negative zero, subnormals, values that
// need every mantissa bit.
TemporalState awkwardState() {
    TemporalState s;
    s.frameIndex = 23;
    s.timeS = 1.0f / 3.0f;
    s.width = 7;
    s.height = 5;
    s.frameParams.resize(96);
    for (size_t i = 0; i < s.frameParams.size(); ++i)
        s.frameParams[i] = static_cast<uint8_t>(i * 37 + 11);
    const size_t n = 35;
    for (size_t i = 0; i < n * 4; ++i)
        s.cloud.push_back(std::nextafter(0.1f * static_cast<float>(i), 1e9f));
    s.cloud[3] = -0.0f;
    s.cloud[7] = std::numeric_limits<float>::denorm_min();
    for (size_t i = 0; i < n; ++i) {
        s.depth.push_back(i % 3 == 0 ? std::numeric_limits<float>::infinity()
                                     : 1234.567f * static_cast<float>(i));
        s.weight.push_back(static_cast<float>(i % 9));
    }
    // A ring longer than one plane and not a whole number of them.
    s.gatherFrames.assign(40, 0x5a);
    for (size_t i = 0; i < 3 * n + 7; ++i)
        s.gatherRing.push_back(std::nextafter(-3.5f * static_cast<float>(i), -1e9f));
    return s;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

std::string errorOf(const std::string& path) {
    try {
        readSequenceCheckpoint(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_F(Checkpoint, RoundTripKeepsEveryBit) {
    const SequenceCheckpoint written{"0123456789abcdef", awkwardState()};
    writeSequenceCheckpoint(path("c.exr"), written);
    const SequenceCheckpoint read = readSequenceCheckpoint(path("c.exr"));
    EXPECT_EQ(read.fingerprint, written.fingerprint);
    EXPECT_EQ(read.state.frameIndex, 23);
    EXPECT_EQ(std::memcmp(&read.state.timeS, &written.state.timeS, sizeof(float)), 0);
    EXPECT_EQ(read.state.width, 7);
    EXPECT_EQ(read.state.height, 5);
    EXPECT_EQ(read.state.frameParams, written.state.frameParams);
    EXPECT_TRUE(sameBits(read.state.cloud, written.state.cloud));
    EXPECT_TRUE(sameBits(read.state.depth, written.state.depth));
    EXPECT_TRUE(sameBits(read.state.weight, written.state.weight));
    EXPECT_TRUE(std::signbit(read.state.cloud[3]));
    EXPECT_EQ(read.state.gatherFrames, written.state.gatherFrames);
    EXPECT_TRUE(sameBits(read.state.gatherRing, written.state.gatherRing));
}

TEST_F(Checkpoint, WhatIsNotACheckpointIsAOneLineErrorNamingTheFile) {
    std::ofstream(path("text.exr")) << "not an image";
    const float pixel[4] = {0, 0, 0, 0};
    writeExr(path("image.exr"), 2, 2, {{"R", pixel}});
    for (const char* name : {"text.exr", "image.exr", "missing.exr"}) {
        const std::string message = errorOf(path(name));
        EXPECT_NE(message.find(path(name)), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // A frame attribute that is not a number.
    SequenceCheckpoint c{"f", awkwardState()};
    writeSequenceCheckpoint(path("good.exr"), c);
    const ExrImage good = readExr(path("good.exr"));
    std::vector<ExrChannel> channels;
    for (size_t i = 0; i < good.names.size(); ++i)
        channels.push_back({good.names[i], good.channels[i].data()});
    auto attributes = good.attributes;
    attributes["cloudscape.frame"] = "twelve";
    writeExr(path("bad.exr"), good.width, good.height, channels, attributes);
    EXPECT_NE(errorOf(path("bad.exr")).find("damaged"), std::string::npos);
    // A ring size that is not a count, or far larger than its planes: damaged, one line.
    for (const char* count : {"-1", "12x", "99999999999999999999", "1000000"}) {
        attributes = good.attributes;
        attributes["cloudscape.gather_floats"] = count;
        writeExr(path("ring.exr"), good.width, good.height, channels, attributes);
        const std::string message = errorOf(path("ring.exr"));
        EXPECT_NE(message.find("damaged"), std::string::npos) << count << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // Nothing to checkpoint is refused, and writes nothing.
    EXPECT_THROW(writeSequenceCheckpoint(path("empty.exr"), {"f", TemporalState{}}), Error);
    EXPECT_FALSE(fs::exists(path("empty.exr")));
}

TEST_F(Checkpoint, TheFingerprintFollowsEverythingTheFramesDependOn) {
    SceneResources resources;
    resources.weather.width = resources.weather.height = 2;
    resources.weather.mips = {std::vector<float>(16, 0.5f)};
    const Scene scene;
    const std::string base = sequenceFingerprint(scene, resources, "slow-pan", "", 24.0f, 0, "cpu");
    EXPECT_EQ(base, sequenceFingerprint(scene, resources, "slow-pan", "", 24.0f, 0, "cpu"));
    Scene other = scene;
    other.coverage = std::nextafter(scene.coverage, 1.0f);
    EXPECT_NE(base, sequenceFingerprint(other, resources, "slow-pan", "", 24.0f, 0, "cpu"));
    other = scene;
    other.exposure = 2.0f; // changes the PNGs, not the history: still another sequence
    EXPECT_NE(base, sequenceFingerprint(other, resources, "slow-pan", "", 24.0f, 0, "cpu"));
    EXPECT_NE(base, sequenceFingerprint(scene, resources, "fast-pan", "", 24.0f, 0, "cpu"));
    EXPECT_NE(base, sequenceFingerprint(scene, resources, "slow-pan", "", 25.0f, 0, "cpu"));
    EXPECT_NE(base, sequenceFingerprint(scene, resources, "slow-pan", "", 24.0f, 1, "cpu"));
    EXPECT_NE(base, sequenceFingerprint(scene, resources, "slow-pan", "", 24.0f, 0, "vulkan: x"));
    // Keyframes: none, and two files that differ in one value.
    const cloudscape::Keyframes dawn = cloudscape::parseKeyframes(
        R"({"keyframes": [{"time_s": 0, "set": {"weather.coverage": 0.3}}]})", "a.json", scene);
    const cloudscape::Keyframes later = cloudscape::parseKeyframes(
        R"({"keyframes": [{"time_s": 0, "set": {"weather.coverage": 0.31}}]})", "b.json", scene);
    const std::string keyed =
        sequenceFingerprint(scene, resources, "slow-pan", dawn.fingerprintText(), 24.0f, 0, "cpu");
    EXPECT_NE(base, keyed);
    EXPECT_NE(keyed, sequenceFingerprint(scene, resources, "slow-pan", later.fingerprintText(),
                                         24.0f, 0, "cpu"));
    SceneResources painted = resources;
    painted.weather.mips[0][5] = 0.25f; // the same scene keys, another weather image
    EXPECT_NE(base, sequenceFingerprint(scene, painted, "slow-pan", "", 24.0f, 0, "cpu"));
}
