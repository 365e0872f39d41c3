// Harness: a painted weather map (weather.image), read by loadWeatherImage: the PNG decoder, the
// channel checks, the precipitation rule and the mip chain. A map that loads must hold values
// in [0, 1] at every level.
#include "fuzz_support.h"

#include <cloudscape/weather.h>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = cloudscape::fuzz::scratchFile(".png");
    cloudscape::fuzz::writeScratch(path, data, size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::Texture2D map = cloudscape::loadWeatherImage(path);
        for (const auto& level : map.mips)
            for (float v : level)
                if (!(v >= 0.0f && v <= 1.0f)) {
                    std::fprintf(stderr, "fuzz: weather map value %g outside [0, 1]\n", v);
                    std::abort();
                }
    });
    return 0;
}
