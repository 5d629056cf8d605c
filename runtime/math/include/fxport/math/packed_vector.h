// XNA 4's Microsoft.Xna.Framework.Graphics.PackedVector types: each holds one PackedValue with XNA's
// bit layout (first component in the lowest bits), so an array of them is what SetData/GetData of
// the matching SurfaceFormat or VertexElementFormat moves:
//
//   std::vector<PackedVector::HalfVector4> texels(w * h, PackedVector::HalfVector4(1, 0.5f, 0, 1));
//   texture.SetData(texels);   // a SurfaceFormat::HalfVector4 texture
//
// Packing follows XNA's PackUtils: unsigned normalized values are clamped to [0, 1] and scaled by the
// field's maximum, signed ones clamped to [-1, 1] and scaled by its positive maximum (-1 is -127, not
// -128), integer types clamped to the field's range; rounding is to nearest with ties to even (.NET's
// Math.Round), NaN packs as 0. Halves round to nearest even, overflow to infinity. Unpacking
// returns the stored value / maximum (the signed minimum field value reads as -1).
#pragma once

#include <cstdint>

#include "fxport/math/vector2.h"
#include "fxport/math/vector3.h"
#include "fxport/math/vector4.h"

namespace fxport::PackedVector {

// IEEE 754 binary16 <-> float, as XNA's HalfUtils.
std::uint16_t packHalf(float value);
float unpackHalf(std::uint16_t half);

// The field helpers the types use (exposed for tests): `max` is the field's largest value
// (255, 1023, 65535 ...); signed fields are two's complement of `bits` bits.
std::uint32_t packUNorm(float value, std::uint32_t max);
std::uint32_t packSNorm(float value, int bits);
float unpackSNorm(std::uint32_t field, int bits);
std::uint32_t packSigned(float value, int bits);    // clamped to the field's signed range, not scaled
float unpackSigned(std::uint32_t field, int bits);

struct Alpha8 {
    std::uint8_t PackedValue = 0;
    Alpha8() = default;
    explicit Alpha8(float alpha) : PackedValue(std::uint8_t(packUNorm(alpha, 255))) {}
    float ToAlpha() const { return PackedValue / 255.0f; }
    Vector4 ToVector4() const { return Vector4(0, 0, 0, ToAlpha()); }
    bool operator==(const Alpha8&) const = default;
};

struct Bgr565 {
    std::uint16_t PackedValue = 0;
    Bgr565() = default;
    Bgr565(float x, float y, float z) : PackedValue(std::uint16_t(packUNorm(x, 31) << 11 | packUNorm(y, 63) << 5 | packUNorm(z, 31))) {}
    explicit Bgr565(Vector3 v) : Bgr565(v.X, v.Y, v.Z) {}
    Vector3 ToVector3() const { return Vector3((PackedValue >> 11) / 31.0f, ((PackedValue >> 5) & 63) / 63.0f, (PackedValue & 31) / 31.0f); }
    Vector4 ToVector4() const { return Vector4(ToVector3(), 1.0f); }
    bool operator==(const Bgr565&) const = default;
};

struct Bgra4444 {
    std::uint16_t PackedValue = 0;
    Bgra4444() = default;
    Bgra4444(float x, float y, float z, float w)
        : PackedValue(std::uint16_t(packUNorm(w, 15) << 12 | packUNorm(x, 15) << 8 | packUNorm(y, 15) << 4 | packUNorm(z, 15))) {}
    explicit Bgra4444(Vector4 v) : Bgra4444(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(((PackedValue >> 8) & 15) / 15.0f, ((PackedValue >> 4) & 15) / 15.0f, (PackedValue & 15) / 15.0f, (PackedValue >> 12) / 15.0f);
    }
    bool operator==(const Bgra4444&) const = default;
};

struct Bgra5551 {
    std::uint16_t PackedValue = 0;
    Bgra5551() = default;
    Bgra5551(float x, float y, float z, float w)
        : PackedValue(std::uint16_t(packUNorm(w, 1) << 15 | packUNorm(x, 31) << 10 | packUNorm(y, 31) << 5 | packUNorm(z, 31))) {}
    explicit Bgra5551(Vector4 v) : Bgra5551(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(((PackedValue >> 10) & 31) / 31.0f, ((PackedValue >> 5) & 31) / 31.0f, (PackedValue & 31) / 31.0f, float(PackedValue >> 15));
    }
    bool operator==(const Bgra5551&) const = default;
};

struct Byte4 {
    std::uint32_t PackedValue = 0;
    Byte4() = default;
    Byte4(float x, float y, float z, float w);  // each clamped to 0..255, not scaled
    explicit Byte4(Vector4 v) : Byte4(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(float(PackedValue & 255), float((PackedValue >> 8) & 255), float((PackedValue >> 16) & 255), float(PackedValue >> 24));
    }
    bool operator==(const Byte4&) const = default;
};

struct HalfSingle {
    std::uint16_t PackedValue = 0;
    HalfSingle() = default;
    explicit HalfSingle(float value) : PackedValue(packHalf(value)) {}
    float ToSingle() const { return unpackHalf(PackedValue); }
    Vector4 ToVector4() const { return Vector4(ToSingle(), 0, 0, 1); }
    bool operator==(const HalfSingle&) const = default;
};

struct HalfVector2 {
    std::uint32_t PackedValue = 0;
    HalfVector2() = default;
    HalfVector2(float x, float y) : PackedValue(std::uint32_t(packHalf(x)) | std::uint32_t(packHalf(y)) << 16) {}
    explicit HalfVector2(Vector2 v) : HalfVector2(v.X, v.Y) {}
    Vector2 ToVector2() const { return Vector2(unpackHalf(std::uint16_t(PackedValue)), unpackHalf(std::uint16_t(PackedValue >> 16))); }
    Vector4 ToVector4() const { return Vector4(ToVector2().X, ToVector2().Y, 0, 1); }
    bool operator==(const HalfVector2&) const = default;
};

struct HalfVector4 {
    std::uint64_t PackedValue = 0;
    HalfVector4() = default;
    HalfVector4(float x, float y, float z, float w)
        : PackedValue(std::uint64_t(packHalf(x)) | std::uint64_t(packHalf(y)) << 16 | std::uint64_t(packHalf(z)) << 32 |
                      std::uint64_t(packHalf(w)) << 48) {}
    explicit HalfVector4(Vector4 v) : HalfVector4(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(unpackHalf(std::uint16_t(PackedValue)), unpackHalf(std::uint16_t(PackedValue >> 16)),
                       unpackHalf(std::uint16_t(PackedValue >> 32)), unpackHalf(std::uint16_t(PackedValue >> 48)));
    }
    bool operator==(const HalfVector4&) const = default;
};

struct NormalizedByte2 {
    std::uint16_t PackedValue = 0;
    NormalizedByte2() = default;
    NormalizedByte2(float x, float y) : PackedValue(std::uint16_t(packSNorm(x, 8) | packSNorm(y, 8) << 8)) {}
    explicit NormalizedByte2(Vector2 v) : NormalizedByte2(v.X, v.Y) {}
    Vector2 ToVector2() const { return Vector2(unpackSNorm(PackedValue & 255u, 8), unpackSNorm(PackedValue >> 8, 8)); }
    Vector4 ToVector4() const { return Vector4(ToVector2().X, ToVector2().Y, 0, 1); }
    bool operator==(const NormalizedByte2&) const = default;
};

struct NormalizedByte4 {
    std::uint32_t PackedValue = 0;
    NormalizedByte4() = default;
    NormalizedByte4(float x, float y, float z, float w)
        : PackedValue(packSNorm(x, 8) | packSNorm(y, 8) << 8 | packSNorm(z, 8) << 16 | packSNorm(w, 8) << 24) {}
    explicit NormalizedByte4(Vector4 v) : NormalizedByte4(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(unpackSNorm(PackedValue & 255u, 8), unpackSNorm((PackedValue >> 8) & 255u, 8), unpackSNorm((PackedValue >> 16) & 255u, 8),
                       unpackSNorm(PackedValue >> 24, 8));
    }
    bool operator==(const NormalizedByte4&) const = default;
};

struct NormalizedShort2 {
    std::uint32_t PackedValue = 0;
    NormalizedShort2() = default;
    NormalizedShort2(float x, float y) : PackedValue(packSNorm(x, 16) | packSNorm(y, 16) << 16) {}
    explicit NormalizedShort2(Vector2 v) : NormalizedShort2(v.X, v.Y) {}
    Vector2 ToVector2() const { return Vector2(unpackSNorm(PackedValue & 0xFFFFu, 16), unpackSNorm(PackedValue >> 16, 16)); }
    Vector4 ToVector4() const { return Vector4(ToVector2().X, ToVector2().Y, 0, 1); }
    bool operator==(const NormalizedShort2&) const = default;
};

struct NormalizedShort4 {
    std::uint64_t PackedValue = 0;
    NormalizedShort4() = default;
    NormalizedShort4(float x, float y, float z, float w)
        : PackedValue(std::uint64_t(packSNorm(x, 16)) | std::uint64_t(packSNorm(y, 16)) << 16 | std::uint64_t(packSNorm(z, 16)) << 32 |
                      std::uint64_t(packSNorm(w, 16)) << 48) {}
    explicit NormalizedShort4(Vector4 v) : NormalizedShort4(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(unpackSNorm(std::uint32_t(PackedValue & 0xFFFF), 16), unpackSNorm(std::uint32_t((PackedValue >> 16) & 0xFFFF), 16),
                       unpackSNorm(std::uint32_t((PackedValue >> 32) & 0xFFFF), 16), unpackSNorm(std::uint32_t(PackedValue >> 48), 16));
    }
    bool operator==(const NormalizedShort4&) const = default;
};

struct Rg32 {
    std::uint32_t PackedValue = 0;
    Rg32() = default;
    Rg32(float x, float y) : PackedValue(packUNorm(x, 65535) | packUNorm(y, 65535) << 16) {}
    explicit Rg32(Vector2 v) : Rg32(v.X, v.Y) {}
    Vector2 ToVector2() const { return Vector2((PackedValue & 0xFFFF) / 65535.0f, (PackedValue >> 16) / 65535.0f); }
    Vector4 ToVector4() const { return Vector4(ToVector2().X, ToVector2().Y, 0, 1); }
    bool operator==(const Rg32&) const = default;
};

struct Rgba1010102 {
    std::uint32_t PackedValue = 0;
    Rgba1010102() = default;
    Rgba1010102(float x, float y, float z, float w)
        : PackedValue(packUNorm(x, 1023) | packUNorm(y, 1023) << 10 | packUNorm(z, 1023) << 20 | packUNorm(w, 3) << 30) {}
    explicit Rgba1010102(Vector4 v) : Rgba1010102(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4((PackedValue & 1023) / 1023.0f, ((PackedValue >> 10) & 1023) / 1023.0f, ((PackedValue >> 20) & 1023) / 1023.0f,
                       (PackedValue >> 30) / 3.0f);
    }
    bool operator==(const Rgba1010102&) const = default;
};

struct Rgba64 {
    std::uint64_t PackedValue = 0;
    Rgba64() = default;
    Rgba64(float x, float y, float z, float w)
        : PackedValue(std::uint64_t(packUNorm(x, 65535)) | std::uint64_t(packUNorm(y, 65535)) << 16 |
                      std::uint64_t(packUNorm(z, 65535)) << 32 | std::uint64_t(packUNorm(w, 65535)) << 48) {}
    explicit Rgba64(Vector4 v) : Rgba64(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4((PackedValue & 0xFFFF) / 65535.0f, ((PackedValue >> 16) & 0xFFFF) / 65535.0f, ((PackedValue >> 32) & 0xFFFF) / 65535.0f,
                       (PackedValue >> 48) / 65535.0f);
    }
    bool operator==(const Rgba64&) const = default;
};

struct Short2 {
    std::uint32_t PackedValue = 0;
    Short2() = default;
    Short2(float x, float y) : PackedValue(packSigned(x, 16) | packSigned(y, 16) << 16) {}
    explicit Short2(Vector2 v) : Short2(v.X, v.Y) {}
    Vector2 ToVector2() const { return Vector2(unpackSigned(PackedValue & 0xFFFF, 16), unpackSigned(PackedValue >> 16, 16)); }
    Vector4 ToVector4() const { return Vector4(ToVector2().X, ToVector2().Y, 0, 1); }
    bool operator==(const Short2&) const = default;
};

struct Short4 {
    std::uint64_t PackedValue = 0;
    Short4() = default;
    Short4(float x, float y, float z, float w)
        : PackedValue(std::uint64_t(packSigned(x, 16)) | std::uint64_t(packSigned(y, 16)) << 16 | std::uint64_t(packSigned(z, 16)) << 32 |
                      std::uint64_t(packSigned(w, 16)) << 48) {}
    explicit Short4(Vector4 v) : Short4(v.X, v.Y, v.Z, v.W) {}
    Vector4 ToVector4() const {
        return Vector4(unpackSigned(std::uint32_t(PackedValue & 0xFFFF), 16), unpackSigned(std::uint32_t((PackedValue >> 16) & 0xFFFF), 16),
                       unpackSigned(std::uint32_t((PackedValue >> 32) & 0xFFFF), 16), unpackSigned(std::uint32_t(PackedValue >> 48), 16));
    }
    bool operator==(const Short4&) const = default;
};

}  // namespace fxport::PackedVector
