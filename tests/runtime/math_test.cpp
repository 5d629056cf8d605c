// fxport_math against independent expectations: values worked out by hand from XNA's documented
// conventions, GLM's right-handed zero-to-one projections (transposed, since GLM uses column
// vectors), and algebraic identities on random inputs. Comments give the arithmetic.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "fxport/math.h"

namespace fxport {

// gtest prints these in failure messages.
void PrintTo(const Vector2& v, std::ostream* os) { *os << "(" << v.X << ", " << v.Y << ")"; }
void PrintTo(const Vector3& v, std::ostream* os) {
    *os << "(" << v.X << ", " << v.Y << ", " << v.Z << ")";
}
void PrintTo(const Vector4& v, std::ostream* os) {
    *os << "(" << v.X << ", " << v.Y << ", " << v.Z << ", " << v.W << ")";
}
void PrintTo(const Quaternion& q, std::ostream* os) {
    *os << "(" << q.X << ", " << q.Y << ", " << q.Z << ", " << q.W << ")";
}
void PrintTo(const Color& c, std::ostream* os) {
    *os << "(" << int(c.R) << ", " << int(c.G) << ", " << int(c.B) << ", " << int(c.A) << ")";
}
void PrintTo(const Matrix& m, std::ostream* os) {
    for (int i = 0; i < 16; ++i) {
        *os << (i % 4 == 0 ? (i == 0 ? "[" : "; ") : " ") << m.data()[i];
    }
    *os << "]";
}

}  // namespace fxport

