// Sequence checkpoints as EXR files: the history as float channels (exact: EXR stores the 32-bit
// patterns, ZIP is lossless), the scalars and the frame parameters as exact text attributes.
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/sequence_checkpoint.h>

#include "core/fnv1a.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace cloudscape {
namespace {

constexpr const char* kFormatAttribute = "cloudscape.checkpoint";
// Bump when the state's meaning or layout changes: older checkpoints are then refused.
// 2: FrameParams of 128 bytes and the ring of gathered marches. 3: the entering ring after the
// ring's records (sample_gather.glsl.h).
constexpr const char* kFormat = "temporal-sequence 3";
constexpr const char* kFingerprintAttribute = "cloudscape.fingerprint";
constexpr const char* kFrameAttribute = "cloudscape.frame";
constexpr const char* kTimeAttribute = "cloudscape.time_bits";
constexpr const char* kParamsAttribute = "cloudscape.frame_params";
const char* const kCloudChannels[4] = {"cloud.R", "cloud.G", "cloud.B", "cloud.T"};
// The ring of gathered marches (TemporalState::gatherRing): its floats in as many image-sized
// channels "gather.N" as they fill, the last padded with zeros; its frames' parameters as hex.
constexpr const char* kGatherFramesAttribute = "cloudscape.gather_frames";
constexpr const char* kGatherFloatsAttribute = "cloudscape.gather_floats";

std::string gatherChannel(size_t plane) {
    return "gather." + std::to_string(plane);
}

std::string hexOf(const uint8_t* bytes, size_t size) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (size_t i = 0; i < size; ++i) {
        out += digits[bytes[i] >> 4];
        out += digits[bytes[i] & 15];
    }
    return out;
}

// Returns false on anything but an even number of hex digits.
bool bytesOfHex(const std::string& hex, std::vector<uint8_t>& out) {
    auto nibble = [](char c) {
        return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    };
    if (hex.size() % 2 != 0)
        return false;
    out.clear();
    for (size_t i = 0; i < hex.size(); i += 2) {
        const int hi = nibble(hex[i]), lo = nibble(hex[i + 1]);
        if (hi < 0 || lo < 0)
            return false;
        out.push_back(static_cast<uint8_t>(hi * 16 + lo));
    }
    return true;
}

const std::string& attribute(const ExrImage& exr, const char* name, const std::string& path) {
    const auto it = exr.attributes.find(name);
    if (it == exr.attributes.end())
        throw Error(path + ": not a cloudscape sequence checkpoint (no " + name + " attribute)");
    return it->second;
}

// The ring of gathered marches written by writeSequenceCheckpoint; its size checked against the
// frames by checkTemporalState when the state is taken.
void readGatherRing(const ExrImage& exr, const std::string& path, TemporalState& s) {
    if (!bytesOfHex(attribute(exr, kGatherFramesAttribute, path), s.gatherFrames))
        throw Error("the gathered frames' parameters are not hex");
    const std::string& count = attribute(exr, kGatherFloatsAttribute, path);
    size_t floats = 0;
    const bool digits =
        !count.empty() && count.size() <= 18 &&
        std::all_of(count.begin(), count.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits)
        throw Error("the ring's size '" + count + "' is not a count");
    floats = std::stoull(count);
    const size_t pixels = static_cast<size_t>(s.width) * s.height;
    // 16 frames of 2x2 blocks of 8 floats take 32 planes (a 1x1 image's 128) at most.
    if (floats / pixels > 4096)
        throw Error("a ring of " + count + " floats is too large for its image");
    const size_t planes = (floats + pixels - 1) / pixels;
    s.gatherRing.clear();
    for (size_t plane = 0; plane < planes; ++plane) {
        const std::vector<float>& values = exr.channel(gatherChannel(plane));
        s.gatherRing.insert(s.gatherRing.end(), values.begin(), values.end());
    }
    s.gatherRing.resize(floats);
}

} // namespace

