// Harness: the path tracer's checkpoint reader (`pathtrace --resume`, readPathTraceCheckpoint):
// an EXR whose header holds the sample count and the scene fingerprint. The harness passes the
// fingerprint its seeds carry ("fuzz"), so mutated files get past the fingerprint check into the
// sample count and planes. A loaded estimate has three values (the mean) per pixel.
#include <cloudscape/pathtrace.h>
#include <cloudscape/render_files.h>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = cloudscape::fuzz::scratchFile(".exr");
    cloudscape::fuzz::writeScratch(path, data, size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::PathTraceImage image = cloudscape::readPathTraceCheckpoint(path, "fuzz");
        if (image.mean.size() != static_cast<size_t>(image.width) * image.height * 3) {
            std::fprintf(stderr, "fuzz: checkpoint of %dx%d pixels holds %zu values\n", image.width,
                         image.height, image.mean.size());
            std::abort();
        }
    });
    return 0;
}
