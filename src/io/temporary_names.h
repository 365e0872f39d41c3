#pragma once
// The naming of the atomic writers' temporaries, `.NAME.tmp-PID-K`, parsed back: for cleaning up
// after killed runs (atomic_files.cpp) and for recognising an output in test faults.
#include <string>
#include <sys/types.h>

namespace cloudscape::io {

// If `filename` (no directory) is `.INNER.tmp-PID-K` with decimal PID and K, sets inner and pid
// and returns true.
bool parseTemporaryName(const std::string& filename, std::string& inner, pid_t& pid);

// The output a (possibly nested) temporary belongs to: `..a.png.tmp-1-2.tmp-1-3` -> `a.png`;
// any other name is returned as it is.
std::string outputNameOf(const std::string& filename);

} // namespace cloudscape::io
