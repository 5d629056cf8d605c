#include "fxport/math/packed_vector.h"

#include <bit>
#include <cmath>

namespace fxport::PackedVector {

namespace {

// XNA's PackUtils.ClampAndRound: NaN 0, clamped, then .NET's Math.Round (ties to even).
double clampAndRound(double value, double lo, double hi) {
    if (std::isnan(value)) return 0;
    if (value < lo) return lo;
    if (value > hi) return hi;
    return std::nearbyint(value);  // the default rounding mode: to nearest, ties to even
}

}  // namespace

std::uint32_t packUNorm(float value, std::uint32_t max) {
    return std::uint32_t(clampAndRound(double(value) * max, 0, max));
}

std::uint32_t packSNorm(float value, int bits) {
    const double max = double((1u << (bits - 1)) - 1);
    const auto field = std::int32_t(clampAndRound(double(value) * max, -max, max));
    return std::uint32_t(field) & ((1u << bits) - 1);
}

float unpackSNorm(std::uint32_t field, int bits) {
    const std::uint32_t sign = 1u << (bits - 1), mask = (1u << bits) - 1;
    field &= mask;
    if (field == sign) return -1.0f;  // the extra negative value reads as -1, as in XNA
    const std::int32_t value = (field & sign) ? std::int32_t(field | ~mask) : std::int32_t(field);
    return float(value) / float(sign - 1);
}

std::uint32_t packSigned(float value, int bits) {
    const double max = double((1u << (bits - 1)) - 1);
    return std::uint32_t(std::int32_t(clampAndRound(value, -max - 1, max))) & ((1u << bits) - 1);
}

float unpackSigned(std::uint32_t field, int bits) {
    const std::uint32_t sign = 1u << (bits - 1), mask = (1u << bits) - 1;
    field &= mask;
    return float((field & sign) ? std::int32_t(field | ~mask) : std::int32_t(field));
}

Byte4::Byte4(float x, float y, float z, float w)
    : PackedValue(std::uint32_t(clampAndRound(x, 0, 255)) | std::uint32_t(clampAndRound(y, 0, 255)) << 8 |
                  std::uint32_t(clampAndRound(z, 0, 255)) << 16 | std::uint32_t(clampAndRound(w, 0, 255)) << 24) {}

std::uint16_t packHalf(float value) {
    const std::uint32_t f = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t sign = (f >> 16) & 0x8000u;
    const std::uint32_t magnitude = f & 0x7FFFFFFFu;
    if (magnitude >= 0x7F800000u)  // infinity or NaN (a quiet NaN keeps a payload bit)
        return std::uint16_t(sign | 0x7C00u | (magnitude > 0x7F800000u ? 0x200u : 0u));
    if (magnitude >= 0x477FF000u) return std::uint16_t(sign | 0x7C00u);  // rounds past 65504: infinity
    if (magnitude < 0x38800000u) {  // below 2^-14: a subnormal half (or zero)
        if (magnitude < 0x33000000u) return std::uint16_t(sign);  // below half the smallest subnormal
        const std::uint32_t mantissa = (magnitude & 0x7FFFFFu) | 0x800000u;
        const int shift = 126 - int(magnitude >> 23);  // the half is mantissa24 * 2^(exponent - 126)
        const std::uint32_t kept = mantissa >> shift, rest = mantissa & ((1u << shift) - 1), half = 1u << (shift - 1);
        const std::uint32_t rounded = kept + ((rest > half || (rest == half && (kept & 1))) ? 1 : 0);
        return std::uint16_t(sign | rounded);
    }
    // Normal: rebias the exponent (127 -> 15), keep 10 mantissa bits, round to nearest even.
    const std::uint32_t rebased = magnitude - 0x38000000u;  // (127 - 15) << 23
    const std::uint32_t kept = rebased >> 13, rest = rebased & 0x1FFFu;
    const std::uint32_t rounded = kept + ((rest > 0x1000u || (rest == 0x1000u && (kept & 1))) ? 1 : 0);
    return std::uint16_t(sign | rounded);
}

float unpackHalf(std::uint16_t half) {
    const std::uint32_t sign = std::uint32_t(half & 0x8000u) << 16;
    const std::uint32_t exponent = (half >> 10) & 31, mantissa = half & 1023u;
    if (exponent == 31) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    if (exponent == 0) {
        const float value = std::ldexp(float(mantissa), -24);  // subnormal: mantissa * 2^-24
        return sign ? -value : value;
    }
    return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
}

}  // namespace fxport::PackedVector
