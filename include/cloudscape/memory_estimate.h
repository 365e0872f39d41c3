#pragma once
// What a render will need in host memory, checked before any of it is allocated: a render that
// cannot fit fails up front with the estimate, not with std::bad_alloc half-way through (or the
// machine swapping to a halt). The figures are measured peaks (docs/RELIABILITY.md), rounded up.
#include <cloudscape/scene.h>

#include <cstdint>
#include <string>

namespace cloudscape {

enum class RenderJob { StillPng, StillExr, Sequence, PathTrace };

struct MemoryEstimate {
    uint64_t fixedBytes = 0;     // program, noise textures
    uint64_t weatherBytes = 0;   // the weather map and its mips
    uint64_t imageBytes = 0;     // per-pixel buffers and the encoded output
    uint64_t shadowMapBytes = 0; // the clouds' shadow map (cloudShadowMapBytes)
    uint64_t total() const { return fixedBytes + weatherBytes + imageBytes + shadowMapBytes; }
};

MemoryEstimate estimateRenderMemory(const Scene& scene, RenderJob job);

// The clouds' shadow map a real-time render of `scene` holds (one vec4 of floats per texel, on
// the host for the CPU backend, in a device buffer for Vulkan): 0 while cloud_shadow is off. Up
// to 64 MiB at 2048^2. The path tracer has none.
uint64_t cloudShadowMapBytes(const Scene& scene);

// MemAvailable from /proc/meminfo (what can be allocated without swapping), or the address-
// space limit (`ulimit -v`) if that is smaller; 0 if neither is known.
uint64_t availableHostMemory();

// Throws cloudscape::Error giving the estimate and what is available when the job cannot fit
// in `available` bytes (0 = unknown: no check).
void requireHostMemory(const Scene& scene, RenderJob job, uint64_t available);

// The Vulkan backend's side: before allocating a width x height render's buffers (`needed`
// bytes, summed by the backend from the buffers it is about to create), throws
// cloudscape::Error giving both figures when they exceed the `heap` their memory comes from on
// `device` (a VkMemoryHeap's size), instead of failing in the driver or losing the device.
void requireDeviceMemory(int width, int height, uint64_t needed, uint64_t heap,
                         const std::string& device);

} // namespace cloudscape
