#pragma once
// Running the cloudscape tool from tests: a child process with optional environment (the
// CLOUDSCAPE_TEST_FAULT injection), its exit status or the signal that killed it, its stderr;
// scratch directories and their contents.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cloudscape::testing {

namespace fs = std::filesystem;

struct ToolRun {
    int status = -1;     // exit status, if it exited
    bool killed = false; // ended by SIGKILL (the injected kill -9)
    std::string stderrText;
};

// `environment` is prefixed to the command ("CLOUDSCAPE_TEST_FAULT=fail:x.png"); arguments are
// passed through the shell as written.
inline ToolRun runToolWith(const std::string& environment, const std::string& args) {
    static int counter = 0;
    const fs::path errFile =
        fs::temp_directory_path() /
        ("cloudscape_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".txt");
    const std::string cmd =
        environment + " " + CLOUDSCAPE_CLI + " " + args + " >/dev/null 2>" + errFile.string();
    const int raw = std::system(cmd.c_str());
    ToolRun r;
    // The shell may run the tool as its child (then it exits with 128 + the signal) or exec it.
    if (WIFSIGNALED(raw))
        r.killed = WTERMSIG(raw) == SIGKILL;
    else if (WIFEXITED(raw)) {
        r.status = WEXITSTATUS(raw);
        r.killed = r.status == 128 + SIGKILL;
    }
    std::ifstream in(errFile);
    std::stringstream s;
    s << in.rdbuf();
    r.stderrText = s.str();
    fs::remove(errFile);
    return r;
}

class ScratchDir {
public:
    explicit ScratchDir(const std::string& tag) {
        path_ =
            fs::temp_directory_path() / ("cloudscape_" + tag + "_" + std::to_string(::getpid()) +
                                         "_" + std::to_string(counter_++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() { fs::remove_all(path_); }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string path() const { return path_.string(); }

private:
    fs::path path_;
    static inline int counter_ = 0;
};

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every file of a directory (not recursive): name -> bytes.
inline std::map<std::string, std::string> snapshot(const std::string& directory) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(directory))
        files[entry.path().filename().string()] = readBytes(entry.path().string());
    return files;
}

} // namespace cloudscape::testing
