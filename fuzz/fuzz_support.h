#pragma once
// Shared pieces of the libFuzzer harnesses (see docs/RELIABILITY.md).
//
// What counts as a finding: a sanitizer report (memory error, undefined behaviour, leak), a
// crash, a hang, an allocation beyond libFuzzer's limit, or an exception that is not
// cloudscape::Error when CLOUDSCAPE_FUZZ_STRICT=1 (every bad input must give the one-line
// cloudscape::Error; the tool still turns other exceptions into a line, so by default they
// are tolerated and only the strict mode reports them).
#include <cloudscape/error.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace cloudscape::fuzz {

inline bool strictExceptions() {
    static const bool strict = [] {
        const char* v = std::getenv("CLOUDSCAPE_FUZZ_STRICT");
        return v && std::string_view(v) == "1";
    }();
    return strict;
}

// Runs one input: cloudscape::Error is the expected outcome of bad input; anything else aborts
// in strict mode so libFuzzer saves the input.
template <class F> void runExpectingOnlyCloudscapeErrors(F&& f) {
    try {
        f();
    } catch (const cloudscape::Error&) {
    } catch (const std::exception& e) {
        if (strictExceptions()) {
            std::fprintf(stderr, "fuzz: exception that is not cloudscape::Error: %s\n", e.what());
            std::abort();
        }
    }
}

// The readers take file paths: each input is written to one scratch file per process (on tmpfs
// when TMPDIR points there).
inline std::string scratchFile(const std::string& extension) {
    return (std::filesystem::temp_directory_path() /
            ("cloudscape-fuzz-" + std::to_string(::getpid()) + extension))
        .string();
}

inline const std::string& writeScratch(const std::string& path, const uint8_t* data, size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
        std::fprintf(stderr, "fuzz: cannot write the scratch file %s\n", path.c_str());
        std::abort();
    }
    return path;
}

} // namespace cloudscape::fuzz
