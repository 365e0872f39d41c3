// `cloudscape compare A.exr B.exr`: how far B is from the reference A.
#include "commands.h"
#include "validate_only.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/metrics.h>
#include <cloudscape/renderer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace cloudscape::cli {
namespace {

struct CompareArgs {
    std::string reference;
    std::string test;
    std::string heatmap;
    float exposure = 1.0f;
    float clamp = 0.0f; // > 0: clamp both images' radiance to this before measuring
    std::string sideBySide;
};

std::vector<float> interleavedRgb(const ExrImage& img) {
    const auto& r = img.channel("R");
    const auto& g = img.channel("G");
    const auto& b = img.channel("B");
    std::vector<float> out(r.size() * 3);
    for (size_t i = 0; i < r.size(); ++i) {
        out[i * 3] = r[i];
        out[i * 3 + 1] = g[i];
        out[i * 3 + 2] = b[i];
    }
    return out;
}

// NaN or infinite radiance makes every measure meaningless (PSNR prints inf): refuse it and say
// where the first bad pixel is.
void requireFinite(const std::string& path, const std::vector<float>& rgb, int width) {
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < rgb.size(); ++i)
        if (!std::isfinite(rgb[i]) && bad++ == 0)
            first = i / 3;
    if (bad > 0)
        throw Error(path + ": " + std::to_string(bad) +
                    " R/G/B values are NaN or infinite (the first at pixel " +
                    std::to_string(first % static_cast<size_t>(width)) + ", " +
                    std::to_string(first / static_cast<size_t>(width)) +
                    "); expected finite radiance");
}

void runCompare(const CompareArgs& args) {
    if (!args.sideBySide.empty() && args.heatmap.empty())
        throw Error("--side-by-side: needs --heatmap (its third panel)");
    if (!args.heatmap.empty())
        checkOutputWritable(args.heatmap);
    const ExrImage a = readExr(args.reference);
    const ExrImage b = readExr(args.test);
    if (a.width != b.width || a.height != b.height)
        throw Error(args.test + ": size " + std::to_string(b.width) + "x" +
                    std::to_string(b.height) + " differs from the reference's " +
                    std::to_string(a.width) + "x" + std::to_string(a.height));
    if (!args.sideBySide.empty())
        checkOutputWritable(args.sideBySide);
    stopIfValidatingOnly();
    std::vector<float> ra = interleavedRgb(a), rb = interleavedRgb(b);
    requireFinite(args.reference, ra, a.width);
    requireFinite(args.test, rb, b.width);
    if (args.clamp > 0.0f) {
        // The sun disc is tens of thousands of times brighter than anything else and is
        // sampled differently by the renderers (point vs area); clamping keeps it from
        // swamping the HDR measures.
        for (float& v : ra)
            v = std::min(v, args.clamp);
        for (float& v : rb)
            v = std::min(v, args.clamp);
    }
    const ImageDifference d = compareImages(ra, rb, 3);
    const std::vector<float> la = displayLuminance(ra, 3, args.exposure);
    const std::vector<float> lb = displayLuminance(rb, 3, args.exposure);
    std::printf("PSNR (HDR RGB, peak of reference)  %.2f dB\n", d.psnr);
    std::printf("SSIM (display luminance)           %.4f\n", ssim(la, lb, a.width, a.height));
    std::printf("MS-SSIM (display luminance)        %.4f\n", msSsim(la, lb, a.width, a.height));
    std::printf("relative HDR error                 %.4f\n", relativeError(ra, rb));
    std::printf("max abs error                      %.4g\n", d.maxError);
    // Energy bias: mean radiance of the test over that of the reference (1 = same brightness).
    double sumA = 0.0, sumB = 0.0;
    for (size_t i = 0; i < ra.size(); ++i) {
        sumA += ra[i];
        sumB += rb[i];
    }
    std::printf("mean radiance ratio (test / ref)   %.4f\n", sumA > 0.0 ? sumB / sumA : 0.0);
    if (!args.heatmap.empty()) {
        // Per-pixel relative error |B - A| / (|A| + 0.01), 0 black -> 0.25 and above white, through
        // red and yellow.
        std::vector<uint8_t> rgba(static_cast<size_t>(a.width) * a.height * 4);
        for (size_t i = 0; i < rgba.size() / 4; ++i) {
            double err = 0.0, ref = 0.0;
            for (int c = 0; c < 3; ++c) {
                err += std::abs(rb[i * 3 + c] - ra[i * 3 + c]);
                ref += std::abs(ra[i * 3 + c]);
            }
            const float t = static_cast<float>(std::clamp(err / (ref + 0.01) / 0.25, 0.0, 1.0));
            rgba[i * 4 + 0] = static_cast<uint8_t>(255.0f * std::clamp(t * 3.0f, 0.0f, 1.0f));
            rgba[i * 4 + 1] =
                static_cast<uint8_t>(255.0f * std::clamp(t * 3.0f - 1.0f, 0.0f, 1.0f));
            rgba[i * 4 + 2] =
                static_cast<uint8_t>(255.0f * std::clamp(t * 3.0f - 2.0f, 0.0f, 1.0f));
            rgba[i * 4 + 3] = 255;
        }
        writePng(args.heatmap, a.width, a.height, rgba);
        if (!args.sideBySide.empty()) {
            // Reference | test | heat map, for looking at.
            const std::vector<uint8_t> ta = toneMapRgbToSrgb8(ra, args.exposure);
            const std::vector<uint8_t> tb = toneMapRgbToSrgb8(rb, args.exposure);
            const int w = a.width;
            std::vector<uint8_t> row3(static_cast<size_t>(w) * 3 * a.height * 4);
            for (int y = 0; y < a.height; ++y)
                for (int x = 0; x < w; ++x)
                    for (int c = 0; c < 4; ++c) {
                        const size_t src = (static_cast<size_t>(y) * w + x) * 4 + c;
                        const size_t dst = (static_cast<size_t>(y) * w * 3 + x) * 4 + c;
                        row3[dst] = ta[src];
                        row3[dst + static_cast<size_t>(w) * 4] = tb[src];
                        row3[dst + static_cast<size_t>(w) * 8] = rgba[src];
                    }
            writePng(args.sideBySide, w * 3, a.height, row3);
        }
    }
}

} // namespace

void addCompareCommand(CLI::App& app) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App* cmd = app.add_subcommand(
        "compare", "Compare an EXR with a reference: PSNR, SSIM, MS-SSIM, relative HDR error");
    cmd->add_option("reference", args->reference, "Reference EXR")->required();
    cmd->add_option("test", args->test, "EXR to compare")->required();
    cmd->add_option("--heatmap", args->heatmap, "Write a per-pixel relative error map (PNG)");
    cmd->add_option("--exposure", args->exposure, "Exposure of the display image SSIM compares");
    cmd->add_option("--clamp", args->clamp,
                    "Clamp both images' radiance to this first (keeps the sun disc out of the "
                    "HDR measures)");
    cmd->add_option("--side-by-side", args->sideBySide,
                    "With --heatmap: also write reference | test | heat map as one PNG");
    cmd->callback([args]() { runCompare(*args); });
}

} // namespace cloudscape::cli