namespace {

using namespace fxport;

constexpr float kEps = 1e-5f;

template <typename T>
std::string str(const T& value) {
    std::ostringstream os;
    PrintTo(value, &os);
    return os.str();
}

testing::AssertionResult floatsNear(const float* a, const float* b, int n, float eps,
                                    const std::string& as, const std::string& bs) {
    for (int i = 0; i < n; ++i) {
        if (!(std::fabs(a[i] - b[i]) <= eps)) {
            return testing::AssertionFailure() << as << " != " << bs << " (component " << i
                                               << ", tolerance " << eps << ")";
        }
    }
    return testing::AssertionSuccess();
}

testing::AssertionResult Near(Vector2 a, Vector2 b, float eps = kEps) {
    return floatsNear(&a.X, &b.X, 2, eps, str(a), str(b));
}
testing::AssertionResult Near(Vector3 a, Vector3 b, float eps = kEps) {
    return floatsNear(&a.X, &b.X, 3, eps, str(a), str(b));
}
testing::AssertionResult Near(Vector4 a, Vector4 b, float eps = kEps) {
    return floatsNear(&a.X, &b.X, 4, eps, str(a), str(b));
}
testing::AssertionResult Near(const Matrix& a, const Matrix& b, float eps = kEps) {
    return floatsNear(a.data(), b.data(), 16, eps, str(a), str(b));
}
// q and -q are the same rotation.
testing::AssertionResult SameRotation(Quaternion a, Quaternion b, float eps = kEps) {
    const Quaternion nb = Quaternion::Dot(a, b) < 0.0f ? -b : b;
    return floatsNear(&a.X, &nb.X, 4, eps, str(a), str(b));
}

// GLM builds column-vector matrices; their memory order is XNA's row-vector order of the same
// transform, so the floats compare one to one.
Matrix fromGlm(const glm::mat4& m) {
    Matrix result;
    std::memcpy(result.data(), glm::value_ptr(m), sizeof(Matrix));
    return result;
}

glm::vec3 toGlm(Vector3 v) { return {v.X, v.Y, v.Z}; }

// Clip coordinates after the perspective divide.
Vector3 project(Vector3 position, const Matrix& m) {
    const Vector4 clip = Vector4::Transform(position, m);
    return {clip.X / clip.W, clip.Y / clip.W, clip.Z / clip.W};
}

struct Random {
    std::mt19937 engine{12345};
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(engine); }
    Vector3 vector(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    Vector3 unitVector() {
        Vector3 v;
        do {
            v = vector(-1.0f, 1.0f);
        } while (v.LengthSquared() < 0.01f);
        return Vector3::Normalize(v);
    }
    Quaternion rotation() {
        return Quaternion::CreateFromAxisAngle(unitVector(), uniform(-MathHelper::Pi, MathHelper::Pi));
    }
};

// ---- layout ----------------------------------------------------------------------------------

TEST(MathLayout, MatrixIs16FloatsInXnaRowOrder) {
    static_assert(sizeof(Matrix) == 64);
    static_assert(offsetof(Matrix, M14) == 12 && offsetof(Matrix, M41) == 48);
    const Matrix m(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    for (int i = 0; i < 16; ++i) {
        EXPECT_EQ(m.data()[i], float(i + 1)) << "float " << i;
    }
    EXPECT_EQ(Matrix(), Matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0));
}

TEST(MathLayout, VectorsAndColorArePackedForVertexBuffers) {
    EXPECT_EQ(sizeof(Vector2), 8u);
    EXPECT_EQ(sizeof(Vector3), 12u);
    EXPECT_EQ(sizeof(Vector4), 16u);
    EXPECT_EQ(sizeof(Color), 4u);
    const Color c(1, 2, 3, 4);
    unsigned char bytes[4];
    std::memcpy(bytes, &c, 4);
    EXPECT_EQ(bytes[0], 1);  // R first in memory: GL_RGBA / GL_UNSIGNED_BYTE
    EXPECT_EQ(bytes[3], 4);
}

// ---- MathHelper ------------------------------------------------------------------------------

TEST(MathHelper, ConstantsAndAngleConversion) {
    EXPECT_EQ(MathHelper::Pi, static_cast<float>(3.14159265358979323846));
    EXPECT_EQ(MathHelper::PiOver2 * 2.0f, MathHelper::Pi);
    EXPECT_EQ(MathHelper::TwoPi, 2.0f * MathHelper::Pi);
    EXPECT_EQ(MathHelper::ToRadians(180.0f), MathHelper::Pi);
    EXPECT_FLOAT_EQ(MathHelper::ToDegrees(MathHelper::PiOver4), 45.0f);
    EXPECT_FLOAT_EQ(MathHelper::E, std::exp(1.0f));
}

TEST(MathHelper, ClampLerpSmoothStep) {
    EXPECT_EQ(MathHelper::Clamp(5.0f, 0.0f, 1.0f), 1.0f);
    EXPECT_EQ(MathHelper::Clamp(-5.0f, 0.0f, 1.0f), 0.0f);
    EXPECT_EQ(MathHelper::Clamp(0.25f, 0.0f, 1.0f), 0.25f);
    EXPECT_EQ(MathHelper::Lerp(10.0f, 20.0f, 0.25f), 12.5f);
    EXPECT_EQ(MathHelper::Lerp(10.0f, 20.0f, 2.0f), 30.0f);  // not clamped
    // t = 0.25: t²(3 - 2t) = 0.0625 * 2.5 = 0.15625
    EXPECT_FLOAT_EQ(MathHelper::SmoothStep(0.0f, 10.0f, 0.25f), 1.5625f);
    EXPECT_EQ(MathHelper::SmoothStep(0.0f, 10.0f, 7.0f), 10.0f);  // clamped
    EXPECT_EQ(MathHelper::Min(2.0f, 3.0f), 2.0f);
    EXPECT_EQ(MathHelper::Max(2.0f, 3.0f), 3.0f);
    EXPECT_EQ(MathHelper::Distance(2.0f, -3.0f), 5.0f);
    EXPECT_EQ(MathHelper::Barycentric(1.0f, 3.0f, 5.0f, 0.5f, 0.25f), 1.0f + 1.0f + 1.0f);
}

TEST(MathHelper, WrapAngleIntoMinusPiPi) {
    EXPECT_NEAR(MathHelper::WrapAngle(1.5f * MathHelper::Pi), -0.5f * MathHelper::Pi, kEps);
    EXPECT_NEAR(MathHelper::WrapAngle(3.0f * MathHelper::TwoPi + 1.0f), 1.0f, 1e-5f);
    EXPECT_NEAR(MathHelper::WrapAngle(-1.25f * MathHelper::Pi), 0.75f * MathHelper::Pi, kEps);
    EXPECT_EQ(MathHelper::WrapAngle(MathHelper::Pi), MathHelper::Pi);
    EXPECT_EQ(MathHelper::WrapAngle(-MathHelper::Pi), MathHelper::Pi);  // the interval is (-Pi, Pi]
    EXPECT_EQ(MathHelper::WrapAngle(0.5f), 0.5f);
}

// ---- vectors ---------------------------------------------------------------------------------

TEST(Vector, NamedVectorsFollowXnaRightHandedAxes) {
    EXPECT_EQ(Vector3::Forward, Vector3(0, 0, -1));
    EXPECT_EQ(Vector3::Backward, Vector3(0, 0, 1));
    EXPECT_EQ(Vector3::Up, Vector3(0, 1, 0));
    EXPECT_EQ(Vector3::Down, Vector3(0, -1, 0));
    EXPECT_EQ(Vector3::Right, Vector3(1, 0, 0));
    EXPECT_EQ(Vector3::Left, Vector3(-1, 0, 0));
    EXPECT_EQ(Vector3::One, Vector3(1.0f));
    EXPECT_EQ(Vector3(), Vector3::Zero);
    EXPECT_EQ(Vector4::UnitW, Vector4(0, 0, 0, 1));
    EXPECT_EQ(Vector4(Vector3(1, 2, 3), 4), Vector4(1, 2, 3, 4));
    EXPECT_EQ(Vector3(Vector2(1, 2), 3), Vector3(1, 2, 3));
}

TEST(Vector, Arithmetic) {
    const Vector3 a(1, 2, 3), b(4, 5, 6);
    EXPECT_EQ(a + b, Vector3(5, 7, 9));
    EXPECT_EQ(b - a, Vector3(3, 3, 3));
    EXPECT_EQ(a * b, Vector3(4, 10, 18));
    EXPECT_EQ(a * 2.0f, Vector3(2, 4, 6));
    EXPECT_EQ(2.0f * a, Vector3(2, 4, 6));
    EXPECT_EQ(b / a, Vector3(4, 2.5f, 2));
    EXPECT_EQ(Vector3(2, 4, 8) / 2.0f, Vector3(1, 2, 4));
    EXPECT_EQ(-a, Vector3(-1, -2, -3));
    EXPECT_NE(a, b);
    Vector3 c = a;
    c += b;
    c *= 0.5f;
    EXPECT_EQ(c, Vector3(2.5f, 3.5f, 4.5f));
    EXPECT_EQ(Vector2(1, 2) + Vector2(3, 4), Vector2(4, 6));
    EXPECT_EQ(Vector4(1, 2, 3, 4) * 2.0f, Vector4(2, 4, 6, 8));
}

TEST(Vector, DotCrossLengthNormalize) {
    EXPECT_EQ(Vector3::Dot({1, 2, 3}, {4, 5, 6}), 32.0f);
    EXPECT_EQ(Vector3::Cross(Vector3::UnitX, Vector3::UnitY), Vector3::UnitZ);  // right-handed
    EXPECT_EQ(Vector3::Cross({1, 2, 3}, {4, 5, 6}), Vector3(-3, 6, -3));
    EXPECT_EQ(Vector3(3, 4, 0).Length(), 5.0f);
    EXPECT_EQ(Vector3(3, 4, 0).LengthSquared(), 25.0f);
    Vector3 v(3, 4, 0);
    const Vector3 n = Vector3::Normalize(v);
    EXPECT_EQ(v, Vector3(3, 4, 0));  // the static one leaves its argument alone
    EXPECT_TRUE(Near(n, {0.6f, 0.8f, 0.0f}));
    v.Normalize();
    EXPECT_TRUE(Near(v, {0.6f, 0.8f, 0.0f}));
    EXPECT_NEAR(Vector4::Normalize({1, 1, 1, 1}).X, 0.5f, kEps);
    EXPECT_EQ(Vector2::Dot({1, 2}, {3, 4}), 11.0f);
}

TEST(Vector, DistanceLerpMinMaxClampReflect) {
    EXPECT_EQ(Vector3::Distance({1, 1, 1}, {1, 4, 5}), 5.0f);
    EXPECT_EQ(Vector3::DistanceSquared({1, 1, 1}, {1, 4, 5}), 25.0f);
    EXPECT_EQ(Vector3::Lerp({0, 10, 20}, {10, 20, 40}, 0.5f), Vector3(5, 15, 30));
    EXPECT_EQ(Vector3::Min({1, 5, 3}, {4, 2, 6}), Vector3(1, 2, 3));
    EXPECT_EQ(Vector3::Max({1, 5, 3}, {4, 2, 6}), Vector3(4, 5, 6));
    EXPECT_EQ(Vector3::Clamp({-1, 0.5f, 9}, Vector3::Zero, Vector3::One), Vector3(0, 0.5f, 1));
    // A ball falling at 45 degrees onto the ground bounces up at 45 degrees.
    EXPECT_EQ(Vector3::Reflect({1, -1, 0}, Vector3::Up), Vector3(1, 1, 0));
    EXPECT_EQ(Vector2::Reflect({1, -1}, Vector2::UnitY), Vector2(1, 1));
}

// ---- matrix: basics --------------------------------------------------------------------------

TEST(Matrix, MultiplyIsTheRowMajorProduct) {
    const Matrix m(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    EXPECT_EQ(m * Matrix::Identity, m);
    EXPECT_EQ(Matrix::Identity * m, m);
    const Matrix p = m * m;
    EXPECT_EQ(p.M11, 90.0f);   // 1*1 + 2*5 + 3*9 + 4*13
    EXPECT_EQ(p.M12, 100.0f);  // 1*2 + 2*6 + 3*10 + 4*14
    EXPECT_EQ(p.M21, 202.0f);  // 5*1 + 6*5 + 7*9 + 8*13
    EXPECT_EQ(p.M44, 600.0f);  // 13*4 + 14*8 + 15*12 + 16*16
    EXPECT_EQ(Matrix::Transpose(m).M12, 5.0f);
    EXPECT_EQ(Matrix::Transpose(m).M41, 4.0f);
    EXPECT_EQ((m + m).M23, 14.0f);
    EXPECT_EQ((m - m), Matrix());
    EXPECT_EQ((m * 2.0f).M44, 32.0f);
    EXPECT_EQ(Matrix::Lerp(Matrix(), m, 0.5f).M34, 6.0f);
}

TEST(Matrix, ProductMeansFirstThenSecond) {
    const Matrix rotate = Matrix::CreateRotationY(MathHelper::PiOver2);
    const Matrix move = Matrix::CreateTranslation(10, 0, 0);
    // Rotate (1,0,0) to (0,0,-1), then move: (10, 0, -1).
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitX, rotate * move), {10, 0, -1}));
    // Move to (11,0,0), then rotate about the origin: (0, 0, -11).
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitX, move * rotate), {0, 0, -11}, 1e-5f * 11));

    Random random;
    for (int i = 0; i < 20; ++i) {
        const Matrix a = Matrix::CreateScale(random.vector(0.5f, 2.0f)) *
                         Matrix::CreateFromQuaternion(random.rotation()) *
                         Matrix::CreateTranslation(random.vector(-5, 5));
        const Matrix b = Matrix::CreateFromQuaternion(random.rotation()) *
                         Matrix::CreateTranslation(random.vector(-5, 5));
        const Vector3 v = random.vector(-3, 3);
        EXPECT_TRUE(Near(Vector3::Transform(v, a * b),
                         Vector3::Transform(Vector3::Transform(v, a), b), 1e-4f));
    }
}

