// Quaternion: XNA's rotation quaternion, (X, Y, Z) the vector part and W the scalar part.
//
// Order of composition: q1 * q2 is the Hamilton product, which as a rotation of row vectors means
// "q2, then q1" — CreateFromQuaternion(q1 * q2) == CreateFromQuaternion(q2) * CreateFromQuaternion(q1).
// Concatenate(a, b) == b * a reads "a, then b", like Matrix's a * b.
#pragma once

#include <cmath>
#include <type_traits>

#include "fxport/math/vector3.h"

namespace fxport {

struct Matrix;

struct Quaternion {
    float X = 0.0f;
    float Y = 0.0f;
    float Z = 0.0f;
    float W = 0.0f;

    // Zero, as C#'s default(Quaternion); use Quaternion::Identity for "no rotation".
    constexpr Quaternion() = default;
    constexpr Quaternion(float x, float y, float z, float w) : X(x), Y(y), Z(z), W(w) {}
    constexpr Quaternion(Vector3 vectorPart, float scalarPart)
        : X(vectorPart.X), Y(vectorPart.Y), Z(vectorPart.Z), W(scalarPart) {}

    static const Quaternion Identity;

    float Length() const { return std::sqrt(LengthSquared()); }
    constexpr float LengthSquared() const { return X * X + Y * Y + Z * Z + W * W; }
    // In place. Like XNA, a zero quaternion becomes NaN.
    void Normalize() {
        const float inv = 1.0f / Length();
        X *= inv;
        Y *= inv;
        Z *= inv;
        W *= inv;
    }
    // In place: negates the vector part (the inverse rotation of a unit quaternion).
    constexpr void Conjugate() {
        X = -X;
        Y = -Y;
        Z = -Z;
    }

    static Quaternion Normalize(Quaternion value) {
        value.Normalize();
        return value;
    }
    static constexpr Quaternion Conjugate(Quaternion value) {
        value.Conjugate();
        return value;
    }
    // Conjugate divided by the squared length, so it also inverts non-unit quaternions.
    static constexpr Quaternion Inverse(Quaternion value) {
        const float inv = 1.0f / value.LengthSquared();
        return {-value.X * inv, -value.Y * inv, -value.Z * inv, value.W * inv};
    }
    static constexpr float Dot(Quaternion a, Quaternion b) {
        return a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
    }

    // Rotation of angle radians about axis (which must be unit length), counter-clockwise when
    // looking down the axis towards the origin.
    static Quaternion CreateFromAxisAngle(Vector3 axis, float angle);
    // Roll about Z first, then pitch about X, then yaw about Y (XNA's order).
    static Quaternion CreateFromYawPitchRoll(float yaw, float pitch, float roll);
    // From the rotation part (upper 3x3) of a matrix without scale.
    static Quaternion CreateFromRotationMatrix(const Matrix& matrix);

    // Spherical interpolation along the shorter arc (the sign of q2 is flipped when the dot
    // product is negative); nearly parallel inputs fall back to a linear blend, as XNA does.
    static Quaternion Slerp(Quaternion quaternion1, Quaternion quaternion2, float amount);
    // Linear blend along the shorter arc, then normalised.
    static Quaternion Lerp(Quaternion quaternion1, Quaternion quaternion2, float amount);

    static constexpr Quaternion Multiply(Quaternion q1, Quaternion q2) {
        return {q1.X * q2.W + q2.X * q1.W + (q1.Y * q2.Z - q1.Z * q2.Y),
                q1.Y * q2.W + q2.Y * q1.W + (q1.Z * q2.X - q1.X * q2.Z),
                q1.Z * q2.W + q2.Z * q1.W + (q1.X * q2.Y - q1.Y * q2.X),
                q1.W * q2.W - (q1.X * q2.X + q1.Y * q2.Y + q1.Z * q2.Z)};
    }
    static constexpr Quaternion Multiply(Quaternion q, float scale) {
        return {q.X * scale, q.Y * scale, q.Z * scale, q.W * scale};
    }
    // XNA's arithmetic statics (the operators do the same). Divide is q1 * Inverse(q2).
    static constexpr Quaternion Add(Quaternion a, Quaternion b) { return {a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W}; }
    static constexpr Quaternion Subtract(Quaternion a, Quaternion b) {
        return {a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W};
    }
    static constexpr Quaternion Negate(Quaternion q) { return {-q.X, -q.Y, -q.Z, -q.W}; }
    static constexpr Quaternion Divide(Quaternion q1, Quaternion q2) { return Multiply(q1, Inverse(q2)); }

    // Rotation value1 followed by rotation value2.
    static constexpr Quaternion Concatenate(Quaternion value1, Quaternion value2) {
        return Multiply(value2, value1);
    }

    friend constexpr bool operator==(const Quaternion&, const Quaternion&) = default;
};

inline constexpr Quaternion Quaternion::Identity{0.0f, 0.0f, 0.0f, 1.0f};

constexpr Quaternion operator*(Quaternion a, Quaternion b) { return Quaternion::Multiply(a, b); }
constexpr Quaternion operator*(Quaternion q, float s) { return Quaternion::Multiply(q, s); }
constexpr Quaternion operator+(Quaternion a, Quaternion b) {
    return {a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W};
}
constexpr Quaternion operator-(Quaternion a, Quaternion b) {
    return {a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W};
}
constexpr Quaternion operator-(Quaternion q) { return {-q.X, -q.Y, -q.Z, -q.W}; }
constexpr Quaternion operator/(Quaternion a, Quaternion b) { return Quaternion::Divide(a, b); }

static_assert(sizeof(Quaternion) == 16 && std::is_standard_layout_v<Quaternion>);

}  // namespace fxport
