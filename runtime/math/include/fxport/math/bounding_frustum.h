// BoundingFrustum: XNA's view frustum from a view * projection matrix, for culling (e.g. a deferred
// renderer's light volumes). XNA's conventions: row vectors and Direct3D's clip space (0 <= z <= w),
// six planes whose normals point out of the frustum.
#pragma once

#include <array>
#include <optional>

#include "fxport/math/bounding_box.h"
#include "fxport/math/bounding_sphere.h"
#include "fxport/math/matrix.h"
#include "fxport/math/plane.h"
#include "fxport/math/ray.h"

namespace fxport {

class BoundingFrustum {
public:
    // The number of corners GetCorners returns.
    static constexpr int CornerCount = 8;

    explicit BoundingFrustum(const Matrix& viewProjection);

    // XNA's settable Matrix property (docs/API.md: a property whose setter does work is a get/set
    // pair; "get" because a member function named Matrix would hide the type): setMatrix
    // recomputes the planes.
    const Matrix& getMatrix() const { return matrix_; }
    void setMatrix(const Matrix& viewProjection);
    const Plane& Near() const { return planes_[0]; }
    const Plane& Far() const { return planes_[1]; }
    const Plane& Left() const { return planes_[2]; }
    const Plane& Right() const { return planes_[3]; }
    const Plane& Top() const { return planes_[4]; }
    const Plane& Bottom() const { return planes_[5]; }

    // Near plane corners first (as XNA: near top-left, top-right, bottom-right, bottom-left), then far.
    std::array<Vector3, CornerCount> GetCorners() const;

    // A point on a plane counts as inside (Contains).
    ContainmentType Contains(Vector3 point) const;
    // Tested plane by plane, as XNA: Disjoint when the sphere is wholly outside one plane, Contains
    // when inside all six, else Intersects. Conservative: a sphere just outside an edge or corner,
    // outside no single plane, reports Intersects.
    ContainmentType Contains(const BoundingSphere& sphere) const;
    // Plane by plane as well (XNA tests Intersects(BoundingSphere) exactly): a sphere just outside an
    // edge or corner counts as intersecting. Culling stays conservative.
    bool Intersects(const BoundingSphere& sphere) const { return Contains(sphere) != ContainmentType::Disjoint; }

    // Plane by plane, as XNA: Disjoint when the box is wholly in front of one plane, Contains when
    // behind all six, else Intersects.
    ContainmentType Contains(const BoundingBox& box) const;
    // Disjoint when they do not meet, Contains when every corner of `frustum` is inside this one.
    ContainmentType Contains(const BoundingFrustum& frustum) const;
    // Exact (separating axes: the frustum's face normals, the box's axes and their edges' cross
    // products); touching counts as intersecting.
    bool Intersects(const BoundingBox& box) const;
    bool Intersects(const BoundingFrustum& frustum) const;
    // Which side of the plane the frustum's corners lie on.
    PlaneIntersectionType Intersects(const Plane& plane) const;
    // Distance along the ray to where it enters the frustum; 0 when it starts inside.
    std::optional<float> Intersects(const Ray& ray) const;

    friend bool operator==(const BoundingFrustum& a, const BoundingFrustum& b) { return a.matrix_ == b.matrix_; }

private:
    Matrix matrix_;
    std::array<Plane, 6> planes_;  // near, far, left, right, top, bottom
};

}  // namespace fxport
