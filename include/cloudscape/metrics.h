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

// Luminance of the tone-mapped display image (the renderer's ACES + sRGB at `exposure`), in
// [0, 1]: what SSIM compares, since it was designed for display values. rgb has `stride` floats
// per pixel, red first.
std::vector<float> displayLuminance(const std::vector<float>& rgb, int stride, float exposure);

// Relative HDR error: sum |test - reference| / sum |reference| over the listed channels.
double relativeError(const std::vector<float>& reference, const std::vector<float>& test);

// Structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004) of two single-channel images
// with values in [0, 1] (e.g. display luminance): an 11x11 Gaussian window (sigma 1.5), K1 = 0.01,
// K2 = 0.03, averaged over every window position that fits. Images smaller than the window use
// one window over the whole image. 1 means identical.
double ssim(const std::vector<float>& a, const std::vector<float>& b, int width, int height);

// Multi-scale SSIM (Wang, Simoncelli and Bovik 2003): contrast-structure at 5 scales (2x2 box
// downsampling) and luminance at the coarsest, weighted 0.0448, 0.2856, 0.3001, 0.2363, 0.1333;
// as in Wang's reference code, each finer scale contributes its mean contrast-structure and the
// coarsest its mean SSIM. Small images use fewer scales (the coarsest must hold a window) with
// the weights renormalised. Checked against an independent implementation
// (scripts/ssim-reference-values.py).
double msSsim(const std::vector<float>& a, const std::vector<float>& b, int width, int height);

} // namespace cloudscape
