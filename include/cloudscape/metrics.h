#pragma once
// Image comparison on linear HDR data (interleaved channels, any count).
#include <cstddef>
#include <vector>

namespace cloudscape {

struct ImageDifference {
    double psnr = 0.0;     // dB, against `peak`; +infinity for identical images
    double maxError = 0.0; // largest absolute difference of any channel
    double meanError = 0.0;
};

// Compares a test image with a reference of the same size. peak <= 0 uses the reference's
// largest value (the usual choice for HDR radiance). Channels listed in skip (e.g. alpha of
// RGBA = {3} with stride 4) are ignored; stride is the channel count.
ImageDifference compareImages(const std::vector<float>& reference, const std::vector<float>& test,
                              int stride, const std::vector<int>& skip = {}, double peak = 0.0);

} // namespace cloudscape
