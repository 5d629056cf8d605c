#include "fxport/math/bounding_frustum.h"

namespace fxport {

namespace {

// The point where three planes meet (the planes of a frustum corner are never parallel).
Vector3 intersection(const Plane& a, const Plane& b, const Plane& c) {
    const Vector3 bc = Vector3::Cross(b.Normal, c.Normal);
    const float det = Vector3::Dot(a.Normal, bc);
    return (bc * -a.D + Vector3::Cross(c.Normal, a.Normal) * -b.D + Vector3::Cross(a.Normal, b.Normal) * -c.D) *
           (1.0f / det);
}

}  // namespace

BoundingFrustum::BoundingFrustum(const Matrix& m) : matrix_(m) {
    // A point p (row vector) is inside when clip = p * m has -w <= x <= w, -w <= y <= w, 0 <= z <= w;
    // each inequality is a plane, with its normal negated so that it points out.
    planes_[0] = Plane(-m.M13, -m.M23, -m.M33, -m.M43);                                  // z >= 0
    planes_[1] = Plane(m.M13 - m.M14, m.M23 - m.M24, m.M33 - m.M34, m.M43 - m.M44);      // z <= w
    planes_[2] = Plane(-m.M14 - m.M11, -m.M24 - m.M21, -m.M34 - m.M31, -m.M44 - m.M41);  // x >= -w
    planes_[3] = Plane(m.M11 - m.M14, m.M21 - m.M24, m.M31 - m.M34, m.M41 - m.M44);      // x <= w
    planes_[4] = Plane(m.M12 - m.M14, m.M22 - m.M24, m.M32 - m.M34, m.M42 - m.M44);      // y <= w
    planes_[5] = Plane(-m.M14 - m.M12, -m.M24 - m.M22, -m.M34 - m.M32, -m.M44 - m.M42);  // y >= -w
    for (Plane& p : planes_) p.Normalize();
}

std::array<Vector3, BoundingFrustum::CornerCount> BoundingFrustum::GetCorners() const {
    return {intersection(Near(), Left(), Top()),    intersection(Near(), Right(), Top()),
            intersection(Near(), Right(), Bottom()), intersection(Near(), Left(), Bottom()),
            intersection(Far(), Left(), Top()),     intersection(Far(), Right(), Top()),
            intersection(Far(), Right(), Bottom()),  intersection(Far(), Left(), Bottom())};
}

ContainmentType BoundingFrustum::Contains(Vector3 point) const {
    for (const Plane& p : planes_)
        if (p.DotCoordinate(point) > 0.0f) return ContainmentType::Disjoint;
    return ContainmentType::Contains;
}

ContainmentType BoundingFrustum::Contains(const BoundingSphere& sphere) const {
    bool intersects = false;
    for (const Plane& p : planes_) {
        const float distance = p.DotCoordinate(sphere.Center);
        if (distance > sphere.Radius) return ContainmentType::Disjoint;
        if (distance > -sphere.Radius) intersects = true;
    }
    return intersects ? ContainmentType::Intersects : ContainmentType::Contains;
}

}  // namespace fxport
