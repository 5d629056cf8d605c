// BoundingSphere: XNA's sphere for coarse culling and picking.
#pragma once

#include <cmath>

#include "fxport/math/vector3.h"

namespace fxport {

struct Matrix;

// How one volume relates to another (XNA's ContainmentType).
enum class ContainmentType { Disjoint, Contains, Intersects };

struct BoundingSphere {
    Vector3 Center;
    float Radius = 0.0f;

    constexpr BoundingSphere() = default;
    constexpr BoundingSphere(Vector3 center, float radius) : Center(center), Radius(radius) {}

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
    // Touching spheres do not intersect.
    constexpr bool Intersects(const BoundingSphere& sphere) const {
        const float radii = Radius + sphere.Radius;
        return Vector3::DistanceSquared(Center, sphere.Center) < radii * radii;
    }

    friend constexpr bool operator==(const BoundingSphere&, const BoundingSphere&) = default;
};

}  // namespace fxport
