#include <cloudscape/error.h>
#include <cloudscape/metrics.h>

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
