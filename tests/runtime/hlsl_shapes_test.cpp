// Type and shape conversions as fxc performs them (issue 23): intrinsics called with values of
// different shapes, drawn into a 1x1 float target at SM2..SM5 and compared with the same
// arithmetic written in C++ with fxc's rules (the independent reference). Values come in as
// uniforms, so the GPU computes them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "one_pixel_effect.h"
#include "runtime_test_support.h"

namespace fxport::test {
namespace {

class HlslShapes : public OnePixelEffect {
protected:
    void expectPixel(const std::vector<float>& px, const float (&expected)[4], float tolerance = 1e-5f) {
        ASSERT_EQ(px.size(), 4u);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[k], tolerance) << "channel " << k;
    }
};

// lerp(float3x2, float2x3, float3x4) is a float2x2: each argument's top-left 2x2, fxc's common
// type of an element-wise intrinsic (smallest rows, smallest columns).
TEST_P(HlslShapes, ElementwiseIntrinsicOfMatricesTakesTheSmallestShape) {
    const float a[3][2] = {{6, 5}, {4, 3}, {2, 1}}, b[2][3] = {{1, 2, 3}, {4.25f, 5.25f, 6.25f}}, s = 0.375f;
    auto e = effect("float4 A;",
                    "float3x2 a = {A.x, 5, 4, 3, 2, 1}; float2x3 b = {1, 2, 3, A.y, 5.25, 6.25}; float3x4 c = A.z;"
                    "float2x2 r = lerp(a, b, c); return float4(r[0], r[1]);");
    e->Parameters["A"].SetValue(Vector4(a[0][0], b[1][0], s, 0));
    float expected[4];
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) expected[r * 2 + c] = a[r][c] + s * (b[r][c] - a[r][c]);
    expectPixel(draw(*e), expected);
}

// clamp of an int matrix between a float matrix and a literal: float (the highest component
// type), the 2x2 both have; the int literal fills every component.
TEST_P(HlslShapes, ElementwiseIntrinsicConvertsComponentTypesAndScalars) {
    auto e = effect("float4 A;",
                    "int3x3 x = {-4, 1, 9, 3, 7, 2, 0, 0, 0}; float2x4 lo = {A.x, A.x, A.x, A.x, A.y, A.y, A.y, A.y};"
                    "float2x2 r = clamp(x, lo, 5); return float4(r[0], r[1]);");
    const float lo0 = -1.5f, lo1 = 3.5f;
    e->Parameters["A"].SetValue(Vector4(lo0, lo1, 0, 0));
    const float expected[4] = {std::clamp(-4.0f, lo0, 5.0f), std::clamp(1.0f, lo0, 5.0f), std::clamp(3.0f, lo1, 5.0f), std::clamp(7.0f, lo1, 5.0f)};
    expectPixel(draw(*e), expected);
}

// One-column matrices are vectors to glslang: smoothstep(float4x1, float, float3x1) is a float3x1.
// (glslang truncated these vectors before; this pins the helpers' spelling of one-column matrices.)
TEST_P(HlslShapes, ElementwiseIntrinsicOfOneColumnMatrices) {
    auto e = effect("float4 A;", "float4x1 a = {0, 0, 0, 0}; float b = A.w; float3x1 x = {A.x, A.y, A.z};"
                                 "float3x1 r = smoothstep(a, b, x); return float4(r, 1);");
    const float x[3] = {0.25f, 0.5f, 1.5f}, b = 2.0f;
    e->Parameters["A"].SetValue(Vector4(x[0], x[1], x[2], b));
    float expected[4] = {0, 0, 0, 1};
    for (int k = 0; k < 3; ++k) {
        const float t = std::clamp(x[k] / b, 0.0f, 1.0f);
        expected[k] = t * t * (3 - 2 * t);
    }
    expectPixel(draw(*e), expected);
}

