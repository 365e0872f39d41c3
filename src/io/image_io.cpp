// PNG and EXR in and out, with atomic writes: temp file in the target's directory, then rename.
#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include "io/exr_header_check.h"
#include "io/fault_injection.h"
#include "io/sync_to_disk.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <thread>
#include <unistd.h>

namespace cloudscape {
namespace fs = std::filesystem;

namespace {

std::string systemError() {
    return std::strerror(errno);
}

void requireImageArgs(const std::string& path, int width, int height, int channels,
                      size_t dataSize) {
    if (width <= 0 || height <= 0)
        throw Error(path + ": invalid image size " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (channels < 1 || channels > 4)
        throw Error(path + ": invalid channel count " + std::to_string(channels));
    const size_t expected = static_cast<size_t>(width) * height * channels;
    if (dataSize != expected)
        throw Error(path + ": image data has " + std::to_string(dataSize) + " values, expected " +
                    std::to_string(expected));
}

// Renames a finished temp file into place, or removes it and throws. The temp file's data is
// on disk before the rename and the rename itself is on disk after it (the directory is
// synced), so a power cut leaves the old file or the new one, never an empty one.
void commitTemporary(const std::string& temp, const std::string& path) {
    if (!io::syncToDisk(temp, false)) {
        const std::string reason = systemError();
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw Error("cannot write " + path + ": " + reason);
    }
    io::faultBeforeCommit(temp, path); // tests only (CLOUDSCAPE_TEST_FAULT)
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) {
        const std::string reason = ec.message(); // before remove() reuses nothing of it
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw Error("cannot write " + path + ": " + reason);
    }
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!io::syncToDisk(dir.string(), true))
        throw Error("cannot write " + path + ": syncing directory " + dir.string() + ": " +
                    systemError());
    io::faultAfterCommit(path);
}

} // namespace

void checkOutputWritable(const std::string& path) {
    if (path.empty())
        throw Error("output path is empty");
    const fs::path target(path);
    std::error_code ec;
    if (fs::is_directory(target, ec))
        throw Error("cannot write " + path + ": it is a directory");
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec))
        throw Error("cannot write " + path + ": directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw Error("cannot write " + path + ": directory " + dir.string() + " is not writable (" +
                    systemError() + ")");
}

void writeFileAtomic(const std::string& path, const void* data, size_t size) {
    checkOutputWritable(path);
    const std::string temp = temporaryPathFor(path);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        throw Error("cannot write " + path + ": " + systemError());
    const char* bytes = static_cast<const char*>(data);
    size_t written = 0;
    while (written < size) {
        const ssize_t n = ::write(fd, bytes + written, size - written);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const std::string reason = systemError();
            ::close(fd);
            ::unlink(temp.c_str());
            throw Error("cannot write " + path + ": " + reason);
        }
        written += static_cast<size_t>(n);
    }
    if (::close(fd) != 0) { // commitTemporary syncs the data before the rename
        const std::string reason = systemError();
        ::unlink(temp.c_str());
        throw Error("cannot write " + path + ": " + reason);
    }
    commitTemporary(temp, path);
}

void writePngChannels(const std::string& path, int width, int height, int channels,
                      const std::vector<uint8_t>& data) {
    requireImageArgs(path, width, height, channels, data.size());
    std::vector<uint8_t> encoded;
    auto sink = [](void* context, void* bytes, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(context);
        const auto* b = static_cast<const uint8_t*>(bytes);
        out->insert(out->end(), b, b + size);
    };
    if (!stbi_write_png_to_func(sink, &encoded, width, height, channels, data.data(),
                                width * channels))
        throw Error("cannot write " + path + ": PNG encoding failed");
    writeFileAtomic(path, encoded.data(), encoded.size());
}

void writePng(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba) {
    writePngChannels(path, width, height, 4, rgba);
}

