// HLSL operations compute what fxc and D3D compute: each shader here is drawn into a 1x1 float
// target at SM2..SM5, and its result compared with the same operation written in C++ with fxc's
// meaning (the independent reference). Values come in as uniforms, so the GPU computes them, and
// as literals, so glslang's and spirv-opt's constant folding is checked too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "one_pixel_effect.h"
#include "runtime_test_support.h"

namespace fxport::test {
namespace {

class HlslSemantics : public OnePixelEffect {};

// `%` truncates like C's fmod, whatever the signs (GLSL's mod() floors: 42 % -5 would be -3).
TEST_P(HlslSemantics, FloatRemainderTruncatesTowardZero) {
    const float a[4] = {42, -42, 0.42f, -4.21f}, b[4] = {-5, 5, 0.05f, -0.5f};
    auto fromUniforms = effect("float4 A; float4 B;", "return A % B;");
    fromUniforms->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    fromUniforms->Parameters["B"].SetValue(Vector4(b[0], b[1], b[2], b[3]));
    auto fromLiterals = effect("", "float4 x = float4(42, -42, 0.42, -4.21); float4 y = float4(-5, 5, 0.05, -0.5); return x % y;");
    auto viaFmod = effect("float4 A; float4 B;", "return fmod(A, B);");
    viaFmod->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    viaFmod->Parameters["B"].SetValue(Vector4(b[0], b[1], b[2], b[3]));
    for (Effect* e : {fromUniforms.get(), fromLiterals.get(), viaFmod.get()}) {
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], std::fmod(a[k], b[k]), 2e-6) << "channel " << k;
    }
}

// A global `const` without a value is a uniform the shader may not write (fxc puts it in the
// constant buffer), not a constant 0.
TEST_P(HlslSemantics, GlobalConstWithoutValueIsAUniform) {
    auto e = effect("const float4 A; const uniform float4 B; const float4 C = float4(0.5, 0.5, 0.5, 0.5);", "return A + B + C;");
    e->Parameters["A"].SetValue(Vector4(1, 2, 3, 4));
    e->Parameters["B"].SetValue(Vector4(0.125f, 0.25f, 0.375f, 0.5f));
    std::vector<float> px = draw(*e);
    const float expected[4] = {1.625f, 2.75f, 3.875f, 5.0f};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// Integer `/` and `%` truncate toward zero at every shader model (SM2/3 emulate ints with floats;
// fxc still truncates the quotient).
TEST_P(HlslSemantics, IntegerDivisionAndRemainderTruncateTowardZero) {
    const int a[4] = {42, -42, 42, -45}, b[4] = {5, 5, -5, -5};
    auto fromUniforms = effect("int4 A; int4 B;", "return float4(A / B) + float4(A % B) / 100.0;");
    fromUniforms->Parameters["A"].SetValue(std::vector<int>(a, a + 4));
    fromUniforms->Parameters["B"].SetValue(std::vector<int>(b, b + 4));
    auto fromLiterals = effect("", "int4 x = int4(42, -42, 42, -45); int4 y = int4(5, 5, -5, -5); return float4(x / y) + float4(x % y) / 100.0;");
    for (Effect* e : {fromUniforms.get(), fromLiterals.get()}) {
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], float(a[k] / b[k]) + float(a[k] % b[k]) / 100.0f, 1e-5) << "channel " << k;
    }
}

// Brace initializers written flat fill the declared type's components in order: array elements,
// struct members, matrix rows (fxc); glslang wants them nested (xlate/src/rewrite/initializer_lists.cpp).
TEST_P(HlslSemantics, FlatBraceInitializersFillComponentsInOrder) {
    struct Case {
        const char* globals;
        const char* body;
        float expected[4];
    };
    const Case cases[] = {
        {"static const float2 o[2] = {1, 2, 3, -4.5};", "return float4(o[0], o[1]);", {1, 2, 3, -4.5f}},
        {"", "float2x2 m = {1, 2, 3, 4}; return float4(m[0], m[1]);", {1, 2, 3, 4}},
        {"", "float4 v[2] = {1, 2, 3, 4, 5, 6, 7, 8}; return v[1];", {5, 6, 7, 8}},
        {"struct S { float a; float2 b; float c; };", "S s = {1, float2(2, 3), 4}; return float4(s.a, s.b, s.c);", {1, 2, 3, 4}},
        {"static const float2 q[] = {1, 2, 3, 4, 5, 6};", "return float4(q[2], q[1]);", {5, 6, 3, 4}},
        {"struct P { float2 xy; }; static const P ps[2] = {0.25, 0.5, 0.75, 1};", "return float4(ps[1].xy, ps[0].xy);", {0.75f, 1, 0.25f, 0.5f}},
        // A vector's list with nested braces fills it in order too (glslang alone gives 1, 4, 0, 0).
        {"", "float4 v = {1, {{{2, {3}}, 4}}}; return v;", {1, 2, 3, 4}},
    };
    for (const Case& c : cases) {
        auto e = effect(c.globals, c.body);
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], c.expected[k]) << c.globals << " " << c.body << " channel " << k;
    }
}