TEST(Matrix, TranslationScaleAndProperties) {
    const Matrix t = Matrix::CreateTranslation({1, 2, 3});
    EXPECT_EQ(t.M41, 1.0f);
    EXPECT_EQ(t.M43, 3.0f);
    EXPECT_EQ(t.Translation(), Vector3(1, 2, 3));
    EXPECT_EQ(Vector3::Transform({1, 1, 1}, t), Vector3(2, 3, 4));
    EXPECT_EQ(Vector3::TransformNormal({1, 1, 1}, t), Vector3(1, 1, 1));  // w = 0: no translation
    EXPECT_EQ(Vector2::Transform({1, 1}, t), Vector2(2, 3));
    EXPECT_EQ(Vector2::TransformNormal({1, 1}, t), Vector2(1, 1));
    EXPECT_TRUE(Near(Vector2::Transform({1, 0}, Matrix::CreateRotationZ(MathHelper::PiOver2)), {0, 1}));
    EXPECT_EQ(Vector4::Transform(Vector4(1, 1, 1, 0), t), Vector4(1, 1, 1, 0));
    EXPECT_EQ(Vector3::Transform({1, 1, 1}, Matrix::CreateScale(2, 3, 4)), Vector3(2, 3, 4));
    EXPECT_EQ(Matrix::CreateScale(2.0f), Matrix::CreateScale(Vector3(2.0f)));

    EXPECT_EQ(Matrix::Identity.Forward(), Vector3::Forward);
    EXPECT_EQ(Matrix::Identity.Backward(), Vector3::Backward);
    EXPECT_EQ(Matrix::Identity.Up(), Vector3::Up);
    EXPECT_EQ(Matrix::Identity.Right(), Vector3::Right);
    EXPECT_EQ(Matrix::Identity.Left(), Vector3::Left);
    EXPECT_EQ(Matrix::Identity.Down(), Vector3::Down);
    Matrix m = Matrix::Identity;
    m.setTranslation({4, 5, 6});
    m.setForward({0, 0, 1});
    EXPECT_EQ(m.M41, 4.0f);
    EXPECT_EQ(m.M33, -1.0f);  // Forward is the negated third row
}

TEST(Matrix, RotationsFollowXnaSigns) {
    const float h = MathHelper::PiOver2;
    // Counter-clockwise looking down each axis towards the origin.
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitX, Matrix::CreateRotationY(h)), {0, 0, -1}));
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitY, Matrix::CreateRotationX(h)), {0, 0, 1}));
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitZ, Matrix::CreateRotationX(h)), {0, -1, 0}));
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitX, Matrix::CreateRotationZ(h)), {0, 1, 0}));
    // Element placement, XNA's CreateRotationY: M13 = -sin, M31 = +sin.
    const Matrix y = Matrix::CreateRotationY(0.3f);
    EXPECT_EQ(y.M11, std::cos(0.3f));
    EXPECT_EQ(y.M13, -std::sin(0.3f));
    EXPECT_EQ(y.M31, std::sin(0.3f));
    EXPECT_EQ(y.M22, 1.0f);
    EXPECT_EQ(Matrix::CreateRotationX(0.3f).M23, std::sin(0.3f));
    EXPECT_EQ(Matrix::CreateRotationZ(0.3f).M12, std::sin(0.3f));
}

TEST(Matrix, FromAxisAngleMatchesGlmAndAxisRotations) {
    EXPECT_TRUE(Near(Matrix::CreateFromAxisAngle(Vector3::UnitY, 0.7f), Matrix::CreateRotationY(0.7f)));
    EXPECT_TRUE(Near(Matrix::CreateFromAxisAngle(Vector3::UnitX, -1.2f), Matrix::CreateRotationX(-1.2f)));
    Random random;
    for (int i = 0; i < 10; ++i) {
        const Vector3 axis = random.unitVector();
        const float angle = random.uniform(-3, 3);
        EXPECT_TRUE(Near(Matrix::CreateFromAxisAngle(axis, angle),
                         fromGlm(glm::rotate(glm::mat4(1.0f), angle, toGlm(axis)))));
    }
}

