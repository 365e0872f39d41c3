// Harness: the path tracer's checkpoint reader (`pathtrace --resume`): an EXR whose header holds
// the sample count and the scene fingerprint. The harness passes the fingerprint its seeds carry
// ("fuzz"), so mutated files get past the fingerprint check into the sample count and planes.
//
// loadEstimate lives in an anonymous namespace of the command's file; the harness includes that
// file rather than moving the function, to keep this change out of the way of the reader's own
// fixes (issue 9 part 1, issue 16). A loaded estimate has three sums per pixel.
#include "pathtrace_command.cpp"

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = cloudscape::fuzz::scratchFile(".exr");
    cloudscape::fuzz::writeScratch(path, data, size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::PathTraceImage image = cloudscape::cli::loadEstimate(path, "fuzz");
        if (image.mean.size() != static_cast<size_t>(image.width) * image.height * 3) {
            std::fprintf(stderr, "fuzz: checkpoint of %dx%d pixels holds %zu sums\n", image.width,
                         image.height, image.mean.size());
            std::abort();
        }
    });
    return 0;
}
