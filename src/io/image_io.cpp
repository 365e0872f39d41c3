// PNG and EXR in and out, with atomic writes: temp file in the target's directory, then rename.
#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include "io/fault_injection.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
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

// Flushes a file's (or directory's) contents to the disk; false with errno set on failure.
bool syncPath(const std::string& path, int flags) {
    const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0)
        return false;
    const bool synced = ::fsync(fd) == 0;
    const int savedErrno = errno;
    ::close(fd);
    errno = savedErrno;
    return synced;
}

// Renames a finished temp file into place, or removes it and throws. The temp file's data is
// on disk before the rename and the rename itself is on disk after it (the directory is
// synced), so a power cut leaves the old file or the new one, never an empty one.
void commitTemporary(const std::string& temp, const std::string& path) {
    if (!syncPath(temp, O_RDONLY)) {
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
    if (!syncPath(dir.string(), O_RDONLY | O_DIRECTORY))
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
    const std::string temp = temporaryPathFor(path);
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
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

std::vector<uint8_t> readPng(const std::string& path, int& width, int& height, int& channels) {
    if (!fs::is_regular_file(path))
        throw Error(path + ": cannot read PNG: no such file");
    if (stbi_info(path.c_str(), &width, &height, &channels) &&
        (width > kMaxImageDimension || height > kMaxImageDimension))
        throw Error(path + ": cannot read PNG: " + std::to_string(width) + "x" +
                    std::to_string(height) + " is larger than " +
                    std::to_string(kMaxImageDimension) + " pixels a side");
    stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 0);
    if (!pixels)
        throw Error(path + ": cannot read PNG: " + stbi_failure_reason());
    std::vector<uint8_t> out(pixels, pixels + static_cast<size_t>(width) * height * channels);
    stbi_image_free(pixels);
    return out;
}

const std::vector<float>& ExrImage::channel(const std::string& name) const {
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return channels[i];
    throw Error((source.empty() ? std::string("EXR image") : source) + ": has no channel '" +
                name + "'");
}

ExrImage readExr(const std::string& path) {
    ExrImage image;
    image.source = path;
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (w < 1 || h < 1 || w > kMaxImageDimension || h > kMaxImageDimension)
            throw Error(path + ": cannot read EXR: data window " + std::to_string(w) + "x" +
                        std::to_string(h) + " is not between 1 and " +
                        std::to_string(kMaxImageDimension) + " pixels a side");
        image.width = static_cast<int>(w);
        image.height = static_cast<int>(h);
        const size_t n = static_cast<size_t>(image.width) * image.height;
        Imf::FrameBuffer frame;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end();
             ++it) {
            image.names.emplace_back(it.name());
            image.channels.emplace_back(n);
        }
        for (size_t i = 0; i < image.names.size(); ++i) {
            char* base = reinterpret_cast<char*>(image.channels[i].data()) -
                         (static_cast<ptrdiff_t>(window.min.x) +
                          static_cast<ptrdiff_t>(window.min.y) * image.width) *
                             static_cast<ptrdiff_t>(sizeof(float));
            frame.insert(image.names[i],
                         Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * image.width));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
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
