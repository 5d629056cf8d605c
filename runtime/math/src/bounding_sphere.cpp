// BoundingSphere: construction (from points, box, frustum, two spheres), transform, containment and
// intersection tests with XNA's rules.
#include "fxport/math/bounding_sphere.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fxport/math/bounding_box.h"
#include "fxport/math/bounding_frustum.h"
#include "fxport/math/matrix.h"
#include "fxport/math/plane.h"
#include "fxport/math/ray.h"

namespace fxport {

BoundingSphere BoundingSphere::Transform(const Matrix& m) const {
    const float xScaleSquared = m.M11 * m.M11 + m.M12 * m.M12 + m.M13 * m.M13;
    const float yScaleSquared = m.M21 * m.M21 + m.M22 * m.M22 + m.M23 * m.M23;
    const float zScaleSquared = m.M31 * m.M31 + m.M32 * m.M32 + m.M33 * m.M33;
    const float maxScaleSquared = std::max({xScaleSquared, yScaleSquared, zScaleSquared});
    return {Vector3::Transform(Center, m), Radius * std::sqrt(maxScaleSquared)};
}

}  // namespace fxport

namespace fxport {

BoundingSphere BoundingSphere::CreateFromPoints(std::span<const Vector3> points) {
    if (points.empty()) throw std::invalid_argument("BoundingSphere.CreateFromPoints: no points");
    // Ritter: the pair of axis-extreme points farthest apart gives a first sphere ...
    Vector3 minX = points[0], maxX = points[0], minY = points[0], maxY = points[0], minZ = points[0], maxZ = points[0];
    for (Vector3 p : points) {
        if (p.X < minX.X) minX = p;
        if (p.X > maxX.X) maxX = p;
        if (p.Y < minY.Y) minY = p;
        if (p.Y > maxY.Y) maxY = p;
        if (p.Z < minZ.Z) minZ = p;
        if (p.Z > maxZ.Z) maxZ = p;
    }
    const float spanX = Vector3::DistanceSquared(minX, maxX), spanY = Vector3::DistanceSquared(minY, maxY),
                spanZ = Vector3::DistanceSquared(minZ, maxZ);
    Vector3 a = minX, b = maxX;
    if (spanY > spanX && spanY >= spanZ) a = minY, b = maxY;
    else if (spanZ > spanX && spanZ > spanY) a = minZ, b = maxZ;
    Vector3 center = (a + b) * 0.5f;
    float radius = Vector3::Distance(a, b) * 0.5f;
    // ... grown towards each point outside it, just enough to take it in.
    for (Vector3 p : points) {
        const float distance = Vector3::Distance(p, center);
        if (distance > radius) {
            const float grown = (radius + distance) * 0.5f;
            center = center + (p - center) * ((grown - radius) / distance);
            radius = grown;
        }
    }
    return {center, radius};
}

BoundingSphere BoundingSphere::CreateFromBoundingBox(const BoundingBox& box) {
    const Vector3 center = (box.Min + box.Max) * 0.5f;
    return {center, Vector3::Distance(center, box.Max)};
}

BoundingSphere BoundingSphere::CreateFromFrustum(const BoundingFrustum& frustum) {
    const auto corners = frustum.GetCorners();
    return CreateFromPoints(corners);
}

BoundingSphere BoundingSphere::CreateMerged(const BoundingSphere& original, const BoundingSphere& additional) {
    const Vector3 between = additional.Center - original.Center;
    const float distance = between.Length();
    if (original.Radius + additional.Radius >= distance) {
        if (original.Radius - additional.Radius >= distance) return original;
        if (additional.Radius - original.Radius >= distance) return additional;
    }
    // Along the line of centres: from the far side of one to the far side of the other.
    const Vector3 direction = between * (1.0f / distance);
    const float low = std::min(-original.Radius, distance - additional.Radius);
    const float radius = (std::max(original.Radius, distance + additional.Radius) - low) * 0.5f;
    return {original.Center + direction * (radius + low), radius};
}

ContainmentType BoundingSphere::Contains(const BoundingBox& box) const {
    if (!box.Intersects(*this)) return ContainmentType::Disjoint;
    for (Vector3 corner : box.GetCorners())
        if (Vector3::DistanceSquared(corner, Center) > Radius * Radius) return ContainmentType::Intersects;
    return ContainmentType::Contains;
}

ContainmentType BoundingSphere::Contains(const BoundingFrustum& frustum) const {
    if (!frustum.Intersects(*this)) return ContainmentType::Disjoint;
    for (Vector3 corner : frustum.GetCorners())
        if (Vector3::DistanceSquared(corner, Center) > Radius * Radius) return ContainmentType::Intersects;
    return ContainmentType::Contains;
}

bool BoundingSphere::Intersects(const BoundingBox& box) const { return box.Intersects(*this); }
bool BoundingSphere::Intersects(const BoundingFrustum& frustum) const { return frustum.Intersects(*this); }
PlaneIntersectionType BoundingSphere::Intersects(const Plane& plane) const { return plane.Intersects(*this); }
std::optional<float> BoundingSphere::Intersects(const Ray& ray) const { return ray.Intersects(*this); }

}  // namespace fxport
