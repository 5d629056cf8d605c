// The double-precision 3x3 algebra both games' pixel checks evaluate XNA's math with (row vectors,
// v' = v * M, as XNA), kept apart from the GPU's float path.
#pragma once

#include <array>
#include <cmath>

namespace example {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

inline Vec3 times(const Vec3& v, const Mat3& m) {
    Vec3 r{};
    for (int c = 0; c < 3; ++c) r[c] = v[0] * m[0][c] + v[1] * m[1][c] + v[2] * m[2][c];
    return r;
}
inline Mat3 times(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i) r[i] = times(a[i], b);
    return r;
}
inline Mat3 transposed(const Mat3& m) {
    Mat3 t{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) t[r][c] = m[c][r];
    return t;
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// XNA's Matrix.CreateRotationY / CreateRotationX (upper 3x3).
inline Mat3 rotationY(double a) { return {{{std::cos(a), 0, -std::sin(a)}, {0, 1, 0}, {std::sin(a), 0, std::cos(a)}}}; }
inline Mat3 rotationX(double a) { return {{{1, 0, 0}, {0, std::cos(a), std::sin(a)}, {0, -std::sin(a), std::cos(a)}}}; }

}  // namespace example