TEST(Matrix, DeterminantAndTranspose) {
    EXPECT_EQ(Matrix::CreateScale(2, 3, 4).Determinant(), 24.0f);
    EXPECT_NEAR(Matrix::CreateRotationZ(0.4f).Determinant(), 1.0f, kEps);
    EXPECT_EQ(Matrix(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16).Determinant(), 0.0f);
    // Swapping two rows flips the sign.
    EXPECT_EQ(Matrix(0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1).Determinant(), -1.0f);
    // 2x2 block [[1, 2], [3, 4]] (det -2) times diag(5, 6) (det 30).
    EXPECT_EQ(Matrix(1, 2, 0, 0, 3, 4, 0, 0, 0, 0, 5, 0, 0, 0, 0, 6).Determinant(), -60.0f);
}

// ---- matrix: inverse and decomposition -------------------------------------------------------

TEST(Matrix, InvertTimesMatrixIsIdentity) {
    Random random;
    for (int i = 0; i < 50; ++i) {
        Matrix m;
        for (int k = 0; k < 16; ++k) {
            m.data()[k] = random.uniform(-1, 1);
        }
        m += Matrix::Identity * 3.0f;  // diagonally dominant: well conditioned
        const Matrix inverse = Matrix::Invert(m);
        EXPECT_TRUE(Near(inverse * m, Matrix::Identity, 1e-5f)) << "matrix " << i;
        EXPECT_TRUE(Near(m * inverse, Matrix::Identity, 1e-5f)) << "matrix " << i;
    }
    // Hand-computed: the inverse of a translation moves back, of a scale divides.
    EXPECT_TRUE(Near(Matrix::Invert(Matrix::CreateTranslation(1, -2, 3)), Matrix::CreateTranslation(-1, 2, -3)));
    EXPECT_TRUE(Near(Matrix::Invert(Matrix::CreateScale(2, 4, 8)), Matrix::CreateScale(0.5f, 0.25f, 0.125f)));
    // A view matrix's inverse is the camera's world matrix: its translation is the camera position.
    const Matrix view = Matrix::CreateLookAt({3, 4, 5}, {0, 1, 0}, Vector3::Up);
    EXPECT_TRUE(Near(Matrix::Invert(view).Translation(), {3, 4, 5}, 1e-5f));
}

TEST(Matrix, DecomposeRoundTripsScaleRotationTranslation) {
    const Quaternion rotation = Quaternion::CreateFromAxisAngle(Vector3::Normalize({1, 2, 3}), 0.8f);
    const Matrix m = Matrix::CreateScale(2, 3, 4) * Matrix::CreateFromQuaternion(rotation) *
                     Matrix::CreateTranslation(5, -6, 7);
    Vector3 s, t;
    Quaternion r;
    ASSERT_TRUE(m.Decompose(s, r, t));
    EXPECT_TRUE(Near(s, {2, 3, 4}, 1e-5f));
    EXPECT_TRUE(SameRotation(r, rotation));
    EXPECT_EQ(t, Vector3(5, -6, 7));

    Random random;
    for (int i = 0; i < 30; ++i) {
        const Vector3 scale = random.vector(0.2f, 5.0f);
        const Quaternion q = random.rotation();
        const Vector3 position = random.vector(-10, 10);
        const Matrix world = Matrix::CreateScale(scale) * Matrix::CreateFromQuaternion(q) *
                             Matrix::CreateTranslation(position);
        ASSERT_TRUE(Matrix::Decompose(world, s, r, t)) << "matrix " << i;
        EXPECT_TRUE(Near(s, scale, 1e-4f));
        EXPECT_TRUE(SameRotation(r, q, 1e-4f));
        EXPECT_TRUE(Near(t, position, 0.0f));
    }
}

TEST(Matrix, DecomposeMirrorShearAndZeroScale) {
    // A mirror: the negative scale lands on the longest axis (z, length 4) and the product still
    // rebuilds the matrix.
    const Matrix mirror = Matrix::CreateScale(-2, 3, 4) * Matrix::CreateRotationY(0.5f);
    Vector3 s, t;
    Quaternion r;
    ASSERT_TRUE(mirror.Decompose(s, r, t));
    EXPECT_TRUE(Near(s, {2, 3, -4}, 1e-5f));
    EXPECT_TRUE(Near(Matrix::CreateScale(s) * Matrix::CreateFromQuaternion(r), mirror, 1e-5f));

    // Shear is not scale * rotation.
    Matrix shear = Matrix::Identity;
    shear.M21 = 1.0f;
    EXPECT_FALSE(shear.Decompose(s, r, t));
    EXPECT_EQ(r, Quaternion::Identity);

    // A flattened axis keeps a scale of 0 and a valid rotation.
    ASSERT_TRUE(Matrix::CreateScale(0, 1, 1).Decompose(s, r, t));
    EXPECT_EQ(s, Vector3(0, 1, 1));
    EXPECT_TRUE(SameRotation(r, Quaternion::Identity));
}

// ---- matrix: camera and projections ----------------------------------------------------------

TEST(Matrix, LookAtPutsTheTargetOnMinusZ) {
    const Matrix view = Matrix::CreateLookAt({0, 0, 5}, Vector3::Zero, Vector3::Up);
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::Zero, view), {0, 0, -5}));
    EXPECT_TRUE(Near(view, Matrix::CreateTranslation(0, 0, -5)));
    // Camera on +X looking at the origin: world -Z is on the camera's right, world up stays up.
    const Matrix side = Matrix::CreateLookAt({10, 0, 0}, Vector3::Zero, Vector3::Up);
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::Zero, side), {0, 0, -10}));
    EXPECT_TRUE(Near(Vector3::Transform({10, 1, 0}, side), {0, 1, 0}));
    EXPECT_TRUE(Near(Vector3::Transform({0, 0, -1}, side), {1, 0, -10}));
    // Same as GLM's right-handed lookAt.
    Random random;
    for (int i = 0; i < 10; ++i) {
        const Vector3 eye = random.vector(-10, 10), target = random.vector(-1, 1);
        EXPECT_TRUE(Near(Matrix::CreateLookAt(eye, target, Vector3::Up),
                         fromGlm(glm::lookAtRH(toGlm(eye), toGlm(target), glm::vec3(0, 1, 0))),
                         1e-5f));
    }
}