// Casts through bool: nonzero is true, true is 1 (fxc); any() of a scalar and a vector.
TEST_P(HlslSemantics, BoolCastsAndAny) {
    auto e = effect("float4 X; int4 Y; float S;",
                    "return (float4)(bool4)X + 10.0 * (float4)(int4)(bool4)Y + 100.0 * float4(any(S), any(X), any(Y.xz), (float)(bool)S);");
    e->Parameters["X"].SetValue(Vector4(0, 0, 2, -4));
    e->Parameters["Y"].SetValue(std::vector<int>{0, 1, 0, -10});
    e->Parameters["S"].SetValue(0.5f);
    std::vector<float> px = draw(*e);
    const float expected[4] = {0 + 0 + 100, 0 + 10 + 100, 1 + 0 + 0, 1 + 10 + 100};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// fxc expands asin/acos/atan/atan2 into fixed polynomials (D3D bytecode has no such instruction);
// the reference is that expansion written in C++ (float, in fxc's order), e.g. asin(0) = 6.75e-5.
namespace fxc {
float acosPoly(float a) { return ((-0.0187292993f * a + 0.0742610022f) * a - 0.212114394f) * a + 1.57072878f; }
float acos(float x) {
    float a = std::fabs(x), r = acosPoly(a) * std::sqrt(1.0f - a);
    return x < 0 ? r + (r * -2.0f + 3.14159274f) : r;
}
float asin(float x) {
    float a = std::fabs(x), r = 1.57079637f - acosPoly(a) * std::sqrt(1.0f - a);
    return x < 0 ? -r : r;
}
float atanPoly(float t) {
    float t2 = t * t;
    return t * ((((0.0208350997f * t2 - 0.0851330012f) * t2 + 0.180141002f) * t2 - 0.330299497f) * t2 + 0.999866009f);
}
float atan(float x) {
    float a = std::fabs(x), r = atanPoly(std::min(a, 1.0f) * (1.0f / std::max(a, 1.0f)));
    if (a > 1) r = r + (r * -2.0f + 1.57079637f);
    return x < 0 ? -r : r;
}
float atan2(float y, float x) {
    float ax = std::fabs(x), ay = std::fabs(y), r = atanPoly(std::min(ax, ay) * (1.0f / std::max(ax, ay)));
    if (ax < ay) r = r + (r * -2.0f + 1.57079637f);
    if (x < 0) r -= 3.14159274f;
    return std::min(y, x) < 0 && std::max(y, x) >= 0 ? -r : r;
}
}  // namespace fxc

TEST_P(HlslSemantics, InverseTrigonometryIsFxcsExpansion) {
    // The C++ expansion against values D3D produced (vkd3d's inverse-trig tests, SM < 6).
    EXPECT_EQ(std::round(fxc::asin(0) * 20000), 1);
    EXPECT_EQ(std::round(fxc::asin(-0.5f) * 20000), -10473);
    EXPECT_NEAR(fxc::acos(0), 1.57072878f, 1e-7);
    EXPECT_NEAR(fxc::acos(-0.5f), 2.094441441f, 3e-7);
    EXPECT_NEAR(fxc::atan(1), 0.785409629f, 1e-7);
    EXPECT_NEAR(fxc::atan2(5, -5), 2.356194f, 3e-5);
    const float xs[] = {-1, -0.5f, 0, 0.25f, 0.5f, 1};
    const float ys[][2] = {{1, 1}, {5, -5}, {-3, -3}, {1, 0}, {-1, 0}, {0, -1}, {1e-5f, -2e-5f}, {0.3f, 4}};
    auto e = effect("float2 A;", "return float4(asin(A.x), acos(A.x), atan(A.x * 3.0), atan2(A.x, A.y));");
    for (float x : xs) {
        e->Parameters["A"].SetValue(Vector2(x, 0.75f));
        std::vector<float> px = draw(*e);
        EXPECT_NEAR(px[0], fxc::asin(x), 2e-6) << "asin(" << x << ")";
        EXPECT_NEAR(px[1], fxc::acos(x), 2e-6) << "acos(" << x << ")";
        EXPECT_NEAR(px[2], fxc::atan(x * 3), 2e-6) << "atan(" << x * 3 << ")";
        EXPECT_NEAR(px[3], fxc::atan2(x, 0.75f), 2e-6) << "atan2(" << x << ", 0.75)";
    }
    for (const auto& yx : ys) {
        e->Parameters["A"].SetValue(Vector2(yx[0], yx[1]));
        EXPECT_NEAR(draw(*e)[3], fxc::atan2(yx[0], yx[1]), 2e-6) << "atan2(" << yx[0] << ", " << yx[1] << ")";
    }
    auto vec = effect("float4 V;", "return asin(V) + acos(V.wzyx) * 10.0;");
    vec->Parameters["V"].SetValue(Vector4(-1, -0.5f, 0, 0.5f));
    std::vector<float> px = draw(*vec);
    const float v[4] = {-1, -0.5f, 0, 0.5f};
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], fxc::asin(v[k]) + fxc::acos(v[3 - k]) * 10.0f, 2e-5) << "channel " << k;
}