namespace {

// OpenEXR's limit on image and tile sizes, checked whenever it opens a file, for reading or for
// writing; set once, before the first use of either, so a reader refuses a larger file before
// allocating its pixels and a writer never produces a file the readers would refuse. Also once:
// a thread pool for the writer's compression of line blocks, which a sequence's EXRs otherwise
// did on one core between frames (the bytes written are the same). A 720-row frame has 45 ZIP
// blocks, so a few threads suffice; without them (the pool failed to start) writes run serially.
void configureOpenExr() {
    static const bool configured = [] {
        Imf::Header::setMaxImageSize(kMaxImageSide, kMaxImageSide);
        Imf::Header::setMaxTileSize(kMaxImageSide, kMaxImageSide);
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        try {
            Imf::setGlobalThreadCount(static_cast<int>(std::min(cores, 8u)));
        } catch (const std::exception&) {
        }
        return true;
    }();
    (void)configured;
}

} // namespace

void writeExr(const std::string& path, int width, int height,
              const std::vector<ExrChannel>& channels,
              const std::map<std::string, std::string>& attributes) {
    requireImageArgs(path, width, height, 1, static_cast<size_t>(width) * height);
    if (channels.empty())
        throw Error(path + ": no channels to write");
    for (const ExrChannel& c : channels)
        if (c.name.empty() || c.data == nullptr)
            throw Error(path + ": channel without a name or data");
    checkOutputWritable(path);
    configureOpenExr();
    const std::string temp = temporaryPathFor(path);
    try {
        Imf::Header header(width, height);
        // Lossless ZIP at its fastest level: a render's float channels (grain in the low bits)
        // compress about 2:1 at any level, and level 1 took 0.2 s less a 1280x720 frame than the
        // default 4 for 0.6 % more bytes (docs/PERFORMANCE.md).
        header.compression() = Imf::ZIP_COMPRESSION;
        header.zipCompressionLevel() = 1;
        for (const auto& [name, value] : attributes)
            header.insert(name, Imf::StringAttribute(value));
        Imf::FrameBuffer frame;
        for (const ExrChannel& c : channels) {
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            frame.insert(c.name,
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.data)),
                                    sizeof(float), sizeof(float) * width));
        }
        Imf::OutputFile file(temp.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove(temp, ec);
        throw Error("cannot write " + path + ": " + e.what());
    }
    commitTemporary(temp, path);
}

namespace {

uint32_t bigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// The PNG container, checked before stb_image decodes it. stbi_load also decodes JPEG, GIF, PSD,
// HDR, PIC, PNM, TGA and BMP, whose decoders have no business reading a weather map, and it
// allocates a chunk's declared length before reading it: a 70-byte file declaring a 1.8 GB IDAT
// chunk made it allocate 1.8 GB (found by fuzz_weather_png).
void checkPngContainer(const std::string& path, const std::vector<uint8_t>& bytes) {
    static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const std::string what = path + ": cannot read PNG: ";
    if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin()))
        throw Error(what + "not a PNG file (no PNG signature)");
    for (size_t pos = 8;;) {
        if (bytes.size() - pos < 12)
            throw Error(what + "truncated at byte " + std::to_string(pos) + " (no IEND chunk)");
        const uint32_t length = bigEndian32(&bytes[pos]);
        std::string type(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
        for (char& c : type)
            if (!std::isalpha(static_cast<unsigned char>(c)))
                c = '?';
        if (length > bytes.size() - pos - 12)
            throw Error(what + "chunk " + type + " at byte " + std::to_string(pos) + " declares " +
                        std::to_string(length) + " bytes, past the end of the file");
        if (pos == 8 && (type != "IHDR" || length != 13))
            throw Error(what + "the first chunk is not a 13-byte IHDR");
        if (pos == 8) {
            const uint32_t w = bigEndian32(&bytes[16]), h = bigEndian32(&bytes[20]);
            if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
                throw Error(what + std::to_string(w) + "x" + std::to_string(h) +
                            " pixels, expected 1 to " + std::to_string(kMaxImageSide) +
                            " on a side");
        }
        pos += 12 + length;
        if (type == "IEND")
            return;
    }
}