TEST(Matrix, PerspectiveFieldOfViewMapsDepthToZeroOne) {
    const float fov = MathHelper::PiOver4, aspect = 16.0f / 9.0f, nearPlane = 0.5f, farPlane = 200.0f;
    const Matrix p = Matrix::CreatePerspectiveFieldOfView(fov, aspect, nearPlane, farPlane);
    EXPECT_NEAR(project({0, 0, -nearPlane}, p).Z, 0.0f, 1e-6f);
    EXPECT_NEAR(project({0, 0, -farPlane}, p).Z, 1.0f, 1e-6f);
    EXPECT_EQ(Vector4::Transform(Vector3(0, 0, -7), p).W, 7.0f);  // clip w = view distance
    EXPECT_EQ(p.M34, -1.0f);
    EXPECT_EQ(p.M44, 0.0f);
    // The frustum's edges at distance d: half-height d * tan(fov / 2), half-width aspect times that.
    const float d = 10.0f, halfHeight = d * std::tan(fov / 2);
    EXPECT_TRUE(Near(project({aspect * halfHeight, halfHeight, -d}, p),
                     {1, 1, project({0, 0, -d}, p).Z}, 1e-5f));
    const float depth = project({0, 0, -d}, p).Z;
    EXPECT_GT(depth, 0.0f);
    EXPECT_LT(depth, 1.0f);
    EXPECT_TRUE(Near(p, fromGlm(glm::perspectiveRH_ZO(fov, aspect, nearPlane, farPlane)), 1e-6f));
}

TEST(Matrix, PerspectiveRejectsBadArgumentsLikeXna) {
    EXPECT_THROW(Matrix::CreatePerspectiveFieldOfView(0.0f, 1, 1, 10), std::out_of_range);
    EXPECT_THROW(Matrix::CreatePerspectiveFieldOfView(MathHelper::Pi, 1, 1, 10), std::out_of_range);
    EXPECT_THROW(Matrix::CreatePerspectiveFieldOfView(1, 1, 0, 10), std::out_of_range);
    EXPECT_THROW(Matrix::CreatePerspectiveFieldOfView(1, 1, 10, 10), std::out_of_range);
    EXPECT_THROW(Matrix::CreatePerspective(1, 1, 1, -10), std::out_of_range);
    EXPECT_THROW(Matrix::CreatePerspectiveOffCenter(-1, 1, -1, 1, 5, 1), std::out_of_range);
    EXPECT_NO_THROW(Matrix::CreatePerspectiveFieldOfView(1, 1, 0.1f, 10));
}

TEST(Matrix, PerspectiveAndOffCenterMapTheNearRectangle) {
    // CreatePerspective: the near plane's width x height rectangle fills NDC.
    const Matrix p = Matrix::CreatePerspective(4, 2, 1, 100);
    EXPECT_TRUE(Near(project({2, 1, -1}, p), {1, 1, 0}));
    EXPECT_TRUE(Near(project({-200, -100, -100}, p), {-1, -1, 1}, 1e-5f));
    const Matrix off = Matrix::CreatePerspectiveOffCenter(-1, 3, 0, 2, 1, 50);
    EXPECT_TRUE(Near(project({3, 2, -1}, off), {1, 1, 0}));
    EXPECT_TRUE(Near(project({-1, 0, -1}, off), {-1, -1, 0}));
    EXPECT_TRUE(Near(project({-50, 0, -50}, off), {-1, -1, 1}, 1e-5f));
    EXPECT_TRUE(Near(off, fromGlm(glm::frustumRH_ZO(-1.0f, 3.0f, 0.0f, 2.0f, 1.0f, 50.0f)), 1e-6f));
}

TEST(Matrix, OrthographicMapsDepthToZeroOne) {
    const Matrix o = Matrix::CreateOrthographic(800, 600, 1, 101);
    EXPECT_TRUE(Near(Vector3::Transform({400, 300, -1}, o), {1, 1, 0}));
    EXPECT_TRUE(Near(Vector3::Transform({-400, -300, -101}, o), {-1, -1, 1}));
    EXPECT_TRUE(Near(Vector3::Transform({0, 0, -51}, o), {0, 0, 0.5f}));
    // SpriteBatch's projection: pixel (0,0) is the top-left corner, y grows downwards.
    const Matrix screen = Matrix::CreateOrthographicOffCenter(0, 800, 600, 0, 0, 1);
    EXPECT_TRUE(Near(Vector3::Transform({0, 0, 0}, screen), {-1, 1, 0}));
    EXPECT_TRUE(Near(Vector3::Transform({800, 600, 0}, screen), {1, -1, 0}));
    EXPECT_TRUE(Near(Vector3::Transform({400, 300, -1}, screen), {0, 0, 1}));
    EXPECT_TRUE(Near(screen, fromGlm(glm::orthoRH_ZO(0.0f, 800.0f, 600.0f, 0.0f, 0.0f, 1.0f)), 1e-6f));
}

TEST(Matrix, CreateWorldAndBillboard) {
    EXPECT_TRUE(Near(Matrix::CreateWorld(Vector3::Zero, Vector3::Forward, Vector3::Up), Matrix::Identity));
    const Matrix w = Matrix::CreateWorld({1, 2, 3}, {1, 0, 0}, Vector3::Up);
    EXPECT_TRUE(Near(w.Forward(), {1, 0, 0}));
    EXPECT_TRUE(Near(w.Up(), {0, 1, 0}));
    EXPECT_TRUE(Near(w.Right(), {0, 0, 1}));  // facing +X, the right hand points to +Z
    EXPECT_EQ(w.Translation(), Vector3(1, 2, 3));
    // The object's local Forward axis is carried onto the world forward.
    EXPECT_TRUE(Near(Vector3::TransformNormal(Vector3::Forward, w), {1, 0, 0}));
    // A billboard's +Z row (Backward) points from the camera to the object (XNA's formula) ...
    const Matrix b = Matrix::CreateBillboard({0, 0, -10}, Vector3::Zero, Vector3::Up);
    EXPECT_TRUE(Near(b.Backward(), {0, 0, -1}));
    EXPECT_EQ(b.Translation(), Vector3(0, 0, -10));
    // ... and falls back on the camera's forward when the two coincide.
    const Matrix same = Matrix::CreateBillboard(Vector3::Zero, Vector3::Zero, Vector3::Up, Vector3::Right);
    EXPECT_TRUE(Near(same.Backward(), Vector3::Left));
}

