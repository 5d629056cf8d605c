// Ray: XNA's half-line from Position along Direction, for picking. Intersects returns the distance
// along the ray (in units of Direction's length: pass a unit Direction for world distances, as XNA
// assumes) or nullopt -- XNA's Nullable<float>.
#pragma once

#include <optional>

#include "fxport/math/vector3.h"

namespace fxport {

class BoundingFrustum;
struct BoundingBox;
struct BoundingSphere;
struct Plane;

struct Ray {
    Vector3 Position;
    Vector3 Direction;

    constexpr Ray() = default;
    constexpr Ray(Vector3 position, Vector3 direction) : Position(position), Direction(direction) {}

    // 0 when Position is inside the volume.
    std::optional<float> Intersects(const BoundingBox& box) const;
    std::optional<float> Intersects(const BoundingSphere& sphere) const;
    std::optional<float> Intersects(const BoundingFrustum& frustum) const;
    // nullopt when the ray is parallel to the plane or points away from it; 0 when it starts on it.
    std::optional<float> Intersects(const Plane& plane) const;

    friend constexpr bool operator==(const Ray&, const Ray&) = default;
};

}  // namespace fxport
