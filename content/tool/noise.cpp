#include "noise.h"

#include <cmath>

#include "rng.h"

namespace fxport::content {

namespace {

float Quintic(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float Lattice(int x, int y, int period, std::uint32_t seed) {
    const int wx = ((x % period) + period) % period;
    const int wy = ((y % period) + period) % period;
    return HashUnit(static_cast<std::uint32_t>(wx), static_cast<std::uint32_t>(wy), seed);
}

}  // namespace

float TileableValueNoise(float u, float v, int period, std::uint32_t seed) {
    const float x = u * static_cast<float>(period);
    const float y = v * static_cast<float>(period);
    const float fx = std::floor(x);
    const float fy = std::floor(y);
    const int ix = static_cast<int>(fx);
    const int iy = static_cast<int>(fy);
    const float tx = Quintic(x - fx);
    const float ty = Quintic(y - fy);
    const float v00 = Lattice(ix, iy, period, seed);
    const float v10 = Lattice(ix + 1, iy, period, seed);
    const float v01 = Lattice(ix, iy + 1, period, seed);
    const float v11 = Lattice(ix + 1, iy + 1, period, seed);
    const float top = v00 + (v10 - v00) * tx;
    const float bottom = v01 + (v11 - v01) * tx;
    return top + (bottom - top) * ty;
}

float TileableFbm(float u, float v, int basePeriod, int octaves, std::uint32_t seed) {
    float sum = 0.0f;
    float amplitude = 1.0f;
    float total = 0.0f;
    int period = basePeriod;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * TileableValueNoise(u, v, period, seed + static_cast<std::uint32_t>(i) * 7919U);
        total += amplitude;
        amplitude *= 0.5f;
        period *= 2;
    }
    return sum / total;
}

}  // namespace fxport::content
