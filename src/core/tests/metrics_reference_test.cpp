// SSIM and MS-SSIM against an independent implementation: scikit-image's SSIM and a MS-SSIM
// written from Wang's reference code, computed once by scripts/ssim-reference-values.py on
// textured images that both sides build from integers (ssim_reference_values.h holds the values
// and the images' level sums). Flat or 2x2 images cannot tell a wrong window width or a term
// taken at the wrong scale; these can.
#include <cloudscape/metrics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "ssim_reference_values.h"

namespace {

// The script's hash32, tri and image kinds, in the same integer arithmetic.
uint32_t hash32(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = x * 374761393u + y * 668265263u + seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return h ^ (h >> 16);
}

int tri(int v, int period) {
    return std::abs(v % period - period / 2);
}

int baseLevel(int x, int y) {
    return 30 + 3 * tri(x, 40) + 4 * tri(y, 28) + 2 * tri(x + y, 18) +
           static_cast<int>(hash32(x, y, 1) % 48);
}

int level(const std::string& kind, int x, int y) {
    if (kind == "base")
        return baseLevel(x, y);
    if (kind == "shifted")
        return std::clamp(
            3 * baseLevel(x + 1, y) / 4 + 45 + static_cast<int>(hash32(x, y, 2) % 33) - 16, 0, 255);
    if (kind == "brighter")
        return std::clamp(9 * baseLevel(x, y) / 10 + 60, 0, 255);
    if (kind == "blocky")
        return baseLevel(x - x % 4, y - y % 4);
    ADD_FAILURE() << "unknown image kind " << kind;
    return 0;
}

std::vector<float> image(const std::string& kind, int w, int h, long long& levelSum) {
    std::vector<float> img(static_cast<size_t>(w) * h);
    levelSum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int v = level(kind, x, y);
            levelSum += v;
            img[static_cast<size_t>(y) * w + x] = static_cast<float>(v / 255.0);
        }
    return img;
}

} // namespace

TEST(MetricsReference, SsimAndMsSsimMatchAnIndependentImplementation) {
    for (const ssim_reference::Case& c : ssim_reference::kCases) {
        const std::string what = std::string(c.reference) + " vs " + c.test + " at " +
                                 std::to_string(c.width) + "x" + std::to_string(c.height);
        long long refSum = 0, testSum = 0;
        const auto a = image(c.reference, c.width, c.height, refSum);
        const auto b = image(c.test, c.width, c.height, testSum);
        // The images are the script's, level for level (up to a sum collision).
        ASSERT_EQ(refSum, c.referenceSum) << what;
        ASSERT_EQ(testSum, c.testSum) << what;
        // Both work in double from the same float pixels; the downsampled scales are averaged
        // in float here and in double there, a few 1e-8 apart. A 10 % wider Gaussian moves
        // these values by about 1e-3.
        EXPECT_NEAR(cloudscape::ssim(a, b, c.width, c.height), c.ssim, 1e-6) << what;
        EXPECT_NEAR(cloudscape::msSsim(a, b, c.width, c.height), c.msSsim, 1e-6) << what;
        // Symmetric in its arguments.
        EXPECT_NEAR(cloudscape::ssim(b, a, c.width, c.height), c.ssim, 1e-9) << what;
    }
}

TEST(MetricsReference, RelativeErrorIsNormalisedByTheReference) {
    // sum |test - reference| / sum |reference|: (0 + 1 + 2) / (1 + 2 + 3).
    const std::vector<float> reference = {1.0f, 2.0f, -3.0f}, test = {1.0f, 3.0f, -1.0f};
    EXPECT_NEAR(cloudscape::relativeError(reference, test), 0.5, 1e-12);
    EXPECT_NEAR(cloudscape::relativeError(test, reference), 3.0 / 5.0, 1e-12);
}
