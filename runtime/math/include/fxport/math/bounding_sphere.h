// BoundingSphere: XNA's sphere for coarse culling and picking.
#pragma once

#include <cmath>
#include <optional>
#include <span>

#include "fxport/math/vector3.h"

namespace fxport {

struct BoundingBox;
class BoundingFrustum;
struct Matrix;
struct Plane;
struct Ray;
enum class PlaneIntersectionType;

// How one volume relates to another (XNA's ContainmentType).
enum class ContainmentType { Disjoint, Contains, Intersects };

struct BoundingSphere {
    Vector3 Center;
    float Radius = 0.0f;

    constexpr BoundingSphere() = default;
    constexpr BoundingSphere(Vector3 center, float radius) : Center(center), Radius(radius) {}

    // A sphere around the points: Ritter's method as XNA (the extreme points along X, Y and Z give a
    // first sphere, grown to take in every point); close to, not always, the smallest. Throws
    // std::invalid_argument for no points.
    static BoundingSphere CreateFromPoints(std::span<const Vector3> points);
    // The sphere through the box's corners.
    static BoundingSphere CreateFromBoundingBox(const BoundingBox& box);
    // The sphere around the frustum's corners (CreateFromPoints of GetCorners).
    static BoundingSphere CreateFromFrustum(const BoundingFrustum& frustum);
    // The smallest sphere around both (one of them when it contains the other).
    static BoundingSphere CreateMerged(const BoundingSphere& original, const BoundingSphere& additional);

    // The sphere around the transformed sphere: the centre transformed as a point, the radius
    // scaled by the matrix's largest axis scale (exact for rotation, translation and uniform
    // scale; an upper bound otherwise).
    BoundingSphere Transform(const Matrix& matrix) const;

    // A point on the surface counts as outside (Disjoint), as XNA.
    constexpr ContainmentType Contains(Vector3 point) const {
        return Vector3::DistanceSquared(point, Center) < Radius * Radius ? ContainmentType::Contains
                                                                         : ContainmentType::Disjoint;
    }
    ContainmentType Contains(const BoundingSphere& sphere) const {
        const float distance = Vector3::Distance(Center, sphere.Center);
        if (Radius + sphere.Radius < distance) {
            return ContainmentType::Disjoint;
        }
        if (Radius - sphere.Radius < distance) {
            return ContainmentType::Intersects;
        }
        return ContainmentType::Contains;
    }
    // Contains when every corner of the box (frustum) is within the radius, on the surface included;
    // Disjoint when they do not meet; else Intersects (XNA).
    ContainmentType Contains(const BoundingBox& box) const;
    ContainmentType Contains(const BoundingFrustum& frustum) const;
    bool Intersects(const BoundingBox& box) const;
    bool Intersects(const BoundingFrustum& frustum) const;
    PlaneIntersectionType Intersects(const Plane& plane) const;
    std::optional<float> Intersects(const Ray& ray) const;

    // Touching spheres do not intersect.
    constexpr bool Intersects(const BoundingSphere& sphere) const {
        const float radii = Radius + sphere.Radius;
        return Vector3::DistanceSquared(Center, sphere.Center) < radii * radii;
    }

    friend constexpr bool operator==(const BoundingSphere&, const BoundingSphere&) = default;
};

}  // namespace fxport
