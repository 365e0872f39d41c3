#include <cloudscape/metrics.h>

#include <gtest/gtest.h>

#include <cmath>

TEST(Metrics, PsnrOfKnownDifference) {
    // Reference peak 2, one of four values off by 0.2: MSE = 0.01, PSNR = 10 log10(4 / 0.01).
    const std::vector<float> ref = {0.0f, 1.0f, 2.0f, 0.5f};
    const std::vector<float> test = {0.0f, 1.2f, 2.0f, 0.5f};
    const cloudscape::ImageDifference d = cloudscape::compareImages(ref, test, 1);
    EXPECT_NEAR(d.psnr, 10.0 * std::log10(400.0), 1e-4);
    EXPECT_NEAR(d.maxError, 0.2, 1e-6);
    EXPECT_NEAR(d.meanError, 0.05, 1e-6);
}

TEST(Metrics, IdenticalIsInfiniteAndSkippedChannelsDoNotCount) {
    const std::vector<float> a = {1, 2, 3, 0, 4, 5, 6, 0};
    std::vector<float> b = a;
    EXPECT_TRUE(std::isinf(cloudscape::compareImages(a, b, 4).psnr));
    b[3] = 9.0f; // alpha
    EXPECT_TRUE(std::isinf(cloudscape::compareImages(a, b, 4, {3}).psnr));
    EXPECT_FALSE(std::isinf(cloudscape::compareImages(a, b, 4).psnr));
}

#include <random>

namespace {
std::vector<float> pattern(int w, int h) {
    std::vector<float> v(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            v[static_cast<size_t>(y) * w + x] =
                0.5f + 0.4f * std::sin(0.3f * x) * std::cos(0.2f * y);
    return v;
}
} // namespace

TEST(Metrics, SsimOfAnImageWithItselfIsOne) {
    const auto a = pattern(64, 48);
    EXPECT_NEAR(cloudscape::ssim(a, a, 64, 48), 1.0, 1e-12);
    EXPECT_NEAR(cloudscape::msSsim(a, a, 64, 48), 1.0, 1e-12);
}

TEST(Metrics, SsimFallsWithNoise) {
    const auto a = pattern(96, 96);
    std::mt19937 rng(3);
    double previous = 1.0, previousMs = 1.0;
    for (float amount : {0.02f, 0.05f, 0.1f, 0.2f}) {
        std::normal_distribution<float> noise(0.0f, amount);
        auto b = a;
        for (float& v : b)
            v = std::clamp(v + noise(rng), 0.0f, 1.0f);
        const double s = cloudscape::ssim(a, b, 96, 96);
        const double ms = cloudscape::msSsim(a, b, 96, 96);
        EXPECT_LT(s, previous) << amount;
        EXPECT_LT(ms, previousMs) << amount;
        EXPECT_GT(s, 0.0);
        previous = s;
        previousMs = ms;
    }
    EXPECT_LT(previous, 0.5); // heavy noise is clearly different
}

TEST(Metrics, SsimMatchesHandComputedValues) {
    // Two flat 11x11 images, 0.5 and 0.6: no variance, so SSIM is the luminance term alone,
    // (2 * 0.5 * 0.6 + C1) / (0.25 + 0.36 + C1) with C1 = 1e-4.
    const std::vector<float> a(121, 0.5f), b(121, 0.6f);
    EXPECT_NEAR(cloudscape::ssim(a, b, 11, 11), (0.6 + 1e-4) / (0.61 + 1e-4), 1e-6);
    // A 2x2 image uses one window over everything: uniform weights reduce to plain statistics.
    // a = {0, 1, 0, 1}, b = {0, 1, 1, 0}: means 0.5, variances 0.25, covariance 0.
    const std::vector<float> c = {0, 1, 0, 1}, d = {0, 1, 1, 0};
    const double expected = ((2 * 0.25 + 1e-4) / (0.5 + 1e-4)) * (9e-4 / (0.5 + 9e-4));
    EXPECT_NEAR(cloudscape::ssim(c, d, 2, 2), expected, 1e-6);
}
