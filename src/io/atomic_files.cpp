// Temporaries of the atomic writers: their naming, cleaning up after killed runs, and writing a
// set of files as one.
#include <cloudscape/atomic_files.h>
#include <cloudscape/error.h>

#include "io/sync_to_disk.h"
#include "io/temporary_names.h"

#include <atomic>
#include <cerrno>
#include <csignal> // kill(pid, 0)
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <set>
#include <unistd.h>

namespace cloudscape {
namespace fs = std::filesystem;

namespace io {

bool parseTemporaryName(const std::string& filename, std::string& inner, pid_t& pid) {
    const auto marker = filename.rfind(".tmp-");
    if (filename.size() < 2 || filename[0] != '.' || marker == std::string::npos || marker < 2)
        return false;
    const std::string suffix = filename.substr(marker + 5); // "PID-K"
    const auto dash = suffix.find('-');
    if (dash == std::string::npos || dash == 0 || dash + 1 == suffix.size() || dash > 9)
        return false;
    for (size_t i = 0; i < suffix.size(); ++i)
        if (i != dash && (suffix[i] < '0' || suffix[i] > '9'))
            return false;
    inner = filename.substr(1, marker - 1);
    pid = static_cast<pid_t>(std::stol(suffix.substr(0, dash)));
    return true;
}

std::string outputNameOf(const std::string& filename) {
    std::string name = filename, inner;
    pid_t pid = 0;
    while (parseTemporaryName(name, inner, pid))
        name = inner;
    return name;
}

bool syncToDisk(const std::string& path, bool isDirectory) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (isDirectory ? O_DIRECTORY : 0));
    if (fd < 0)
        return false;
    const bool synced = ::fsync(fd) == 0;
    const int savedErrno = errno;
    ::close(fd);
    errno = savedErrno;
    return synced;
}

} // namespace io

namespace {

// A process that may still be writing its temporary: this one, or any that exists (EPERM means
// it exists under another user). PIDs can be reused, which only errs on the side of keeping.
bool processMayBeWriting(pid_t pid) {
    if (pid <= 0)
        return false;
    if (pid == ::getpid())
        return true;
    return ::kill(pid, 0) == 0 || errno == EPERM;
}

// The output name if `filename` is a temporary of a dead process (all nesting levels), else "".
std::string staleTemporaryOutput(const std::string& filename) {
    std::string name = filename, inner;
    pid_t pid = 0;
    bool any = false;
    while (io::parseTemporaryName(name, inner, pid)) {
        if (processMayBeWriting(pid))
            return {};
        name = inner;
        any = true;
    }
    return any ? name : std::string();
}

fs::path directoryOf(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

} // namespace

std::string temporaryPathFor(const std::string& target) {
    static std::atomic<unsigned> counter{0};
    const fs::path path(target);
    return (directoryOf(path) / (std::string(".") + path.filename().string() + ".tmp-" +
                                 std::to_string(::getpid()) + "-" + std::to_string(counter++)))
        .string();
}

int removeStaleTemporaries(const std::vector<std::string>& targets) {
    std::map<fs::path, std::set<std::string>> byDirectory;
    for (const std::string& t : targets)
        if (!t.empty()) // e.g. an optional output that was not asked for
            byDirectory[directoryOf(t)].insert(fs::path(t).filename().string());
    int removed = 0;
    for (const auto& [directory, names] : byDirectory) {
        std::error_code ec;
        fs::directory_iterator it(directory, ec), end;
        std::vector<fs::path> stale;
        for (; !ec && it != end; it.increment(ec)) {
            const std::string output = staleTemporaryOutput(it->path().filename().string());
            if (!output.empty() && names.count(output) &&
                it->symlink_status(ec).type() == fs::file_type::regular)
                stale.push_back(it->path());
        }
        for (const fs::path& p : stale)
            removed += fs::remove(p, ec) ? 1 : 0;
    }
    return removed;
}

AtomicFileSet::~AtomicFileSet() {
    discard();
}

void AtomicFileSet::write(const std::string& target,
                          const std::function<void(const std::string&)>& writer) {
    for (const Entry& e : entries_)
        if (e.target == target)
            throw Error(target + ": written twice in one set of outputs");
    entries_.push_back({target, temporaryPathFor(target), {}});
    const std::string staged = entries_.back().staged;
    try {
        writer(staged);
    } catch (const Error& e) {
        // The writer names the path it was given; the user knows the target.
        std::string message = e.what();
        for (auto at = message.find(staged); at != std::string::npos; at = message.find(staged))
            message.replace(at, staged.size(), target);
        throw Error(message);
    }
}

void AtomicFileSet::discard() {
    std::error_code ec;
    for (const Entry& e : entries_) {
        fs::remove(e.staged, ec);
        if (!e.backup.empty())
            fs::remove(e.backup, ec);
    }
    entries_.clear();
}

void AtomicFileSet::commit() {
    std::error_code ec;
    // 1. Everything staged must be there, and each previous file gets a second name, so a
    // failed rename below can put it back.
    for (Entry& e : entries_) {
        if (!fs::is_regular_file(e.staged, ec)) {
            const std::string target = e.target;
            discard();
            throw Error("cannot write " + target + ": its new content was never written");
        }
        const fs::file_status previous = fs::symlink_status(e.target, ec);
        if (!fs::exists(previous) || fs::is_directory(previous))
            continue; // nothing to keep (renaming over a directory fails below anyway)
        e.backup = temporaryPathFor(e.target);
        if (::link(e.target.c_str(), e.backup.c_str()) != 0 &&
            !fs::copy_file(e.target, e.backup, ec)) {
            const std::string reason = ec ? ec.message() : std::strerror(errno);
            const std::string target = e.target;
            e.backup.clear();
            discard();
            throw Error("cannot write " + target + ": cannot keep the previous file (" + reason +
                        "); nothing was replaced");
        }
    }
    // 2. The renames; on a failure, undo the ones done.
    for (size_t i = 0; i < entries_.size(); ++i) {
        fs::rename(entries_[i].staged, entries_[i].target, ec);
        if (!ec)
            continue;
        const std::string message = "cannot write " + entries_[i].target + ": " + ec.message();
        for (size_t j = 0; j < i; ++j) {
            std::error_code undo;
            Entry& done = entries_[j];
            if (done.backup.empty()) {
                fs::remove(done.target, undo); // there was no file before
                continue;
            }
            fs::rename(done.backup, done.target, undo);
            if (!undo)
                done.backup.clear(); // restored: the backup is the target again
        }
        discard();
        throw Error(message + "; the other files were left as they were");
    }
    // 3. The renames on disk: the staged files' data already is (their writers synced it), so
    // syncing each target's directory once makes a power cut after commit() returns keep the
    // new set, as writeFileAtomic's single rename does.
    std::map<fs::path, std::string> directories; // directory -> a target in it, for the message
    for (Entry& e : entries_) {
        directories.emplace(directoryOf(e.target), e.target);
        e.staged.clear();
    }
    discard(); // the backups
    for (const auto& [directory, target] : directories)
        if (!io::syncToDisk(directory.string(), true))
            throw Error("cannot write " + target + ": syncing directory " + directory.string() +
                        ": " + std::strerror(errno));
}

} // namespace cloudscape
