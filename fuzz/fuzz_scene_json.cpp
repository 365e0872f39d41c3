// Harness: the scene reader on arbitrary JSON text (parseScene = loadScene after the file read):
// the JSON parser, the key table's type and range checks and the cross-key validation.
#include "fuzz_support.h"

#include <cloudscape/scene.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors(
        [&] { cloudscape::parseScene(text, "fuzz.json"); });
    return 0;
}
