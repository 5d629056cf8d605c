// XNA's collision types (BoundingBox, BoundingSphere, BoundingFrustum, Plane, Ray), the spline and
// matrix statics, and Viewport.Project/Unproject, against the results XNA documents and computes:
// values worked out by hand (in the comments) from XNA's definitions, never from the code under test.
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/graphics/viewport.h"
#include "fxport/math.h"

namespace fxport {
namespace {

constexpr float kEps = 1e-5f;

::testing::AssertionResult near(Vector3 a, Vector3 b, float eps = kEps) {
    if (std::fabs(a.X - b.X) <= eps && std::fabs(a.Y - b.Y) <= eps && std::fabs(a.Z - b.Z) <= eps)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.X << ", " << a.Y << ", " << a.Z << ") vs (" << b.X << ", " << b.Y
                                         << ", " << b.Z << ")";
}

// The camera of the frustum tests: at (0, 0, 10) looking at the origin, 90 degrees, square, near 1,
// far 100: the near plane is z = 9 with corners (+-1, +-1, 9), the far plane z = -90 with (+-100, +-100, -90).
Matrix cameraViewProjection() {
    return Matrix::CreateLookAt({0, 0, 10}, Vector3::Zero, Vector3::Up) *
           Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver2, 1.0f, 1.0f, 100.0f);
}

TEST(BoundingBox, ConstructionAndCorners) {
    const std::vector<Vector3> points = {{1, 2, 3}, {-1, 5, 0}, {4, -2, 1}};
    EXPECT_EQ(BoundingBox::CreateFromPoints(points), BoundingBox({-1, -2, 0}, {4, 5, 3}));
    EXPECT_THROW(BoundingBox::CreateFromPoints(std::vector<Vector3>{}), std::invalid_argument);
    EXPECT_EQ(BoundingBox::CreateFromSphere(BoundingSphere({1, 2, 3}, 2)), BoundingBox({-1, 0, 1}, {3, 4, 5}));
    EXPECT_EQ(BoundingBox::CreateMerged(BoundingBox({0, 0, 0}, {1, 1, 1}), BoundingBox({-1, 0.5f, 0}, {0.5f, 3, 0.5f})),
              BoundingBox({-1, 0, 0}, {1, 3, 1}));
    // XNA's order: the Max.Z face (top-left, top-right, bottom-right, bottom-left), then Min.Z.
    const auto c = BoundingBox({0, 0, 0}, {1, 2, 3}).GetCorners();
    const Vector3 expected[8] = {{0, 2, 3}, {1, 2, 3}, {1, 0, 3}, {0, 0, 3}, {0, 2, 0}, {1, 2, 0}, {1, 0, 0}, {0, 0, 0}};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(c[std::size_t(i)], expected[i]) << i;
}

TEST(BoundingBox, ContainsAndIntersects) {
    const BoundingBox box({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(box.Contains(Vector3(0.5f, 0.5f, 0.5f)), ContainmentType::Contains);
    EXPECT_EQ(box.Contains(Vector3(1, 0.5f, 0)), ContainmentType::Contains);  // on a face: inside
    EXPECT_EQ(box.Contains(Vector3(1.01f, 0.5f, 0.5f)), ContainmentType::Disjoint);

    EXPECT_EQ(box.Contains(BoundingBox({0.2f, 0.2f, 0.2f}, {0.8f, 1, 0.8f})), ContainmentType::Contains);
    EXPECT_EQ(box.Contains(BoundingBox({0.5f, 0.5f, 0.5f}, {2, 2, 2})), ContainmentType::Intersects);
    EXPECT_EQ(box.Contains(BoundingBox({1, 0, 0}, {2, 1, 1})), ContainmentType::Intersects);  // sharing a face
    EXPECT_EQ(box.Contains(BoundingBox({1.1f, 0, 0}, {2, 1, 1})), ContainmentType::Disjoint);
    EXPECT_TRUE(box.Intersects(BoundingBox({1, 1, 1}, {2, 2, 2})));  // touching at a corner
    EXPECT_FALSE(box.Intersects(BoundingBox({1, 1, 1.001f}, {2, 2, 2})));

    EXPECT_EQ(box.Contains(BoundingSphere({0.5f, 0.5f, 0.5f}, 0.5f)), ContainmentType::Contains);
    EXPECT_EQ(box.Contains(BoundingSphere({0.5f, 0.5f, 0.5f}, 0.6f)), ContainmentType::Intersects);
    // Beyond the corner (1, 1, 1): distance sqrt(3 * 0.25) = 0.866.
    EXPECT_EQ(box.Contains(BoundingSphere({1.5f, 1.5f, 1.5f}, 0.8f)), ContainmentType::Disjoint);
    EXPECT_EQ(box.Contains(BoundingSphere({1.5f, 1.5f, 1.5f}, 0.9f)), ContainmentType::Intersects);
    EXPECT_FALSE(box.Intersects(BoundingSphere({1.5f, 1.5f, 1.5f}, 0.8f)));

    EXPECT_EQ(box.Intersects(Plane(0, 1, 0, -2)), PlaneIntersectionType::Back);  // y = 2 is above the box
    EXPECT_EQ(box.Intersects(Plane(0, 1, 0, -0.5f)), PlaneIntersectionType::Intersecting);
    EXPECT_EQ(box.Intersects(Plane(0, 1, 0, 1)), PlaneIntersectionType::Front);  // y = -1 is below
    EXPECT_EQ(box.Intersects(Plane(0, -1, 0, 1)), PlaneIntersectionType::Intersecting);  // y = 1 touches the top
}

TEST(Ray, AgainstBoxSpherePlane) {
    const BoundingBox box({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(Ray({-5, 0.5f, 0.5f}, {1, 0, 0}).Intersects(box), std::optional<float>(5.0f));
    EXPECT_EQ(Ray({0.5f, 0.5f, 0.5f}, {1, 0, 0}).Intersects(box), std::optional<float>(0.0f));  // starts inside
    EXPECT_EQ(Ray({-5, 0.5f, 0.5f}, {-1, 0, 0}).Intersects(box), std::nullopt);                  // points away
    EXPECT_EQ(Ray({-5, 2, 0.5f}, {1, 0, 0}).Intersects(box), std::nullopt);                      // parallel, above
    // Diagonal: from (-1, -1, 0.5) along (1, 1, 0)/sqrt(2) the box starts at distance sqrt(2).
    const float s = std::sqrt(0.5f);
    EXPECT_NEAR(*Ray({-1, -1, 0.5f}, {s, s, 0}).Intersects(box), std::sqrt(2.0f), kEps);
    EXPECT_EQ(box.Intersects(Ray({-5, 0.5f, 0.5f}, {1, 0, 0})), std::optional<float>(5.0f));

    const BoundingSphere sphere({0, 0, 0}, 1);
    EXPECT_EQ(Ray({-5, 0, 0}, {1, 0, 0}).Intersects(sphere), std::optional<float>(4.0f));
    EXPECT_EQ(Ray({0.5f, 0, 0}, {1, 0, 0}).Intersects(sphere), std::optional<float>(0.0f));
    EXPECT_EQ(Ray({-5, 0, 0}, {-1, 0, 0}).Intersects(sphere), std::nullopt);
    EXPECT_EQ(Ray({-5, 1.01f, 0}, {1, 0, 0}).Intersects(sphere), std::nullopt);
    // Off-centre: at height 0.6 the ray meets the sphere at x = -0.8, distance 5 - 0.8.
    EXPECT_NEAR(*Ray({-5, 0.6f, 0}, {1, 0, 0}).Intersects(sphere), 4.2f, kEps);
    EXPECT_NEAR(*sphere.Intersects(Ray({-5, 0.6f, 0}, {1, 0, 0})), 4.2f, kEps);

    const Plane ground(0, 1, 0, -1);  // y = 1
    EXPECT_EQ(Ray({0, 5, 0}, {0, -1, 0}).Intersects(ground), std::optional<float>(4.0f));
    EXPECT_EQ(Ray({0, 5, 0}, {0, 1, 0}).Intersects(ground), std::nullopt);
    EXPECT_EQ(Ray({0, 5, 0}, {1, 0, 0}).Intersects(ground), std::nullopt);  // parallel
    EXPECT_EQ(Ray({0, 1, 0}, {0, 1, 0}).Intersects(ground), std::optional<float>(0.0f));  // starts on it
}

TEST(BoundingSphere, ConstructionContainsIntersects) {
    const BoundingSphere fromBox = BoundingSphere::CreateFromBoundingBox(BoundingBox({0, 0, 0}, {2, 2, 2}));
    EXPECT_TRUE(near(fromBox.Center, {1, 1, 1}));
    EXPECT_NEAR(fromBox.Radius, std::sqrt(3.0f), kEps);

    // Merged: from x = -1 to x = 5 -> centre 2, radius 3; a contained one gives the container.
    const BoundingSphere merged = BoundingSphere::CreateMerged(BoundingSphere({0, 0, 0}, 1), BoundingSphere({4, 0, 0}, 1));
    EXPECT_TRUE(near(merged.Center, {2, 0, 0}));
    EXPECT_NEAR(merged.Radius, 3.0f, kEps);
    EXPECT_EQ(BoundingSphere::CreateMerged(BoundingSphere({0, 0, 0}, 5), BoundingSphere({1, 0, 0}, 1)),
              BoundingSphere({0, 0, 0}, 5));
    EXPECT_EQ(BoundingSphere::CreateMerged(BoundingSphere({1, 0, 0}, 1), BoundingSphere({0, 0, 0}, 5)),
              BoundingSphere({0, 0, 0}, 5));

    // The octahedron's six vertices: exactly the unit sphere.
    const std::vector<Vector3> octahedron = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const BoundingSphere unit = BoundingSphere::CreateFromPoints(octahedron);
    EXPECT_TRUE(near(unit.Center, Vector3::Zero));
    EXPECT_NEAR(unit.Radius, 1.0f, kEps);
    EXPECT_THROW(BoundingSphere::CreateFromPoints(std::vector<Vector3>{}), std::invalid_argument);
    // Random clouds: every point inside, the radius no more than 15 % over the box's half diagonal
    // (Ritter's bound is about 5 % over the optimum in practice).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3, 3);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Vector3> cloud(50);
        for (Vector3& p : cloud) p = Vector3(u(rng), u(rng) * 0.5f, u(rng) * 2);
        const BoundingSphere s = BoundingSphere::CreateFromPoints(cloud);
        for (Vector3 p : cloud) EXPECT_LE(Vector3::Distance(p, s.Center), s.Radius * (1 + 1e-5f));
        EXPECT_LE(s.Radius, 1.15f * BoundingSphere::CreateFromBoundingBox(BoundingBox::CreateFromPoints(cloud)).Radius);
    }

    const BoundingSphere s({0, 0, 0}, 2);
    EXPECT_EQ(s.Contains(BoundingBox({-1, -1, -1}, {1, 1, 1})), ContainmentType::Contains);  // corners at 1.73
    EXPECT_EQ(s.Contains(BoundingBox({-1.2f, -1.2f, -1.2f}, {1, 1, 1})), ContainmentType::Intersects);  // 2.08
    EXPECT_EQ(s.Contains(BoundingBox({3, 3, 3}, {4, 4, 4})), ContainmentType::Disjoint);
    EXPECT_TRUE(s.Intersects(BoundingBox({1.9f, -1, -1}, {3, 1, 1})));
    EXPECT_EQ(s.Intersects(Plane(1, 0, 0, -3)), PlaneIntersectionType::Back);   // x = 3
    EXPECT_EQ(s.Intersects(Plane(1, 0, 0, -1)), PlaneIntersectionType::Intersecting);
    EXPECT_EQ(s.Intersects(Plane(1, 0, 0, 3)), PlaneIntersectionType::Front);   // x = -3
}

TEST(Plane, ConstructionDotsNormalizeTransform) {
    // Through (0,0,0), (1,0,0), (0,0,1): Cross((1,0,0), (0,0,1)) = (0,-1,0).
    const Plane p(Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 0, 1));
    EXPECT_TRUE(near(p.Normal, {0, -1, 0}));
    EXPECT_NEAR(p.D, 0.0f, kEps);
    const Plane q(Vector3(0, 2, 0), Vector3(0, 2, 1), Vector3(1, 2, 0));  // y = 2, normal +y
    EXPECT_TRUE(near(q.Normal, {0, 1, 0}));
    EXPECT_NEAR(q.D, -2.0f, kEps);
    EXPECT_FLOAT_EQ(q.DotCoordinate({5, 7, 1}), 5.0f);
    EXPECT_FLOAT_EQ(q.DotNormal({5, 7, 1}), 7.0f);
    EXPECT_FLOAT_EQ(q.Dot(Vector4(5, 7, 1, 0)), 7.0f);
    EXPECT_FLOAT_EQ(q.Dot(Vector4(5, 7, 1, 1)), 5.0f);
    EXPECT_EQ(Plane(Vector4(1, 2, 3, 4)), Plane(1, 2, 3, 4));

    const Plane n = Plane::Normalize(Plane(0, 2, 0, -4));
    EXPECT_EQ(n, Plane(0, 1, 0, -2));

    // Moving y = 2 up by 3 gives y = 5; turning it a quarter about Z (+Y -> -X) gives x = -2.
    EXPECT_EQ(Plane::Transform(q, Matrix::CreateTranslation(0, 3, 0)), Plane(0, 1, 0, -5));
    const Plane turned = Plane::Transform(q, Matrix::CreateRotationZ(MathHelper::PiOver2));
    EXPECT_TRUE(near(turned.Normal, {-1, 0, 0}));
    EXPECT_NEAR(turned.D, -2.0f, kEps);
    const Plane turnedQ = Plane::Transform(q, Quaternion::CreateFromAxisAngle(Vector3::UnitZ, MathHelper::PiOver2));
    EXPECT_TRUE(near(turnedQ.Normal, {-1, 0, 0}));
    EXPECT_NEAR(turnedQ.D, -2.0f, kEps);
}

TEST(BoundingFrustum, SettableMatrixBoxesRaysPlanesFrusta) {
    BoundingFrustum frustum(Matrix::Identity);
    frustum.setMatrix(cameraViewProjection());
    EXPECT_EQ(frustum.getMatrix(), cameraViewProjection());
    const auto corners = frustum.GetCorners();
    EXPECT_TRUE(near(corners[0], {-1, 1, 9}, 1e-4f));
    EXPECT_TRUE(near(corners[6], {100, -100, -90}, 2e-2f));
    EXPECT_TRUE(near(frustum.Near().Normal, {0, 0, 1}));
    EXPECT_NEAR(frustum.Near().D, -9.0f, 1e-4f);

    EXPECT_EQ(frustum.Contains(BoundingBox({-1, -1, -1}, {1, 1, 1})), ContainmentType::Contains);
    EXPECT_EQ(frustum.Contains(BoundingBox({-1, -1, -300}, {1, 1, -200})), ContainmentType::Disjoint);
    EXPECT_EQ(frustum.Contains(BoundingBox({-0.5f, -0.5f, 8}, {0.5f, 0.5f, 9.5f})), ContainmentType::Intersects);
    EXPECT_TRUE(frustum.Intersects(BoundingBox({-0.5f, -0.5f, 8}, {0.5f, 0.5f, 9.5f})));
    EXPECT_FALSE(frustum.Intersects(BoundingBox({-1, -1, 11}, {1, 1, 12})));  // behind the camera

    // Rays: down the view axis from behind the camera enters the near plane after 11 units.
    EXPECT_NEAR(*frustum.Intersects(Ray({0, 0, 20}, {0, 0, -1})), 11.0f, 1e-4f);
    EXPECT_EQ(frustum.Intersects(Ray({0, 0, 0}, {1, 0, 0})), std::optional<float>(0.0f));  // starts inside
    EXPECT_EQ(frustum.Intersects(Ray({0, 0, 20}, {0, 0, 1})), std::nullopt);
    EXPECT_EQ(Ray({0, 0, 20}, {0, 1, 0}).Intersects(frustum), std::nullopt);  // parallel to near, above it
    // Across the side: from (-50, 0, 0) along +X it enters where the left plane x = -(10 - z) = -10 is.
    EXPECT_NEAR(*frustum.Intersects(Ray({-50, 0, 0}, {1, 0, 0})), 40.0f, 1e-3f);

    EXPECT_EQ(frustum.Intersects(Plane(0, 0, 1, 0)), PlaneIntersectionType::Intersecting);   // z = 0
    EXPECT_EQ(frustum.Intersects(Plane(0, 0, 1, -50)), PlaneIntersectionType::Back);         // z = 50
    EXPECT_EQ(Plane(0, 0, 1, 200).Intersects(frustum), PlaneIntersectionType::Front);        // z = -200, normal +z

    // A narrower, shorter frustum from the same camera lies inside; one looking away does not meet it.
    const BoundingFrustum inner(Matrix::CreateLookAt({0, 0, 10}, Vector3::Zero, Vector3::Up) *
                                Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 1.0f, 2.0f, 50.0f));
    EXPECT_EQ(frustum.Contains(inner), ContainmentType::Contains);
    EXPECT_EQ(inner.Contains(frustum), ContainmentType::Intersects);
    const BoundingFrustum away(Matrix::CreateLookAt({0, 0, 12}, {0, 0, 30}, Vector3::Up) *
                               Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 1.0f, 1.0f, 50.0f));
    EXPECT_FALSE(frustum.Intersects(away));
    EXPECT_EQ(frustum.Contains(away), ContainmentType::Disjoint);

    const BoundingSphere around = BoundingSphere::CreateFromFrustum(frustum);
    for (Vector3 c : corners) EXPECT_LE(Vector3::Distance(c, around.Center), around.Radius * (1 + 1e-5f));
    EXPECT_EQ(around.Contains(frustum), ContainmentType::Contains);
    EXPECT_EQ(BoundingBox::CreateFromPoints(corners).Contains(frustum), ContainmentType::Contains);
    EXPECT_EQ(BoundingBox({-1, -1, -1}, {1, 1, 1}).Contains(frustum), ContainmentType::Intersects);
}

// Intersects(BoundingBox) is exact: checked against points sampled in each box (a box with a
// sample inside must intersect), and it rules out a box beside a frustum corner that the
// plane-by-plane test (Contains) cannot.
TEST(BoundingFrustum, BoxIntersectionIsExact) {
    const BoundingFrustum frustum(cameraViewProjection());
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> centre(-14, 14), size(0.2f, 4);
    int intersecting = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vector3 c(centre(rng), centre(rng), centre(rng) * 0.5f + 6);
        const Vector3 h(size(rng), size(rng), size(rng));
        const BoundingBox box(c - h, c + h);
        bool sampleInside = false;
        for (int i = 0; i <= 6 && !sampleInside; ++i)
            for (int j = 0; j <= 6 && !sampleInside; ++j)
                for (int k = 0; k <= 6 && !sampleInside; ++k) {
                    const Vector3 p(box.Min.X + (box.Max.X - box.Min.X) * float(i) / 6,
                                    box.Min.Y + (box.Max.Y - box.Min.Y) * float(j) / 6,
                                    box.Min.Z + (box.Max.Z - box.Min.Z) * float(k) / 6);
                    sampleInside = frustum.Contains(p) == ContainmentType::Contains;
                }
        const bool exact = frustum.Intersects(box);
        if (sampleInside) {
            EXPECT_TRUE(exact) << "box around (" << c.X << ", " << c.Y << ", " << c.Z << ")";
        }
        if (exact) ++intersecting;
    }
    EXPECT_GT(intersecting, 300);  // the sample covers both outcomes
    EXPECT_LT(intersecting, 2700);
    // Beside the far right corner (100, -90), where the far plane and the right plane x = 10 - z
    // meet at 45 degrees: the box straddles both planes (so no single plane rules it out) but the
    // frustum's points there have x <= 10 - z <= 100 < 100.5.
    const BoundingBox corner({100.5f, -1, -95}, {104, 1, -89.8f});
    EXPECT_EQ(frustum.Contains(corner), ContainmentType::Intersects);
    EXPECT_FALSE(frustum.Intersects(corner));
    EXPECT_FALSE(corner.Intersects(frustum));
    EXPECT_EQ(corner.Contains(frustum), ContainmentType::Disjoint);
    EXPECT_TRUE(frustum.Intersects(BoundingBox({99.5f, -1, -95}, {104, 1, -89.8f})));  // reaches (99.5, -90)
}

