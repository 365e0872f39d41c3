// The blue-noise map of the march's start offsets: uniform values, little low-frequency energy
// (the definition of blue noise) and no seams where it tiles.
#include <cloudscape/blue_noise.h>
#include <cloudscape/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

namespace {

// Radially binned power spectrum of an n x n image (mean removed), by a separable DFT; the image
// is periodic, so the DFT sees it tiled, seams included.
std::vector<double> radialPower(const std::vector<double>& image, int n) {
    double mean = 0.0;
    for (double v : image)
        mean += v;
    mean /= static_cast<double>(image.size());
    using C = std::complex<double>;
    std::vector<C> rows(image.size()), spectrum(image.size());
    std::vector<C> twiddle(n);
    for (int k = 0; k < n; ++k)
        twiddle[k] = std::polar(1.0, -2.0 * std::numbers::pi * k / n);
    for (int y = 0; y < n; ++y)
        for (int u = 0; u < n; ++u) {
            C s = 0.0;
            for (int x = 0; x < n; ++x)
                s += (image[y * n + x] - mean) * twiddle[(u * x) % n];
            rows[y * n + u] = s;
        }
    for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
            C s = 0.0;
            for (int y = 0; y < n; ++y)
                s += rows[y * n + u] * twiddle[(v * y) % n];
            spectrum[v * n + u] = s;
        }
    std::vector<double> power(n, 0.0);
    std::vector<int> count(n, 0);
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const int fu = std::min(u, n - u), fv = std::min(v, n - v);
            const int r = static_cast<int>(std::lround(std::sqrt(double(fu * fu + fv * fv))));
            if (r < n) {
                power[r] += std::norm(spectrum[v * n + u]);
                ++count[r];
            }
        }
    for (int r = 0; r < n; ++r)
        if (count[r])
            power[r] /= count[r];
    return power;
}

// Share of the (non-DC) spectral energy below a quarter of the Nyquist frequency.
double lowFrequencyShare(const std::vector<double>& image, int n) {
    const std::vector<double> p = radialPower(image, n);
    double low = 0.0, all = 0.0;
    for (int r = 1; r <= n / 2; ++r) {
        all += p[r];
        if (r <= n / 8)
            low += p[r];
    }
    return low / all;
}

std::vector<double> values(const cloudscape::Texture2D& t) {
    std::vector<double> v(static_cast<size_t>(t.width) * t.height);
    for (size_t i = 0; i < v.size(); ++i)
        v[i] = t.mips[0][i * 4];
    return v;
}

} // namespace

TEST(BlueNoise, ValuesAreUniformRgba8Levels) {
    const cloudscape::Texture2D& t = cloudscape::blueNoiseTexture();
    ASSERT_EQ(t.width, 64);
    ASSERT_EQ(t.height, 64);
    ASSERT_EQ(t.levelCount(), 1);
    // 4096 ranks in 256 levels: every level holds exactly 16 texels.
    std::vector<int> histogram(256, 0);
    for (double v : values(t)) {
        const double level = v * 255.0;
        ASSERT_NEAR(level, std::round(level), 1e-4);
        ++histogram[static_cast<int>(std::lround(level))];
    }
    for (int l = 0; l < 256; ++l)
        EXPECT_EQ(histogram[l], 16) << "level " << l;
}

TEST(BlueNoise, HasLittleLowFrequencyEnergy) {
    const int n = 64;
    const double blue = lowFrequencyShare(values(cloudscape::blueNoiseTexture()), n);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> white(n * n);
    for (double& v : white)
        v = u(rng);
    const double whiteShare = lowFrequencyShare(white, n);
    // White noise spreads its energy evenly (about 1/16 of the area below n/8 of Nyquist's
    // n/2 ... measured ~0.05); blue noise leaves the low frequencies nearly empty.
    EXPECT_LT(blue, 0.1 * whiteShare) << "blue " << blue << " white " << whiteShare;
}

TEST(BlueNoise, ThresholdPatternsAreEvenAcrossTheSeams) {
    // The 10 % darkest texels form a well-spread dot pattern: no two dots touch (8-neighbours),
    // neither inside the tile nor across its wrap-around edges, which is what tiling needs.
    const cloudscape::Texture2D& t = cloudscape::blueNoiseTexture();
    const int n = t.width;
    auto dot = [&](int x, int y) { return t.texel(0, (x + n) % n, (y + n) % n)[0] < 0.1f; };
    int dots = 0, touching = 0, seamTouching = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            if (!dot(x, y))
                continue;
            ++dots;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((dx || dy) && dot(x + dx, y + dy)) {
                        ++touching;
                        const bool seam = x + dx < 0 || x + dx >= n || y + dy < 0 || y + dy >= n;
                        seamTouching += seam;
                    }
                }
        }
    EXPECT_NEAR(dots, n * n / 10, n * n / 100);
    EXPECT_EQ(touching, 0);
    EXPECT_EQ(seamTouching, 0);
}

TEST(BlueNoise, DeterministicAndSeeded) {
    const cloudscape::Texture2D a = cloudscape::generateBlueNoise(16, 3);
    const cloudscape::Texture2D b = cloudscape::generateBlueNoise(16, 3);
    const cloudscape::Texture2D c = cloudscape::generateBlueNoise(16, 4);
    EXPECT_EQ(a.mips, b.mips);
    EXPECT_NE(a.mips, c.mips);
    EXPECT_THROW(cloudscape::generateBlueNoise(48, 1), cloudscape::Error);
}
