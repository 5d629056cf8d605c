// Tileable lattice noise for the procedural textures: value noise on a grid whose period divides
// the texture, so every texture repeats without a seam (the materials use WRAP addressing).
#pragma once

#include <cstdint>

namespace fxport::content {

// Value noise in [0, 1] at texture position (u, v) in [0, 1), on a `period` x `period` lattice
// that wraps at u, v = 1. Quintic interpolation between lattice values.
float TileableValueNoise(float u, float v, int period, std::uint32_t seed);

// Sum of `octaves` layers of TileableValueNoise, period doubling and amplitude halving per octave,
// normalised back to [0, 1].
float TileableFbm(float u, float v, int basePeriod, int octaves, std::uint32_t seed);

}  // namespace fxport::content
