#include <cloudscape/error.h>
#include <cloudscape/metrics.h>

#include "model/output.glsl.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cloudscape {

ImageDifference compareImages(const std::vector<float>& reference, const std::vector<float>& test,
                              int stride, const std::vector<int>& skip, double peak) {
    if (reference.size() != test.size() || stride <= 0 || reference.size() % stride != 0)
        throw Error("compareImages: images differ in size or stride");
    double squared = 0.0, absolute = 0.0, largest = 0.0, refMax = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < reference.size(); ++i) {
        const int channel = static_cast<int>(i % static_cast<size_t>(stride));
        if (std::find(skip.begin(), skip.end(), channel) != skip.end())
            continue;
        const double d = static_cast<double>(test[i]) - reference[i];
        squared += d * d;
        absolute += std::abs(d);
        largest = std::max(largest, std::abs(d));
        refMax = std::max(refMax, static_cast<double>(reference[i]));
        ++count;
    }
    ImageDifference r;
    r.maxError = largest;
    r.meanError = count ? absolute / count : 0.0;
    const double mse = count ? squared / count : 0.0;
    const double p = peak > 0.0 ? peak : refMax;
    r.psnr = mse > 0.0 ? 10.0 * std::log10(p * p / mse) : std::numeric_limits<double>::infinity();
    return r;
}

} // namespace cloudscape

namespace cloudscape {
namespace {

constexpr double kC1 = 0.01 * 0.01; // (K1 L)^2 with L = 1
constexpr double kC2 = 0.03 * 0.03; // (K2 L)^2

struct SsimParts {
    double contrastStructure = 0.0; // mean of c(x, y) s(x, y)
    double ssim = 0.0;              // mean of the product
};

// Gaussian-windowed statistics at every window position (valid region).
SsimParts ssimParts(const std::vector<float>& a, const std::vector<float>& b, int w, int h) {
    const int size = std::min({11, w, h});
    const double sigma = 1.5 * size / 11.0;
    std::vector<double> kernel(size);
    double norm = 0.0;
    for (int i = 0; i < size; ++i) {
        const double x = i - (size - 1) / 2.0;
        kernel[i] = std::exp(-x * x / (2.0 * sigma * sigma));
        norm += kernel[i];
    }
    for (double& k : kernel)
        k /= norm;
    SsimParts parts;
    size_t windows = 0;
    for (int y0 = 0; y0 + size <= h; ++y0)
        for (int x0 = 0; x0 + size <= w; ++x0) {
            double ma = 0, mb = 0, saa = 0, sbb = 0, sab = 0;
            for (int j = 0; j < size; ++j)
                for (int i = 0; i < size; ++i) {
                    const double k = kernel[i] * kernel[j];
                    const size_t p = static_cast<size_t>(y0 + j) * w + (x0 + i);
                    ma += k * a[p];
                    mb += k * b[p];
                    saa += k * a[p] * a[p];
                    sbb += k * b[p] * b[p];
                    sab += k * a[p] * b[p];
                }
            const double va = std::max(saa - ma * ma, 0.0);
            const double vb = std::max(sbb - mb * mb, 0.0);
            const double cov = sab - ma * mb;
            const double l = (2.0 * ma * mb + kC1) / (ma * ma + mb * mb + kC1);
            const double cs = (2.0 * cov + kC2) / (va + vb + kC2);
            parts.contrastStructure += cs;
            parts.ssim += l * cs;
            ++windows;
        }
    parts.contrastStructure /= static_cast<double>(windows);
    parts.ssim /= static_cast<double>(windows);
    return parts;
}

void requireSameSize(const std::vector<float>& a, const std::vector<float>& b, int w, int h) {
    if (w <= 0 || h <= 0 || a.size() != static_cast<size_t>(w) * h || b.size() != a.size())
        throw Error("ssim: images must both be " + std::to_string(w) + "x" + std::to_string(h));
}

std::vector<float> halve(const std::vector<float>& img, int w, int h) {
    const int hw = w / 2, hh = h / 2;
    std::vector<float> out(static_cast<size_t>(hw) * hh);
    for (int y = 0; y < hh; ++y)
        for (int x = 0; x < hw; ++x) {
            const size_t p = static_cast<size_t>(2 * y) * w + 2 * x;
            out[static_cast<size_t>(y) * hw + x] =
                0.25f * (img[p] + img[p + 1] + img[p + w] + img[p + w + 1]);
        }
    return out;
}

} // namespace

std::vector<float> displayLuminance(const std::vector<float>& rgb, int stride, float exposure) {
    std::vector<float> out(rgb.size() / static_cast<size_t>(stride));
    for (size_t i = 0; i < out.size(); ++i) {
        const glm::vec3 c(rgb[i * stride], rgb[i * stride + 1], rgb[i * stride + 2]);
        const glm::vec3 d = model::toneMap(c, exposure);
        out[i] = 0.2126f * d.x + 0.7152f * d.y + 0.0722f * d.z;
    }
    return out;
}

double relativeError(const std::vector<float>& reference, const std::vector<float>& test) {
    if (reference.size() != test.size())
        throw Error("relativeError: images differ in size");
    double diff = 0.0, total = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
        diff += std::abs(static_cast<double>(test[i]) - reference[i]);
        total += std::abs(static_cast<double>(reference[i]));
    }
    return total > 0.0 ? diff / total
                       : (diff > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
}

double ssim(const std::vector<float>& a, const std::vector<float>& b, int width, int height) {
    requireSameSize(a, b, width, height);
    return ssimParts(a, b, width, height).ssim;
}

double msSsim(const std::vector<float>& a, const std::vector<float>& b, int width, int height) {
    requireSameSize(a, b, width, height);
    static const double weights[5] = {0.0448, 0.2856, 0.3001, 0.2363, 0.1333};
    int scales = 1;
    while (scales < 5 && (width >> scales) >= 11 && (height >> scales) >= 11)
        ++scales;
    double weightSum = 0.0;
    for (int s = 0; s < scales; ++s)
        weightSum += weights[s];
    std::vector<float> x = a, y = b;
    int w = width, h = height;
    double result = 1.0;
    for (int s = 0; s < scales; ++s) {
        const SsimParts parts = ssimParts(x, y, w, h);
        const double exponent = weights[s] / weightSum;
        // Negative contrast-structure (anti-correlated images) is clamped so the fractional
        // power stays defined; such images score 0. The coarsest scale contributes its mean SSIM
        // (luminance times contrast-structure per window), as Wang's reference code does.
        const double term = s + 1 == scales ? parts.ssim : parts.contrastStructure;
        result *= std::pow(std::max(term, 0.0), exponent);
        if (s + 1 < scales) {
            x = halve(x, w, h);
            y = halve(y, w, h);
            w /= 2;
            h /= 2;
        }
    }
    return result;
}

} // namespace cloudscape
