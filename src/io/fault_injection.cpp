// CLOUDSCAPE_TEST_FAULT: see fault_injection.h. Tests set it on a child process; nothing else
// does.
#include "io/fault_injection.h"

#include <cloudscape/error.h>

#include "io/temporary_names.h"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

namespace cloudscape::io {
namespace {

enum class Action { None, KillBeforeCommit, KillAfterCommit, Fail, DeviceLost, DeviceHeap };

struct Fault {
    Action action = Action::None;
    std::string name;
    int occurrence = 1;
};

// Parsed once; a malformed value is ignored rather than failing real runs.
const Fault& configuredFault() {
    static const Fault fault = [] {
        Fault f;
        const char* text = std::getenv("CLOUDSCAPE_TEST_FAULT");
        if (!text)
            return f;
        const std::string value(text);
        const auto colon = value.find(':');
        if (colon == std::string::npos)
            return f;
        const std::string action = value.substr(0, colon);
        std::string name = value.substr(colon + 1);
        if (const auto hash = name.rfind('#'); hash != std::string::npos) {
            f.occurrence = std::atoi(name.c_str() + hash + 1);
            name.resize(hash);
        }
        f.name = name;
        if (action == "kill-before-commit")
            f.action = Action::KillBeforeCommit;
        else if (action == "kill-after-commit")
            f.action = Action::KillAfterCommit;
        else if (action == "fail")
            f.action = Action::Fail;
        else if (action == "device-lost")
            f.action = Action::DeviceLost;
        else if (action == "device-heap")
            f.action = Action::DeviceHeap;
        return f;
    }();
    return fault;
}

// True when this is the configured occurrence of a write of the configured output (a file
// action, not a device one). Each write is counted once, at its before-commit point.
bool hits(const std::string& target, bool count) {
    const Fault& f = configuredFault();
    if (f.action == Action::None || f.action == Action::DeviceLost ||
        f.action == Action::DeviceHeap)
        return false;
    if (outputNameOf(std::filesystem::path(target).filename().string()) != f.name)
        return false;
    static std::mutex mutex;
    static int seen = 0;
    std::lock_guard<std::mutex> lock(mutex);
    if (count)
        ++seen;
    return seen == f.occurrence;
}

} // namespace

void faultBeforeCommit(const std::string& temporary, const std::string& target) {
    if (!hits(target, true))
        return;
    const Action action = configuredFault().action;
    if (action == Action::KillBeforeCommit)
        std::raise(SIGKILL);
    if (action == Action::Fail) {
        std::error_code ec;
        std::filesystem::remove(temporary, ec);
        throw Error("cannot write " + target + ": No space left on device (" +
                    "CLOUDSCAPE_TEST_FAULT)");
    }
}

void faultAfterCommit(const std::string& target) {
    if (configuredFault().action == Action::KillAfterCommit && hits(target, false))
        std::raise(SIGKILL);
}

bool faultDeviceLostAtSubmit() {
    const Fault& f = configuredFault();
    if (f.action != Action::DeviceLost || f.name != "submit")
        return false;
    static std::mutex mutex;
    static int submitted = 0;
    std::lock_guard<std::mutex> lock(mutex);
    return ++submitted == f.occurrence;
}

uint64_t faultDeviceHeapBytes() {
    const Fault& f = configuredFault();
    return f.action == Action::DeviceHeap ? std::strtoull(f.name.c_str(), nullptr, 10) : 0;
}

} // namespace cloudscape::io
