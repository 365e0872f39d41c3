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
//
// and, for the Vulkan backend, where NAME is not a file:
//   device-lost:submit#N  the N-th command buffer this process submits reports
//                         VK_ERROR_DEVICE_LOST once it has run, as a driver crash or GPU reset
//                         would (waiting for it fails; the device is not really lost)
//   device-heap:BYTES     the device's memory heaps hold BYTES, as on a smaller GPU
#include <cstdint>
#include <string>

namespace cloudscape::io {

// Called by the writers with the finished temporary, before renaming it over `target`. May
// not return (kill) or throw cloudscape::Error (fail).
void faultBeforeCommit(const std::string& temporary, const std::string& target);
// Called right after `target` was renamed into place. May not return (kill).
void faultAfterCommit(const std::string& target);

// Called by the Vulkan backend once per command buffer submitted: true when this submission
// is to report a lost device.
bool faultDeviceLostAtSubmit();
// The device heap size the Vulkan backend is to assume instead of the device's; 0 = no fault.
uint64_t faultDeviceHeapBytes();

} // namespace cloudscape::io
