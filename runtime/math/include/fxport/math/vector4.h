// Vector4: XNA's four-component float vector. Plain data (16 bytes, X Y Z W).
#pragma once

#include <cmath>
#include <type_traits>

#include "fxport/math/math_helper.h"
#include "fxport/math/vector2.h"
#include "fxport/math/vector3.h"

namespace fxport {

struct Matrix;
struct Quaternion;

struct Vector4 {
    float X = 0.0f;
    float Y = 0.0f;
    float Z = 0.0f;
    float W = 0.0f;

    constexpr Vector4() = default;
    constexpr explicit Vector4(float value) : X(value), Y(value), Z(value), W(value) {}
    constexpr Vector4(float x, float y, float z, float w) : X(x), Y(y), Z(z), W(w) {}
    constexpr Vector4(Vector2 value, float z, float w) : X(value.X), Y(value.Y), Z(z), W(w) {}
    constexpr Vector4(Vector3 value, float w) : X(value.X), Y(value.Y), Z(value.Z), W(w) {}

    static const Vector4 Zero;
    static const Vector4 One;
    static const Vector4 UnitX;
    static const Vector4 UnitY;
    static const Vector4 UnitZ;
    static const Vector4 UnitW;

    float Length() const { return std::sqrt(LengthSquared()); }
    constexpr float LengthSquared() const { return X * X + Y * Y + Z * Z + W * W; }
    // In place. Like XNA, a zero vector becomes NaN.
    void Normalize() {
        const float inv = 1.0f / Length();
        X *= inv;
        Y *= inv;
        Z *= inv;
        W *= inv;
    }

    static Vector4 Normalize(Vector4 value) {
        value.Normalize();
        return value;
    }
    static constexpr float Dot(Vector4 a, Vector4 b) {
        return a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
    }
    static constexpr float DistanceSquared(Vector4 a, Vector4 b) {
        const float dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z, dw = a.W - b.W;
        return dx * dx + dy * dy + dz * dz + dw * dw;
    }
    static float Distance(Vector4 a, Vector4 b) { return std::sqrt(DistanceSquared(a, b)); }
    static constexpr Vector4 Lerp(Vector4 a, Vector4 b, float amount) {
        return {a.X + (b.X - a.X) * amount, a.Y + (b.Y - a.Y) * amount, a.Z + (b.Z - a.Z) * amount,
                a.W + (b.W - a.W) * amount};
    }
    static constexpr Vector4 Min(Vector4 a, Vector4 b) {
        return {a.X < b.X ? a.X : b.X, a.Y < b.Y ? a.Y : b.Y, a.Z < b.Z ? a.Z : b.Z,
                a.W < b.W ? a.W : b.W};
    }
    static constexpr Vector4 Max(Vector4 a, Vector4 b) {
        return {a.X > b.X ? a.X : b.X, a.Y > b.Y ? a.Y : b.Y, a.Z > b.Z ? a.Z : b.Z,
                a.W > b.W ? a.W : b.W};
    }
    // Per component, with MathHelper::Clamp's order of tests.
    static constexpr Vector4 Clamp(Vector4 value, Vector4 min, Vector4 max) {
        return {MathHelper::Clamp(value.X, min.X, max.X), MathHelper::Clamp(value.Y, min.Y, max.Y),
                MathHelper::Clamp(value.Z, min.Z, max.Z), MathHelper::Clamp(value.W, min.W, max.W)};
    }
    // Row vector times matrix. The Vector2/Vector3 overloads take z = 0 (Vector2) and w = 1, so
    // Transform(Vector3 position, projection) gives clip coordinates, w included.
    static Vector4 Transform(Vector4 vector, const Matrix& matrix);
    static Vector4 Transform(Vector3 position, const Matrix& matrix);
    static Vector4 Transform(Vector2 position, const Matrix& matrix);
    // Rotated by a (unit) quaternion: X, Y, Z rotated, W kept (Vector3: W = 1, Vector2: Z = 0, W = 1).
    static Vector4 Transform(Vector4 value, const Quaternion& rotation);
    static Vector4 Transform(Vector3 value, const Quaternion& rotation);
    static Vector4 Transform(Vector2 value, const Quaternion& rotation);