// lit(n.l, n.h, m) = (1, max(n.l, 0), n.l < 0 || n.h < 0 ? 0 : pow(n.h, m), 1) (D3D's definition).
TEST_P(HlslSemantics, LitRaisesTheHalfVectorTermToThePower) {
    auto e = effect("float3 L;", "return lit(L.x, L.y, L.z);");
    const float cases[][3] = {{1.2f, 2.0f, 3.0f}, {-0.1f, 10.0f, 0.0f}, {1.2f, -0.1f, 0.0f}, {0.5f, 0.8f, 16.0f}};
    for (const auto& c : cases) {
        e->Parameters["L"].SetValue(Vector3(c[0], c[1], c[2]));
        std::vector<float> px = draw(*e);
        const float expected[4] = {1, std::max(c[0], 0.0f), c[0] < 0 || c[1] < 0 ? 0.0f : std::pow(c[1], c[2]), 1};
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[k], 1e-5 * std::max(1.0f, expected[k])) << "lit(" << c[0] << ", " << c[1] << ", " << c[2] << ") channel " << k;
    }
}

// ldexp(x, e) = x * 2^e for any float e (fxc: exp then mul); GLSL's ldexp takes an int exponent,
// which truncated 0.5 to 0 and -1.5 to -1.
TEST_P(HlslSemantics, LdexpRaisesTwoToAFractionalExponent) {
    const float x[4] = {3, 3, -2, 5}, e[4] = {0.5f, -1.5f, 2.25f, 3};
    auto fromUniforms = effect("float4 X; float4 E;", "return ldexp(X, E);");
    fromUniforms->Parameters["X"].SetValue(Vector4(x[0], x[1], x[2], x[3]));
    fromUniforms->Parameters["E"].SetValue(Vector4(e[0], e[1], e[2], e[3]));
    auto fromLiterals = effect("", "return ldexp(float4(3, 3, -2, 5), float4(0.5, -1.5, 2.25, 3));");
    for (Effect* fx : {fromUniforms.get(), fromLiterals.get()}) {
        std::vector<float> px = draw(*fx);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], x[k] * std::exp2(e[k]), 2e-5 * std::fabs(x[k] * std::exp2(e[k]))) << "channel " << k;
    }
}

// fxc folds constants and refuses a divisor that folds to zero: integers at every model, floats
// at SM2-3 (SM4+ computes inf). The error names the entry point.
TEST_P(HlslSemantics, DivisionByAConstantZeroIsRefusedAsFxcRefusesIt) {
    const bool sm2or3 = GetParam()[0] < '4';
    EXPECT_THROW(draw(*effect("", "int x = 7; int y = 0; return float4(x / y, 0, 0, 0);")), xlate::CompileError);
    EXPECT_THROW(draw(*effect("", "uint x = 7; uint y = 0; return float4(x % y, 0, 0, 0);")), xlate::CompileError);
    if (sm2or3) {
        EXPECT_THROW(draw(*effect("", "float x = 1; float y = 0; return x / y;")), xlate::CompileError);
    } else {
        auto e = effect("", "float x = 1; float y = 0; return x / y;");
        EXPECT_TRUE(std::isinf(draw(*e)[0]));
    }
    auto fine = effect("int D;", "int x = 7; return float4(x / D, 0, 0, 0);");  // not a constant
    fine->Parameters["D"].SetValue(2);
    EXPECT_FLOAT_EQ(draw(*fine)[0], 3.0f);
}

