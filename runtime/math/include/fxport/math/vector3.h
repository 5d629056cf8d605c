// Vector3: XNA's three-component float vector, in XNA's right-handed world: +Y up, +X right, and
// Forward = -Z. Plain data (12 bytes, X Y Z), usable directly in vertex buffers.
#pragma once

#include <cmath>
#include <type_traits>

#include "fxport/math/math_helper.h"
#include "fxport/math/vector2.h"

namespace fxport {

struct Matrix;
struct Quaternion;

struct Vector3 {
    float X = 0.0f;
    float Y = 0.0f;
    float Z = 0.0f;

    constexpr Vector3() = default;
    constexpr explicit Vector3(float value) : X(value), Y(value), Z(value) {}
    constexpr Vector3(float x, float y, float z) : X(x), Y(y), Z(z) {}
    constexpr Vector3(Vector2 value, float z) : X(value.X), Y(value.Y), Z(z) {}

    static const Vector3 Zero;
    static const Vector3 One;
    static const Vector3 UnitX;
    static const Vector3 UnitY;
    static const Vector3 UnitZ;
    static const Vector3 Up;        // (0, 1, 0)
    static const Vector3 Down;      // (0, -1, 0)
    static const Vector3 Right;     // (1, 0, 0)
    static const Vector3 Left;      // (-1, 0, 0)
    static const Vector3 Forward;   // (0, 0, -1): right-handed, the camera looks down -Z
    static const Vector3 Backward;  // (0, 0, 1)

    float Length() const { return std::sqrt(LengthSquared()); }
    constexpr float LengthSquared() const { return X * X + Y * Y + Z * Z; }
    // In place. Like XNA, a zero vector becomes NaN.
    void Normalize() {
        const float inv = 1.0f / Length();
        X *= inv;
        Y *= inv;
        Z *= inv;
    }

    static Vector3 Normalize(Vector3 value) {
        value.Normalize();
        return value;
    }
    static constexpr float Dot(Vector3 a, Vector3 b) { return a.X * b.X + a.Y * b.Y + a.Z * b.Z; }
    static constexpr Vector3 Cross(Vector3 a, Vector3 b) {
        return {a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X};
    }
    static constexpr float DistanceSquared(Vector3 a, Vector3 b) {
        const float dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
        return dx * dx + dy * dy + dz * dz;
    }
    static float Distance(Vector3 a, Vector3 b) { return std::sqrt(DistanceSquared(a, b)); }
    static constexpr Vector3 Lerp(Vector3 a, Vector3 b, float amount) {
        return {a.X + (b.X - a.X) * amount, a.Y + (b.Y - a.Y) * amount, a.Z + (b.Z - a.Z) * amount};
    }
    static constexpr Vector3 Min(Vector3 a, Vector3 b) {
        return {a.X < b.X ? a.X : b.X, a.Y < b.Y ? a.Y : b.Y, a.Z < b.Z ? a.Z : b.Z};
    }
    static constexpr Vector3 Max(Vector3 a, Vector3 b) {
        return {a.X > b.X ? a.X : b.X, a.Y > b.Y ? a.Y : b.Y, a.Z > b.Z ? a.Z : b.Z};
    }
    // Per component, with MathHelper::Clamp's order of tests.
    static constexpr Vector3 Clamp(Vector3 value, Vector3 min, Vector3 max) {
        return {MathHelper::Clamp(value.X, min.X, max.X), MathHelper::Clamp(value.Y, min.Y, max.Y),
                MathHelper::Clamp(value.Z, min.Z, max.Z)};
    }
    // Reflects vector off a surface with the given (unit) normal.
    static constexpr Vector3 Reflect(Vector3 vector, Vector3 normal) {
        const float d = 2.0f * Dot(vector, normal);
        return {vector.X - d * normal.X, vector.Y - d * normal.Y, vector.Z - d * normal.Z};
    }
    // Row vector times matrix, as XNA: Transform treats the vector as a point (w = 1, translation
    // applies, no divide by w), TransformNormal as a direction (w = 0).
    static Vector3 Transform(Vector3 position, const Matrix& matrix);
    static Vector3 TransformNormal(Vector3 normal, const Matrix& matrix);
    // Rotates by a (unit) quaternion; equals Transform(value, Matrix::CreateFromQuaternion(rotation)).
    static Vector3 Transform(Vector3 value, const Quaternion& rotation);

