#pragma once
// Test-only fault injection for the atomic writers, driven by the environment variable
// CLOUDSCAPE_TEST_FAULT so that end-to-end tests can kill a run, or make a write fail as on a
// full disk, at an exact point. Unset (always, outside tests) it costs one getenv per process.
//
//   CLOUDSCAPE_TEST_FAULT=ACTION:NAME[#N]
//
// NAME is the file name (no directory) of an output; #N picks its N-th write in this process
// (default 1). ACTION is one of
//   kill-before-commit  SIGKILL once the temporary is written in full, before the rename: the
//                       state a kill -9 during the write leaves (a stale temporary, old target)
//   kill-after-commit   SIGKILL right after the rename: the file is complete, nothing after it ran
//   fail                the write fails with ENOSPC ("No space left on device"), as on a full
//                       disk; the temporary is removed as in any failed write
#include <string>

namespace cloudscape::io {

// Called by the writers with the finished temporary, before renaming it over `target`. May
// not return (kill) or throw cloudscape::Error (fail).
void faultBeforeCommit(const std::string& temporary, const std::string& target);
// Called right after `target` was renamed into place. May not return (kill).
void faultAfterCommit(const std::string& target);

} // namespace cloudscape::io