void writeSequenceCheckpoint(const std::string& path, const SequenceCheckpoint& checkpoint) {
    const TemporalState& s = checkpoint.state;
    if (s.empty())
        throw Error("cannot write " + path + ": no temporal history to checkpoint");
    const size_t pixels = static_cast<size_t>(s.width) * s.height;
    std::vector<std::vector<float>> planes(4, std::vector<float>(pixels));
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 4; ++c)
            planes[c][i] = s.cloud[i * 4 + c];
    uint32_t timeBits = 0;
    std::memcpy(&timeBits, &s.timeS, sizeof timeBits);
    char timeText[16];
    std::snprintf(timeText, sizeof timeText, "%08x", timeBits);
    const std::vector<float> noFlash =
        s.flash.empty() ? std::vector<float>(pixels) : std::vector<float>{};
    // The ring, padded to whole planes (names kept alive for the channel list).
    std::vector<float> ring = s.gatherRing;
    ring.resize((ring.size() + pixels - 1) / pixels * pixels, 0.0f);
    std::vector<std::string> ringNames;
    for (size_t plane = 0; plane < ring.size() / pixels; ++plane)
        ringNames.push_back(gatherChannel(plane));
    std::vector<ExrChannel> channels = {
        {kCloudChannels[0], planes[0].data()},
        {kCloudChannels[1], planes[1].data()},
        {kCloudChannels[2], planes[2].data()},
        {kCloudChannels[3], planes[3].data()},
        {"depth", s.depth.data()},
        {"weight", s.weight.data()},
        {"flash", s.flash.empty() ? noFlash.data() : s.flash.data()}};
    for (size_t plane = 0; plane < ringNames.size(); ++plane)
        channels.push_back({ringNames[plane], ring.data() + plane * pixels});
    writeExr(path, s.width, s.height, channels,
             {{kFormatAttribute, kFormat},
              {kFingerprintAttribute, checkpoint.fingerprint},
              {kFrameAttribute, std::to_string(s.frameIndex)},
              {kTimeAttribute, timeText},
              {kParamsAttribute, hexOf(s.frameParams.data(), s.frameParams.size())},
              {kGatherFramesAttribute, hexOf(s.gatherFrames.data(), s.gatherFrames.size())},
              {kGatherFloatsAttribute, std::to_string(s.gatherRing.size())}});
}

SequenceCheckpoint readSequenceCheckpoint(const std::string& path) {
    ExrImage exr;
    try {
        exr = readExr(path);
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + " (not a sequence checkpoint?)");
    }
    if (attribute(exr, kFormatAttribute, path) != kFormat)
        throw Error(path + ": a sequence checkpoint of another format (" +
                    exr.attributes.at(kFormatAttribute) + ", expected " + kFormat + ")");
    SequenceCheckpoint checkpoint;
    checkpoint.fingerprint = attribute(exr, kFingerprintAttribute, path);
    TemporalState& s = checkpoint.state;
    s.width = exr.width;
    s.height = exr.height;
    const std::string& frame = attribute(exr, kFrameAttribute, path);
    const std::string& time = attribute(exr, kTimeAttribute, path);
    unsigned timeBits = 0;
    int consumed = 0;
    try {
        size_t end = 0;
        s.frameIndex = std::stoi(frame, &end);
        if (end != frame.size() || s.frameIndex < 0)
            throw std::invalid_argument("frame");
        if (std::sscanf(time.c_str(), "%8x%n", &timeBits, &consumed) != 1 ||
            consumed != static_cast<int>(time.size()) || time.size() != 8)
            throw std::invalid_argument("time");
    } catch (const std::exception&) {
        throw Error(path + ": damaged sequence checkpoint (frame '" + frame + "', time '" + time +
                    "')");
    }
    const uint32_t bits = timeBits;
    std::memcpy(&s.timeS, &bits, sizeof bits);
    if (!bytesOfHex(attribute(exr, kParamsAttribute, path), s.frameParams))
        throw Error(path + ": damaged sequence checkpoint (frame parameters are not hex)");
    try {
        const size_t pixels = static_cast<size_t>(s.width) * s.height;
        s.cloud.resize(pixels * 4);
        for (int c = 0; c < 4; ++c) {
            const std::vector<float>& plane = exr.channel(kCloudChannels[c]);
            for (size_t i = 0; i < pixels; ++i)
                s.cloud[i * 4 + c] = plane[i];
        }
        s.depth = exr.channel("depth");
        s.weight = exr.channel("weight");
        // Written since the lightning's flash channel was kept (checkpoints from before have
        // none: their history starts without a flash, as it then did).
        if (std::find(exr.names.begin(), exr.names.end(), "flash") != exr.names.end())
            s.flash = exr.channel("flash");
        readGatherRing(exr, path, s);
    } catch (const Error& e) {
        throw Error(path + ": damaged sequence checkpoint (" + e.what() + ")");
    }
    return checkpoint;
}

std::string sequenceFingerprint(const Scene& base, const SceneResources& resources,
                                const std::string& cameraPath, const std::string& keyframes,
                                float fps, int firstFrame, const std::string& backend) {
    // Bump when the temporal reconstruction changes what a history means.
    constexpr uint64_t kVersion = 1;
    uint64_t h = fnv1a(&kVersion, sizeof kVersion);
    const std::string settings = sceneSettingsText(base);
    for (const std::string* text : {&settings, &cameraPath, &keyframes, &backend}) {
        const uint64_t size = text->size(); // lengths too, so boundaries cannot shift
        h = fnv1a(&size, sizeof size, h);
        h = fnv1a(text->data(), text->size(), h);
    }
    h = fnv1a(&fps, sizeof fps, h);
    h = fnv1a(&firstFrame, sizeof firstFrame, h);
    for (const auto& level : resources.weather.mips)
        h = fnv1a(level.data(), level.size() * sizeof(float), h);
    h = fnv1a(resources.depth.metres.data(), resources.depth.metres.size() * sizeof(float), h);
    char text[32];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

} // namespace cloudscape
