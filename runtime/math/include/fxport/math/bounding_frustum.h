// BoundingFrustum: XNA's view frustum from a view * projection matrix, for culling (e.g. a deferred
// renderer's light volumes). XNA's conventions: row vectors and Direct3D's clip space (0 <= z <= w),
// six planes whose normals point out of the frustum.
#pragma once

#include <array>

#include "fxport/math/bounding_sphere.h"
#include "fxport/math/matrix.h"
#include "fxport/math/plane.h"

namespace fxport {

class BoundingFrustum {
public:
    // The number of corners GetCorners returns.
    static constexpr int CornerCount = 8;

    explicit BoundingFrustum(const Matrix& viewProjection);

    const Matrix& getMatrix() const { return matrix_; }
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
    bool Intersects(const BoundingSphere& sphere) const { return Contains(sphere) != ContainmentType::Disjoint; }

private:
    Matrix matrix_;
    std::array<Plane, 6> planes_;  // near, far, left, right, top, bottom
};

}  // namespace fxport
