// Plane: construction from points, transforms, and which side of it a volume lies on (XNA's rules).
#include "fxport/math/plane.h"

#include "fxport/math/bounding_box.h"
#include "fxport/math/bounding_frustum.h"
#include "fxport/math/bounding_sphere.h"
#include "fxport/math/matrix.h"
#include "fxport/math/quaternion.h"

namespace fxport {

Plane::Plane(Vector3 point1, Vector3 point2, Vector3 point3) {
    Normal = Vector3::Normalize(Vector3::Cross(point2 - point1, point3 - point1));
    D = -Vector3::Dot(Normal, point1);
}

Plane Plane::Transform(const Plane& plane, const Matrix& matrix) {
    // Planes transform by the inverse transpose: (N, D) * transpose(inverse(M)) as a row vector.
    const Matrix m = Matrix::Invert(matrix);
    const float x = plane.Normal.X, y = plane.Normal.Y, z = plane.Normal.Z, d = plane.D;
    return Plane(x * m.M11 + y * m.M12 + z * m.M13 + d * m.M14, x * m.M21 + y * m.M22 + z * m.M23 + d * m.M24,
                 x * m.M31 + y * m.M32 + z * m.M33 + d * m.M34, x * m.M41 + y * m.M42 + z * m.M43 + d * m.M44);
}

Plane Plane::Transform(const Plane& plane, const Quaternion& rotation) {
    return Plane(Vector3::Transform(plane.Normal, rotation), plane.D);
}

PlaneIntersectionType Plane::Intersects(const BoundingBox& box) const {
    // The corners nearest to and farthest along the normal decide.
    const Vector3 nearest(Normal.X >= 0 ? box.Min.X : box.Max.X, Normal.Y >= 0 ? box.Min.Y : box.Max.Y,
                          Normal.Z >= 0 ? box.Min.Z : box.Max.Z);
    const Vector3 farthest(Normal.X >= 0 ? box.Max.X : box.Min.X, Normal.Y >= 0 ? box.Max.Y : box.Min.Y,
                           Normal.Z >= 0 ? box.Max.Z : box.Min.Z);
    if (DotCoordinate(nearest) > 0.0f) return PlaneIntersectionType::Front;
    if (DotCoordinate(farthest) < 0.0f) return PlaneIntersectionType::Back;
    return PlaneIntersectionType::Intersecting;
}

PlaneIntersectionType Plane::Intersects(const BoundingSphere& sphere) const {
    const float distance = DotCoordinate(sphere.Center);
    if (distance > sphere.Radius) return PlaneIntersectionType::Front;
    if (distance < -sphere.Radius) return PlaneIntersectionType::Back;
    return PlaneIntersectionType::Intersecting;
}

PlaneIntersectionType Plane::Intersects(const BoundingFrustum& frustum) const { return frustum.Intersects(*this); }

}  // namespace fxport
