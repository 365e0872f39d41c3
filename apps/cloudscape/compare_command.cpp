// `cloudscape compare A.exr B.exr`: how far B is from the reference A.
#include "commands.h"

#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/metrics.h>

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

void runCompare(const CompareArgs& args) {
    if (!args.heatmap.empty())
        checkOutputWritable(args.heatmap);
    const ExrImage a = readExr(args.reference);
    const ExrImage b = readExr(args.test);
    if (a.width != b.width || a.height != b.height)
        throw Error(args.test + ": size " + std::to_string(b.width) + "x" +
                    std::to_string(b.height) + " differs from the reference's " +
                    std::to_string(a.width) + "x" + std::to_string(a.height));
    const std::vector<float> ra = interleavedRgb(a), rb = interleavedRgb(b);
    const ImageDifference d = compareImages(ra, rb, 3);
    const std::vector<float> la = displayLuminance(ra, 3, args.exposure);
    const std::vector<float> lb = displayLuminance(rb, 3, args.exposure);
    std::printf("PSNR (HDR RGB, peak of reference)  %.2f dB\n", d.psnr);
    std::printf("SSIM (display luminance)           %.4f\n", ssim(la, lb, a.width, a.height));
    std::printf("MS-SSIM (display luminance)        %.4f\n", msSsim(la, lb, a.width, a.height));
    std::printf("relative HDR error                 %.4f\n", relativeError(ra, rb));
    std::printf("max abs error                      %.4g\n", d.maxError);
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
    cmd->callback([args]() { runCompare(*args); });
}

} // namespace cloudscape::cli
