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
