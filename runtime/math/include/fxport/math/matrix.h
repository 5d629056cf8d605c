// Matrix: XNA's 4x4 float matrix, with XNA's conventions throughout.
//
//  * Row vectors: a point is transformed as v' = v * M, so the translation sits in the fourth row
//    (M41, M42, M43) and a * b means "apply a, then b":
//        Vector3::Transform(v, a * b) == Vector3::Transform(Vector3::Transform(v, a), b)
//    World * View * Projection reads in the order the transforms happen.
//  * Memory order M11, M12, M13, M14, M21, ... (64 bytes, no padding), exactly XNA's. data() hands
//    those 16 floats out for uploading; how they meet a shader's matrix layout is the runtime's job.
//  * Right-handed view space (the camera looks down -Z) and Direct3D's clip space: projections map
//    view depth onto NDC z in [0, 1], not OpenGL's [-1, 1]. The effects we run were written for D3D
//    and their shaders (and the depth values they read back) expect [0, 1]; the runtime sets
//    glClipControl(..., GL_ZERO_TO_ONE) to match (shared/ARCHITECTURE.md) instead of rewriting
//    every projection.
#pragma once

#include <cstddef>
#include <optional>
#include <type_traits>

#include "fxport/math/quaternion.h"
#include "fxport/math/vector3.h"

namespace fxport {

struct Plane;

struct Matrix {
    float M11 = 0.0f, M12 = 0.0f, M13 = 0.0f, M14 = 0.0f;
    float M21 = 0.0f, M22 = 0.0f, M23 = 0.0f, M24 = 0.0f;
    float M31 = 0.0f, M32 = 0.0f, M33 = 0.0f, M34 = 0.0f;
    float M41 = 0.0f, M42 = 0.0f, M43 = 0.0f, M44 = 0.0f;

    // All zero, as C#'s default(Matrix); use Matrix::Identity for "no transform".
    constexpr Matrix() = default;
    constexpr Matrix(float m11, float m12, float m13, float m14,
                     float m21, float m22, float m23, float m24,
                     float m31, float m32, float m33, float m34,
                     float m41, float m42, float m43, float m44)
        : M11(m11), M12(m12), M13(m13), M14(m14),
          M21(m21), M22(m22), M23(m23), M24(m24),
          M31(m31), M32(m32), M33(m33), M34(m34),
          M41(m41), M42(m42), M43(m43), M44(m44) {}

    static const Matrix Identity;

    // The 16 floats in XNA memory order (row by row). The members are contiguous without padding
    // (checked below), which is what makes reading past M11 valid in practice.
    const float* data() const { return &M11; }
    float* data() { return &M11; }

    // XNA's properties. Rows 1-3 are the transformed axes: Right = +X row, Up = +Y row,
    // Backward = +Z row, Forward = -(third row) since forward is -Z.
    constexpr Vector3 Translation() const { return {M41, M42, M43}; }
    constexpr Vector3 Right() const { return {M11, M12, M13}; }
    constexpr Vector3 Left() const { return {-M11, -M12, -M13}; }
    constexpr Vector3 Up() const { return {M21, M22, M23}; }
    constexpr Vector3 Down() const { return {-M21, -M22, -M23}; }
    constexpr Vector3 Backward() const { return {M31, M32, M33}; }
    constexpr Vector3 Forward() const { return {-M31, -M32, -M33}; }
    constexpr void setTranslation(Vector3 v) { M41 = v.X; M42 = v.Y; M43 = v.Z; }
    constexpr void setRight(Vector3 v) { M11 = v.X; M12 = v.Y; M13 = v.Z; }
    constexpr void setLeft(Vector3 v) { setRight(-v); }
    constexpr void setUp(Vector3 v) { M21 = v.X; M22 = v.Y; M23 = v.Z; }
    constexpr void setDown(Vector3 v) { setUp(-v); }
    constexpr void setBackward(Vector3 v) { M31 = v.X; M32 = v.Y; M33 = v.Z; }
    constexpr void setForward(Vector3 v) { setBackward(-v); }

    float Determinant() const;
    // Splits an affine matrix into scale, rotation and translation (M = S * R * T). Returns false,
    // with rotation = Identity, when the upper 3x3 is not a rotation times a scale (shear, or a
    // scale of zero). A mirroring matrix comes back as a negative scale on its largest axis.
    bool Decompose(Vector3& scale, Quaternion& rotation, Vector3& translation) const;
    static bool Decompose(const Matrix& matrix, Vector3& scale, Quaternion& rotation,
                          Vector3& translation) {
        return matrix.Decompose(scale, rotation, translation);
    }

    static Matrix Multiply(const Matrix& a, const Matrix& b);
    static Matrix Multiply(Matrix matrix, float scale);
    static Matrix Add(Matrix a, const Matrix& b);
    static Matrix Subtract(Matrix a, const Matrix& b);
    static Matrix Negate(Matrix matrix);
    static Matrix Transpose(const Matrix& matrix);
    // A singular matrix yields infinities/NaN, as in XNA.
    static Matrix Invert(const Matrix& matrix);
    static Matrix Lerp(const Matrix& a, const Matrix& b, float amount);

    static Matrix CreateTranslation(Vector3 position);
    static Matrix CreateTranslation(float x, float y, float z);
    static Matrix CreateScale(float scale);
    static Matrix CreateScale(float x, float y, float z);
    static Matrix CreateScale(Vector3 scales);
    // Counter-clockwise rotations when looking down the axis towards the origin, so
    // CreateRotationY(Pi/2) turns +X into -Z (Forward).
    static Matrix CreateRotationX(float radians);
    static Matrix CreateRotationY(float radians);
    static Matrix CreateRotationZ(float radians);
    // axis must be unit length.
    static Matrix CreateFromAxisAngle(Vector3 axis, float angle);
    static Matrix CreateFromQuaternion(Quaternion quaternion);
    // Roll about Z, then pitch about X, then yaw about Y.
    static Matrix CreateFromYawPitchRoll(float yaw, float pitch, float roll);

