// Harness: a scene depth buffer (render.depth_file), read by loadDepthBuffer at the size the
// file claims (so the size check passes and the channel and value checks run): OpenEXR's
// reader, readExr's channel layout, the R/Z/only-channel choice and the depth checks. A buffer
// that loads holds no NaN and no negative depth.
#include "fuzz_support.h"

#include <cloudscape/image_io.h>
#include <cloudscape/renderer.h>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = cloudscape::fuzz::scratchFile(".exr");
    cloudscape::fuzz::writeScratch(path, data, size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::ExrImage image = cloudscape::readExr(path);
        const cloudscape::DepthBuffer depth =
            cloudscape::loadDepthBuffer(path, image.width, image.height);
        for (float m : depth.metres)
            if (!(m >= 0.0f)) {
                std::fprintf(stderr, "fuzz: depth %g passed the checks\n", m);
                std::abort();
            }
    });
    return 0;
}
