// Vector2: XNA's two-component float vector. Plain data (8 bytes, X then Y), so arrays of it can go
// straight into a vertex buffer.
#pragma once

#include <cmath>
#include <type_traits>

#include "fxport/math/math_helper.h"

namespace fxport {

struct Matrix;
struct Quaternion;

struct Vector2 {
    float X = 0.0f;
    float Y = 0.0f;

    constexpr Vector2() = default;
    constexpr explicit Vector2(float value) : X(value), Y(value) {}
    constexpr Vector2(float x, float y) : X(x), Y(y) {}

    static const Vector2 Zero;
    static const Vector2 One;
    static const Vector2 UnitX;
    static const Vector2 UnitY;

    float Length() const { return std::sqrt(LengthSquared()); }
    constexpr float LengthSquared() const { return X * X + Y * Y; }
    // In place. Like XNA, a zero vector becomes NaN.
    void Normalize() {
        const float inv = 1.0f / Length();
        X *= inv;
        Y *= inv;
    }

    static Vector2 Normalize(Vector2 value) {
        value.Normalize();
        return value;
    }
    static constexpr float Dot(Vector2 a, Vector2 b) { return a.X * b.X + a.Y * b.Y; }
    static constexpr float DistanceSquared(Vector2 a, Vector2 b) {
        return (a.X - b.X) * (a.X - b.X) + (a.Y - b.Y) * (a.Y - b.Y);
    }
    static float Distance(Vector2 a, Vector2 b) { return std::sqrt(DistanceSquared(a, b)); }
    static constexpr Vector2 Lerp(Vector2 a, Vector2 b, float amount) {
        return {a.X + (b.X - a.X) * amount, a.Y + (b.Y - a.Y) * amount};
    }
    static constexpr Vector2 Min(Vector2 a, Vector2 b) {
        return {a.X < b.X ? a.X : b.X, a.Y < b.Y ? a.Y : b.Y};
    }
    static constexpr Vector2 Max(Vector2 a, Vector2 b) {
        return {a.X > b.X ? a.X : b.X, a.Y > b.Y ? a.Y : b.Y};
    }
    // Per component, with MathHelper::Clamp's order of tests.
    static constexpr Vector2 Clamp(Vector2 value, Vector2 min, Vector2 max) {
        return {MathHelper::Clamp(value.X, min.X, max.X), MathHelper::Clamp(value.Y, min.Y, max.Y)};
    }
    // Reflects vector off a surface with the given (unit) normal.
    static constexpr Vector2 Reflect(Vector2 vector, Vector2 normal) {
        const float d = 2.0f * Dot(vector, normal);
        return {vector.X - d * normal.X, vector.Y - d * normal.Y};
    }
    // As a point (w = 1: translation applies) and as a direction (w = 0).
    static Vector2 Transform(Vector2 position, const Matrix& matrix);
    static Vector2 TransformNormal(Vector2 normal, const Matrix& matrix);
    // Rotated by a (unit) quaternion, as the point (X, Y, 0).
    static Vector2 Transform(Vector2 value, const Quaternion& rotation);

    // XNA's spline and blend statics, per component (MathHelper's formulas).
    static constexpr Vector2 SmoothStep(Vector2 value1, Vector2 value2, float amount) {
        return Vector2(MathHelper::SmoothStep(value1.X, value2.X, amount), MathHelper::SmoothStep(value1.Y, value2.Y, amount));
    }
    static constexpr Vector2 CatmullRom(Vector2 value1, Vector2 value2, Vector2 value3, Vector2 value4, float amount) {
        return Vector2(MathHelper::CatmullRom(value1.X, value2.X, value3.X, value4.X, amount), MathHelper::CatmullRom(value1.Y, value2.Y, value3.Y, value4.Y, amount));
    }
    static constexpr Vector2 Hermite(Vector2 value1, Vector2 tangent1, Vector2 value2, Vector2 tangent2, float amount) {
        return Vector2(MathHelper::Hermite(value1.X, tangent1.X, value2.X, tangent2.X, amount), MathHelper::Hermite(value1.Y, tangent1.Y, value2.Y, tangent2.Y, amount));
    }
    static constexpr Vector2 Barycentric(Vector2 value1, Vector2 value2, Vector2 value3, float amount1, float amount2) {
        return Vector2(MathHelper::Barycentric(value1.X, value2.X, value3.X, amount1, amount2), MathHelper::Barycentric(value1.Y, value2.Y, value3.Y, amount1, amount2));
    }
    // XNA's arithmetic statics (the operators do the same).
    static constexpr Vector2 Add(Vector2 a, Vector2 b) { return Vector2(a.X + b.X, a.Y + b.Y); }
    static constexpr Vector2 Subtract(Vector2 a, Vector2 b) { return Vector2(a.X - b.X, a.Y - b.Y); }
    static constexpr Vector2 Multiply(Vector2 a, Vector2 b) { return Vector2(a.X * b.X, a.Y * b.Y); }
    static constexpr Vector2 Multiply(Vector2 a, float s) { return Vector2(a.X * s, a.Y * s); }
    static constexpr Vector2 Divide(Vector2 a, Vector2 b) { return Vector2(a.X / b.X, a.Y / b.Y); }
    static constexpr Vector2 Divide(Vector2 a, float d) { return Multiply(a, 1.0f / d); }
    static constexpr Vector2 Negate(Vector2 a) { return Vector2(-a.X, -a.Y); }

    constexpr Vector2& operator+=(Vector2 v) { X += v.X; Y += v.Y; return *this; }
    constexpr Vector2& operator-=(Vector2 v) { X -= v.X; Y -= v.Y; return *this; }
    constexpr Vector2& operator*=(Vector2 v) { X *= v.X; Y *= v.Y; return *this; }
    constexpr Vector2& operator*=(float s) { X *= s; Y *= s; return *this; }
    constexpr Vector2& operator/=(Vector2 v) { X /= v.X; Y /= v.Y; return *this; }
    // XNA divides by a scalar as a multiply by its reciprocal; so do we, for the same results.
    constexpr Vector2& operator/=(float s) { return *this *= 1.0f / s; }

    friend constexpr bool operator==(const Vector2&, const Vector2&) = default;
};

inline constexpr Vector2 Vector2::Zero{0.0f, 0.0f};
inline constexpr Vector2 Vector2::One{1.0f, 1.0f};
inline constexpr Vector2 Vector2::UnitX{1.0f, 0.0f};
inline constexpr Vector2 Vector2::UnitY{0.0f, 1.0f};

constexpr Vector2 operator+(Vector2 a, Vector2 b) { return a += b; }
constexpr Vector2 operator-(Vector2 a, Vector2 b) { return a -= b; }
constexpr Vector2 operator*(Vector2 a, Vector2 b) { return a *= b; }
constexpr Vector2 operator*(Vector2 v, float s) { return v *= s; }
constexpr Vector2 operator*(float s, Vector2 v) { return v *= s; }
constexpr Vector2 operator/(Vector2 a, Vector2 b) { return a /= b; }
constexpr Vector2 operator/(Vector2 v, float s) { return v /= s; }
constexpr Vector2 operator-(Vector2 v) { return {-v.X, -v.Y}; }

static_assert(sizeof(Vector2) == 8 && std::is_standard_layout_v<Vector2> &&
              std::is_trivially_copyable_v<Vector2>);

}  // namespace fxport
