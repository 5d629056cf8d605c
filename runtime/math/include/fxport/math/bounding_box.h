// BoundingBox: XNA's axis-aligned box (Min, Max), for culling and picking. Points and boxes on the
// box's faces count as inside and intersecting, as XNA.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "fxport/math/bounding_sphere.h"
#include "fxport/math/plane.h"
#include "fxport/math/vector3.h"

namespace fxport {

class BoundingFrustum;
struct Ray;

struct BoundingBox {
    static constexpr int CornerCount = 8;

    Vector3 Min;
    Vector3 Max;

    constexpr BoundingBox() = default;
    constexpr BoundingBox(Vector3 min, Vector3 max) : Min(min), Max(max) {}

    // The smallest box around the points. Throws std::invalid_argument for none (XNA's ArgumentException).
    static BoundingBox CreateFromPoints(std::span<const Vector3> points);
    static BoundingBox CreateFromSphere(const BoundingSphere& sphere);
    static constexpr BoundingBox CreateMerged(const BoundingBox& original, const BoundingBox& additional) {
        return {Vector3::Min(original.Min, additional.Min), Vector3::Max(original.Max, additional.Max)};
    }

    // XNA's order: the Max.Z face (top-left, top-right, bottom-right, bottom-left seen from +Z), then
    // the Min.Z face in the same order.
    std::array<Vector3, CornerCount> GetCorners() const;

    ContainmentType Contains(Vector3 point) const;
    ContainmentType Contains(const BoundingBox& box) const;
    ContainmentType Contains(const BoundingSphere& sphere) const;
    ContainmentType Contains(const BoundingFrustum& frustum) const;

    bool Intersects(const BoundingBox& box) const;
    bool Intersects(const BoundingSphere& sphere) const;
    bool Intersects(const BoundingFrustum& frustum) const;
    PlaneIntersectionType Intersects(const Plane& plane) const { return plane.Intersects(*this); }
    // Distance along the ray to the box (0 when the ray starts inside); nullopt when it misses.
    std::optional<float> Intersects(const Ray& ray) const;

    friend constexpr bool operator==(const BoundingBox&, const BoundingBox&) = default;
};

}  // namespace fxport
