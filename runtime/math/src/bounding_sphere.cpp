#include "fxport/math/bounding_sphere.h"

#include <algorithm>
#include <cmath>

#include "fxport/math/matrix.h"

namespace fxport {

BoundingSphere BoundingSphere::Transform(const Matrix& m) const {
    const float xScaleSquared = m.M11 * m.M11 + m.M12 * m.M12 + m.M13 * m.M13;
    const float yScaleSquared = m.M21 * m.M21 + m.M22 * m.M22 + m.M23 * m.M23;
    const float zScaleSquared = m.M31 * m.M31 + m.M32 * m.M32 + m.M33 * m.M33;
    const float maxScaleSquared = std::max({xScaleSquared, yScaleSquared, zScaleSquared});
    return {Vector3::Transform(Center, m), Radius * std::sqrt(maxScaleSquared)};
}

}  // namespace fxport
