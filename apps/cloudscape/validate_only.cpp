#include "validate_only.h"

namespace cloudscape::cli {
namespace {
bool validateOnly = false;
}

void setValidateOnly(bool on) {
    validateOnly = on;
}

void stopIfValidatingOnly() {
    if (validateOnly)
        throw ValidationComplete{};
}

} // namespace cloudscape::cli