// ---- quaternion ------------------------------------------------------------------------------

TEST(Quaternion, HamiltonProductAndComposition) {
    const Quaternion i(1, 0, 0, 0), j(0, 1, 0, 0), k(0, 0, 1, 0);
    EXPECT_EQ(i * j, k);
    EXPECT_EQ(j * i, -k);
    EXPECT_EQ(i * i, Quaternion(0, 0, 0, -1));
    EXPECT_EQ(Quaternion::Identity * k, k);
    Random random;
    for (int n = 0; n < 10; ++n) {
        const Quaternion a = random.rotation(), b = random.rotation();
        // a * b as rotations of row vectors: b first, then a.
        EXPECT_TRUE(Near(Matrix::CreateFromQuaternion(a * b),
                         Matrix::CreateFromQuaternion(b) * Matrix::CreateFromQuaternion(a), 1e-5f));
        EXPECT_TRUE(Near(Matrix::CreateFromQuaternion(Quaternion::Concatenate(a, b)),
                         Matrix::CreateFromQuaternion(a) * Matrix::CreateFromQuaternion(b), 1e-5f));
    }
}

TEST(Quaternion, AgreesWithMatrixRotations) {
    const Quaternion y = Quaternion::CreateFromAxisAngle(Vector3::Up, MathHelper::PiOver2);
    EXPECT_NEAR(y.Y, std::sqrt(0.5f), kEps);
    EXPECT_NEAR(y.W, std::sqrt(0.5f), kEps);
    EXPECT_TRUE(Near(Matrix::CreateFromQuaternion(y), Matrix::CreateRotationY(MathHelper::PiOver2)));
    EXPECT_TRUE(Near(Vector3::Transform(Vector3::UnitX, y), {0, 0, -1}));
    EXPECT_TRUE(Near(Matrix::CreateFromQuaternion(Quaternion::Identity), Matrix::Identity, 0.0f));
    Random random;
    for (int n = 0; n < 20; ++n) {
        const Vector3 axis = random.unitVector();
        const float angle = random.uniform(-3, 3);
        const Quaternion q = Quaternion::CreateFromAxisAngle(axis, angle);
        const Matrix m = Matrix::CreateFromAxisAngle(axis, angle);
        EXPECT_TRUE(Near(Matrix::CreateFromQuaternion(q), m, 1e-5f));
        const Vector3 v = random.vector(-2, 2);
        EXPECT_TRUE(Near(Vector3::Transform(v, q), Vector3::Transform(v, m), 1e-5f));
        EXPECT_NEAR(q.Length(), 1.0f, kEps);
    }
}

TEST(Quaternion, FromRotationMatrixRoundTripsOnEveryBranch) {
    // Angles near Pi make the trace negative, reaching the x-, y- and z-dominant branches.
    const Vector3 axes[] = {Vector3::UnitX, Vector3::UnitY, Vector3::UnitZ, Vector3::Normalize({1, 1, 1})};
    for (const Vector3 axis : axes) {
        for (const float angle : {0.3f, 2.0f, 3.1f, -3.1f}) {
            const Quaternion q = Quaternion::CreateFromAxisAngle(axis, angle);
            EXPECT_TRUE(SameRotation(Quaternion::CreateFromRotationMatrix(Matrix::CreateFromQuaternion(q)), q))
                << str(axis) << " " << angle;
        }
    }
    EXPECT_TRUE(SameRotation(Quaternion::CreateFromRotationMatrix(Matrix::CreateRotationZ(1.0f)),
                             Quaternion::CreateFromAxisAngle(Vector3::UnitZ, 1.0f)));
}

TEST(Quaternion, YawPitchRollIsRollThenPitchThenYaw) {
    const float yaw = 0.7f, pitch = -0.4f, roll = 1.1f;
    const Matrix expected = Matrix::CreateRotationZ(roll) * Matrix::CreateRotationX(pitch) *
                            Matrix::CreateRotationY(yaw);
    EXPECT_TRUE(Near(Matrix::CreateFromYawPitchRoll(yaw, pitch, roll), expected, 1e-5f));
    EXPECT_TRUE(SameRotation(Quaternion::CreateFromYawPitchRoll(yaw, 0, 0),
                             Quaternion::CreateFromAxisAngle(Vector3::Up, yaw)));
}

TEST(Quaternion, SlerpLerpInverseConjugate) {
    const Quaternion a = Quaternion::Identity;
    const Quaternion b = Quaternion::CreateFromAxisAngle(Vector3::Up, MathHelper::PiOver2);
    EXPECT_TRUE(SameRotation(Quaternion::Slerp(a, b, 0.5f),
                             Quaternion::CreateFromAxisAngle(Vector3::Up, MathHelper::PiOver4)));
    EXPECT_TRUE(SameRotation(Quaternion::Slerp(a, b, 0.0f), a));
    EXPECT_TRUE(SameRotation(Quaternion::Slerp(a, b, 1.0f), b));
    // -b is the same rotation; Slerp still takes the short way (45 degrees, not 135).
    EXPECT_TRUE(SameRotation(Quaternion::Slerp(a, -b, 0.5f),
                             Quaternion::CreateFromAxisAngle(Vector3::Up, MathHelper::PiOver4)));
    const Quaternion l = Quaternion::Lerp(a, b, 0.5f);
    EXPECT_NEAR(l.Length(), 1.0f, kEps);
    EXPECT_TRUE(SameRotation(l, Quaternion::CreateFromAxisAngle(Vector3::Up, MathHelper::PiOver4)));

    const Quaternion q(1, 2, 3, 4);  // not unit: Inverse divides by the squared length (30)
    EXPECT_TRUE(SameRotation(q * Quaternion::Inverse(q), Quaternion::Identity));
    EXPECT_EQ(Quaternion::Conjugate(q), Quaternion(-1, -2, -3, 4));
    EXPECT_EQ(q.LengthSquared(), 30.0f);
    Quaternion n = q;
    n.Normalize();
    EXPECT_NEAR(n.Length(), 1.0f, kEps);
}

// ---- colour ----------------------------------------------------------------------------------