    // View matrix of a camera at cameraPosition looking at cameraTarget (right-handed: the target
    // ends up on view -Z).
    static Matrix CreateLookAt(Vector3 cameraPosition, Vector3 cameraTarget, Vector3 cameraUpVector);
    // Object-to-world matrix placing an object at position, its Forward() along forward.
    static Matrix CreateWorld(Vector3 position, Vector3 forward, Vector3 up);
    // Spherical billboard at objectPosition facing the camera. cameraForwardVector is used only
    // when the object sits on the camera (XNA's Nullable<Vector3>).
    static Matrix CreateBillboard(Vector3 objectPosition, Vector3 cameraPosition,
                                  Vector3 cameraUpVector,
                                  std::optional<Vector3> cameraForwardVector = std::nullopt);

    // Cylindrical billboard: rotates about rotateAxis only, towards the camera. When the camera (or,
    // with the camera on the object, cameraForwardVector) lies along the axis, objectForwardVector
    // (else Forward, else Right) fixes the facing, as XNA.
    static Matrix CreateConstrainedBillboard(Vector3 objectPosition, Vector3 cameraPosition, Vector3 rotateAxis,
                                             std::optional<Vector3> cameraForwardVector = std::nullopt,
                                             std::optional<Vector3> objectForwardVector = std::nullopt);
    // Mirror through a plane (normalised first).
    static Matrix CreateReflection(const Plane& value);
    // Flattens geometry onto a plane as a shadow cast along lightDirection (the direction towards a
    // directional light; XNA's w = 0 light). The result has M44 = Dot(plane normal, lightDirection):
    // divide by w (Vector4::Transform) for the point on the plane.
    static Matrix CreateShadow(Vector3 lightDirection, const Plane& plane);
    // Rotates a matrix by a quaternion: matrix * CreateFromQuaternion(rotation).
    static Matrix Transform(const Matrix& value, const Quaternion& rotation);
    // Element by element, as XNA.
    static Matrix Divide(const Matrix& a, const Matrix& b);
    static Matrix Divide(const Matrix& matrix, float divider);

    // Projections, Direct3D style: view z = -nearPlaneDistance maps to NDC depth 0 and
    // z = -farPlaneDistance to 1. Like XNA, arguments outside their range (fov not in (0, Pi),
    // near <= 0, far <= 0, near >= far) throw std::out_of_range.
    static Matrix CreatePerspectiveFieldOfView(float fieldOfView, float aspectRatio,
                                               float nearPlaneDistance, float farPlaneDistance);
    static Matrix CreatePerspective(float width, float height, float nearPlaneDistance,
                                    float farPlaneDistance);
    static Matrix CreatePerspectiveOffCenter(float left, float right, float bottom, float top,
                                             float nearPlaneDistance, float farPlaneDistance);
    // Orthographic: view z = -zNearPlane maps to depth 0 and z = -zFarPlane to 1 (no range checks,
    // as XNA).
    static Matrix CreateOrthographic(float width, float height, float zNearPlane, float zFarPlane);
    static Matrix CreateOrthographicOffCenter(float left, float right, float bottom, float top,
                                              float zNearPlane, float zFarPlane);

    Matrix& operator*=(const Matrix& m) { return *this = Multiply(*this, m); }
    Matrix& operator*=(float s) { return *this = Multiply(*this, s); }
    Matrix& operator+=(const Matrix& m) { return *this = Add(*this, m); }
    Matrix& operator-=(const Matrix& m) { return *this = Subtract(*this, m); }
    Matrix& operator/=(const Matrix& m) { return *this = Divide(*this, m); }
    Matrix& operator/=(float d) { return *this = Divide(*this, d); }

    friend constexpr bool operator==(const Matrix&, const Matrix&) = default;
};

inline constexpr Matrix Matrix::Identity{1.0f, 0.0f, 0.0f, 0.0f,
                                         0.0f, 1.0f, 0.0f, 0.0f,
                                         0.0f, 0.0f, 1.0f, 0.0f,
                                         0.0f, 0.0f, 0.0f, 1.0f};

// "a, then b".
inline Matrix operator*(const Matrix& a, const Matrix& b) { return Matrix::Multiply(a, b); }
inline Matrix operator*(const Matrix& m, float s) { return Matrix::Multiply(m, s); }
inline Matrix operator*(float s, const Matrix& m) { return Matrix::Multiply(m, s); }
inline Matrix operator+(const Matrix& a, const Matrix& b) { return Matrix::Add(a, b); }
inline Matrix operator-(const Matrix& a, const Matrix& b) { return Matrix::Subtract(a, b); }
inline Matrix operator-(const Matrix& m) { return Matrix::Negate(m); }
inline Matrix operator/(const Matrix& a, const Matrix& b) { return Matrix::Divide(a, b); }
inline Matrix operator/(const Matrix& m, float d) { return Matrix::Divide(m, d); }

static_assert(sizeof(Matrix) == 64 && std::is_standard_layout_v<Matrix> &&
              std::is_trivially_copyable_v<Matrix>);
static_assert(offsetof(Matrix, M12) == 4 && offsetof(Matrix, M21) == 16 &&
              offsetof(Matrix, M41) == 48 && offsetof(Matrix, M44) == 60);

}  // namespace fxport
