#pragma once
// Periodic (tileable) gradient and cellular noise over the unit cube / square. A noise of
// "period" n has n lattice cells across the tile and repeats exactly at integer coordinates, so
// textures built from it wrap seamlessly. All randomness is a hash of (seed, lattice point), so
// evaluation order and threading never change the result.
//
// The free functions hash every lattice corner on each call; the classes precompute the same
// per-lattice-point randomness into tables once and return bit-identical values much faster
// (the 128^3 base noise evaluates them 2M times).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace cloudscape::noise {

uint32_t hash32(uint32_t x);
uint32_t hashCombine(uint32_t seed, int a, int b = 0, int c = 0);

// Perlin gradient noise in about [-1, 1], period cells per unit.
float perlin3(glm::vec3 p, int period, uint32_t seed);
float perlin2(glm::vec2 p, int period, uint32_t seed);

// Fractal sum of `octaves` Perlin octaves starting at `period` cells, each doubling the
// frequency and halving the amplitude; normalised to about [-1, 1]. Octave o uses the seed
// seed + 101 * o.
float perlinFbm3(glm::vec3 p, int period, int octaves, uint32_t seed);
float perlinFbm2(glm::vec2 p, int period, int octaves, uint32_t seed);

// perlinFbm3 with each octave's lattice gradients precomputed: the same values, bit for bit.
class PerlinFbm3 {
public:
    PerlinFbm3(int period, int octaves, uint32_t seed);
    float operator()(glm::vec3 p) const;
    // operator() at (xs[t], y, z) for t in [0, count), into out[t]: the same values bit for
    // bit, with each lattice cell's gradients looked up once a row; scratch holds count floats.
    void row(const float* xs, int count, float y, float z, float* out, float* scratch) const;

private:
    struct Octave {
        int period;
        uint32_t seed;
        std::vector<uint8_t> gradient; // gradient index (0..11) per lattice point, x fastest;
                                       // empty for lattices too large to tabulate
    };
    std::vector<Octave> octaves_;
};

// perlinFbm2 with each octave's lattice gradients precomputed: the same values, bit for bit.
class PerlinFbm2 {
public:
    // Octaves whose lattice has more than maxTable points are hashed on each evaluation (a
    // caller that evaluates few points passes its point count: a table would not pay).
    PerlinFbm2(int period, int octaves, uint32_t seed, int64_t maxTable = int64_t(1) << 22);
    float operator()(glm::vec2 p) const;
    // Octave o alone: perlin2(p, period << o, seed + 101 * o), bit for bit.
    float octave(int o, glm::vec2 p) const;

private:
    struct Octave {
        int period;
        uint32_t seed;
        std::vector<glm::vec2> gradient; // unit gradient per lattice point, x fastest; empty
                                         // for lattices too large to tabulate
    };
    std::vector<Octave> octaves_;
};

// Worley (cellular) noise: one random feature point per cell of a periodic grid. Evaluating
// returns 1 - F1 (distance to the nearest feature point in cell units, clamped to 1): bright
// round cells, the "billowy" pattern of GPU Pro 7 Figure 4.7.
class Worley3 {
public:
    Worley3(int cells, uint32_t seed);
    float inverted(glm::vec3 p) const;
    // inverted() at (xs[t], y, z) for t in [0, count), into out[t] (inverted() is a row of
    // one): texels of a row in one cell share its 27 candidate points, so a long row is several
    // times faster than its points one by one.
    void invertedRow(const float* xs, int count, float y, float z, float* out) const;

private:
    int cells_;
    std::vector<glm::vec3> points_; // feature point of each cell, in cell units within the cell
};

// Three Worley octaves at cells, 2 cells and 4 cells weighted 0.625, 0.25, 0.125 (the weights
// the seed uses to combine its noise channels).
class WorleyFbm3 {
public:
    WorleyFbm3(int cells, uint32_t seed);
    float operator()(glm::vec3 p) const;
    // operator() along a row, as Worley3::invertedRow; scratch holds 2 * count floats.
    void row(const float* xs, int count, float y, float z, float* out, float* scratch) const;

private:
    Worley3 a_, b_, c_;
};

} // namespace cloudscape::noise