TEST(Color, FloatChannelsRoundLikeXna) {
    EXPECT_EQ(Color(1.0f, 0.5f, 0, 1), Color(255, 128, 0, 255));  // 127.5 rounds to 128
    EXPECT_EQ(Color(0.25f, 0.0f, 1.0f), Color(64, 0, 255, 255));  // 63.75 -> 64, alpha defaults to 1
    EXPECT_EQ(Color(-1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f), Color(0, 255, 0, 0));
    // Ties go to the even neighbour (.NET Math.Round): 2.5 -> 2, 3.5 -> 4, 0.5 -> 0.
    ASSERT_EQ(2.5f / 255.0f * 255.0f, 2.5f);
    ASSERT_EQ(3.5f / 255.0f * 255.0f, 3.5f);
    ASSERT_EQ(0.5f / 255.0f * 255.0f, 0.5f);
    EXPECT_EQ(Color(2.5f / 255.0f, 3.5f / 255.0f, 0.5f / 255.0f, 1.0f), Color(2, 4, 0, 255));
    EXPECT_EQ(Color(Vector3(1, 0, 0)), Color::Red);
    EXPECT_EQ(Color(Vector4(0, 0, 1, 0.5f)), Color(0, 0, 255, 128));
}

TEST(Color, IntegerChannelsClampAndPack) {
    EXPECT_EQ(Color(300, -5, 128), Color(255, 0, 128, 255));
    EXPECT_EQ(Color(1, 2, 3, 4).PackedValue(), 0x04030201u);  // R in the low byte
    EXPECT_EQ(Color::Red.PackedValue(), 0xFF0000FFu);
    Color c;
    EXPECT_EQ(c, Color::Transparent);  // default is transparent black
    c.setPackedValue(0x80402010u);
    EXPECT_EQ(c, Color(0x10, 0x20, 0x40, 0x80));
    EXPECT_TRUE(Near(Color(255, 0, 51).ToVector4(), {1, 0, 0.2f, 1}));
    EXPECT_TRUE(Near(Color(255, 0, 51).ToVector3(), {1, 0, 0.2f}));
}

TEST(Color, NamedColorsHaveXnaValues) {
    EXPECT_EQ(Color::CornflowerBlue, Color(100, 149, 237, 255));
    EXPECT_EQ(Color::Green, Color(0, 128, 0, 255));
    EXPECT_EQ(Color::White, Color(255, 255, 255, 255));
    EXPECT_EQ(Color::Black, Color(0, 0, 0, 255));
    EXPECT_EQ(Color::Transparent.PackedValue(), 0u);
    EXPECT_EQ(Color::TransparentBlack.PackedValue(), 0u);
    EXPECT_EQ(Color::Gray, Color(128, 128, 128, 255));
    EXPECT_EQ(Color::DarkGray, Color(169, 169, 169, 255));
    EXPECT_EQ(Color::LightGray, Color(211, 211, 211, 255));
    EXPECT_EQ(Color::Orange, Color(255, 165, 0, 255));
    EXPECT_EQ(Color::Purple, Color(128, 0, 128, 255));
    EXPECT_EQ(Color::Yellow.PackedValue(), 0xFF00FFFFu);
    EXPECT_EQ(Color::Cyan, Color(0, 255, 255, 255));
    EXPECT_EQ(Color::Magenta, Color(255, 0, 255, 255));
    EXPECT_EQ(Color::Blue, Color(0, 0, 255, 255));
}

TEST(Color, MultiplyAndLerpInFixedPoint) {
    EXPECT_EQ(Color::White * 0.5f, Color(127, 127, 127, 127));  // 255 * 32768 >> 16 = 127
    EXPECT_EQ(Color(200, 100, 50, 255) * 2.0f, Color(255, 200, 100, 255));
    EXPECT_EQ(Color::White * -1.0f, Color::Transparent);
    EXPECT_EQ(Color(10, 20, 30, 40) * 1.0f, Color(10, 20, 30, 40));
    EXPECT_EQ(Color::Lerp(Color::Black, Color::White, 0.5f), Color(127, 127, 127, 255));
    // Downwards the shift rounds towards -inf: 255 + floor(-127.5) = 127.
    EXPECT_EQ(Color::Lerp(Color::White, Color::Black, 0.5f), Color(127, 127, 127, 255));
    EXPECT_EQ(Color::Lerp(Color::Red, Color::Blue, 0.0f), Color::Red);
    EXPECT_EQ(Color::Lerp(Color::Red, Color::Blue, 1.0f), Color::Blue);
    EXPECT_EQ(Color::Lerp(Color::Red, Color::Blue, 3.0f), Color::Blue);  // clamped
    EXPECT_EQ(Color::FromNonPremultiplied(255, 128, 0, 128), Color(128, 64, 0, 128));
    EXPECT_EQ(Color::FromNonPremultiplied(Vector4(1, 0.5f, 0, 0.5f)), Color(128, 64, 0, 128));
}

// ---- rectangle, bounding sphere --------------------------------------------------------------

TEST(Rectangle, EdgesContainsIntersects) {
    const Rectangle r(10, 20, 30, 40);
    EXPECT_EQ(r.Left(), 10);
    EXPECT_EQ(r.Right(), 40);
    EXPECT_EQ(r.Top(), 20);
    EXPECT_EQ(r.Bottom(), 60);
    EXPECT_EQ(r.Center(), Point(25, 40));
    EXPECT_EQ(Rectangle(0, 0, 3, 3).Center(), Point(1, 1));
    EXPECT_TRUE(r.Contains(10, 20));        // top-left corner is inside
    EXPECT_FALSE(r.Contains(40, 30));       // right edge is outside
    EXPECT_FALSE(r.Contains(Point(15, 60)));  // bottom edge is outside
    EXPECT_TRUE(r.Contains(Rectangle(10, 20, 30, 40)));
    EXPECT_FALSE(r.Contains(Rectangle(9, 20, 5, 5)));
    EXPECT_TRUE(r.Intersects(Rectangle(35, 55, 10, 10)));
    EXPECT_FALSE(r.Intersects(Rectangle(40, 20, 10, 10)));  // sharing an edge is not overlap
    EXPECT_EQ(Rectangle::Intersect(r, Rectangle(35, 55, 10, 10)), Rectangle(35, 55, 5, 5));
    EXPECT_EQ(Rectangle::Intersect(r, Rectangle(100, 100, 1, 1)), Rectangle::Empty);
    EXPECT_EQ(Rectangle::Union(r, Rectangle(0, 0, 1, 1)), Rectangle(0, 0, 40, 60));
    EXPECT_TRUE(Rectangle::Empty.IsEmpty());
    Rectangle g = r;
    g.Inflate(1, 2);
    EXPECT_EQ(g, Rectangle(9, 18, 32, 44));
}

