// BoundingBox: construction, corners, containment and intersection tests with XNA's rules.
#include "fxport/math/bounding_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fxport/math/bounding_frustum.h"
#include "fxport/math/ray.h"

namespace fxport {

namespace {

// Squared distance from a point to the box (0 inside).
float distanceSquared(const BoundingBox& box, Vector3 p) {
    const Vector3 nearest = Vector3::Clamp(p, box.Min, box.Max);
    return Vector3::DistanceSquared(p, nearest);
}

}  // namespace

BoundingBox BoundingBox::CreateFromPoints(std::span<const Vector3> points) {
    if (points.empty()) throw std::invalid_argument("BoundingBox.CreateFromPoints: no points");
    BoundingBox box(points[0], points[0]);
    for (Vector3 p : points) {
        box.Min = Vector3::Min(box.Min, p);
        box.Max = Vector3::Max(box.Max, p);
    }
    return box;
}

BoundingBox BoundingBox::CreateFromSphere(const BoundingSphere& sphere) {
    const Vector3 r(sphere.Radius);
    return {sphere.Center - r, sphere.Center + r};
}

std::array<Vector3, BoundingBox::CornerCount> BoundingBox::GetCorners() const {
    return {Vector3(Min.X, Max.Y, Max.Z), Vector3(Max.X, Max.Y, Max.Z), Vector3(Max.X, Min.Y, Max.Z),
            Vector3(Min.X, Min.Y, Max.Z), Vector3(Min.X, Max.Y, Min.Z), Vector3(Max.X, Max.Y, Min.Z),
            Vector3(Max.X, Min.Y, Min.Z), Vector3(Min.X, Min.Y, Min.Z)};
}

ContainmentType BoundingBox::Contains(Vector3 p) const {
    const bool inside = Min.X <= p.X && p.X <= Max.X && Min.Y <= p.Y && p.Y <= Max.Y && Min.Z <= p.Z && p.Z <= Max.Z;
    return inside ? ContainmentType::Contains : ContainmentType::Disjoint;
}

ContainmentType BoundingBox::Contains(const BoundingBox& box) const {
    if (!Intersects(box)) return ContainmentType::Disjoint;
    const bool inside = Min.X <= box.Min.X && box.Max.X <= Max.X && Min.Y <= box.Min.Y && box.Max.Y <= Max.Y &&
                        Min.Z <= box.Min.Z && box.Max.Z <= Max.Z;
    return inside ? ContainmentType::Contains : ContainmentType::Intersects;
}

ContainmentType BoundingBox::Contains(const BoundingSphere& sphere) const {
    const Vector3 r(sphere.Radius);
    const Vector3 low = sphere.Center - r, high = sphere.Center + r;
    if (Min.X <= low.X && high.X <= Max.X && Min.Y <= low.Y && high.Y <= Max.Y && Min.Z <= low.Z && high.Z <= Max.Z)
        return ContainmentType::Contains;
    return Intersects(sphere) ? ContainmentType::Intersects : ContainmentType::Disjoint;
}

ContainmentType BoundingBox::Contains(const BoundingFrustum& frustum) const {
    if (!frustum.Intersects(*this)) return ContainmentType::Disjoint;
    for (Vector3 corner : frustum.GetCorners())
        if (Contains(corner) == ContainmentType::Disjoint) return ContainmentType::Intersects;
    return ContainmentType::Contains;
}

bool BoundingBox::Intersects(const BoundingBox& box) const {
    return !(Max.X < box.Min.X || Min.X > box.Max.X || Max.Y < box.Min.Y || Min.Y > box.Max.Y || Max.Z < box.Min.Z ||
             Min.Z > box.Max.Z);
}

bool BoundingBox::Intersects(const BoundingSphere& sphere) const {
    return distanceSquared(*this, sphere.Center) <= sphere.Radius * sphere.Radius;
}

bool BoundingBox::Intersects(const BoundingFrustum& frustum) const { return frustum.Intersects(*this); }

std::optional<float> BoundingBox::Intersects(const Ray& ray) const {
    // Slabs: the ray's parameter range inside each pair of faces, intersected.
    float enter = 0.0f, leave = std::numeric_limits<float>::max();
    const float position[3] = {ray.Position.X, ray.Position.Y, ray.Position.Z};
    const float direction[3] = {ray.Direction.X, ray.Direction.Y, ray.Direction.Z};
    const float low[3] = {Min.X, Min.Y, Min.Z}, high[3] = {Max.X, Max.Y, Max.Z};
    for (int axis = 0; axis < 3; ++axis) {
        if (std::fabs(direction[axis]) < 1e-6f) {  // parallel to the slab: inside it or never
            if (position[axis] < low[axis] || position[axis] > high[axis]) return std::nullopt;
            continue;
        }
        const float inv = 1.0f / direction[axis];
        float t1 = (low[axis] - position[axis]) * inv, t2 = (high[axis] - position[axis]) * inv;
        if (t1 > t2) std::swap(t1, t2);
        enter = std::max(enter, t1);
        leave = std::min(leave, t2);
        if (enter > leave) return std::nullopt;
    }
    return enter;
}

}  // namespace fxport
