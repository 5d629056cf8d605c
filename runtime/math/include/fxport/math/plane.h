// Plane: XNA's plane, the points p with Dot(Normal, p) + D == 0. BoundingFrustum's planes face
// outwards: DotCoordinate > 0 is outside.
#pragma once

#include <cmath>

#include "fxport/math/vector3.h"

namespace fxport {

struct Plane {
    Vector3 Normal;
    float D = 0.0f;

    constexpr Plane() = default;
    constexpr Plane(Vector3 normal, float d) : Normal(normal), D(d) {}
    constexpr Plane(float a, float b, float c, float d) : Normal(a, b, c), D(d) {}

    // Signed distance of `point` times the normal's length (the distance itself once normalized).
    constexpr float DotCoordinate(Vector3 point) const { return Vector3::Dot(Normal, point) + D; }

    // Scales Normal to unit length and D with it (the plane is unchanged).
    void Normalize() {
        const float inv = 1.0f / Normal.Length();
        Normal = Normal * inv;
        D *= inv;
    }

    friend constexpr bool operator==(const Plane&, const Plane&) = default;
};

}  // namespace fxport