    // XNA's spline and blend statics, per component (MathHelper's formulas).
    static constexpr Vector4 SmoothStep(Vector4 value1, Vector4 value2, float amount) {
        return Vector4(MathHelper::SmoothStep(value1.X, value2.X, amount), MathHelper::SmoothStep(value1.Y, value2.Y, amount), MathHelper::SmoothStep(value1.Z, value2.Z, amount), MathHelper::SmoothStep(value1.W, value2.W, amount));
    }
    static constexpr Vector4 CatmullRom(Vector4 value1, Vector4 value2, Vector4 value3, Vector4 value4, float amount) {
        return Vector4(MathHelper::CatmullRom(value1.X, value2.X, value3.X, value4.X, amount), MathHelper::CatmullRom(value1.Y, value2.Y, value3.Y, value4.Y, amount), MathHelper::CatmullRom(value1.Z, value2.Z, value3.Z, value4.Z, amount), MathHelper::CatmullRom(value1.W, value2.W, value3.W, value4.W, amount));
    }
    static constexpr Vector4 Hermite(Vector4 value1, Vector4 tangent1, Vector4 value2, Vector4 tangent2, float amount) {
        return Vector4(MathHelper::Hermite(value1.X, tangent1.X, value2.X, tangent2.X, amount), MathHelper::Hermite(value1.Y, tangent1.Y, value2.Y, tangent2.Y, amount), MathHelper::Hermite(value1.Z, tangent1.Z, value2.Z, tangent2.Z, amount), MathHelper::Hermite(value1.W, tangent1.W, value2.W, tangent2.W, amount));
    }
    static constexpr Vector4 Barycentric(Vector4 value1, Vector4 value2, Vector4 value3, float amount1, float amount2) {
        return Vector4(MathHelper::Barycentric(value1.X, value2.X, value3.X, amount1, amount2), MathHelper::Barycentric(value1.Y, value2.Y, value3.Y, amount1, amount2), MathHelper::Barycentric(value1.Z, value2.Z, value3.Z, amount1, amount2), MathHelper::Barycentric(value1.W, value2.W, value3.W, amount1, amount2));
    }
    // XNA's arithmetic statics (the operators do the same).
    static constexpr Vector4 Add(Vector4 a, Vector4 b) { return Vector4(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W); }
    static constexpr Vector4 Subtract(Vector4 a, Vector4 b) { return Vector4(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W); }
    static constexpr Vector4 Multiply(Vector4 a, Vector4 b) { return Vector4(a.X * b.X, a.Y * b.Y, a.Z * b.Z, a.W * b.W); }
    static constexpr Vector4 Multiply(Vector4 a, float s) { return Vector4(a.X * s, a.Y * s, a.Z * s, a.W * s); }
    static constexpr Vector4 Divide(Vector4 a, Vector4 b) { return Vector4(a.X / b.X, a.Y / b.Y, a.Z / b.Z, a.W / b.W); }
    static constexpr Vector4 Divide(Vector4 a, float d) { return Multiply(a, 1.0f / d); }
    static constexpr Vector4 Negate(Vector4 a) { return Vector4(-a.X, -a.Y, -a.Z, -a.W); }

    constexpr Vector4& operator+=(Vector4 v) { X += v.X; Y += v.Y; Z += v.Z; W += v.W; return *this; }
    constexpr Vector4& operator-=(Vector4 v) { X -= v.X; Y -= v.Y; Z -= v.Z; W -= v.W; return *this; }
    constexpr Vector4& operator*=(Vector4 v) { X *= v.X; Y *= v.Y; Z *= v.Z; W *= v.W; return *this; }
    constexpr Vector4& operator*=(float s) { X *= s; Y *= s; Z *= s; W *= s; return *this; }
    constexpr Vector4& operator/=(Vector4 v) { X /= v.X; Y /= v.Y; Z /= v.Z; W /= v.W; return *this; }
    // XNA divides by a scalar as a multiply by its reciprocal; so do we, for the same results.
    constexpr Vector4& operator/=(float s) { return *this *= 1.0f / s; }

    friend constexpr bool operator==(const Vector4&, const Vector4&) = default;
};

inline constexpr Vector4 Vector4::Zero{0.0f, 0.0f, 0.0f, 0.0f};
inline constexpr Vector4 Vector4::One{1.0f, 1.0f, 1.0f, 1.0f};
inline constexpr Vector4 Vector4::UnitX{1.0f, 0.0f, 0.0f, 0.0f};
inline constexpr Vector4 Vector4::UnitY{0.0f, 1.0f, 0.0f, 0.0f};
inline constexpr Vector4 Vector4::UnitZ{0.0f, 0.0f, 1.0f, 0.0f};
inline constexpr Vector4 Vector4::UnitW{0.0f, 0.0f, 0.0f, 1.0f};

constexpr Vector4 operator+(Vector4 a, Vector4 b) { return a += b; }
constexpr Vector4 operator-(Vector4 a, Vector4 b) { return a -= b; }
constexpr Vector4 operator*(Vector4 a, Vector4 b) { return a *= b; }
constexpr Vector4 operator*(Vector4 v, float s) { return v *= s; }
constexpr Vector4 operator*(float s, Vector4 v) { return v *= s; }
constexpr Vector4 operator/(Vector4 a, Vector4 b) { return a /= b; }
constexpr Vector4 operator/(Vector4 v, float s) { return v /= s; }
constexpr Vector4 operator-(Vector4 v) { return {-v.X, -v.Y, -v.Z, -v.W}; }

static_assert(sizeof(Vector4) == 16 && std::is_standard_layout_v<Vector4> &&
              std::is_trivially_copyable_v<Vector4>);

}  // namespace fxport
