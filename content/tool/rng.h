// Deterministic pseudo-random numbers for the content tool. Everything random in the generated
// content comes from here, seeded with fixed constants, so two runs write identical bytes. (The
// standard <random> distributions are implementation-defined, hence these few lines instead.)
#pragma once

#include <cstdint>

namespace fxport::content {

// Integer hash (Chris Wellons' "lowbias32"): well mixed, cheap, used for lattice noise and
// per-brick/per-tile variation.
inline std::uint32_t Hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

inline std::uint32_t Hash32(std::uint32_t a, std::uint32_t b, std::uint32_t seed) {
    return Hash32(a ^ Hash32(b ^ Hash32(seed)));
}

// Hash mapped to [0, 1).
inline float HashUnit(std::uint32_t a, std::uint32_t b, std::uint32_t seed) {
    return static_cast<float>(Hash32(a, b, seed) >> 8) * (1.0f / 16777216.0f);
}

// SplitMix64 (Steele, Lea, Flood): a sequential generator for streams of random values.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t Next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1), 24 bits (exactly representable as float).
    float NextUnit() { return static_cast<float>(Next() >> 40) * (1.0f / 16777216.0f); }

private:
    std::uint64_t state_;
};

}  // namespace fxport::content