// Matrices of one row or one column are vectors of as many components to fxc wherever they meet
// one: constructors, brace lists, returns, arguments; `m[0]` of a 1xN is its row, `m[i][0]` of an
// Nx1 its component i; a 1x1 is a scalar.
TEST_P(HlslSemantics, OneRowAndOneColumnMatricesActAsVectors) {
    const float a[4] = {0.5f, -1.25f, 3.0f, 8.0f};
    struct Case {
        const char* globals;
        const char* body;
        float expected[4];
    };
    const Case cases[] = {
        {"float4 A;", "float1x4 m = float1x4(A.x, A.y, A.z, A.w); return m[0] * 2;", {2 * a[0], 2 * a[1], 2 * a[2], 2 * a[3]}},
        {"float4 A;", "float4x1 c = {A.w, A.z, A.y, A.x}; return float4(c[0][0], c[1], c[2][0], c[3]);", {a[3], a[2], a[1], a[0]}},
        {"float4 A; float3 F(float1x3 m) { return m; }", "return float4(F(A.xyz), 1);", {a[0], a[1], a[2], 1}},
        {"float4 A; float4x1 G() { return A.wzyx; }", "return G();", {a[3], a[2], a[1], a[0]}},
        {"float4 A; float3 H() { return float4x1(A.x, A.y, A.z, A.w); }", "return float4(H(), 0);", {a[0], a[1], a[2], 0}},
        {"float4 A;", "float1x1 s = A.y; matrix<float, 1, 2> p = {A.z, s[0][0]}; return float4(p[0], s * 2, s);", {a[2], a[1], 2 * a[1], a[1]}},
        {"float4 A; static float1x4 K = {1, 2, 3, 4};", "return (float4)K + A;", {1 + a[0], 2 + a[1], 3 + a[2], 4 + a[3]}},
        {"float4 A; static float1x4 K = {1, 2, 3, 4};", "float1x4 q = A; return (A.x > 0 ? K : q)[0];", {1, 2, 3, 4}},
        {"float4 A; static float1x4 C = {1, 0, 0, 1};", "return (C ? A : -A)[0];", {a[0], a[0], a[0], a[0]}},
    };
    for (const Case& c : cases) {
        auto e = effect(c.globals, c.body);
        e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], c.expected[k]) << c.globals << " " << c.body << " channel " << k;
    }
}

// What fxc refuses of those conversions (X3017, X3013): a matrix to one of other rows or columns,
// a vector into a column of another size, a matrix where an intrinsic takes vectors.
TEST_P(HlslSemantics, OneRowAndOneColumnMatrixMismatchesAreRefused) {
    const char* const refused[][2] = {
        {"float3x1 F() { return float1x3(1, 2, 3); }", "return float4(F(), 0);"},
        {"", "float4 v = float4(1, 2, 3, 4); float3x1 m = (float3x1)v; return m[0][0];"},
        {"", "float2x2 m = {1, 2, 3, 4}; return float4((float3)m, 0);"},
        {"", "float4x1 v = 0; return dot(v, v);"},
    };
    for (const auto& r : refused) EXPECT_THROW(draw(*effect(r[0], r[1])), xlate::CompileError) << r[0] << " " << r[1];
    // A vector into a row takes its first components, as fxc does.
    auto fine = effect("float1x3 F() { return float4(1, 2, 3, 4); }", "return float4(F(), 0);");
    std::vector<float> px = draw(*fine);
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], k < 3 ? float(k + 1) : 0.0f) << "channel " << k;
}

