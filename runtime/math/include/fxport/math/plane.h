// Plane: XNA's plane, the points p with Dot(Normal, p) + D == 0. BoundingFrustum's planes face
// outwards: DotCoordinate > 0 is outside.
#pragma once

#include <cmath>
#include <optional>

#include "fxport/math/vector3.h"
#include "fxport/math/vector4.h"

namespace fxport {

struct BoundingBox;
struct BoundingSphere;
class BoundingFrustum;
struct Matrix;
struct Quaternion;
struct Ray;

// Which side of a plane a volume lies on (XNA's PlaneIntersectionType): Front is the side the
// normal points to.
enum class PlaneIntersectionType { Front, Back, Intersecting };

struct Plane {
    Vector3 Normal;
    float D = 0.0f;

    constexpr Plane() = default;
    constexpr Plane(Vector3 normal, float d) : Normal(normal), D(d) {}
    constexpr Plane(float a, float b, float c, float d) : Normal(a, b, c), D(d) {}
    constexpr explicit Plane(Vector4 value) : Normal(value.X, value.Y, value.Z), D(value.W) {}
    // The plane through three points, as XNA: Normal = Normalize(Cross(point2 - point1,
    // point3 - point1)), D = -Dot(Normal, point1).
    Plane(Vector3 point1, Vector3 point2, Vector3 point3);

    // Dot(Normal, point) + D: the signed distance when Normal has unit length.
    constexpr float DotCoordinate(Vector3 point) const { return Vector3::Dot(Normal, point) + D; }
    // Dot(Normal, vector): the plane's tilt against a direction (no D).
    constexpr float DotNormal(Vector3 vector) const { return Vector3::Dot(Normal, vector); }
    // Dot with (Normal, D) of a homogeneous point.
    constexpr float Dot(Vector4 value) const {
        return Normal.X * value.X + Normal.Y * value.Y + Normal.Z * value.Z + D * value.W;
    }

    // Scales Normal to unit length and D with it (the plane is unchanged). Like XNA, a normal
    // already within 1.192093e-7 of unit length is left as it is.
    void Normalize() {
        const float lengthSquared = Normal.LengthSquared();
        if (std::fabs(lengthSquared - 1.0f) < 1.192093e-7f) return;
        const float inv = 1.0f / std::sqrt(lengthSquared);
        Normal = Normal * inv;
        D *= inv;
    }
    static Plane Normalize(Plane value) {
        value.Normalize();
        return value;
    }
    // The plane moved by a matrix (points p on it go to p * matrix; the matrix must be invertible).
    static Plane Transform(const Plane& plane, const Matrix& matrix);
    // The plane rotated by a quaternion.
    static Plane Transform(const Plane& plane, const Quaternion& rotation);

    PlaneIntersectionType Intersects(const BoundingBox& box) const;
    PlaneIntersectionType Intersects(const BoundingSphere& sphere) const;
    PlaneIntersectionType Intersects(const BoundingFrustum& frustum) const;

    friend constexpr bool operator==(const Plane&, const Plane&) = default;
};

}  // namespace fxport
