#pragma once
// Image files in and out. Every writer is atomic: it writes to a temporary file in the target's
// directory and renames it into place, so a failure leaves no partial file and never touches an
// existing file at the target path. Failures throw cloudscape::Error with a one-line message
// naming the path.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace cloudscape {

// 8-bit RGBA PNG from already tone-mapped, sRGB-encoded bytes (width*height*4).
void writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba);

// 8-bit PNG with 1..4 channels (used for texture slice atlases and weather maps).
void writePngChannels(const std::string& path, int width, int height, int channels,
                      const std::vector<uint8_t>& data);

// A named float channel of an EXR file; data holds width*height floats, row-major, top row
// first. Names with dots make layers ("cloud.R").
struct ExrChannel {
    std::string name;
    const float* data = nullptr;
};
// Scanline EXR, 32-bit float channels, ZIP compression, with optional string attributes in the
// header (name -> value; the path tracer keeps its sample count there).
void writeExr(const std::string& path, int width, int height,
              const std::vector<ExrChannel>& channels,
              const std::map<std::string, std::string>& attributes = {});

// The largest width or height the readers accept, render.width/height's limit: a file that
// claims more is refused before its pixels are allocated.
constexpr int kMaxImageSide = 16384;

// Read a PNG as 8-bit values; returns the data and sets width, height and channel count. Only
// PNG: a file without the PNG signature, whose chunks run past its end, or larger than
// kMaxImageSide on a side is refused before decoding.
std::vector<uint8_t> readPng(const std::string& path, int& width, int& height, int& channels);
// The same checks, for a 16-bit PNG only (height maps): values as they are in the file; an 8-bit
// (or 1, 2, 4-bit) PNG is refused with a message naming its depth.
std::vector<uint16_t> readPng16(const std::string& path, int& width, int& height, int& channels);

// Read a whole EXR back (for tests and `compare`): channel name -> width*height floats.
struct ExrImage {
    int width = 0;
    int height = 0;
    std::vector<std::string> names;
    std::vector<std::vector<float>> channels;
    std::map<std::string, std::string> attributes; // the header's string attributes
    std::string source;                            // the file it was read from, for messages
    const std::vector<float>& channel(const std::string& name) const; // throws if absent
};
// Hostile files: headers are walked before OpenEXR opens the file (every attribute inside it),
// at most kMaxImageSide a side and 2^28 values, and the planes grow as the pixels are
// decoded, so a small file that claims a large image fails having allocated about 4 MiB.
ExrImage readExr(const std::string& path);

// Write arbitrary bytes atomically (raw texture export). Same guarantees as above.
void writeFileAtomic(const std::string& path, const void* data, size_t size);

// Check up front that a file can be created at `path` (the directory exists and is writable)
// so a long render fails before it starts. Throws cloudscape::Error naming the path.
void checkOutputWritable(const std::string& path);

} // namespace cloudscape