// The bytes without their empty IDAT chunks (the container is checked). stb_image copies each
// IDAT chunk into a buffer it allocates at the first non-empty one, so an empty first IDAT was
// copied to a null pointer (memcpy(NULL, p, 0): undefined behaviour, found by
// fuzz_weather_png). Empty IDAT chunks hold no image data; the image is the same without them.
std::vector<uint8_t> withoutEmptyIdatChunks(std::vector<uint8_t> bytes) {
    static const uint8_t emptyIdat[8] = {0, 0, 0, 0, 'I', 'D', 'A', 'T'};
    size_t kept = 8; // bytes[0, kept) is the result so far; chunks move down over dropped ones
    for (size_t pos = 8; pos < bytes.size();) {
        // Up to IEND every chunk lies inside the file (checkPngContainer); what follows IEND is
        // kept as it is.
        const bool end = std::equal(bytes.begin() + pos + 4, bytes.begin() + pos + 8, "IEND");
        const size_t size = end ? bytes.size() - pos : 12 + size_t(bigEndian32(&bytes[pos]));
        if (size != 12 || !std::equal(emptyIdat, emptyIdat + 8, bytes.begin() + pos)) {
            std::copy(bytes.begin() + pos, bytes.begin() + pos + size, bytes.begin() + kept);
            kept += size;
        }
        pos += size;
    }
    bytes.resize(kept);
    return bytes;
}

// A PNG file's bytes, checked as a container (signature, chunks inside the file) and without
// the empty IDAT chunks stb_image rejects: what both readers hand to stb_image.
std::vector<uint8_t> checkedPngBytes(const std::string& path) {
    if (fs::is_directory(path))
        throw Error(path + ": cannot read PNG: is a directory");
    if (!fs::is_regular_file(path))
        throw Error(path + ": cannot read PNG: no such file");
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    if (in.bad())
        throw Error(path + ": cannot read PNG: " + systemError());
    if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        throw Error(path + ": cannot read PNG: larger than 2 GiB");
    checkPngContainer(path, bytes);
    return withoutEmptyIdatChunks(std::move(bytes));
}

} // namespace

std::vector<uint8_t> readPng(const std::string& path, int& width, int& height, int& channels) {
    const std::vector<uint8_t> bytes = checkedPngBytes(path);
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                            &height, &channels, 0);
    if (!pixels)
        throw Error(path + ": cannot read PNG: " + stbi_failure_reason());
    std::vector<uint8_t> out(pixels, pixels + static_cast<size_t>(width) * height * channels);
    stbi_image_free(pixels);
    return out;
}

std::vector<uint16_t> readPng16(const std::string& path, int& width, int& height, int& channels) {
    const std::vector<uint8_t> bytes = checkedPngBytes(path);
    // IHDR's bit depth (byte 24): checked here so an 8-bit file gets a message that says so.
    if (bytes[24] != 16)
        throw Error(path + ": a " + std::to_string(bytes[24]) +
                    "-bit PNG; expected a 16-bit greyscale PNG");
    stbi_us* pixels = stbi_load_16_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                               &height, &channels, 0);
    if (!pixels)
        throw Error(path + ": cannot read PNG: " + stbi_failure_reason());
    std::vector<uint16_t> out(pixels, pixels + static_cast<size_t>(width) * height * channels);
    stbi_image_free(pixels);
    return out;
}

const std::vector<float>& ExrImage::channel(const std::string& name) const {
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return channels[i];
    throw Error((source.empty() ? std::string("EXR image") : source) + ": has no channel '" + name +
                "'");
}