// A binary operator between matrices of different shapes computes in the smaller rows and
// columns: float1x4 + float4x4 adds the first row, float4x1 * float4x4 multiplies the first column,
// float3x3 - float2x2 subtracts in the top-left 2x2.
TEST_P(HlslShapes, BinaryOperatorOfMatricesTakesTheSmallerShape) {
    auto e = effect("float4 A;",
                    "float1x4 row = {A.x, A.y, A.z, A.w}; float4x1 column = {A.x, A.y, A.z, A.w};"
                    "float4x4 m = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};"
                    "float3x3 n = {A.x, A.y, 0, A.z, A.w, 0, 0, 0, 0}; float2x2 d = n - m;"
                    "float4 sum = row + m; float4 product = column * m;"
                    "return float4(sum.y, product.z, d[1][0], d[1][1]);");
    const float a[4] = {0.5f, -1.25f, 2.0f, 8.0f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {a[1] + 2, a[2] * 9, a[2] - 5, a[3] - 6};
    expectPixel(draw(*e), expected);
}

// mul with a one-component vector or a one-row/one-column matrix: a vector is a row on the left and
// a column on the right, the inner dimension the smaller one. mul(float1 s, float4x4 m) is s times
// m's first row; mul(float4x4 m, float1x4 r) the outer product of m's first column and r.
TEST_P(HlslShapes, MulWithOneComponentAndOneRowArguments) {
    auto e = effect("float4 A;",
                    "float1 s = A.x; float1x4 r = {A.x, A.y, A.z, A.w};"
                    "float4x4 m = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};"
                    "float4 scaled = mul(s, m); float4 outer = mul(m, r)[2];"
                    "return float4(scaled.y, scaled.w, outer.x, outer.z);");
    const float a[4] = {0.5f, -1.25f, 2.0f, 8.0f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {a[0] * 2, a[0] * 4, 9 * a[0], 9 * a[2]};
    expectPixel(draw(*e), expected);
}

// determinant of a matrix that is not square takes its top-left square; transpose of a one-row
// matrix is the same components as a column.
TEST_P(HlslShapes, DeterminantOfNonSquareAndTransposeOfOneRow) {
    auto e = effect("float4 A;",
                    "float3x4 m = {A.x, 2, 3, 100, 5, A.y, 7, 100, 9, 10, A.z, 100}; float2x3 n = {A.w, 2, 5, 3, 4, 5};"
                    "float1x4 r = {A.x, A.y, A.z, A.w}; float4x1 c = transpose(r);"
                    "return float4(determinant(m), determinant(n), c[1][0], c[3][0]);");
    const float a[4] = {1.5f, -6.0f, 11.0f, 0.25f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float det3 = a[0] * (a[1] * a[2] - 7 * 10) - 2 * (5 * a[2] - 7 * 9) + 3 * (5 * 10 - a[1] * 9);
    const float expected[4] = {det3, a[3] * 4 - 2 * 3, a[1], a[3]};
    expectPixel(draw(*e), expected, 1e-3f);
}

// determinant of a matrix of one row or one column is its first element (the top-left 1x1), as
// for float1x1.
TEST_P(HlslShapes, DeterminantOfOneRowOrOneColumnIsTheFirstElement) {
    auto e = effect("float4 A;",
                    "float2x1 c = {A.y, A.x}; float1x3 r = {A.z, A.x, A.y}; float1x1 one = A.w;"
                    "return float4(determinant(c), determinant(r), determinant(one), 1);");
    const float a[4] = {1.5f, -6.0f, 11.0f, 0.25f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {a[1], a[2], a[3], 1};
    expectPixel(draw(*e), expected);
}

// Uniforms of one row or one column: set as XNA sets a matrix (values row by row), read by
// element, by matrix swizzle, whole (mul of a 1x3 and a 3x1 is their dot product) and through
// determinant (the first element). row_major and column_major differ only in registers.
TEST_P(HlslShapes, OneRowAndOneColumnUniformsReadTheValuesSet) {
    auto e = effect("float1x3 r; float3x1 c; row_major float1x2 rr; row_major float2x1 rc; float1x1 one;",
                    "return float4(r[0][2] + 10 * c[1][0], rr._m01 + 10 * rc._m10, mul(r, c), determinant(c) + one[0][0]);");
    const std::vector<float> r = {0.5f, -2.0f, 3.0f}, c = {1.5f, 0.25f, -4.0f}, rr = {7.0f, -1.0f}, rc = {2.0f, 0.75f};
    e->Parameters["r"].SetValue(r);
    e->Parameters["c"].SetValue(c);
    e->Parameters["rr"].SetValue(rr);
    e->Parameters["rc"].SetValue(rc);
    e->Parameters["one"].SetValue(std::vector<float>{-6.0f});
    const float expected[4] = {r[2] + 10 * c[1], rr[1] + 10 * rc[1], r[0] * c[0] + r[1] * c[1] + r[2] * c[2], c[0] - 6.0f};
    expectPixel(draw(*e), expected);
}

// Matrix swizzles of local one-row and one-column matrices (`_m01`, `_31`, several elements)
// read the components of their line.
TEST_P(HlslShapes, MatrixSwizzlesOfOneRowAndOneColumnLocals) {
    auto e = effect("float4 A;", "float1x3 l = A.xyz; float3x1 k = A.yzw; return float4(l._m01, k._31, l._m00_m02);");
    const float a[4] = {1.5f, -6.0f, 11.0f, 0.25f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {a[1], a[3], a[0], a[2]};
    expectPixel(draw(*e), expected);
}

// An array passed to a parameter that is an array of another shape with as many elements: the
// elements in order (float a[2][3] from a float f[3][2] or a float g[6]).
TEST_P(HlslShapes, ArrayArgumentOfAnotherShapeTakesElementsInOrder) {
    auto e = effect("float4 A; float pick(float a[2][3], float s) { return s * (a[0][2] + 10 * a[1][0]); }",
                    "float f[3][2] = {{A.x, A.y}, {A.z, A.w}, {5, 6}}; float g[6] = {A.w, A.z, A.y, A.x, 1, 2};"
                    "return float4(pick(f, 1), pick(g, 2), 0, 1);");
    const float a[4] = {1.5f, -6.0f, 11.0f, 0.25f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    // f's elements in order: x y z w 5 6 -> a[0][2] = z, a[1][0] = w; g's: w z y x 1 2 -> y, x.
    const float expected[4] = {a[2] + 10 * a[3], 2 * (a[1] + 10 * a[0]), 0, 1};
    expectPixel(draw(*e), expected);
}

// A function of the effect named like an intrinsic is called wherever the arguments convert to
// its parameters (scalars fill its float2s); the intrinsic only where they do not (a float2 cannot
// become the float3 it takes).
TEST_P(HlslShapes, EffectFunctionNamedLikeAnIntrinsicIsCalledWhereArgumentsConvert) {
    auto e = effect("float4 A; float2 max(float2 a, float3 b) { return a + b.xy; }",
                    "float2 user = max(A.x, A.y); float2 builtin = max(A.zw, A.wz); return float4(user, builtin);");
    const float a[4] = {0.125f, 0.5f, -2.0f, 3.0f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {a[0] + a[1], a[0] + a[1], std::max(a[2], a[3]), std::max(a[3], a[2])};
    expectPixel(draw(*e), expected);
}

// `c ? a : b` with a matrix condition selects component by component.
TEST_P(HlslShapes, MatrixConditionSelectsComponentByComponent) {
    auto e = effect("float4 A;", "float2x2 c = {A.x, 0, 0, A.y}; float2x2 a = {1, 2, 3, 4}; float2x2 b = {5, 6, 7, 8};"
                                 "float2x2 r = c ? a : b; return float4(r[0], r[1]);");
    e->Parameters["A"].SetValue(Vector4(1.0f, 0.0f, 0, 0));
    const float expected[4] = {1, 6, 7, 8};
    expectPixel(draw(*e), expected);
}

// `*` between two matrices multiplies component by component, as fxc does (mul() is the matrix
// product): float2x2 * float2x2 and `*=` (glslang's OpMatrixTimesMatrix before).
TEST_P(HlslShapes, SquareMatrixTimesMatrixIsPerComponent) {
    const float a[4] = {0.5f, -1.25f, 2.0f, 8.0f}, b[4] = {3.0f, 0.25f, -2.0f, 1.5f};
    auto e = effect("float4 A; float4 B;",
                    "float2x2 a = {A.x, A.y, A.z, A.w}; float2x2 b = {B.x, B.y, B.z, B.w};"
                    "float2x2 p = a * b; a *= b; return float4(p[0][1], p[1][0], a[0][0], a[1][1]);");
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    e->Parameters["B"].SetValue(Vector4(b[0], b[1], b[2], b[3]));
    const float expected[4] = {a[1] * b[1], a[2] * b[2], a[0] * b[0], a[3] * b[3]};
    expectPixel(draw(*e), expected);
}

// The same for float2x3 * float2x3 (refused before) and float3x3 * float2x2, in the smaller shape.
TEST_P(HlslShapes, NonSquareAndMixedMatrixTimesMatrixArePerComponent) {
    const float a[4] = {0.5f, -1.25f, 2.0f, 8.0f}, b[4] = {3.0f, 0.25f, -2.0f, 1.5f};
    auto e = effect("float4 A; float4 B;",
                    "float2x2 b = {B.x, B.y, B.z, B.w};"
                    "float2x3 c = {A.x, A.y, 1, A.z, A.w, 2}; float2x3 d = {B.y, B.x, 3, B.w, B.z, 4};"
                    "float3x3 n = {A.w, A.z, 0, A.y, A.x, 0, 0, 0, 1};"
                    "float2x3 q = c * d; float2x2 r = n * b; c *= d;"
                    "return float4(q[1][0], q[0][2], r[1][0], c[0][1]);");
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    e->Parameters["B"].SetValue(Vector4(b[0], b[1], b[2], b[3]));
    const float expected[4] = {a[2] * b[3], 1 * 3, a[1] * b[2], a[1] * b[0]};
    expectPixel(draw(*e), expected);
}

// A comparison of matrices is a bool matrix, per component (glslang crashed on it), stored, passed
// to any() or used as a `?:` condition.
TEST_P(HlslShapes, MatrixComparisonsGiveBoolMatrices) {
    const float a[4] = {0.5f, -1.25f, 2.0f, 8.0f};
    auto e = effect("float4 A;",
                    "float2x2 m = {A.x, A.y, A.z, A.w}; bool2x2 b = m > 1; float2x2 f = (m > 1) ? m : 0;"
                    "return float4(b[0][1] + 2 * b[1][1], any(m > 7), f[1][0], f[0][0]);");
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    const float expected[4] = {float(int(a[1] > 1) + 2 * int(a[3] > 1)), float(a[0] > 7 || a[1] > 7 || a[2] > 7 || a[3] > 7),
                               a[2] > 1 ? a[2] : 0, a[0] > 1 ? a[0] : 0};
    expectPixel(draw(*e), expected);
}

// Matrix products per component also where the whole expression is beyond the rewrite's typer
// or no assignment holds it: a `for` condition and an array index. a * b is {1, 2, 3, 4} per
// component; a matrix product would give {3, 3, 7, 7} or, in glslang's transposed storage,
// {4, 4, 6, 6}.
TEST_P(HlslShapes, MatrixTimesMatrixInLoopConditionsAndIndices) {
    auto e = effect("float4 A; float4 B;",
                    "float2x2 a = {A.x, A.y, A.z, A.w}; float2x2 b = {B.x, B.y, B.z, B.w};"
                    "float n = 0; for (int k = 0; k < (int)(a * b)[1][1]; ++k) n += 1;"
                    "float4 v = {10, 11, 12, 13}; return float4(n, v[(int)(a * b)[0][1]], v[(int)(a * b)[1][0]], 0);");
    e->Parameters["A"].SetValue(Vector4(1, 2, 3, 4));
    e->Parameters["B"].SetValue(Vector4(1, 1, 1, 1));
    const float expected[4] = {4, 12, 13, 0};
    expectPixel(draw(*e), expected);
}

// The same inside a method's arguments (SM4+): the expression around it (T.Load(...)) has no
// type to the rewrite, its arguments do. Texel (x, y) holds (x, y).
class HlslShapesSm4 : public HlslShapes {};
TEST_P(HlslShapesSm4, MatrixTimesMatrixInMethodArguments) {
    Texture2D tex(device, 8, 8, false, SurfaceFormat::Vector4);
    std::vector<Vector4> texels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) texels.emplace_back(float(x), float(y), 0.0f, 1.0f);
    tex.SetData(texels.data(), texels.size());
    auto e = effect("float4 A; float4 B; Texture2D<float4> T;",
                    "float2x2 a = {A.x, A.y, A.z, A.w}; float2x2 b = {B.x, B.y, B.z, B.w};"
                    "float4 t = T.Load(int3((a * b)[0], 0)); return float4(t.xy, T.Load(int3((a * b)[1], 0)).xy);");
    e->Parameters["T"].SetValue(&tex);
    e->Parameters["A"].SetValue(Vector4(1, 2, 3, 4));
    e->Parameters["B"].SetValue(Vector4(1, 1, 1, 1));
    const float expected[4] = {1, 2, 3, 4};
    expectPixel(draw(*e), expected);
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslShapesSm4, ::testing::Values("4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslShapes, ::testing::Values("2_0", "3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
