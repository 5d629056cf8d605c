// Quaternion: XNA's formulas, term by term.
#include "fxport/math/quaternion.h"

#include <cmath>

#include "fxport/math/matrix.h"

namespace fxport {

Quaternion Quaternion::CreateFromAxisAngle(Vector3 axis, float angle) {
    const float half = angle * 0.5f;
    const float s = std::sin(half);
    return {axis.X * s, axis.Y * s, axis.Z * s, std::cos(half)};
}

Quaternion Quaternion::CreateFromYawPitchRoll(float yaw, float pitch, float roll) {
    // The product yaw(Y) * pitch(X) * roll(Z) written out: as a rotation, roll first, yaw last.
    const float sr = std::sin(roll * 0.5f), cr = std::cos(roll * 0.5f);
    const float sp = std::sin(pitch * 0.5f), cp = std::cos(pitch * 0.5f);
    const float sy = std::sin(yaw * 0.5f), cy = std::cos(yaw * 0.5f);
    return {cy * sp * cr + sy * cp * sr,
            sy * cp * cr - cy * sp * sr,
            cy * cp * sr - sy * sp * cr,
            cy * cp * cr + sy * sp * sr};
}

Quaternion Quaternion::CreateFromRotationMatrix(const Matrix& m) {
    // Shepperd's method: take the square root of the largest of w², x², y², z² (read off the
    // trace and the diagonal) for accuracy, and the other three from the off-diagonal sums.
    const float trace = m.M11 + m.M22 + m.M33;
    if (trace > 0.0f) {
        const float root = std::sqrt(trace + 1.0f);
        const float inv = 0.5f / root;
        return {(m.M23 - m.M32) * inv, (m.M31 - m.M13) * inv, (m.M12 - m.M21) * inv, root * 0.5f};
    }
    if (m.M11 >= m.M22 && m.M11 >= m.M33) {
        const float root = std::sqrt(1.0f + m.M11 - m.M22 - m.M33);
        const float inv = 0.5f / root;
        return {0.5f * root, (m.M12 + m.M21) * inv, (m.M13 + m.M31) * inv, (m.M23 - m.M32) * inv};
    }
    if (m.M22 > m.M33) {
        const float root = std::sqrt(1.0f + m.M22 - m.M11 - m.M33);
        const float inv = 0.5f / root;
        return {(m.M21 + m.M12) * inv, 0.5f * root, (m.M32 + m.M23) * inv, (m.M31 - m.M13) * inv};
    }
    const float root = std::sqrt(1.0f + m.M33 - m.M11 - m.M22);
    const float inv = 0.5f / root;
    return {(m.M31 + m.M13) * inv, (m.M32 + m.M23) * inv, 0.5f * root, (m.M12 - m.M21) * inv};
}

Quaternion Quaternion::Slerp(Quaternion quaternion1, Quaternion quaternion2, float amount) {
    float cosAngle = Dot(quaternion1, quaternion2);
    const bool flip = cosAngle < 0.0f;  // q and -q are the same rotation: take the shorter arc
    if (flip) {
        cosAngle = -cosAngle;
    }
    float weight1, weight2;
    if (cosAngle > 0.999999f) {
        // Nearly the same rotation: sin(angle) ~ 0, so blend linearly.
        weight1 = 1.0f - amount;
        weight2 = flip ? -amount : amount;
    } else {
        const float angle = std::acos(cosAngle);
        const float invSin = 1.0f / std::sin(angle);
        weight1 = std::sin((1.0f - amount) * angle) * invSin;
        weight2 = flip ? -std::sin(amount * angle) * invSin : std::sin(amount * angle) * invSin;
    }
    return quaternion1 * weight1 + quaternion2 * weight2;
}

Quaternion Quaternion::Lerp(Quaternion quaternion1, Quaternion quaternion2, float amount) {
    const float weight2 = Dot(quaternion1, quaternion2) >= 0.0f ? amount : -amount;
    return Normalize(quaternion1 * (1.0f - amount) + quaternion2 * weight2);
}

}  // namespace fxport
