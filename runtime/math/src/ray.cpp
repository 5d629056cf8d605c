// Ray: intersection distances with XNA's rules (0 when the ray starts inside, nullopt on a miss).
#include "fxport/math/ray.h"

#include <cmath>
#include <limits>

#include "fxport/math/bounding_box.h"
#include "fxport/math/bounding_frustum.h"
#include "fxport/math/bounding_sphere.h"
#include "fxport/math/plane.h"

namespace fxport {

std::optional<float> Ray::Intersects(const BoundingBox& box) const { return box.Intersects(*this); }

std::optional<float> Ray::Intersects(const BoundingSphere& sphere) const {
    const Vector3 toCenter = sphere.Center - Position;
    const float distanceSquared = toCenter.LengthSquared();
    const float radiusSquared = sphere.Radius * sphere.Radius;
    if (distanceSquared <= radiusSquared) return 0.0f;
    const float along = Vector3::Dot(toCenter, Direction);
    if (along < 0.0f) return std::nullopt;  // the sphere is behind
    const float missSquared = distanceSquared - along * along;
    if (missSquared > radiusSquared) return std::nullopt;
    return along - std::sqrt(radiusSquared - missSquared);
}

std::optional<float> Ray::Intersects(const Plane& plane) const {
    const float facing = Vector3::Dot(plane.Normal, Direction);
    if (std::fabs(facing) < 1e-5f) return std::nullopt;
    float t = (-plane.D - Vector3::Dot(plane.Normal, Position)) / facing;
    if (t < 0.0f) {
        if (t < -1e-5f) return std::nullopt;
        t = 0.0f;
    }
    return t;
}

std::optional<float> Ray::Intersects(const BoundingFrustum& frustum) const { return frustum.Intersects(*this); }

}  // namespace fxport