TEST(BoundingSphere, TransformContainsIntersects) {
    const BoundingSphere s({1, 0, 0}, 2.0f);
    const BoundingSphere t = s.Transform(Matrix::CreateScale(3) * Matrix::CreateTranslation(0, 5, 0));
    EXPECT_TRUE(Near(t.Center, {3, 5, 0}));
    EXPECT_NEAR(t.Radius, 6.0f, kEps);
    // Non-uniform scale: the radius follows the largest axis.
    EXPECT_NEAR(s.Transform(Matrix::CreateScale(1, 4, 2)).Radius, 8.0f, kEps);
    EXPECT_EQ(s.Contains(Vector3(2, 1, 0)), ContainmentType::Contains);
    EXPECT_EQ(s.Contains(Vector3(3, 0, 0)), ContainmentType::Disjoint);  // on the surface
    EXPECT_EQ(s.Contains(BoundingSphere({1, 0, 0}, 1)), ContainmentType::Contains);
    EXPECT_EQ(s.Contains(BoundingSphere({4, 0, 0}, 2)), ContainmentType::Intersects);
    EXPECT_EQ(s.Contains(BoundingSphere({9, 0, 0}, 2)), ContainmentType::Disjoint);
    EXPECT_TRUE(s.Intersects(BoundingSphere({4, 0, 0}, 2)));
    EXPECT_FALSE(s.Intersects(BoundingSphere({5, 0, 0}, 2)));  // touching
}

// BoundingFrustum against clip space: a point is inside exactly when p * (view * projection) = clip
// has -w <= x, y <= w and 0 <= z <= w (D3D's rule, which XNA's frustum planes encode).
bool insideClipSpace(Vector3 p, const Matrix& viewProjection) {
    const Vector4 c = Vector4::Transform(p, viewProjection);
    return c.W > 0 && std::fabs(c.X) <= c.W && std::fabs(c.Y) <= c.W && c.Z >= 0 && c.Z <= c.W;
}

TEST(BoundingFrustum, PlanesAndCornersOfASimpleFrustum) {
    // Camera at the origin looking down -Z, 90 degrees, square, near 1, far 10: the near plane's
    // corners are at (+-1, +-1, -1), the far plane's at (+-10, +-10, -10).
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver2, 1.0f, 1.0f, 10.0f);
    const BoundingFrustum frustum(Matrix::Identity * projection);
    EXPECT_TRUE(Near(frustum.Near().Normal, {0, 0, 1}));  // outwards: towards the camera
    EXPECT_NEAR(frustum.Near().D, 1.0f, kEps);
    EXPECT_TRUE(Near(frustum.Far().Normal, {0, 0, -1}));
    EXPECT_NEAR(frustum.Far().D, -10.0f, 1e-4f);
    const float s = std::sqrt(0.5f);
    EXPECT_TRUE(Near(frustum.Left().Normal, {-s, 0, s}));
    EXPECT_TRUE(Near(frustum.Top().Normal, {0, s, s}));
    const auto corners = frustum.GetCorners();
    EXPECT_TRUE(Near(corners[0], {-1, 1, -1}));
    EXPECT_TRUE(Near(corners[2], {1, -1, -1}));
    EXPECT_LT(Vector3::Distance(corners[4], {-10, 10, -10}), 1e-3f);
    EXPECT_LT(Vector3::Distance(corners[6], {10, -10, -10}), 1e-3f);

    EXPECT_EQ(frustum.Contains(Vector3(0, 0, -5)), ContainmentType::Contains);
    EXPECT_EQ(frustum.Contains(Vector3(0, 0, -0.5f)), ContainmentType::Disjoint);  // before the near plane
    EXPECT_EQ(frustum.Contains(Vector3(0, 0, -11)), ContainmentType::Disjoint);    // past the far plane
    EXPECT_EQ(frustum.Contains(Vector3(6, 0, -5)), ContainmentType::Disjoint);     // right of x = -z

    EXPECT_EQ(frustum.Contains(BoundingSphere({0, 0, -5}, 1)), ContainmentType::Contains);
    EXPECT_EQ(frustum.Contains(BoundingSphere({0, 0, -5}, 10)), ContainmentType::Intersects);
    EXPECT_EQ(frustum.Contains(BoundingSphere({20, 0, -5}, 1)), ContainmentType::Disjoint);
    EXPECT_EQ(frustum.Contains(BoundingSphere({0, 0, 3}, 1)), ContainmentType::Disjoint);  // behind the camera
    // Centre behind the camera, but the sphere reaches past the near plane (distance 2.5 < 3).
    EXPECT_EQ(frustum.Contains(BoundingSphere({0, 0, 1.5f}, 3)), ContainmentType::Intersects);
    EXPECT_FALSE(frustum.Intersects(BoundingSphere({0, 0, 1.5f}, 2)));
    // Just across the right plane x = -z at z = -5: distance (5.5 - 5) / sqrt(2) = 0.354.
    EXPECT_TRUE(frustum.Intersects(BoundingSphere({5.5f, 0, -5}, 0.36f)));
    EXPECT_FALSE(frustum.Intersects(BoundingSphere({5.5f, 0, -5}, 0.35f)));
}

TEST(BoundingFrustum, AgreesWithClipSpaceForAMovedCamera) {
    const Matrix view = Matrix::CreateLookAt({3, 9, 17}, {0, 1.5f, 0}, Vector3::Up);
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 4.0f / 3.0f, 0.5f, 60.0f);
    const Matrix viewProjection = view * projection;
    const BoundingFrustum frustum(viewProjection);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> coord(-70.0f, 70.0f), radius(0.1f, 8.0f);
    int inside = 0, outside = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vector3 p(coord(rng), coord(rng), coord(rng));
        const bool expected = insideClipSpace(p, viewProjection);
        ASSERT_EQ(frustum.Contains(p) == ContainmentType::Contains, expected) << i;
        (expected ? inside : outside)++;
        // A sphere: Disjoint means no point of it is inside, Contains that all of it is. Checked on
        // its centre and the six points of its axes (samples of the exact answer).
        const BoundingSphere sphere(p, radius(rng));
        const ContainmentType c = frustum.Contains(sphere);
        const Vector3 axes[7] = {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const Vector3& axis : axes) {
            const bool in = insideClipSpace(sphere.Center + axis * (sphere.Radius * 0.999f), viewProjection);
            if (c == ContainmentType::Disjoint) {
                ASSERT_FALSE(in) << i;
            }
            if (c == ContainmentType::Contains) {
                ASSERT_TRUE(in) << i;
            }
        }
    }
    EXPECT_GT(inside, 100);  // the random points test both sides
    EXPECT_GT(outside, 100);
}

}  // namespace
