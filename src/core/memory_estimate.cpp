// Host-memory estimates of a render, from peaks measured with /usr/bin/time on the CPU backend.
#include <cloudscape/error.h>
#include <cloudscape/memory_estimate.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/resource.h>

namespace cloudscape {
namespace {

// Measured (2048x2048 against 256x256, peak resident size): a PNG still about 49 bytes a
// pixel, an EXR still 73, a temporal sequence 91 (history, samples, resolve buffers); the path
// tracer keeps double sums. Rounded up for what the measurement did not exercise.
uint64_t bytesPerPixel(RenderJob job) {
    switch (job) {
    case RenderJob::StillPng:
        return 64;
    case RenderJob::StillExr:
        return 96;
    case RenderJob::Sequence:
        return 128;
    case RenderJob::PathTrace:
        return 96;
    }
    return 128;
}

std::string gibibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
    return text;
}

// GiB, or MiB below one GiB (a device heap can be small).
std::string bytesText(uint64_t bytes) {
    if (bytes >= (1u << 30))
        return gibibytes(bytes);
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1u << 20));
    return text;
}

} // namespace

MemoryEstimate estimateRenderMemory(const Scene& scene, RenderJob job) {
    MemoryEstimate e;
    // The program with its 128^3 RGBA float base noise and mips, the detail and curl noise, and
    // the 512^2 high-altitude texture (6 MB with mips), and the 8-bit copies of the 3D noise the
    // CPU sampler reads (10 MB, Texture3D::unorm8).
    e.fixedBytes = 112ull << 20;
    // RGBA float weather texels with a mip chain (4/3).
    const uint64_t weatherTexels = static_cast<uint64_t>(scene.weatherResolution) *
                                   static_cast<uint64_t>(scene.weatherResolution);
    e.weatherBytes = scene.weatherImage.empty() ? weatherTexels * 16 * 4 / 3 : 0;
    const uint64_t pixels =
        static_cast<uint64_t>(scene.width) * static_cast<uint64_t>(scene.height);
    e.imageBytes = pixels * bytesPerPixel(job);
    if (job == RenderJob::Sequence) {
        // The ring of gathered marches (render.moving_gather_frames): 32 bytes a 2x2 block a
        // frame, held three times while a checkpoint is written (the ring, the saved state's
        // copy, its planes padded for the file).
        const uint64_t blocks = static_cast<uint64_t>((scene.width + 1) / 2) *
                                static_cast<uint64_t>((scene.height + 1) / 2);
        e.imageBytes +=
            3 * blocks * 32 * static_cast<uint64_t>(std::max(scene.movingGatherFrames, 0));
    }
    e.shadowMapBytes = job == RenderJob::PathTrace ? 0 : cloudShadowMapBytes(scene);
    return e;
}

uint64_t cloudShadowMapBytes(const Scene& scene) {
    if (!scene.cloudShadowEnabled)
        return 0;
    const uint64_t side = static_cast<uint64_t>(std::max(scene.cloudShadowResolution, 1));
    return side * side * 16;
}

uint64_t availableHostMemory() {
    uint64_t available = 0;
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        std::istringstream fields(line);
        std::string name;
        uint64_t kib = 0;
        if (fields >> name >> kib && name == "MemAvailable:")
            available = kib * 1024;
    }
    // A user's `ulimit -v` is a budget too: allocations beyond it fail however much is free.
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const uint64_t budget = static_cast<uint64_t>(limit.rlim_cur);
        available = available == 0 ? budget : std::min(available, budget);
    }
    return available;
}

void requireHostMemory(const Scene& scene, RenderJob job, uint64_t available) {
    const MemoryEstimate e = estimateRenderMemory(scene, job);
    if (available == 0 || e.total() <= available)
        return;
    throw Error(std::to_string(scene.width) + "x" + std::to_string(scene.height) + " needs about " +
                gibibytes(e.total()) + " of memory (images " + gibibytes(e.imageBytes) +
                ", weather map " + gibibytes(e.weatherBytes) + ", shadow map " +
                gibibytes(e.shadowMapBytes) + ") but " + gibibytes(available) +
                " is available; choose a smaller --width/--height or weather.resolution");
}

void requireDeviceMemory(int width, int height, uint64_t needed, uint64_t heap,
                         const std::string& device) {
    if (heap == 0 || needed <= heap)
        return;
    throw Error(std::to_string(width) + "x" + std::to_string(height) + " needs about " +
                bytesText(needed) + " of device memory for its buffers but the " + device +
                " heap they come from holds " + bytesText(heap) +
                "; choose a smaller --width/--height or --backend cpu");
}

} // namespace cloudscape