namespace {

// The data window (width x height, at most kMaxImageSide on a side, checked by OpenEXR when it
// opens a file) times the channels: at most 2^28 floats (1 GiB), which holds a 16384 x 16384
// depth buffer or a 8192 x 8192 RGBA image.
constexpr size_t kMaxExrSamples = size_t(1) << 28;
// What the planes grow by at a time: about 2^20 values (4 MiB), at least one row.
constexpr size_t kExrBlockValues = size_t(1) << 20;

// Makes a plane `size` values long, growing its capacity at most to `finalSize` (doubling, so the
// copies add up to one more pass over the image).
void growPlane(std::vector<float>& plane, size_t size, size_t finalSize) {
    if (size > plane.capacity())
        plane.reserve(std::min(finalSize, std::max(size, 2 * plane.capacity())));
    plane.resize(size);
}

// Reads the pixels a block of rows at a time, growing the planes only as the file delivers them:
// a file that claims more pixels than it holds fails at its first missing or corrupt block, having
// allocated about one block, not the image its header claims (found by fuzz_checkpoint: an 865-byte
// header claiming 16384 x 16384 pixels made the reader allocate and clear 1 GiB, 15 s and 1.2 GB of
// memory under ASan, before OpenEXR found the pixels missing). OpenEXR keeps the chunk it decoded
// last, so a block boundary inside a chunk does not decode it twice.
void readPixelsAsTheyArrive(Imf::InputFile& file, const Imath::Box2i& window, ExrImage& image) {
    const size_t width = static_cast<size_t>(image.width);
    const size_t finalSize = width * static_cast<size_t>(image.height);
    const size_t valuesPerRow = width * std::max<size_t>(image.names.size(), 1);
    const long long rowsPerBlock =
        static_cast<long long>(std::max<size_t>(1, kExrBlockValues / valuesPerRow));
    const ptrdiff_t origin = static_cast<ptrdiff_t>(window.min.x) +
                             static_cast<ptrdiff_t>(window.min.y) * static_cast<ptrdiff_t>(width);
    for (long long y = window.min.y; y <= window.max.y; y += rowsPerBlock) {
        const long long last = std::min<long long>(window.max.y, y + rowsPerBlock - 1);
        const size_t rowsSoFar = static_cast<size_t>(last - window.min.y + 1);
        Imf::FrameBuffer frame;
        for (size_t i = 0; i < image.names.size(); ++i) {
            std::vector<float>& plane = image.channels[i];
            growPlane(plane, rowsSoFar * width, finalSize);
            // OpenEXR addresses pixel (x, y) at base + x * xStride + y * yStride.
            char* base = reinterpret_cast<char*>(plane.data()) -
                         origin * static_cast<ptrdiff_t>(sizeof(float));
            frame.insert(image.names[i],
                         Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * width));
        }
        file.setFrameBuffer(frame);
        try {
            file.readPixels(static_cast<int>(y), static_cast<int>(last));
        } catch (const std::exception& e) {
            throw Error(image.source + ": cannot read EXR: rows " + std::to_string(y) + " to " +
                        std::to_string(last) + " of a " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + " image: " + e.what());
        }
    }
}

} // namespace

ExrImage readExr(const std::string& path) {
    configureOpenExr();
    io::checkExrHeaders(path);
    ExrImage image;
    image.source = path;
    try {
        // One line buffer, not one a pool thread: the reader allocates about one block of a
        // hostile file before its checks (readPixelsAsTheyArrive).
        Imf::InputFile file(path.c_str(), 1);
        if (!file.isComplete())
            throw Error(path + ": cannot read EXR: pixels are missing (a truncated file?)");
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
            throw Error(path + ": cannot read EXR: data window " + std::to_string(w) + "x" +
                        std::to_string(h) + " is not between 1 and " +
                        std::to_string(kMaxImageSide) + " pixels a side");
        image.width = static_cast<int>(w);
        image.height = static_cast<int>(h);
        const size_t n = static_cast<size_t>(image.width) * image.height;
        const Imf::ChannelList& list = file.header().channels();
        for (auto it = list.begin(); it != list.end(); ++it)
            image.names.emplace_back(it.name());
        const size_t count = image.names.size();
        if (count > 0 && n > kMaxExrSamples / count)
            throw Error(path + ": cannot read EXR: " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + " pixels of " + std::to_string(count) +
                        " channels, more than the reader's 2^28 values");
        image.channels.resize(count);
        readPixelsAsTheyArrive(file, window, image);
        for (auto it = file.header().begin(); it != file.header().end(); ++it)
            if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                image.attributes[it.name()] = text->value();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(path + ": cannot read EXR: " + e.what());
    }
    return image;
}

} // namespace cloudscape
