// BoundingFrustum: planes from a view * projection matrix (D3D clip space), corners, and containment
// and intersection tests (plane by plane where XNA is, separating axes for the exact box/frustum tests).
#include "fxport/math/bounding_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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

BoundingFrustum::BoundingFrustum(const Matrix& m) { setMatrix(m); }

void BoundingFrustum::setMatrix(const Matrix& m) {
    matrix_ = m;
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


namespace {

// The interval a set of points covers along an axis.
struct Extent {
    float low = std::numeric_limits<float>::max(), high = -std::numeric_limits<float>::max();
};
template <class Points> Extent project(const Points& points, Vector3 axis) {
    Extent e;
    for (Vector3 p : points) {
        const float d = Vector3::Dot(p, axis);
        e.low = std::min(e.low, d);
        e.high = std::max(e.high, d);
    }
    return e;
}

// The 12 edges of a box or frustum given as 8 corners in GetCorners order, as directions.
std::array<Vector3, 12> edgeDirections(const std::array<Vector3, 8>& c) {
    return {c[1] - c[0], c[2] - c[1], c[3] - c[2], c[0] - c[3], c[5] - c[4], c[6] - c[5],
            c[7] - c[6], c[4] - c[7], c[4] - c[0], c[5] - c[1], c[6] - c[2], c[7] - c[3]};
}

// Separating axis test of two convex polyhedra given by corners, face normals and edge directions:
// they are disjoint exactly when some face normal or edge x edge direction separates them.
bool overlap(const std::array<Vector3, 8>& a, const std::vector<Vector3>& aNormals, const std::array<Vector3, 8>& b,
             const std::vector<Vector3>& bNormals) {
    std::vector<Vector3> axes = aNormals;
    axes.insert(axes.end(), bNormals.begin(), bNormals.end());
    for (Vector3 ea : edgeDirections(a))
        for (Vector3 eb : edgeDirections(b)) axes.push_back(Vector3::Cross(ea, eb));
    for (Vector3 axis : axes) {
        if (axis.LengthSquared() < 1e-12f) continue;  // parallel edges: no axis
        const Extent ea = project(a, axis), eb = project(b, axis);
        if (ea.high < eb.low || eb.high < ea.low) return false;
    }
    return true;
}

std::vector<Vector3> normals(const std::array<Plane, 6>& planes) {
    std::vector<Vector3> result;
    for (const Plane& p : planes) result.push_back(p.Normal);
    return result;
}

}  // namespace

ContainmentType BoundingFrustum::Contains(const BoundingBox& box) const {
    bool intersects = false;
    for (const Plane& p : planes_) {
        switch (p.Intersects(box)) {
        case PlaneIntersectionType::Front: return ContainmentType::Disjoint;
        case PlaneIntersectionType::Intersecting: intersects = true; break;
        case PlaneIntersectionType::Back: break;
        }
    }
    return intersects ? ContainmentType::Intersects : ContainmentType::Contains;
}

ContainmentType BoundingFrustum::Contains(const BoundingFrustum& frustum) const {
    if (!Intersects(frustum)) return ContainmentType::Disjoint;
    for (Vector3 corner : frustum.GetCorners())
        if (Contains(corner) == ContainmentType::Disjoint) return ContainmentType::Intersects;
    return ContainmentType::Contains;
}

bool BoundingFrustum::Intersects(const BoundingBox& box) const {
    return overlap(GetCorners(), normals(planes_), box.GetCorners(), {Vector3::UnitX, Vector3::UnitY, Vector3::UnitZ});
}

bool BoundingFrustum::Intersects(const BoundingFrustum& frustum) const {
    return overlap(GetCorners(), normals(planes_), frustum.GetCorners(), normals(frustum.planes_));
}

PlaneIntersectionType BoundingFrustum::Intersects(const Plane& plane) const {
    bool front = false, back = false;
    for (Vector3 corner : GetCorners()) {
        const float d = plane.DotCoordinate(corner);
        front = front || d > 0.0f;
        back = back || d < 0.0f;
    }
    if (front && back) return PlaneIntersectionType::Intersecting;
    if (front) return PlaneIntersectionType::Front;
    if (back) return PlaneIntersectionType::Back;
    return PlaneIntersectionType::Intersecting;  // flat on the plane
}

std::optional<float> BoundingFrustum::Intersects(const Ray& ray) const {
    // Clip the ray's parameter range by each half-space (normals point out).
    float enter = 0.0f, leave = std::numeric_limits<float>::max();
    for (const Plane& p : planes_) {
        const float facing = Vector3::Dot(p.Normal, ray.Direction);
        const float distance = p.DotCoordinate(ray.Position);
        if (std::fabs(facing) < 1e-12f) {
            if (distance > 0.0f) return std::nullopt;  // parallel and outside
            continue;
        }
        const float t = -distance / facing;
        if (facing < 0.0f) enter = std::max(enter, t);
        else leave = std::min(leave, t);
        if (enter > leave) return std::nullopt;
    }
    return enter;
}

}  // namespace fxport
