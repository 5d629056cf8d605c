// The vector Transform functions, here rather than inline because the vector headers cannot see
// Matrix (matrix.h includes them). Row vector times matrix, as XNA.
#include "fxport/math/matrix.h"
#include "fxport/math/quaternion.h"
#include "fxport/math/vector2.h"
#include "fxport/math/vector3.h"
#include "fxport/math/vector4.h"

namespace fxport {

Vector2 Vector2::Transform(Vector2 p, const Matrix& m) {
    return {p.X * m.M11 + p.Y * m.M21 + m.M41, p.X * m.M12 + p.Y * m.M22 + m.M42};
}

Vector2 Vector2::TransformNormal(Vector2 n, const Matrix& m) {
    return {n.X * m.M11 + n.Y * m.M21, n.X * m.M12 + n.Y * m.M22};
}

Vector3 Vector3::Transform(Vector3 p, const Matrix& m) {
    return {p.X * m.M11 + p.Y * m.M21 + p.Z * m.M31 + m.M41,
            p.X * m.M12 + p.Y * m.M22 + p.Z * m.M32 + m.M42,
            p.X * m.M13 + p.Y * m.M23 + p.Z * m.M33 + m.M43};
}

Vector3 Vector3::TransformNormal(Vector3 n, const Matrix& m) {
    return {n.X * m.M11 + n.Y * m.M21 + n.Z * m.M31,
            n.X * m.M12 + n.Y * m.M22 + n.Z * m.M32,
            n.X * m.M13 + n.Y * m.M23 + n.Z * m.M33};
}

Vector3 Vector3::Transform(Vector3 v, const Quaternion& q) {
    // The rows of CreateFromQuaternion(q), applied without building the matrix.
    const float x2 = q.X + q.X, y2 = q.Y + q.Y, z2 = q.Z + q.Z;
    const float wx = q.W * x2, wy = q.W * y2, wz = q.W * z2;
    const float xx = q.X * x2, xy = q.X * y2, xz = q.X * z2;
    const float yy = q.Y * y2, yz = q.Y * z2, zz = q.Z * z2;
    return {v.X * (1.0f - yy - zz) + v.Y * (xy - wz) + v.Z * (xz + wy),
            v.X * (xy + wz) + v.Y * (1.0f - xx - zz) + v.Z * (yz - wx),
            v.X * (xz - wy) + v.Y * (yz + wx) + v.Z * (1.0f - xx - yy)};
}

Vector4 Vector4::Transform(Vector4 v, const Matrix& m) {
    return {v.X * m.M11 + v.Y * m.M21 + v.Z * m.M31 + v.W * m.M41,
            v.X * m.M12 + v.Y * m.M22 + v.Z * m.M32 + v.W * m.M42,
            v.X * m.M13 + v.Y * m.M23 + v.Z * m.M33 + v.W * m.M43,
            v.X * m.M14 + v.Y * m.M24 + v.Z * m.M34 + v.W * m.M44};
}

Vector4 Vector4::Transform(Vector3 p, const Matrix& m) { return Transform(Vector4(p, 1.0f), m); }

Vector4 Vector4::Transform(Vector2 p, const Matrix& m) {
    return Transform(Vector4(p, 0.0f, 1.0f), m);
}

Vector2 Vector2::Transform(Vector2 v, const Quaternion& q) {
    const Vector3 r = Vector3::Transform(Vector3(v, 0.0f), q);
    return {r.X, r.Y};
}

Vector4 Vector4::Transform(Vector4 v, const Quaternion& q) {
    const Vector3 r = Vector3::Transform(Vector3(v.X, v.Y, v.Z), q);
    return {r.X, r.Y, r.Z, v.W};
}

Vector4 Vector4::Transform(Vector3 v, const Quaternion& q) { return Transform(Vector4(v, 1.0f), q); }

Vector4 Vector4::Transform(Vector2 v, const Quaternion& q) { return Transform(Vector4(v, 0.0f, 1.0f), q); }

}  // namespace fxport