TEST(MathStatics, SplinesAndBlends) {
    // Hermite(1, 0, 3, 0, 0.5) = (2 - 6) / 8 + (9 - 3) / 4 + 1 = 2; exact at the ends.
    EXPECT_FLOAT_EQ(MathHelper::Hermite(1, 0, 3, 0, 0.5f), 2.0f);
    EXPECT_EQ(MathHelper::Hermite(1, 5, 3, -7, 0.0f), 1.0f);
    EXPECT_EQ(MathHelper::Hermite(1, 5, 3, -7, 1.0f), 3.0f);
    // Catmull-Rom through evenly spaced data is linear; through 0, 0, 1, 1 at 0.5 it is 0.5.
    EXPECT_FLOAT_EQ(MathHelper::CatmullRom(0, 1, 2, 3, 0.25f), 1.25f);
    EXPECT_FLOAT_EQ(MathHelper::CatmullRom(0, 0, 1, 1, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(MathHelper::CatmullRom(7, 2, 5, 9, 0.0f), 2.0f);
    EXPECT_FLOAT_EQ(MathHelper::CatmullRom(7, 2, 5, 9, 1.0f), 5.0f);

    EXPECT_TRUE(near(Vector3::SmoothStep({0, 0, 0}, {10, 20, -4}, 0.25f), {1.5625f, 3.125f, -0.625f}));
    EXPECT_TRUE(near(Vector3::SmoothStep({0, 0, 0}, {10, 20, -4}, 2.0f), {10, 20, -4}));  // clamped
    EXPECT_TRUE(near(Vector3::Hermite({1, 1, 1}, {0, 0, 0}, {3, 3, 3}, {0, 0, 0}, 0.5f), {2, 2, 2}));
    EXPECT_TRUE(near(Vector3::CatmullRom({0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {3, 6, 9}, 0.5f), {1.5f, 3, 4.5f}));
    EXPECT_TRUE(near(Vector3::Barycentric({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.25f, 0.5f), {0.25f, 0.5f, 0}));
    EXPECT_EQ(Vector2::Barycentric({0, 0}, {4, 0}, {0, 8}, 0.5f, 0.25f), Vector2(2, 2));
    EXPECT_EQ(Vector4::Hermite(Vector4(1), Vector4(0), Vector4(3), Vector4(0), 0.5f), Vector4(2));
    EXPECT_EQ(Vector3::Negate({1, -2, 3}), Vector3(-1, 2, -3));
    EXPECT_EQ(Vector2::Divide({4, 6}, 2.0f), Vector2(2, 3));

    // Quaternion rotations of Vector2/Vector4: a quarter about Z turns +X into +Y.
    const Quaternion quarter = Quaternion::CreateFromAxisAngle(Vector3::UnitZ, MathHelper::PiOver2);
    const Vector2 v2 = Vector2::Transform(Vector2(1, 0), quarter);
    EXPECT_NEAR(v2.X, 0.0f, kEps);
    EXPECT_NEAR(v2.Y, 1.0f, kEps);
    const Vector4 v4 = Vector4::Transform(Vector4(1, 0, 0, 7), quarter);
    EXPECT_NEAR(v4.Y, 1.0f, kEps);
    EXPECT_EQ(v4.W, 7.0f);
    const Quaternion q(1, 2, 3, 4);
    const Quaternion back = Quaternion::Divide(q * quarter, quarter);
    EXPECT_NEAR(back.X, 1, 1e-5f);
    EXPECT_NEAR(back.W, 4, 1e-5f);
    EXPECT_EQ(Quaternion::Negate(q), Quaternion(-1, -2, -3, -4));
}

TEST(MatrixStatics, ReflectionShadowBillboardsTransformDivide) {
    // Mirror through y = 1: (2, 3, 4) -> (2, -1, 4); the plane need not be normalised.
    EXPECT_TRUE(near(Vector3::Transform({2, 3, 4}, Matrix::CreateReflection(Plane(0, 1, 0, -1))), {2, -1, 4}));
    EXPECT_TRUE(near(Vector3::Transform({2, 3, 4}, Matrix::CreateReflection(Plane(0, 2, 0, -2))), {2, -1, 4}));

    // Shadow on y = 0 from a light towards (1, 1, 0): P - L (N.P + D) / (N.L) = (2,3,4) - 3 (1,1,0).
    const Matrix shadow = Matrix::CreateShadow({1, 1, 0}, Plane(0, 1, 0, 0));
    const Vector4 h = Vector4::Transform(Vector3(2, 3, 4), shadow);
    EXPECT_TRUE(near(Vector3(h.X, h.Y, h.Z) / h.W, {-1, 0, 4}));

    // With the camera square to the axis, the constrained billboard is the spherical one.
    const Vector3 object(1, 2, 3), camera(1, 2, 13);
    const Matrix spherical = Matrix::CreateBillboard(object, camera, Vector3::Up);
    const Matrix cylindrical = Matrix::CreateConstrainedBillboard(object, camera, Vector3::Up);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(spherical.data()[i], cylindrical.data()[i], kEps) << i;
    // Camera above: the billboard still stands on its axis (Up row = axis) and turns only about it.
    const Matrix above = Matrix::CreateConstrainedBillboard(object, {4, 30, 7}, Vector3::Up);
    EXPECT_TRUE(near(above.Up(), Vector3::Up));
    EXPECT_NEAR(above.Backward().Y, 0.0f, kEps);
    EXPECT_NEAR(above.Backward().Length(), 1.0f, kEps);
    EXPECT_NEAR(Vector3::Dot(above.Right(), above.Backward()), 0.0f, kEps);
    // Facing: Backward points from the camera to the object in the plane square to the axis.
    EXPECT_TRUE(near(above.Backward(), Vector3::Normalize({1 - 4, 0, 3 - 7})));
    EXPECT_TRUE(near(above.Translation(), object));
    // Camera straight above the object: no facing from it; objectForwardVector decides.
    const Matrix overhead = Matrix::CreateConstrainedBillboard(object, {1, 50, 3}, Vector3::Up, std::nullopt,
                                                               Vector3(1, 0, 0));
    EXPECT_TRUE(near(overhead.Backward(), {1, 0, 0}));

    const Quaternion turn = Quaternion::CreateFromAxisAngle(Vector3::UnitY, 0.7f);
    const Matrix m = Matrix::CreateTranslation(1, 2, 3);
    const Matrix expected = m * Matrix::CreateFromQuaternion(turn);
    const Matrix got = Matrix::Transform(m, turn);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(got.data()[i], expected.data()[i], kEps) << i;
    EXPECT_EQ(Matrix::Divide(Matrix::Identity * 6.0f, 2.0f), Matrix::Identity * 3.0f);
}

TEST(Viewport, ProjectAndUnprojectAsXna) {
    Viewport viewport(10, 20, 640, 480);
    viewport.MinDepth = 0.2f;
    viewport.MaxDepth = 0.8f;
    const Matrix view = Matrix::CreateLookAt({0, 0, 10}, Vector3::Zero, Vector3::Up);
    const float aspect = 640.0f / 480.0f;
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, aspect, 1, 100);
    // The origin, 10 in front of the camera: the centre pixel, depth f/(f-n) (1 - n/10) = 90/99
    // mapped into [0.2, 0.8].
    const Vector3 centre = viewport.Project(Vector3::Zero, projection, view, Matrix::Identity);
    EXPECT_NEAR(centre.X, 10 + 320, 1e-3f);
    EXPECT_NEAR(centre.Y, 20 + 240, 1e-3f);
    EXPECT_NEAR(centre.Z, 0.2 + 0.6 * 90.0 / 99.0, 1e-6);
    // (1, 1, 0) in a world moved by (0, 0, -10) is 20 away: x = 1 / (20 tan(pi/8) aspect), y up = screen up.
    const Matrix world = Matrix::CreateTranslation(0, 0, -10);
    const Vector3 p = viewport.Project({1, 1, 0}, projection, view, world);
    const double t = std::tan(3.14159265358979323846 / 8);
    EXPECT_NEAR(p.X, 10 + 320 + 320 * (1 / (20 * t * aspect)), 1e-3);
    EXPECT_NEAR(p.Y, 20 + 240 - 240 * (1 / (20 * t)), 1e-3);
    // Unproject inverts it.
    EXPECT_TRUE(near(viewport.Unproject(p, projection, view, world), {1, 1, 0}, 1e-4f));
    // Picking: the pixel's near and far points (depth MinDepth, MaxDepth) lie on the ray through it.
    const Vector3 nearPoint = viewport.Unproject({p.X, p.Y, 0.2f}, projection, view, Matrix::Identity);
    const Vector3 farPoint = viewport.Unproject({p.X, p.Y, 0.8f}, projection, view, Matrix::Identity);
    EXPECT_NEAR(nearPoint.Z, 9.0f, 1e-4f);
    EXPECT_NEAR(farPoint.Z, -90.0f, 1e-2f);
    const Ray pick(nearPoint, Vector3::Normalize(farPoint - nearPoint));
    const float along = *pick.Intersects(Plane(0, 0, 1, 10));  // z = -10
    EXPECT_TRUE(near(pick.Position + pick.Direction * along, {1, 1, -10}, 1e-3f));
}

}  // namespace
}  // namespace fxport