    // XNA's spline and blend statics, per component (MathHelper's formulas).
    static constexpr Vector3 SmoothStep(Vector3 value1, Vector3 value2, float amount) {
        return Vector3(MathHelper::SmoothStep(value1.X, value2.X, amount), MathHelper::SmoothStep(value1.Y, value2.Y, amount), MathHelper::SmoothStep(value1.Z, value2.Z, amount));
    }
    static constexpr Vector3 CatmullRom(Vector3 value1, Vector3 value2, Vector3 value3, Vector3 value4, float amount) {
        return Vector3(MathHelper::CatmullRom(value1.X, value2.X, value3.X, value4.X, amount), MathHelper::CatmullRom(value1.Y, value2.Y, value3.Y, value4.Y, amount), MathHelper::CatmullRom(value1.Z, value2.Z, value3.Z, value4.Z, amount));
    }
    static constexpr Vector3 Hermite(Vector3 value1, Vector3 tangent1, Vector3 value2, Vector3 tangent2, float amount) {
        return Vector3(MathHelper::Hermite(value1.X, tangent1.X, value2.X, tangent2.X, amount), MathHelper::Hermite(value1.Y, tangent1.Y, value2.Y, tangent2.Y, amount), MathHelper::Hermite(value1.Z, tangent1.Z, value2.Z, tangent2.Z, amount));
    }
    static constexpr Vector3 Barycentric(Vector3 value1, Vector3 value2, Vector3 value3, float amount1, float amount2) {
        return Vector3(MathHelper::Barycentric(value1.X, value2.X, value3.X, amount1, amount2), MathHelper::Barycentric(value1.Y, value2.Y, value3.Y, amount1, amount2), MathHelper::Barycentric(value1.Z, value2.Z, value3.Z, amount1, amount2));
    }
    // XNA's arithmetic statics (the operators do the same).
    static constexpr Vector3 Add(Vector3 a, Vector3 b) { return Vector3(a.X + b.X, a.Y + b.Y, a.Z + b.Z); }
    static constexpr Vector3 Subtract(Vector3 a, Vector3 b) { return Vector3(a.X - b.X, a.Y - b.Y, a.Z - b.Z); }
    static constexpr Vector3 Multiply(Vector3 a, Vector3 b) { return Vector3(a.X * b.X, a.Y * b.Y, a.Z * b.Z); }
    static constexpr Vector3 Multiply(Vector3 a, float s) { return Vector3(a.X * s, a.Y * s, a.Z * s); }
    static constexpr Vector3 Divide(Vector3 a, Vector3 b) { return Vector3(a.X / b.X, a.Y / b.Y, a.Z / b.Z); }
    static constexpr Vector3 Divide(Vector3 a, float d) { return Multiply(a, 1.0f / d); }
    static constexpr Vector3 Negate(Vector3 a) { return Vector3(-a.X, -a.Y, -a.Z); }

    constexpr Vector3& operator+=(Vector3 v) { X += v.X; Y += v.Y; Z += v.Z; return *this; }
    constexpr Vector3& operator-=(Vector3 v) { X -= v.X; Y -= v.Y; Z -= v.Z; return *this; }
    constexpr Vector3& operator*=(Vector3 v) { X *= v.X; Y *= v.Y; Z *= v.Z; return *this; }
    constexpr Vector3& operator*=(float s) { X *= s; Y *= s; Z *= s; return *this; }
    constexpr Vector3& operator/=(Vector3 v) { X /= v.X; Y /= v.Y; Z /= v.Z; return *this; }
    // XNA divides by a scalar as a multiply by its reciprocal; so do we, for the same results.
    constexpr Vector3& operator/=(float s) { return *this *= 1.0f / s; }

    friend constexpr bool operator==(const Vector3&, const Vector3&) = default;
};

inline constexpr Vector3 Vector3::Zero{0.0f, 0.0f, 0.0f};
inline constexpr Vector3 Vector3::One{1.0f, 1.0f, 1.0f};
inline constexpr Vector3 Vector3::UnitX{1.0f, 0.0f, 0.0f};
inline constexpr Vector3 Vector3::UnitY{0.0f, 1.0f, 0.0f};
inline constexpr Vector3 Vector3::UnitZ{0.0f, 0.0f, 1.0f};
inline constexpr Vector3 Vector3::Up{0.0f, 1.0f, 0.0f};
inline constexpr Vector3 Vector3::Down{0.0f, -1.0f, 0.0f};
inline constexpr Vector3 Vector3::Right{1.0f, 0.0f, 0.0f};
inline constexpr Vector3 Vector3::Left{-1.0f, 0.0f, 0.0f};
inline constexpr Vector3 Vector3::Forward{0.0f, 0.0f, -1.0f};
inline constexpr Vector3 Vector3::Backward{0.0f, 0.0f, 1.0f};

constexpr Vector3 operator+(Vector3 a, Vector3 b) { return a += b; }
constexpr Vector3 operator-(Vector3 a, Vector3 b) { return a -= b; }
constexpr Vector3 operator*(Vector3 a, Vector3 b) { return a *= b; }
constexpr Vector3 operator*(Vector3 v, float s) { return v *= s; }
constexpr Vector3 operator*(float s, Vector3 v) { return v *= s; }
constexpr Vector3 operator/(Vector3 a, Vector3 b) { return a /= b; }
constexpr Vector3 operator/(Vector3 v, float s) { return v /= s; }
constexpr Vector3 operator-(Vector3 v) { return {-v.X, -v.Y, -v.Z}; }

static_assert(sizeof(Vector3) == 12 && std::is_standard_layout_v<Vector3> &&
              std::is_trivially_copyable_v<Vector3>);

}  // namespace fxport
