#pragma once
// FNV-1a, 64-bit: the fingerprints of resumable outputs (path tracer, sequence checkpoints). Not
// cryptographic; it tells a changed scene from the same one.
#include <cstddef>
#include <cstdint>

namespace cloudscape {

inline uint64_t fnv1a(const void* data, size_t size, uint64_t h = 1469598103934665603ULL) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i)
        h = (h ^ bytes[i]) * 1099511628211ULL;
    return h;
}

} // namespace cloudscape
