#pragma once
// The temporary files behind every atomic write, cleaning up the ones a killed run left, and
// writing a set of files as one: all of them or none.
//
// Every writer in image_io.h writes `dir/name` through `dir/.name.tmp-PID-K` (PID of the writing
// process, K a per-process counter) and renames it into place. A process killed mid-write leaves
// that temporary behind; removeStaleTemporaries deletes exactly such leftovers, and only those
// of a process that no longer runs.
#include <functional>
#include <string>
#include <vector>

namespace cloudscape {

// A fresh temporary path beside `target`, unique within this process and across processes.
std::string temporaryPathFor(const std::string& target);

// Removes the temporaries of `targets` (`.name.tmp-PID-K` beside each, and the nested ones an
// AtomicFileSet's staged file may leave) whose process PID is no longer running. Files of a live
// process (another run writing the same output), of this process, and anything not named exactly
// so are never touched. Empty targets are skipped. Returns how many files were removed.
int removeStaleTemporaries(const std::vector<std::string>& targets);

// Writes several files so that either all of them are replaced or none is. Each file is written
// in full to a temporary beside its target first (write()); commit() renames them into place only
// once all were written, and if a rename fails part-way, it restores the files that were there
// before. Destroying an uncommitted set removes what it staged, so a failed writer leaves the
// directory as it was. (A kill -9 during commit itself, a few renames long, can leave a mix;
// removeStaleTemporaries cleans its files.)
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    ~AtomicFileSet();
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;

    // Writes the new content of `target` by calling writer(path) with a temporary path beside
    // it; writer is one of the atomic writers (writePng, writeExr, writeFileAtomic, ...). Errors
    // name the target. Each target may be written once per set.
    void write(const std::string& target, const std::function<void(const std::string&)>& writer);
    // Renames every staged file into place, then syncs each target's directory, so the new set is
    // on disk when it returns; throws cloudscape::Error (after restoring the previous files) if
    // any rename fails, or naming the directory if its sync fails (the new files are in place).
    void commit();

private:
    struct Entry {
        std::string target;
        std::string staged;
        std::string backup; // hard link to the previous file during commit, if there was one
    };
    void discard();
    std::vector<Entry> entries_;
};

} // namespace cloudscape
