#pragma once
// The path tracer's random numbers: O'Neill's PCG32 (XSH-RR output of a 64-bit LCG), small,
// fast and statistically solid. Every pixel sample seeds its own stream from (pixel, sample
// index, scene seed), so a render is reproducible and a resumed render draws new samples.
#include <cstdint>

namespace cloudscape::pathtrace {

class Random {
public:
    Random(uint64_t seed, uint64_t stream) {
        increment_ = (stream << 1u) | 1u;
        state_ = 0;
        next();
        state_ += seed;
        next();
    }

    uint32_t next() {
        const uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + increment_;
        const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): 24 random bits, so the largest value is 1 - 2^-24 (never 1).
    float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }

private:
    uint64_t state_ = 0;
    uint64_t increment_ = 1;
};

// SplitMix64, for turning (pixel, sample, seed) into well-spread stream seeds.
inline uint64_t mixBits(uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

} // namespace cloudscape::pathtrace
