// Matrix: the factories follow XNA's formulas term by term, so results agree with XNA to float
// rounding. Only Invert goes through GLM.
#include "fxport/math/matrix.h"

#include "fxport/math/plane.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

namespace fxport {

Matrix Matrix::Multiply(const Matrix& a, const Matrix& b) {
    return {
        a.M11 * b.M11 + a.M12 * b.M21 + a.M13 * b.M31 + a.M14 * b.M41,
        a.M11 * b.M12 + a.M12 * b.M22 + a.M13 * b.M32 + a.M14 * b.M42,
        a.M11 * b.M13 + a.M12 * b.M23 + a.M13 * b.M33 + a.M14 * b.M43,
        a.M11 * b.M14 + a.M12 * b.M24 + a.M13 * b.M34 + a.M14 * b.M44,
        a.M21 * b.M11 + a.M22 * b.M21 + a.M23 * b.M31 + a.M24 * b.M41,
        a.M21 * b.M12 + a.M22 * b.M22 + a.M23 * b.M32 + a.M24 * b.M42,
        a.M21 * b.M13 + a.M22 * b.M23 + a.M23 * b.M33 + a.M24 * b.M43,
        a.M21 * b.M14 + a.M22 * b.M24 + a.M23 * b.M34 + a.M24 * b.M44,
        a.M31 * b.M11 + a.M32 * b.M21 + a.M33 * b.M31 + a.M34 * b.M41,
        a.M31 * b.M12 + a.M32 * b.M22 + a.M33 * b.M32 + a.M34 * b.M42,
        a.M31 * b.M13 + a.M32 * b.M23 + a.M33 * b.M33 + a.M34 * b.M43,
        a.M31 * b.M14 + a.M32 * b.M24 + a.M33 * b.M34 + a.M34 * b.M44,
        a.M41 * b.M11 + a.M42 * b.M21 + a.M43 * b.M31 + a.M44 * b.M41,
        a.M41 * b.M12 + a.M42 * b.M22 + a.M43 * b.M32 + a.M44 * b.M42,
        a.M41 * b.M13 + a.M42 * b.M23 + a.M43 * b.M33 + a.M44 * b.M43,
        a.M41 * b.M14 + a.M42 * b.M24 + a.M43 * b.M34 + a.M44 * b.M44,
    };
}

Matrix Matrix::Multiply(Matrix matrix, float scale) {
    float* m = matrix.data();
    for (int i = 0; i < 16; ++i) {
        m[i] *= scale;
    }
    return matrix;
}

Matrix Matrix::Add(Matrix a, const Matrix& b) {
    float* m = a.data();
    const float* n = b.data();
    for (int i = 0; i < 16; ++i) {
        m[i] += n[i];
    }
    return a;
}

Matrix Matrix::Subtract(Matrix a, const Matrix& b) {
    float* m = a.data();
    const float* n = b.data();
    for (int i = 0; i < 16; ++i) {
        m[i] -= n[i];
    }
    return a;
}

Matrix Matrix::Negate(Matrix matrix) { return Multiply(matrix, -1.0f); }

Matrix Matrix::Lerp(const Matrix& a, const Matrix& b, float amount) {
    Matrix result;
    const float* m = a.data();
    const float* n = b.data();
    float* r = result.data();
    for (int i = 0; i < 16; ++i) {
        r[i] = m[i] + (n[i] - m[i]) * amount;
    }
    return result;
}

Matrix Matrix::Transpose(const Matrix& m) {
    return {m.M11, m.M21, m.M31, m.M41,
            m.M12, m.M22, m.M32, m.M42,
            m.M13, m.M23, m.M33, m.M43,
            m.M14, m.M24, m.M34, m.M44};
}

float Matrix::Determinant() const {
    // Laplace expansion along the first row, with the 2x2 minors of the lower two rows shared.
    const float m3344 = M33 * M44 - M34 * M43;
    const float m3244 = M32 * M44 - M34 * M42;
    const float m3243 = M32 * M43 - M33 * M42;
    const float m3144 = M31 * M44 - M34 * M41;
    const float m3143 = M31 * M43 - M33 * M41;
    const float m3142 = M31 * M42 - M32 * M41;
    return M11 * (M22 * m3344 - M23 * m3244 + M24 * m3243) -
           M12 * (M21 * m3344 - M23 * m3144 + M24 * m3143) +
           M13 * (M21 * m3244 - M22 * m3144 + M24 * m3142) -
           M14 * (M21 * m3243 - M22 * m3143 + M23 * m3142);
}

Matrix Matrix::Invert(const Matrix& matrix) {
    // GLM is column-major: reading our row-major floats gives it the transpose, and since
    // inverse(transpose(M)) == transpose(inverse(M)), writing its result back in the same order
    // yields inverse(M) in XNA layout.
    const glm::mat4 inverse = glm::inverse(glm::make_mat4(matrix.data()));
    Matrix result;
    std::memcpy(result.data(), glm::value_ptr(inverse), sizeof(Matrix));
    return result;
}

bool Matrix::Decompose(Vector3& scale, Quaternion& rotation, Vector3& translation) const {
    // XNA's (and D3DX's) algorithm: the rows of the upper 3x3 are the scaled axes. Normalise them,
    // rebuilding degenerate ones (scale ~0) orthogonal to the others, starting from the longest;
    // a negative determinant (mirroring) is put on the longest axis as a negative scale.
    constexpr float epsilon = 0.0001f;
    translation = Translation();
    Vector3 axes[3] = {Right(), Up(), Backward()};
    float lengths[3] = {axes[0].Length(), axes[1].Length(), axes[2].Length()};

    int a, b, c;  // longest, middle, shortest (XNA's tie-breaking)
    if (lengths[0] < lengths[1]) {
        if (lengths[1] < lengths[2]) {
            a = 2, b = 1, c = 0;
        } else {
            a = 1;
            if (lengths[0] < lengths[2]) {
                b = 2, c = 0;
            } else {
                b = 0, c = 2;
            }
        }
    } else {
        if (lengths[0] < lengths[2]) {
            a = 2, b = 0, c = 1;
        } else {
            a = 0;
            if (lengths[1] < lengths[2]) {
                b = 2, c = 1;
            } else {
                b = 1, c = 2;
            }
        }
    }

    const Vector3 canonical[3] = {Vector3::UnitX, Vector3::UnitY, Vector3::UnitZ};
    if (lengths[a] < epsilon) {
        axes[a] = canonical[a];
    }
    axes[a].Normalize();
    if (lengths[b] < epsilon) {
        // Perpendicular to axes[a], through the canonical axis least aligned with it.
        const float x = std::fabs(axes[a].X), y = std::fabs(axes[a].Y), z = std::fabs(axes[a].Z);
        const int least = (x < y) ? ((y < z || x < z) ? 0 : 2) : ((x < z || y < z) ? 1 : 2);
        axes[b] = Vector3::Cross(axes[a], canonical[least]);
    }
    axes[b].Normalize();
    if (lengths[c] < epsilon) {
        axes[c] = Vector3::Cross(axes[a], axes[b]);
    }
    axes[c].Normalize();

    float det = Vector3::Dot(Vector3::Cross(axes[0], axes[1]), axes[2]);
    if (det < 0.0f) {
        lengths[a] = -lengths[a];
        axes[a] = -axes[a];
        det = -det;
    }
    scale = {lengths[0], lengths[1], lengths[2]};

    // Unit axes with determinant 1 are a rotation; anything else had shear in it.
    det -= 1.0f;
    if (det * det > epsilon) {
        rotation = Quaternion::Identity;
        return false;
    }
    Matrix basis = Identity;
    basis.setRight(axes[0]);
    basis.setUp(axes[1]);
    basis.setBackward(axes[2]);
    rotation = Quaternion::CreateFromRotationMatrix(basis);
    return true;
}

Matrix Matrix::CreateTranslation(Vector3 position) {
    return CreateTranslation(position.X, position.Y, position.Z);
}

Matrix Matrix::CreateTranslation(float x, float y, float z) {
    Matrix result = Identity;
    result.setTranslation({x, y, z});
    return result;
}

Matrix Matrix::CreateScale(float scale) { return CreateScale(scale, scale, scale); }

Matrix Matrix::CreateScale(Vector3 scales) { return CreateScale(scales.X, scales.Y, scales.Z); }

Matrix Matrix::CreateScale(float x, float y, float z) {
    Matrix result = Identity;
    result.M11 = x;
    result.M22 = y;
    result.M33 = z;
    return result;
}

Matrix Matrix::CreateRotationX(float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    Matrix result = Identity;
    result.M22 = c;
    result.M23 = s;
    result.M32 = -s;
    result.M33 = c;
    return result;
}

Matrix Matrix::CreateRotationY(float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    Matrix result = Identity;
    result.M11 = c;
    result.M13 = -s;
    result.M31 = s;
    result.M33 = c;
    return result;
}

Matrix Matrix::CreateRotationZ(float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    Matrix result = Identity;
    result.M11 = c;
    result.M12 = s;
    result.M21 = -s;
    result.M22 = c;
    return result;
}

Matrix Matrix::CreateFromAxisAngle(Vector3 axis, float angle) {
    const float x = axis.X, y = axis.Y, z = axis.Z;
    const float s = std::sin(angle), c = std::cos(angle);
    const float xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z;
    Matrix result = Identity;
    result.M11 = xx + c * (1.0f - xx);
    result.M12 = xy - c * xy + s * z;
    result.M13 = xz - c * xz - s * y;
    result.M21 = xy - c * xy - s * z;
    result.M22 = yy + c * (1.0f - yy);
    result.M23 = yz - c * yz + s * x;
    result.M31 = xz - c * xz + s * y;
    result.M32 = yz - c * yz - s * x;
    result.M33 = zz + c * (1.0f - zz);
    return result;
}

Matrix Matrix::CreateFromQuaternion(Quaternion q) {
    const float xx = q.X * q.X, yy = q.Y * q.Y, zz = q.Z * q.Z;
    const float xy = q.X * q.Y, zw = q.Z * q.W, zx = q.Z * q.X;
    const float yw = q.Y * q.W, yz = q.Y * q.Z, xw = q.X * q.W;
    Matrix result = Identity;
    result.M11 = 1.0f - 2.0f * (yy + zz);
    result.M12 = 2.0f * (xy + zw);
    result.M13 = 2.0f * (zx - yw);
    result.M21 = 2.0f * (xy - zw);
    result.M22 = 1.0f - 2.0f * (zz + xx);
    result.M23 = 2.0f * (yz + xw);
    result.M31 = 2.0f * (zx + yw);
    result.M32 = 2.0f * (yz - xw);
    result.M33 = 1.0f - 2.0f * (yy + xx);
    return result;
}

Matrix Matrix::CreateFromYawPitchRoll(float yaw, float pitch, float roll) {
    return CreateFromQuaternion(Quaternion::CreateFromYawPitchRoll(yaw, pitch, roll));
}

Matrix Matrix::CreateLookAt(Vector3 cameraPosition, Vector3 cameraTarget, Vector3 cameraUpVector) {
    // View space axes in world space: z points from the target back to the camera (the camera
    // looks down -z), x to the right, y up. The view matrix is the inverse of the camera's world
    // matrix: those axes as columns, and the position rotated into view space and negated.
    const Vector3 zAxis = Vector3::Normalize(cameraPosition - cameraTarget);
    const Vector3 xAxis = Vector3::Normalize(Vector3::Cross(cameraUpVector, zAxis));
    const Vector3 yAxis = Vector3::Cross(zAxis, xAxis);
    return {xAxis.X, yAxis.X, zAxis.X, 0.0f,
            xAxis.Y, yAxis.Y, zAxis.Y, 0.0f,
            xAxis.Z, yAxis.Z, zAxis.Z, 0.0f,
            -Vector3::Dot(xAxis, cameraPosition), -Vector3::Dot(yAxis, cameraPosition),
            -Vector3::Dot(zAxis, cameraPosition), 1.0f};
}

Matrix Matrix::CreateWorld(Vector3 position, Vector3 forward, Vector3 up) {
    const Vector3 zAxis = Vector3::Normalize(-forward);
    const Vector3 xAxis = Vector3::Normalize(Vector3::Cross(up, zAxis));
    const Vector3 yAxis = Vector3::Cross(zAxis, xAxis);
    Matrix result = Identity;
    result.setRight(xAxis);
    result.setUp(yAxis);
    result.setBackward(zAxis);
    result.setTranslation(position);
    return result;
}

Matrix Matrix::CreateBillboard(Vector3 objectPosition, Vector3 cameraPosition,
                               Vector3 cameraUpVector, std::optional<Vector3> cameraForwardVector) {
    Vector3 zAxis = objectPosition - cameraPosition;
    const float lengthSquared = zAxis.LengthSquared();
    if (lengthSquared < 0.0001f) {
        zAxis = cameraForwardVector ? -*cameraForwardVector : Vector3::Forward;
    } else {
        zAxis *= 1.0f / std::sqrt(lengthSquared);
    }
    const Vector3 xAxis = Vector3::Normalize(Vector3::Cross(cameraUpVector, zAxis));
    const Vector3 yAxis = Vector3::Cross(zAxis, xAxis);
    Matrix result = Identity;
    result.setRight(xAxis);
    result.setUp(yAxis);
    result.setBackward(zAxis);
    result.setTranslation(objectPosition);
    return result;
}

namespace {

void checkNearFar(float nearPlaneDistance, float farPlaneDistance) {
    if (!(nearPlaneDistance > 0.0f)) {
        throw std::out_of_range("nearPlaneDistance must be positive");
    }
    if (!(farPlaneDistance > 0.0f)) {
        throw std::out_of_range("farPlaneDistance must be positive");
    }
    if (!(nearPlaneDistance < farPlaneDistance)) {
        throw std::out_of_range("nearPlaneDistance must be less than farPlaneDistance");
    }
}

// The depth part shared by the perspective projections. Clip z = z * far / (near - far)
// + near * far / (near - far) and clip w = -z, so after the divide view z = -near lands on
// depth 0 and z = -far on 1 — Direct3D's range (see matrix.h).
void setPerspectiveDepth(Matrix& m, float nearPlaneDistance, float farPlaneDistance) {
    m.M33 = farPlaneDistance / (nearPlaneDistance - farPlaneDistance);
    m.M34 = -1.0f;
    m.M43 = nearPlaneDistance * farPlaneDistance / (nearPlaneDistance - farPlaneDistance);
    m.M44 = 0.0f;
}

}  // namespace

Matrix Matrix::CreatePerspectiveFieldOfView(float fieldOfView, float aspectRatio,
                                            float nearPlaneDistance, float farPlaneDistance) {
    if (!(fieldOfView > 0.0f && fieldOfView < MathHelper::Pi)) {
        throw std::out_of_range("fieldOfView must be in (0, Pi)");
    }
    checkNearFar(nearPlaneDistance, farPlaneDistance);
    const float yScale = 1.0f / std::tan(fieldOfView * 0.5f);
    Matrix result;
    result.M11 = yScale / aspectRatio;
    result.M22 = yScale;
    setPerspectiveDepth(result, nearPlaneDistance, farPlaneDistance);
    return result;
}

Matrix Matrix::CreatePerspective(float width, float height, float nearPlaneDistance,
                                 float farPlaneDistance) {
    checkNearFar(nearPlaneDistance, farPlaneDistance);
    Matrix result;
    result.M11 = 2.0f * nearPlaneDistance / width;
    result.M22 = 2.0f * nearPlaneDistance / height;
    setPerspectiveDepth(result, nearPlaneDistance, farPlaneDistance);
    return result;
}

Matrix Matrix::CreatePerspectiveOffCenter(float left, float right, float bottom, float top,
                                          float nearPlaneDistance, float farPlaneDistance) {
    checkNearFar(nearPlaneDistance, farPlaneDistance);
    Matrix result;
    result.M11 = 2.0f * nearPlaneDistance / (right - left);
    result.M22 = 2.0f * nearPlaneDistance / (top - bottom);
    result.M31 = (left + right) / (right - left);
    result.M32 = (top + bottom) / (top - bottom);
    setPerspectiveDepth(result, nearPlaneDistance, farPlaneDistance);
    return result;
}

Matrix Matrix::CreateOrthographic(float width, float height, float zNearPlane, float zFarPlane) {
    Matrix result;
    result.M11 = 2.0f / width;
    result.M22 = 2.0f / height;
    result.M33 = 1.0f / (zNearPlane - zFarPlane);
    result.M43 = zNearPlane / (zNearPlane - zFarPlane);
    result.M44 = 1.0f;
    return result;
}

Matrix Matrix::CreateOrthographicOffCenter(float left, float right, float bottom, float top,
                                           float zNearPlane, float zFarPlane) {
    // z' = (z + zNear) / (zNear - zFar): 0 at z = -zNear, 1 at z = -zFar.
    Matrix result;
    result.M11 = 2.0f / (right - left);
    result.M22 = 2.0f / (top - bottom);
    result.M33 = 1.0f / (zNearPlane - zFarPlane);
    result.M41 = (left + right) / (left - right);
    result.M42 = (top + bottom) / (bottom - top);
    result.M43 = zNearPlane / (zNearPlane - zFarPlane);
    result.M44 = 1.0f;
    return result;
}


Matrix Matrix::CreateConstrainedBillboard(Vector3 objectPosition, Vector3 cameraPosition, Vector3 rotateAxis,
                                          std::optional<Vector3> cameraForwardVector,
                                          std::optional<Vector3> objectForwardVector) {
    // XNA's threshold: within about 3.4 degrees of the axis, the camera direction gives no facing.
    constexpr float kNearlyParallel = 0.9982547f;
    Vector3 toObject = objectPosition - cameraPosition;
    const float distanceSquared = toObject.LengthSquared();
    if (distanceSquared < 0.0001f) toObject = cameraForwardVector ? -*cameraForwardVector : Vector3::Forward;
    else toObject = toObject * (1.0f / std::sqrt(distanceSquared));
    Vector3 right, backward;
    if (std::fabs(Vector3::Dot(rotateAxis, toObject)) > kNearlyParallel) {
        Vector3 facing = objectForwardVector ? *objectForwardVector : Vector3::Forward;
        if (std::fabs(Vector3::Dot(rotateAxis, facing)) > kNearlyParallel)
            facing = std::fabs(Vector3::Dot(rotateAxis, Vector3::Forward)) > kNearlyParallel ? Vector3::Right
                                                                                             : Vector3::Forward;
        right = Vector3::Normalize(Vector3::Cross(rotateAxis, facing));
        backward = Vector3::Normalize(Vector3::Cross(right, rotateAxis));
    } else {
        right = Vector3::Normalize(Vector3::Cross(rotateAxis, toObject));
        backward = Vector3::Normalize(Vector3::Cross(right, rotateAxis));
    }
    return {right.X,          right.Y,          right.Z,          0.0f,
            rotateAxis.X,     rotateAxis.Y,     rotateAxis.Z,     0.0f,
            backward.X,       backward.Y,       backward.Z,       0.0f,
            objectPosition.X, objectPosition.Y, objectPosition.Z, 1.0f};
}

Matrix Matrix::CreateReflection(const Plane& value) {
    const Plane p = Plane::Normalize(value);
    const float x = p.Normal.X, y = p.Normal.Y, z = p.Normal.Z;
    const float a = -2.0f * x, b = -2.0f * y, c = -2.0f * z;
    return {a * x + 1.0f, b * x,        c * x,        0.0f,
            a * y,        b * y + 1.0f, c * y,        0.0f,
            a * z,        b * z,        c * z + 1.0f, 0.0f,
            a * p.D,      b * p.D,      c * p.D,      1.0f};
}

Matrix Matrix::CreateShadow(Vector3 lightDirection, const Plane& plane) {
    const Plane p = Plane::Normalize(plane);
    const float dot = Vector3::Dot(p.Normal, lightDirection);
    const float a = -p.Normal.X, b = -p.Normal.Y, c = -p.Normal.Z, d = -p.D;
    const Vector3 l = lightDirection;
    return {a * l.X + dot, a * l.Y,       a * l.Z,       0.0f,
            b * l.X,       b * l.Y + dot, b * l.Z,       0.0f,
            c * l.X,       c * l.Y,       c * l.Z + dot, 0.0f,
            d * l.X,       d * l.Y,       d * l.Z,       dot};
}

Matrix Matrix::Transform(const Matrix& value, const Quaternion& rotation) {
    return value * CreateFromQuaternion(rotation);
}

Matrix Matrix::Divide(const Matrix& a, const Matrix& b) {
    Matrix r;
    for (int i = 0; i < 16; ++i) r.data()[i] = a.data()[i] / b.data()[i];
    return r;
}

Matrix Matrix::Divide(const Matrix& matrix, float divider) { return Multiply(matrix, 1.0f / divider); }

}  // namespace fxport
