// The library's image file formats: a render's EXR layers, and the path tracer's progressive
// checkpoint (an EXR whose header carries the sample count and the scene's fingerprint).
#include <cloudscape/error.h>
#include <cloudscape/image_io.h>
#include <cloudscape/pathtrace.h>
#include <cloudscape/render_files.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape {
namespace {

constexpr const char* kSamplesAttribute = "cloudscape.samples";
constexpr const char* kSceneAttribute = "cloudscape.scene";

// The sample count a checkpoint claims: digits only, at least 1 (a negative or garbled count
// would scale the stored mean into nonsense).
uint64_t parseSampleCount(const std::string& path, const std::string& text) {
    constexpr uint64_t kMaxSamples = 1000000000;
    uint64_t count = 0;
    bool valid = !text.empty() && text.size() <= 10;
    for (char c : text) {
        valid = valid && c >= '0' && c <= '9';
        if (valid)
            count = count * 10 + static_cast<uint64_t>(c - '0');
    }
    if (!valid || count < 1 || count > kMaxSamples)
        throw Error(path + ": attribute " + kSamplesAttribute + " = '" + text.substr(0, 40) +
                    "' is not a sample count (expected an integer from 1 to " +
                    std::to_string(kMaxSamples) + "); cannot resume it");
    return count;
}

} // namespace

void writeRenderExr(const std::string& path, const RenderResult& r) {
    const size_t n = static_cast<size_t>(r.width) * r.height;
    if (r.cloud.size() != n * 4 || r.depth.size() != n || r.composite.size() != n * 4)
        throw Error(path + ": an EXR needs every layer of the render (Readback::All)");
    // Planar copies: EXR channels are separate planes.
    std::vector<std::vector<float>> planes(9, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i) {
        planes[0][i] = r.composite[i * 4 + 0];
        planes[1][i] = r.composite[i * 4 + 1];
        planes[2][i] = r.composite[i * 4 + 2];
        planes[3][i] = 1.0f;
        planes[4][i] = r.cloud[i * 4 + 0];
        planes[5][i] = r.cloud[i * 4 + 1];
        planes[6][i] = r.cloud[i * 4 + 2];
        planes[7][i] = r.cloud[i * 4 + 3];
        planes[8][i] = r.depth[i];
    }
    // Premultiplied cloud layer: cloud.A = 1 - transmittance, for compositors; cloud.T is the
    // transmittance itself; cloud.Z is the distance to the first cloud (+inf where none).
    std::vector<float> alpha(n);
    for (size_t i = 0; i < n; ++i)
        alpha[i] = 1.0f - planes[7][i];
    writeExr(path, r.width, r.height,
             {{"R", planes[0].data()},
              {"G", planes[1].data()},
              {"B", planes[2].data()},
              {"A", planes[3].data()},
              {"cloud.R", planes[4].data()},
              {"cloud.G", planes[5].data()},
              {"cloud.B", planes[6].data()},
              {"cloud.A", alpha.data()},
              {"cloud.T", planes[7].data()},
              {"cloud.Z", planes[8].data()}});
}

void writePathTraceCheckpoint(const std::string& path, const PathTraceImage& image,
                              const std::string& fingerprint) {
    const std::vector<float>& mean = image.mean;
    const size_t n = static_cast<size_t>(image.width) * image.height;
    std::vector<std::vector<float>> planes(4, std::vector<float>(n, 1.0f));
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            planes[c][i] = mean[i * 3 + c];
    writeExr(path, image.width, image.height,
             {{"R", planes[0].data()},
              {"G", planes[1].data()},
              {"B", planes[2].data()},
              {"A", planes[3].data()}},
             {{kSamplesAttribute, std::to_string(image.samplesPerPixel)},
              {kSceneAttribute, fingerprint}});
}

PathTraceImage readPathTraceCheckpoint(const std::string& path, const std::string& fingerprint) {
    const ExrImage exr = readExr(path);
    const auto samples = exr.attributes.find(kSamplesAttribute);
    const auto scene = exr.attributes.find(kSceneAttribute);
    if (samples == exr.attributes.end() || scene == exr.attributes.end())
        throw Error(path + ": not a cloudscape pathtrace output (no " + kSamplesAttribute +
                    " attribute); cannot resume it");
    if (scene->second != fingerprint)
        throw Error(path + ": was rendered from a different scene or settings; cannot resume it "
                           "(use --force to start again)");
    PathTraceImage image;
    image.width = exr.width;
    image.height = exr.height;
    image.samplesPerPixel = parseSampleCount(path, samples->second);
    const size_t n = static_cast<size_t>(exr.width) * exr.height;
    image.mean.resize(n * 3);
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>& plane = exr.channel(names[c]);
        for (size_t i = 0; i < n; ++i)
            image.mean[i * 3 + c] = plane[i]; // the whole state: resuming is exact
    }
    return image;
}

} // namespace cloudscape
