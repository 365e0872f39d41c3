// The headers of an EXR, walked before OpenEXR opens the file. OpenEXR trusts a header: it
// allocates an attribute's declared size before reading it (a 1 KB file declaring a 2 GB
// attribute made it allocate 2 GB, found by fuzz_depth_exr and fuzz_checkpoint), and it reads a
// typed attribute as its type says, not as its declared size says, so a channel list or a box
// whose declared size is wrong shifts where it reads the next attribute from; from there a
// string's size was read from the middle of another attribute (1.9 GB, found by
// fuzz_checkpoint). So every attribute must lie inside the file, and an attribute of a type
// OpenEXR knows must declare exactly the bytes its value takes; then OpenEXR reads the header
// the way this walk did.
#include "io/exr_header_check.h"

#include <cloudscape/error.h>

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace cloudscape::io {
namespace {

uint32_t littleEndian32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

std::string printable(std::string text) {
    for (char& c : text)
        if (!std::isprint(static_cast<unsigned char>(c)))
            c = '?';
    return text;
}

// The size of a value of each fixed-size type OpenEXR reads (OpenEXR 3.1's registered types).
const std::map<std::string, int64_t>& fixedSizes() {
    static const std::map<std::string, int64_t> sizes = {
        {"box2f", 16},      {"box2i", 16},    {"chromaticities", 32},
        {"compression", 1}, {"double", 8},    {"deepImageState", 1},
        {"envmap", 1},      {"float", 4},     {"int", 4},
        {"keycode", 28},    {"lineOrder", 1}, {"m33d", 72},
        {"m33f", 36},       {"m44d", 128},    {"m44f", 64},
        {"rational", 8},    {"tiledesc", 9},  {"timecode", 8},
        {"v2d", 16},        {"v2f", 8},       {"v2i", 8},
        {"v3d", 24},        {"v3f", 12},      {"v3i", 12}};
    return sizes;
}

// The bytes a channel list takes as OpenEXR reads it: entries of a name (at most 255
// characters, NUL-terminated) and 16 bytes, up to an empty name. -1 if it runs past `value`.
int64_t channelListSize(const std::vector<unsigned char>& value) {
    size_t pos = 0;
    for (;;) {
        size_t length = 0;
        while (pos + length < value.size() && value[pos + length] != 0 && length <= 255)
            ++length;
        if (pos + length >= value.size() || length > 255)
            return -1;
        pos += length + 1;
        if (length == 0)
            return static_cast<int64_t>(pos);
        pos += 16; // pixel type, pLinear, 3 reserved bytes, x and y sampling
    }
}

// A string vector: strings of a 4-byte length and that many bytes, filling the value exactly.
bool isStringVector(const std::vector<unsigned char>& value) {
    size_t pos = 0;
    while (pos < value.size()) {
        if (value.size() - pos < 4)
            return false;
        const int64_t length = static_cast<int32_t>(littleEndian32(&value[pos]));
        pos += 4;
        if (length < 0 || length > static_cast<int64_t>(value.size() - pos))
            return false;
        pos += static_cast<size_t>(length);
    }
    return true;
}

// A preview image: width, height, then 4 bytes a pixel, filling the value exactly.
bool isPreview(const std::vector<unsigned char>& value) {
    if (value.size() < 8)
        return false;
    const int64_t w = static_cast<int32_t>(littleEndian32(&value[0]));
    const int64_t h = static_cast<int32_t>(littleEndian32(&value[4]));
    const size_t pixelBytes = value.size() - 8;
    // w * h < 2^62 fits; w * h * 4 might not (found by fuzz_depth_exr and fuzz_checkpoint).
    return w >= 0 && h >= 0 && pixelBytes % 4 == 0 && w * h == static_cast<int64_t>(pixelBytes / 4);
}

bool needsItsValueRead(const std::string& type) {
    return type == "chlist" || type == "stringvector" || type == "preview";
}

// Whether OpenEXR reads exactly `length` bytes for a value of this type (and, for the types
// whose value says how long it is, `value`).
bool valueFitsItsType(const std::string& type, int64_t length,
                      const std::vector<unsigned char>& value) {
    if (const auto fixed = fixedSizes().find(type); fixed != fixedSizes().end())
        return length == fixed->second;
    if (type == "floatvector")
        return length % 4 == 0;
    if (type == "chlist")
        return channelListSize(value) == length;
    if (type == "stringvector")
        return isStringVector(value);
    if (type == "preview")
        return isPreview(value);
    return true; // string, and types OpenEXR does not know: read as `length` bytes
}

} // namespace

void checkExrHeaders(const std::string& path) {
    const std::string what = path + ": cannot read EXR: ";
    std::error_code ec;
    const uintmax_t fileSize = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in)
        throw Error(what + (std::filesystem::exists(path) ? "cannot open it" : "no such file"));
    unsigned char head[8];
    if (!in.read(reinterpret_cast<char*>(head), 8) || littleEndian32(head) != 20000630)
        throw Error(what + "not an OpenEXR file (no EXR magic number)");
    const uint32_t flags = littleEndian32(head + 4);
    const size_t longestName = (flags & 0x400) ? 255 : 31;
    const bool multiPart = flags & 0x1000;
    auto readName = [&] {
        std::string name;
        for (char c; in.get(c) && c != '\0';)
            if ((name += c).size() > longestName)
                throw Error(what + "header name '" + printable(name) + "...' is longer than " +
                            std::to_string(longestName) + " characters");
        if (!in)
            throw Error(what + "truncated header");
        return name;
    };
    for (;;) {
        for (std::string name = readName(); !name.empty(); name = readName()) {
            const std::string type = readName();
            unsigned char size[4];
            if (!in.read(reinterpret_cast<char*>(size), 4))
                throw Error(what + "truncated header");
            const int64_t length = static_cast<int32_t>(littleEndian32(size));
            const auto at = static_cast<int64_t>(in.tellg());
            const std::string attribute = "attribute '" + printable(name) + "' (" +
                                          printable(type) + ") declares " + std::to_string(length) +
                                          " bytes";
            if (length < 0 || length > static_cast<int64_t>(fileSize) - at)
                throw Error(what + attribute + ", past the end of the file");
            std::vector<unsigned char> value;
            if (needsItsValueRead(type)) {
                value.resize(static_cast<size_t>(length));
                in.read(reinterpret_cast<char*>(value.data()), length);
            } else {
                in.seekg(length, std::ios::cur);
            }
            if (!in || !valueFitsItsType(type, length, value))
                throw Error(what + attribute + ", not what a " + printable(type) + " takes");
        }
        // A multi-part file has a header per part; an empty one ends them.
        if (!multiPart || in.peek() == 0 || in.peek() == EOF)
            return;
    }
}

} // namespace cloudscape::io
