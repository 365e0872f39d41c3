// Cleaning up after killed runs touches only the writers' own temporaries of dead processes, and
// a set of files is written all or nothing.
#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using cloudscape::AtomicFileSet;

// fsync, interposed in this test binary (the library is linked statically, so its calls land
// here): while a test sets onDirectorySync, it is told of every directory synced, before the
// sync, which still happens.
static std::function<void(const fs::path&)> onDirectorySync;
extern "C" int fsync(int fd) {
    if (onDirectorySync) {
        char link[64];
        std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
        std::error_code ec;
        const fs::path target = fs::read_symlink(link, ec);
        if (!ec && fs::is_directory(target, ec))
            onDirectorySync(target);
    }
    return static_cast<int>(::syscall(SYS_fsync, fd));
}

namespace {

class AtomicFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cloudscape_atomic_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void put(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
    }
    std::map<std::string, std::string> contents() const {
        std::map<std::string, std::string> out;
        for (const auto& e : fs::directory_iterator(dir_)) {
            std::ifstream in(e.path(), std::ios::binary);
            std::stringstream s;
            s << in.rdbuf();
            out[e.path().filename().string()] = e.is_directory() ? "<dir>" : s.str();
        }
        return out;
    }
    fs::path dir_;
};

// A PID that certainly ran and is gone: a child that exited and was reaped.
pid_t deadPid() {
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

void writeText(const std::string& path, const std::string& text) {
    cloudscape::writeFileAtomic(path, text.data(), text.size());
}

} // namespace

TEST_F(AtomicFiles, TemporariesFollowTheWritersNaming) {
    const std::string t = cloudscape::temporaryPathFor(path("frame.png"));
    const std::string name = fs::path(t).filename().string();
    EXPECT_EQ(fs::path(t).parent_path(), dir_);
    EXPECT_EQ(name.rfind(".frame.png.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << name;
    EXPECT_NE(cloudscape::temporaryPathFor(path("frame.png")), t) << "unique per call";
}

TEST_F(AtomicFiles, OnlyStaleTemporariesOfTheTargetsAreRemoved) {
    const std::string dead = std::to_string(deadPid());
    const std::string self = std::to_string(::getpid());
    const std::vector<std::string> stale = {
        ".a.png.tmp-" + dead + "-0", ".a.png.tmp-" + dead + "-17",
        "..a.png.tmp-" + dead + "-1.tmp-" + dead + "-2", // a set's staged file, mid-write
    };
    const std::vector<std::string> kept = {
        "a.png",
        ".a.png.tmp-" + self + "-0",         // this process may be writing it
        ".a.png.tmp-1-0",                    // PID 1 is alive
        ".b.png.tmp-" + dead + "-0",         // not an output of this run
        "a.png.tmp-" + dead + "-0",          // no leading dot: a user's file
        ".a.png.tmp-" + dead,                // not the writers' naming
        ".a.png.tmp-" + dead + "-x",         //
        ".a.png.tmp-" + dead + "-0.bak",     //
        ".a.png.tmp--0",                     //
        "..a.png.tmp-1-1.tmp-" + dead + "-2" // the inner writer (PID 1) is alive
    };
    for (const auto& name : stale)
        put(name, "stale");
    for (const auto& name : kept)
        put(name, "kept");
    fs::create_directory(path(".a.png.tmp-" + dead + "-9")); // only regular files are removed
    EXPECT_EQ(cloudscape::removeStaleTemporaries({path("a.png"), path("c.png")}), 3);
    for (const auto& name : stale)
        EXPECT_FALSE(fs::exists(path(name))) << name;
    for (const auto& name : kept)
        EXPECT_TRUE(fs::exists(path(name))) << name;
    EXPECT_TRUE(fs::is_directory(path(".a.png.tmp-" + dead + "-9")));
    EXPECT_EQ(cloudscape::removeStaleTemporaries({path("missing/a.png")}), 0);
}

TEST_F(AtomicFiles, ASetLandsWhole) {
    put("a.txt", "old a");
    {
        AtomicFileSet set;
        set.write(path("a.txt"), [](const std::string& p) { writeText(p, "new a"); });
        set.write(path("b.txt"), [](const std::string& p) { writeText(p, "new b"); });
        EXPECT_EQ(contents().at("a.txt"), "old a") << "nothing lands before commit";
        EXPECT_FALSE(fs::exists(path("b.txt")));
        set.commit();
    }
    EXPECT_EQ(contents(),
              (std::map<std::string, std::string>{{"a.txt", "new a"}, {"b.txt", "new b"}}));
}

// commit() returns with the renames on disk: each target's directory is synced after its final
// rename. (The staged files' writers sync the same directories, but before those renames.)
TEST_F(AtomicFiles, CommitSyncsEachDirectoryAfterTheRenames) {
    fs::create_directories(path("sub"));
    put("a.txt", "old a");
    std::vector<std::string> syncedAfterTheRenames;
    onDirectorySync = [&](const fs::path& directory) {
        const auto top = contents();
        if (top.count("a.txt") && top.at("a.txt") == "new a" && fs::exists(path("sub/b.txt")))
            syncedAfterTheRenames.push_back(directory.string());
    };
    try {
        AtomicFileSet set;
        set.write(path("a.txt"), [](const std::string& p) { writeText(p, "new a"); });
        set.write(path("sub/b.txt"), [](const std::string& p) { writeText(p, "new b"); });
        set.commit();
    } catch (...) {
        onDirectorySync = nullptr;
        throw;
    }
    onDirectorySync = nullptr;
    std::sort(syncedAfterTheRenames.begin(), syncedAfterTheRenames.end());
    EXPECT_EQ(syncedAfterTheRenames,
              (std::vector<std::string>{fs::canonical(dir_).string(),
                                        fs::canonical(path("sub")).string()}));
}

TEST_F(AtomicFiles, AFailedWriterLeavesTheDirectoryAsItWas) {
    put("a.txt", "old a");
    put("b.txt", "old b");
    const auto before = contents();
    try {
        AtomicFileSet set;
        set.write(path("a.txt"), [](const std::string& p) { writeText(p, "new a"); });
        set.write(path("c.txt"), [](const std::string& p) { writeText(p, "new c"); });
        set.write(path("b.txt"), [](const std::string& p) {
            throw cloudscape::Error("cannot write " + p + ": No space left on device");
        });
        set.commit();
        FAIL() << "the write should have failed";
    } catch (const cloudscape::Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write " + path("b.txt") + ": No space left on device")
            << "errors name the target, not the temporary";
    }
    EXPECT_EQ(contents(), before);
}

TEST_F(AtomicFiles, AFailedRenameRestoresThePreviousFiles) {
    put("a.txt", "old a");
    fs::create_directories(path("c.txt/inside")); // renaming a file over it fails
    const auto before = contents();
    AtomicFileSet set;
    set.write(path("a.txt"), [](const std::string& p) { writeText(p, "new a"); });
    set.write(path("b.txt"), [](const std::string& p) { writeText(p, "new b"); });
    set.write(path("c.txt"), [](const std::string& p) { writeText(p, "new c"); });
    try {
        set.commit();
        FAIL() << "renaming over a directory should have failed";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find(path("c.txt")), std::string::npos) << e.what();
    }
    EXPECT_EQ(contents(), before);
}

TEST_F(AtomicFiles, TheSameTargetTwiceIsAnError) {
    AtomicFileSet set;
    set.write(path("a.txt"), [](const std::string& p) { writeText(p, "1"); });
    EXPECT_THROW(set.write(path("a.txt"), [](const std::string& p) { writeText(p, "2"); }),
                 cloudscape::Error);
}