// A cast on the left of '=' assigns the target's first components, the value converted by the
// outermost cast (fxc); changing the component type there is refused from SM4 on (X3025).
TEST_P(HlslSemantics, CastOnTheLeftAssignsTheFirstComponents) {
    const float a[4] = {0.5f, -1.25f, 3.0f, 8.0f};
    struct Case {
        const char* body;
        float expected[4];
    };
    const Case cases[] = {
        {"float4 p = {-1, -2, -3, -4}; (float2) p = A.yz; return p;", {a[1], a[2], -3, -4}},
        {"float4 p = 0; (float4) p = A; return p;", {a[0], a[1], a[2], a[3]}},
        {"float4 p = {-1, -2, -3, -4}; (float2) p.yz = A.yz; return p;", {-1, a[1], a[2], -4}},
        {"float4 p = 0; (float) p = A.w; return p;", {a[3], 0, 0, 0}},
    };
    for (const Case& c : cases) {
        auto e = effect("float4 A;", c.body);
        e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], c.expected[k]) << c.body << " channel " << k;
    }
    const char* changesType = "float4 p = 0; (int4)(half4) p = A * 3; return p;";
    if (GetParam()[0] >= '4') {
        EXPECT_THROW(draw(*effect("float4 A;", changesType)), xlate::CompileError);
    } else {
        auto e = effect("float4 A;", changesType);
        e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], std::trunc(3 * a[k])) << "channel " << k;
    }
}

// Casts between arrays, structs and vectors take the source's components in order: array
// elements, struct members, vector components; arrays and structs whose components have the
// same types assign to each other.
TEST_P(HlslSemantics, ComponentwiseCastsTakeComponentsInOrder) {
    const float a[4] = {0.5f, -1.25f, 3.0f, 8.0f};
    struct Case {
        const char* globals;
        const char* body;
        float expected[4];
    };
    const char* s = "float4 A; struct S { float3 aa; int bb; }; struct P { float2 a; float b; float c; };";
    const Case cases[] = {
        {s, "float f[5] = {A.x, A.y, A.z, A.w, 9}; return (float4) f + 1;", {a[0] + 1, a[1] + 1, a[2] + 1, a[3] + 1}},
        {s, "float f[4] = {A.x, A.y, A.z, A.w}; S t; t = (S) f; return float4(t.aa, t.bb);", {a[0], a[1], a[2], std::trunc(a[3])}},
        {s, "S t = {1, 2, 3, 7}; float f[4]; f = (float[4]) t; return float4(f) + A;", {1 + a[0], 2 + a[1], 3 + a[2], 7 + a[3]}},
        {s, "float f[4] = {A.w, A.z, A.y, A.x}; P p; p = f; return float4(p.a, p.b, p.c);", {a[3], a[2], a[1], a[0]}},
    };
    for (const Case& c : cases) {
        auto e = effect(c.globals, c.body);
        e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], c.expected[k]) << c.body << " channel " << k;
    }
    // A matrix takes exactly its count (X3017).
    EXPECT_THROW(draw(*effect("", "float f[5] = {1, 2, 3, 4, 5}; float2x2 m = (float2x2) f; return float4(m[0], m[1]);")), xlate::CompileError);
}

// normalize, determinant, transpose, reflect and refract of scalars, as fxc computes them:
// x / |x|, x, x, i - 2n(in), and refract's formula on one component (0 past the critical angle).
TEST_P(HlslSemantics, VectorIntrinsicsOfScalars) {
    const float a[4] = {0.5f, -1.25f, 0.6f, 0.2f};
    auto e = effect("float4 A;",
                    "float x = A.y; float i = A.x; float1 n = A.z; float eta = A.w;"
                    "return float4(normalize(x), determinant(x) + transpose(3), reflect(i, n), refract(i, n, eta));");
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    std::vector<float> px = draw(*e);
    const float i = a[0], n = a[2], eta = a[3], c = i * n, k = 1 - eta * eta * (1 - c * c);
    const float expected[4] = {-1.0f, a[1] + 3, i - 2 * n * (i * n), eta * i - (eta * c + std::sqrt(k)) * n};
    for (int ch = 0; ch < 4; ++ch) EXPECT_NEAR(px[size_t(ch)], expected[ch], 1e-5f) << "channel " << ch;
}

// A struct member may name its struct type with the `struct` keyword, as a variable may.
TEST_P(HlslSemantics, StructKeywordInAMemberType) {
    auto e = effect("float4 A; struct In { float2 v; }; struct Out { struct In a; float c; };",
                    "Out o; o.a.v = A.xy; o.c = A.z; return float4(o.a.v, o.c, 1);");
    e->Parameters["A"].SetValue(Vector4(0.5f, -1.25f, 3.0f, 8.0f));
    std::vector<float> px = draw(*e);
    const float expected[4] = {0.5f, -1.25f, 3.0f, 1.0f};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslSemantics, ::testing::Values("2_0", "3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
