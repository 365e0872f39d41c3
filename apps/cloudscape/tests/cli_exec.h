#pragma once
// Running the cloudscape tool from tests without a shell: arguments are passed as an argv
// vector, so hostile strings (%n, quotes, spaces) reach the tool exactly as written.
#include <gtest/gtest.h>

#include <algorithm>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

struct ToolRun {
    int status = -1; // exit status, or -1 if the tool died from a signal
    int signal = 0;
    std::string stderrText;
};

// Whether this build (and so the tool it tests, built with the same flags) runs under
// AddressSanitizer, which reserves terabytes of virtual address space for its shadow memory at
// start-up: an address-space limit (`ulimit -v`) stops such a tool before main().
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderAddressSanitizer = true;
#else
inline constexpr bool kUnderAddressSanitizer = false;
#endif
#else
inline constexpr bool kUnderAddressSanitizer = false;
#endif

struct ToolLimits {
    unsigned long long addressSpaceBytes = 0; // RLIMIT_AS for the child; 0 = unlimited
};

// Runs CLOUDSCAPE_CLI with `args` (stdout discarded) and captures stderr.
inline ToolRun runCli(const std::vector<std::string>& args, const ToolLimits& limits = {}) {
    const fs::path errFile =
        fs::temp_directory_path() / ("cloudscape_run_" + std::to_string(::getpid()) + ".err");
    std::vector<std::string> argvStrings{CLOUDSCAPE_CLI};
    argvStrings.insert(argvStrings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argvStrings)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int err = ::open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(err, 2);
        ::dup2(null, 1);
        if (limits.addressSpaceBytes) {
            const rlimit r{limits.addressSpaceBytes, limits.addressSpaceBytes};
            ::setrlimit(RLIMIT_AS, &r);
        }
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    ToolRun r;
    if (WIFEXITED(raw))
        r.status = WEXITSTATUS(raw);
    else if (WIFSIGNALED(raw))
        r.signal = WTERMSIG(raw);
    std::ifstream in(errFile);
    std::stringstream s;
    s << in.rdbuf();
    r.stderrText = s.str();
    fs::remove(errFile);
    return r;
}

// A fresh directory per test, removed afterwards.
class ScratchDir {
public:
    ScratchDir() {
        path_ = fs::temp_directory_path() / ("cloudscape_scratch_" + std::to_string(::getpid()) +
                                             "_" + std::to_string(counter_++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() { fs::remove_all(path_); }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path_))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path path_;
    static inline int counter_ = 0;
};

inline void writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string readFileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace cli_test
