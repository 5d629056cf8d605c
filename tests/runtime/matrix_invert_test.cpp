// Matrix::Invert of singular and near-singular matrices. fxport keeps XNA's contract: Invert does
// not check; it multiplies the adjugate by 1/det. An exactly singular matrix (det == 0 in float)
// therefore comes back with every entry ±Inf or NaN (cofactor × Inf), never a plausible-looking
// finite matrix. A near-singular one comes back finite, with M·M⁻¹ off the identity by about
// cond(M)·2⁻²⁴: the caller decides (Matrix::Determinant) whether that is usable.
#include <gtest/gtest.h>

#include <cmath>

#include "fxport/math.h"

namespace fxport {
namespace {

int nonFiniteEntries(const Matrix& m) {
    int n = 0;
    for (int i = 0; i < 16; ++i) n += std::isfinite(m.data()[i]) ? 0 : 1;
    return n;
}

float maxOffIdentity(const Matrix& a, const Matrix& b) {
    const Matrix p = a * b;
    float worst = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) worst = std::fmax(worst, std::fabs(p.data()[r * 4 + c] - (r == c ? 1.0f : 0.0f)));
    return worst;
}

TEST(MatrixInvert, ExactlySingularGivesNoFiniteEntry) {
    const Matrix singular[] = {
        Matrix::CreateScale(1, 1, 0),                            // flattens z
        Matrix(),                                                // all zeros
        Matrix(1, 2, 3, 4, 2, 4, 6, 8, 0, 0, 1, 0, 0, 0, 0, 1),  // two proportional rows
    };
    for (const Matrix& m : singular) {
        ASSERT_EQ(m.Determinant(), 0.0f);
        EXPECT_EQ(nonFiniteEntries(Matrix::Invert(m)), 16);
    }
}

TEST(MatrixInvert, NearSingularIsFiniteWithErrorGrowingWithTheConditionNumber) {
    // diag(1, 1, eps, 1) has condition number 1/eps: exact in float, so the inverse is exact too.
    for (float eps : {1e-3f, 1e-6f, 1e-12f, 1e-30f}) {
        const Matrix m = Matrix::CreateScale(1, 1, eps);
        const Matrix inverse = Matrix::Invert(m);
        EXPECT_EQ(nonFiniteEntries(inverse), 0) << eps;
        EXPECT_FLOAT_EQ(inverse.M33, 1.0f / eps) << eps;
    }
    // A rotation sheared towards singularity: rows 1 and 2 differ by delta. cond ~ 1/delta.
    for (float delta : {1e-1f, 1e-3f, 1e-5f}) {
        const Matrix m(1, 2, 3, 0, 1, 2 + delta, 3, 0, 0.5f, 0.25f, 1, 0, 0, 0, 0, 1);
        ASSERT_NE(m.Determinant(), 0.0f);
        const Matrix inverse = Matrix::Invert(m);
        EXPECT_EQ(nonFiniteEntries(inverse), 0) << delta;
        // Error bound: a small multiple of cond(M) * float epsilon (cond ~ 30/delta here).
        const float bound = 8.0f * (30.0f / delta) * 1.2e-7f;
        EXPECT_LT(maxOffIdentity(m, inverse), bound) << delta;
    }
}

TEST(MatrixInvert, SmallestNonZeroDeterminantStillInverts) {
    // det = 1e-36 (a float, ~2^-120): 1/det = 1e36 fits in float; the inverse is finite and right.
    const Matrix m = Matrix::CreateScale(1e-12f, 1e-12f, 1e-12f);
    const Matrix inverse = Matrix::Invert(m);
    EXPECT_EQ(nonFiniteEntries(inverse), 0);
    EXPECT_NEAR(inverse.M11 * 1e-12f, 1.0f, 1e-5f);
    // det = 1e-45 flushes through: scale 1e-15 gives det 1e-45 (denormal) -> 1/det overflows.
    const Matrix tiny = Matrix::CreateScale(1e-15f, 1e-15f, 1e-15f);
    EXPECT_GT(nonFiniteEntries(Matrix::Invert(tiny)), 0);
}

}  // namespace
}  // namespace fxport
