#pragma once
// fsync of a file or a directory, shared by the atomic writers (image_io.cpp) and AtomicFileSet
// (atomic_files.cpp): a rename is on disk only once its directory is synced.
#include <string>

namespace cloudscape::io {

// Flushes a file's contents, or a directory's entries (isDirectory), to the disk. Returns false
// with errno set on failure.
bool syncToDisk(const std::string& path, bool isDirectory);

} // namespace cloudscape::io
