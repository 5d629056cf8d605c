// Valid HLSL that fxc compiles and glslang's HLSL front end refuses as written, compiled at SM2..SM5
// and drawn into a 1x1 float target: each result is compared with the value the HLSL means (worked
// out in C++ beside it), so a rewrite that compiles but computes something else fails too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "one_pixel_effect.h"
#include "runtime_test_support.h"

namespace fxport::test {
namespace {

class HlslAcceptedForms : public OnePixelEffect {
protected:
    void expectPixel(const std::string& globals, const std::string& body, const float (&expected)[4], const Vector4& a = {}) {
        SCOPED_TRACE(globals + " | " + body);
        auto e = effect("float4 A;\n" + globals, body);
        e->Parameters["A"].SetValue(a);
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    }
};

// The forms that exist only from SM4 (Texture2D.Sample, int/uint overloads) or SM5 (pixel-shader UAVs)
// run at those models only.
class HlslAcceptedFormsSm4 : public HlslAcceptedForms {};
class HlslAcceptedFormsSm5 : public HlslAcceptedForms {};

// side-effects L33: fxc calls the index's function before the base's (xlate/src/rewrite/
// index_evaluation_order.h): the index call sees i = 1 (1.1 -> element 1), the base call i = 2,
// so element 1 of (2.1, 2.2, 2.3, 2.4); base first would give element 2 of (1.1 ... 1.4), 1.3.
TEST_P(HlslAcceptedForms, SubscriptIndexCallRunsBeforeItsBaseCall) {
    expectPixel("float4 bump() { static uint i; i += 1; return float4(0.1, 0.2, 0.3, 0.4) + i; }", "return bump()[bump().x];",
                {2.2f, 2.2f, 2.2f, 2.2f});
}

// Struct definitions that also declare variables, anonymous ones, and ones inside another struct's
// member list (xlate/src/rewrite/struct_definitions.cpp).
TEST_P(HlslAcceptedForms, StructDefinitionsWithDeclarators) {
    // An anonymous struct typing a static constant, its members filled from a flat list.
    expectPixel("static const struct { float a; float2 b; } s = {1, 2, 3};", "return float4(s.a, s.b, A.x);", {1, 2, 3, 0.5f}, {0.5f, 0, 0, 0});
    // A named definition with a declarator, then used by name again.
    expectPixel("static struct apple { float4 f; } g;", "apple h; h.f = A; g = h; return g.f * 2;", {1, -2, 3, 8}, {0.5f, -1, 1.5f, 4});
    // An anonymous struct as a member of a struct (in a local variable), two levels deep.
    expectPixel("struct Outer { struct { float2 u; struct { float w; } deep; } inner; float v; };",
                "Outer o; o.inner.u = A.xy; o.inner.deep.w = A.z; o.v = A.w; return float4(o.v, o.inner.deep.w, o.inner.u);",
                {4, 3, 1, 2}, {1, 2, 3, 4});
    // An anonymous struct declared in a function body.
    expectPixel("", "struct { float a; float b; } t; t.a = A.y; t.b = A.x; return float4(t.a, t.b, t.a + t.b, 1);", {2, 1, 3, 1}, {1, 2, 0, 0});
}

// Array sizes written as constant expressions: arithmetic, a local constant, a float (truncated)
// and a bool (xlate/src/rewrite/array_sizes.cpp); flat initializers of such arrays fill them in order.
TEST_P(HlslAcceptedForms, ArraySizesFromConstantExpressions) {
    expectPixel("static const float2 g[(2 + 1) * 2] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};", "return float4(g[5], g[1]);", {11, 12, 3, 4});
    expectPixel("static const int n = 3;", "float2 a[n - 1][1 + 1] = {1, 2, 3, 4, 5, 6, 7, 8}; return float4(a[1][0], a[0][1]);", {5, 6, 3, 4});
    expectPixel("", "const int dim = 4; float a[2 * 2] = {A.x, A.y, A.z, A.w}; float b[4.1] = a; float c[dim] = b; float d[true] = {c[3]};"
                " return float4(d[0], c[0], b[1], a[2]);",
                {4, 1, 2, 3}, {1, 2, 3, 4});
    if (std::string(GetParam())[0] >= '4')  // a multisample texture's sample count, SM4 and later
        expectPixel("static const int size = 2; Texture2DMS<float4, size - 1> t;", "return A;", {1, 2, 3, 4}, {1, 2, 3, 4});
}

// A local constant sizes arrays only in its own block: two functions each with `const int n`
// (Intel ASSAO's vaSimpleShadowMap.hlsl: 6 and 14 samples), an inner block's n hiding the
// function's, and a global n hidden by neither outside them. Each array's flat list fills it in order.
TEST_P(HlslAcceptedForms, LocalConstantSizesInTheirOwnScope) {
    const std::string functions =
        "static const int n = 2;\n"
        "float2 a() { const int n = 3; const float2 o[n] = {1, 2, 3, 4, 5, 6}; return o[n - 1]; }\n"
        "float2 b() { const int n = 4; const float2 o[n] = {1, 2, 3, 4, 5, 6, 7, 8}; float2 s = o[n - 1];\n"
        "  { const int n = 1; const float2 p[n] = {10, 20}; s += p[0]; } const float q[n] = {1, 2, 3, 4}; return s + q[n - 1]; }\n"
        "float2 c() { const float2 o[n] = {9, 8, 7, 6}; return o[n - 1]; }\n";
    // a(): o[2] = (5, 6); b(): o[3] + p[0] + q[3] = (7 + 10 + 4, 8 + 20 + 4); c(): o[1] = (7, 6).
    expectPixel(functions, "return float4(a().x, b(), c().x) + A;", {5, 21, 32, 7});
}

// A uniform array sized by its initializer (NVIDIA SoftShadows' Poisson.fxh): three elements whose
// defaults are the listed values, read back by the shader.
TEST_P(HlslAcceptedForms, UniformArraySizedByItsInitializer) {
    expectPixel("float2 P[] = { {1, 2}, {3, 4}, {5, 6} }; float Q[] = {7, 8};", "return float4(P[0] + P[2], P[1].y, Q[1]) + A;", {6, 8, 4, 8});
}

// Brace initializers that name variables: each variable gives its components in fxc's order
// (xlate/src/rewrite/initializer_lists.cpp with aggregate_components.h).
TEST_P(HlslAcceptedForms, BraceInitializersNamingVariables) {
    expectPixel("", "int4 aa = int4(A); float4 foo[3] = {1, aa, aa, 2, 3, 4}; return foo[1];", {40, 10, 20, 30}, {10, 20, 30, 40});
    expectPixel("struct stu { float aa; int bb; };", "stu foo = {A.x, 3}; float4 f = {1.0, foo, 4.0}; return f;", {1, 0.25f, 3, 4}, {0.25f, 0, 0, 0});
    expectPixel("", "float s = A.y; int arr[3] = {2, 3, 4}; float4 f = {s, arr}; return f;", {-1.5f, 2, 3, 4}, {0, -1.5f, 0, 0});
}

// Component-wise casts and constructors (xlate/src/rewrite/componentwise_casts.cpp): structs holding a
// texture (the texture is one component, taken only by a texture), a float4x1 cast to a shorter
// array, an array spelled out among a constructor's arguments, an int matrix made a vector.
TEST_P(HlslAcceptedForms, ComponentwiseCastsAndConstructors) {
    const std::string fruit = "Texture2D tex; struct apple { int2 aa; Texture2D bb; float cc; }; struct banana { float aa[2]; Texture2D bb; int cc; };";
    expectPixel(fruit, "float v = A.x; struct apple a = {1, 2, tex, v}; struct banana b; b = (struct banana) a; return float4(b.aa[0], b.aa[1], b.cc, 0);",
                {1, 2, 7, 0}, {7.25f, 0, 0, 0});
    expectPixel("struct apple { int2 aa; Texture2D bb; float cc; }; struct pear { int aa[2]; Texture2D bb; float cc; }; Texture2D tex;",
                "float v = A.y; struct apple a = {3, 4, tex, v}; struct pear p; p = a; return float4(p.aa[0], p.aa[1], p.cc, 1);", {3, 4, 0.5f, 1},
                {0, 0.5f, 0, 0});
    expectPixel("", "float4x1 mat = {91, 92, 93, 94}; int arr[3]; arr = (int[3]) mat; return float4(arr, A.x);", {91, 92, 93, 2}, {2, 0, 0, 0});
    expectPixel("", "float arr[4] = {61, 62, 63, 64}; int2x2 mat; mat = (int2x2) arr; return float4(mat) + A;", {62, 63, 64, 65}, {1, 1, 1, 1});
}

// A struct becomes another struct type whose members match one for one (xlate/src/rewrite/
// aggregate_conversions.cpp): returned as the other type, initializing one, passed to a parameter of
// it, cast to it in an expression (a cast converts: the int2 member truncates), and an
// array becoming a struct. Xbox-ATG-Samples' SimpleTexturePC vertex shader returns its input so.
TEST_P(HlslAcceptedForms, StructsConvertComponentwise) {
    const std::string structs = "struct P { float2 a; float b; }; struct Q { float2 c; float d; }; struct I { int2 e; float f; };"
                                "Q asQ(P p) { return p; } float sum(Q q) { return q.c.x + q.c.y + q.d; }";
    expectPixel(structs, "P p; p.a = A.xy; p.b = A.z; Q q = asQ(p); Q r = p; return float4(q.c, r.d, sum(p));",
                {1.5f, -2, 4, 3.5f}, {1.5f, -2, 4, 0});
    expectPixel(structs, "float4 v = A; float w[3] = {A.w, A.z, A.y}; Q q = w; return float4(((I)v).e, ((I)v).f, q.d);",
                {2, -3, 4.25f, -3.5f}, {2.75f, -3.5f, 4.25f, 1});
}

// A struct and an array whose components match one for one in type convert into each other both
// ways (xlate/src/rewrite/aggregate_conversions.cpp): a struct assigned to an array member and
// initializing an array, an array member assigned to a struct. Intel AOIT's `data.color = B[i];`
// (struct C { float4 color[2]; } to D's float4 color[2]) in locals; the buffer form is below.
TEST_P(HlslAcceptedForms, StructsAndArraysConvertComponentwiseBothWays) {
    const std::string structs = "struct C { float4 color[2]; }; struct D { float4 depth[1]; float4 color[2]; };";
    // d.color = (A, A.wzyx); a = the same; h = d.color, so h.color[1] is A.wzyx.
    expectPixel(structs,
                "C c; c.color[0] = A; c.color[1] = A.wzyx; D d; d.depth[0] = 0; d.color = c; float4 a[2] = c; C h; h = d.color;"
                " return float4(d.color[1].x, a[0].y, h.color[1].w, h.color[0].z);",
                {4, -1.5f, 0.5f, 2.25f}, {0.5f, -1.5f, 2.25f, 4});
}

// Flat brace lists of expressions that are not literals fill the declared type's components in
// order (xlate/src/rewrite/initializer_lists.cpp). BakingLab's SH.hlsl `SH4 shr = { sh.c[0].x, ... }`
// (struct SH4 { float c[4]; }), scalars filling a struct's float2, scalars filling float2
// elements, and float2 values each filling two float elements.
TEST_P(HlslAcceptedForms, FlatInitializersOfExpressions) {
    const Vector4 a(0.5f, -1.5f, 2.25f, 4);
    const std::string sh = "struct SH4 { float c[4]; }; struct SHV { float3 c[4]; };";
    expectPixel(sh, "SHV sh; sh.c[0] = A.xyz; sh.c[1] = A.yzw; sh.c[2] = A.zwx; sh.c[3] = A.wxy;"
                    " SH4 shr = { sh.c[0].z, sh.c[1].z, sh.c[2].z, sh.c[3].z }; return float4(shr.c[0], shr.c[1], shr.c[2], shr.c[3]);",
                {2.25f, 4, 0.5f, -1.5f}, a);
    expectPixel("struct V { float2 a; float b; };", "V v = { A.x, A.y, A.z }; return float4(v.b, v.a.y, v.a.x, 1);", {2.25f, -1.5f, 0.5f, 1}, a);
    expectPixel("", "float2 a[2] = { A.x, A.y, A.z, A.w }; return float4(a[1], a[0]);", {2.25f, 4, 0.5f, -1.5f}, a);
    expectPixel("", "float c[4] = { A.xy, A.zw }; return float4(c[3], c[2], c[1], c[0]);", {4, 2.25f, -1.5f, 0.5f}, a);
}

// An element with a call that fills several components is evaluated once, and every element in
// order: bump(q) runs once, after q.x is read and before the last q.x is (d = {A.x, A.x + 1,
// A.y + 1, A.x + 1}; twice would give A.y + 2 and A.x + 2).
TEST_P(HlslAcceptedForms, FlatInitializerElementsEvaluatedOnceInOrder) {
    expectPixel("float4 bump(inout float4 q) { q += 1; return q; }",
                "float4 q = A; float d[4] = { q.x, bump(q).xy, q.x }; return float4(d[0], d[1], d[2], d[3]);", {0.5f, 1.5f, -0.5f, 1.5f},
                {0.5f, -1.5f, 2.25f, 4});
}

// Casts on the left of '=' that keep part of the target (xlate/src/rewrite/lvalue_casts.cpp): a matrix
// cast keeps its rows and columns (the top left), an array cast the first components in order.
TEST_P(HlslAcceptedForms, PartialAssignmentsThroughCasts) {
    expectPixel("", "float3x4 a = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}; float4x4 g = 0; (float2x3) g = a; return float4(g[0].xyz, g[1].z) + g[1].w + g[2].x;",
                {1, 2, 3, 7});
    expectPixel("", "float4x4 g = 0; (float2x2)(float2x3) g = float4x4(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16); return g._11_12_21_22 + g._13_23_31_44;",
                {1, 2, 5, 6});
    expectPixel("", "float p[5] = {-1, -2, -3, -4, -5}; float r[2] = {A.x, A.y}; (float[2]) p = r; return float4(p[0], p[1], p[2], p[4]);",
                {0.5f, 0.25f, -3, -5}, {0.5f, 0.25f, 0, 0});
    expectPixel("", "float p[4][3] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}; float r[2][2] = {10, 20, 30, 40}; (float[2][2]) p = r;"
                " return float4(p[0][0], p[1][1], p[1][0], p[2][2]);",
                {10, 5, 40, 9});
}

// `.Length` of a texture is its size as a uint vector (SM4 and later; xlate/src/rewrite/length_property.cpp):
// a 5x3 texture gives uint2(5, 3), and the result picks a uint2 overload. SM2 and 3 refuse it.
TEST_P(HlslAcceptedForms, TextureLengthProperty) {
    const std::string globals = "Texture2D t; float4 pick(float2 x) { return 1; } float4 pick(uint2 x) { return 2; }";
    const std::string body = "return float4(t.Length, pick(t.Length).x, A.x);";
    if (std::string(GetParam())[0] < '4') {
        EXPECT_THROW(draw(*effect(globals, body)), xlate::CompileError);
        return;
    }
    Texture2D tex(device, 5, 3, false, SurfaceFormat::Vector4);
    auto e = effect("float4 A; " + globals, body);
    e->Parameters["t"].SetValue(&tex);
    e->Parameters["A"].SetValue(Vector4(0.5f, 0, 0, 0));
    std::vector<float> px = draw(*e);
    const float expected[4] = {5, 3, 2, 0.5f};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// Static initializers that call the effect's functions run before the entry point (glslang took the
// call as made by the function defined just before: "Recursion detected", or a crash when that one
// is never called; xlate/src/rewrite/static_initializer_calls.h). `other` is called only from an
// initializer, `twice` also from the entry point.
TEST_P(HlslAcceptedForms, StaticInitializersCallEffectFunctions) {
    expectPixel("float twice(float v) { return 2 * v; }\nstatic float a = twice(0.25) + 0.5;\n"
                "float three() { return 3; } float other() { return three(); }\nstatic const float b = other(), c = twice(b);",
                "return float4(a, b, c, twice(A.x));", {1, 3, 6, 0.5f}, {0.25f, 0, 0, 0});
}

// UAVs of matrix or small struct elements that no function uses compile (and are dropped, as fxc
// drops them: xlate/src/rewrite/unused_uavs.cpp); SM5 pixel shaders only.
TEST_P(HlslAcceptedFormsSm5, UnusedUavsOfMatrixOrStructElements) {
    expectPixel("struct s { float3 a; }; RWTexture1D<float2x2> u2; RWTexture2D<struct s> u3;", "return A * 2;", {1, 2, 3, 4}, {0.5f, 1, 1.5f, 2});
}

// A sampler array nothing uses, with one state block per element, compiles (dropped as fxc drops
// it: xlate/src/rewrite/unused_sampler_arrays.cpp); a list of the wrong length is still refused.
TEST_P(HlslAcceptedForms, UnusedSamplerArraysWithStateBlocks) {
    expectPixel("sampler sams[2][2] { { Filter = ANISOTROPIC; }, { }, { }, { Filter = ANISOTROPIC; } }; sampler one[1] { Filter = ANISOTROPIC; };",
                "return A + 1;", {1.5f, 2, 3, 4}, {0.5f, 1, 2, 3});
    EXPECT_THROW(draw(*effect("sampler sams[2] { { } };", "return 1;")), xlate::CompileError);
}

// refract with a vector eta takes its first component (xlate/src/rewrite/refract_eta.cpp).
TEST_P(HlslAcceptedForms, RefractWithAVectorEta) {
    const float in[4] = {0.5f, -0.1f, 0.2f, 0.3f}, n[4] = {0.6f, 0.4f, -0.3f, 1.0f}, eta = 0.2f;
    float d = 0;
    for (int k = 0; k < 4; ++k) d += in[k] * n[k];
    const float root = std::sqrt(1 - eta * eta * (1 - d * d));
    auto e = effect("float4 I; float4 N; float4 E;", "return refract(I, N, E);");
    e->Parameters["I"].SetValue(Vector4(in[0], in[1], in[2], in[3]));
    e->Parameters["N"].SetValue(Vector4(n[0], n[1], n[2], n[3]));
    e->Parameters["E"].SetValue(Vector4(eta, 0.3f, 0.4f, 0.5f));
    std::vector<float> px = draw(*e);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], eta * in[k] - (eta * d + root) * n[k], 1e-5) << "channel " << k;
}

// all, any and asint of a matrix work on every component (xlate/src/rewrite/matrix_rows_intrinsics.cpp);
// asint exists from SM4.
TEST_P(HlslAcceptedForms, MatrixAllAnyAsint) {
    const bool sm4 = std::string(GetParam())[0] >= '4';
    auto e = effect("float2x2 M; float2x2 Z;", std::string("return float4(all(M), any(Z), all(Z), ") +
                                                   (sm4 ? "(float)asint(M)[1][0] / 1073741824.0);" : "0);"));
    e->Parameters["M"].SetValue(std::vector<float>{1, 2, 3, 4});  // rows (1, 2) and (3, 4)
    e->Parameters["Z"].SetValue(std::vector<float>{0, 0, 0, 5});
    std::vector<float> px = draw(*e);
    const float three = 3.0f;
    int bits = 0;
    std::memcpy(&bits, &three, sizeof bits);
    const float expected[4] = {1, 1, 0, sm4 ? float(bits) / 1073741824.0f : 0};
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[k], 1e-6) << "channel " << k;
}

// A static texture variable that only ever holds one global texture is that texture, assigned in
// its initializer or in the function (xlate/src/rewrite/static_object_aliases.cpp); SM4 and later.
TEST_P(HlslAcceptedFormsSm4, StaticTextureVariablesAliasAGlobalTexture) {
    Texture2D tex(device, 1, 1, false, SurfaceFormat::Vector4);
    const float texel[4] = {0.25f, 0.5f, 2, 4};
    tex.SetData(texel, 4);
    for (const char* form : {"static Texture2D tex = real_tex;|", "static Texture2D tex;|tex = real_tex;"}) {
        const std::string f = form;
        const size_t bar = f.find('|');
        auto e = effect("Texture2D real_tex; SamplerState sam; " + f.substr(0, bar), f.substr(bar + 1) + " return tex.Sample(sam, float2(0.5, 0.5));");
        e->Parameters["real_tex"].SetValue(tex);
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], texel[k]) << form << " channel " << k;
    }
}

// A cast to a struct of a value whose type the rewrite cannot tell, a method's result: fxc fills
// the members in order from the value's components, converted (xlate/src/rewrite/
// aggregate_conversions.cpp, overloads of one casting function). `(Pair)tex.Sample(...)` takes
// a = texel.xy, b = texel.zw; `(Mixed)tex.Load(...)` truncates into the int member; a scalar
// (`.Load(...).w`) fills every member.
TEST_P(HlslAcceptedFormsSm4, CastOfAMethodResultToAStruct) {
    Texture2D tex(device, 1, 1, false, SurfaceFormat::Vector4);
    const float texel[4] = {0.25f, -1.5f, 2.75f, 4};
    tex.SetData(texel, 4);
    const std::string globals = "Texture2D tex; SamplerState sam; struct Pair { float2 a; float2 b; }; struct Mixed { int i; float3 f; };"
                                "struct Two { float x; uint y; };";
    const std::vector<std::pair<std::string, std::vector<float>>> cases = {
        {"Pair p = (Pair)tex.Sample(sam, float2(0.5, 0.5)); return float4(p.b, p.a);", {2.75f, 4, 0.25f, -1.5f}},
        {"Mixed m = (Mixed)tex.Load(int3(0, 0, 0)); return float4(m.i, m.f);", {0, -1.5f, 2.75f, 4}},
        {"Two t = (Two)tex.Load(int3(0, 0, 0)).w; return float4(t.x, t.y, 0, 1);", {4, 4, 0, 1}},
        {"return float4(((Pair)tex.Sample(sam, float2(0.5, 0.5)).wzyx).b, 0, 0);", {-1.5f, 0.25f, 0, 0}},
    };
    for (const auto& [body, expected] : cases) {
        SCOPED_TRACE(body);
        auto e = effect(globals, body);
        e->Parameters["tex"].SetValue(tex);
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[size_t(k)]) << "channel " << k;
    }
}

// Integer literals with the `l` suffix are ints (uints with `u`): they pick the int or uint
// overload and keep their value (xlate/src/rewrite/literal_suffixes.cpp); SM4 and later, where int and uint
// overloads differ.
TEST_P(HlslAcceptedFormsSm4, LongLiteralSuffixes) {
    expectPixel("float pick(int x) { return 1; } float pick(uint x) { return 2; }", "return float4(pick(3lu), pick(3l), 0x10L + 1l, A.x);", {2, 1, 17, 0.5f},
                {0.5f, 0, 0, 0});
}

// A typedef named like a DX9 texture type in another case (`texturE`) is the typedef's type.
TEST_P(HlslAcceptedForms, TypedefNamedLikeATextureType) {
    auto e = effect("typedef float4 texturE; texturE var;", "return var * 2;");
    e->Parameters["var"].SetValue(Vector4(0.5f, 1, 1.5f, 2));
    std::vector<float> px = draw(*e);
    const float expected[4] = {1, 2, 3, 4};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// A uniform whose default value holds a shader compiles without a default, as with fxc
// (xlate/src/rewrite/shader_valued_defaults.cpp): it reads 0 until set.
TEST_P(HlslAcceptedForms, ShaderValuedDefaultsAreNotWritten) {
    const std::string globals = "float4 fun() : COLOR { return 0; } float4 f = {1, 2, compile ps_2_0 fun(), 4}; float g = {CompileShader(ps_2_0, fun())};";
    expectPixel(globals, "return f + g + A;", {0.5f, 1, 1.5f, 2}, {0.5f, 1, 1.5f, 2});
}

// A sampler_state among the values of a numeric uniform's default: the types do not match and fxc
// discards the whole initializer (vkd3d's sampler-state): no default, 0 until set.
TEST_P(HlslAcceptedForms, SamplerStateInANumericDefaultDiscardsIt) {
    expectPixel("float4 f = { sampler_state { foo = BAR; bar = FOO; }, 1, 2, 3 };", "return f + A;", {0.5f, 1, 1.5f, 2}, {0.5f, 1, 1.5f, 2});
}

// A literal index past an array's end in code that never runs compiles, as fxc takes it before
// SM6 (vkd3d's hard-copy-prop; xlate/src/rewrite/out_of_range_indices.h): the branch is dead.
TEST_P(HlslAcceptedForms, OutOfRangeIndexInDeadCode) {
    expectPixel("", "static float4 arr[4]; bool x = false; if (x) { arr[100] = 0; return arr[100]; } arr[3] = A; return arr[3] * 2;",
                {1, 2, 3, 4}, {0.5f, 1, 1.5f, 2});
}

// Case labels written as floats are the integers they truncate to (`case 2.1f:` is `case 2:`), and
// from SM4 a float selector is converted to int (xlate/src/rewrite/switch_labels.cpp; vkd3d's switch).
TEST_P(HlslAcceptedForms, SwitchWithFloatLabels) {
    const std::string body = "float4 c = 1; switch (SELECTOR) { case 2.1f: c += 0.5; break; case 0.9f: c += 0.25; break; case -1.5: c = -1; break; } return c;";
    for (std::string selector : {"(int)A.x", "A.x"}) {
        if (selector == "A.x" && std::string(GetParam())[0] < '4') continue;  // fxc refuses a float selector below SM4
        const std::string b = body.substr(0, body.find("SELECTOR")) + selector + body.substr(body.find("SELECTOR") + 8);
        expectPixel("", b, {1.5f, 1.5f, 1.5f, 1.5f}, {2, 0, 0, 0});
        expectPixel("", b, {1.25f, 1.25f, 1.25f, 1.25f}, {0, 0, 0, 0});
        expectPixel("", b, {-1, -1, -1, -1}, {-1, 0, 0, 0});
        expectPixel("", b, {1, 1, 1, 1}, {1, 0, 0, 0});  // 1 matches no label: 0.9f is 0
    }
}

// A matrix among a constructor's arguments gives its components row by row
// (xlate/src/rewrite/matrix_constructor_arguments.cpp; vkd3d's matrix-indexing).
TEST_P(HlslAcceptedForms, MatrixArgumentsOfConstructors) {
    expectPixel("", "float2x2 a = float2x2(A.x, A.y, A.z, A.w); float2x3 m = float2x3(a, 5, 6); return float4(m[0][2], m[1][0], m[1][1], m[1][2]);",
                {3, 4, 5, 6}, {1, 2, 3, 4});
    expectPixel("", "float2x2 a = float2x2(A.x, A.y, A.z, A.w); float4x4 m = float4x4(1, 2, 3, 4, float3(5, 6, 7), 8, 9, 10, a, 15, 16);"
                " return float4(m[2][2], m[2][3], m[3][0], m[3][3]);",
                {11, 12, 13, 16}, {11, 12, 13, 14});
}

// `precise` is a modifier only where a type follows; elsewhere it names a variable, and a
// parameter of that name is set by that name (xlate/src/rewrite/keyword_identifiers.cpp).
TEST_P(HlslAcceptedForms, PreciseAsAName) {
    auto e = effect("float4 precise; precise float4 scaled(float4 v) { precise float4 r = v * 2; return r; }", "return scaled(precise) + precise.x;");
    e->Parameters["precise"].SetValue(Vector4(0.5f, 1, 1.5f, 2));
    std::vector<float> px = draw(*e);
    const float expected[4] = {1.5f, 2.5f, 3.5f, 4.5f};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// Once the effect names a type `precise`, `precise NAME(` and `precise NAME =` use that type; a
// modifier is still a modifier where a type follows (xlate/src/keyword_identifiers.cpp).
TEST_P(HlslAcceptedForms, PreciseAsATypedefName) {
    expectPixel("typedef float4 precise; precise float4 k; precise twice(float4 v) { precise r = v * 2; return r; }", "return twice(A);", {2, 4, 6, 8},
                {1, 2, 3, 4});
}

// A file-scope static without an initializer starts at zero, as fxc zero-fills it (GLSL leaves
// it undefined; xlate/src/static_zero_init.cpp).
TEST_P(HlslAcceptedForms, StaticsWithoutInitializerStartAtZero) {
    expectPixel("static struct { float4 x; float3 y; } s; static float4 arr[2]; static int2 n; static bool b;",
                "return s.x + arr[1] + float4(n, s.y.z, b) + A;", {1, 2, 3, 4}, {1, 2, 3, 4});
}

// State blocks on local variables are dropped, as fxc drops them (xlate/src/local_state_blocks.cpp),
// and a struct defined in a function body is defined before the function for glslang
// (xlate/src/struct_definitions.cpp).
TEST_P(HlslAcceptedForms, StateBlocksOnLocalVariables) {
    expectPixel("", "float a {}; float b { foo = bar; foo = (int)2; }; float c {}, d = A.y, e; struct { float v; } s { x = y; };"
                    " struct named { float w; }; named n; n.w = A.w; a = A.x; s.v = A.z; return float4(a, d, s.v, n.w);",
                {1, 2, 3, 4}, {1, 2, 3, 4});
}

// `v[0]` of a one-component vector, a variable or a parenthesised expression (vkd3d's ternary),
// is the vector's one component (xlate/src/one_component_types.cpp).
TEST_P(HlslAcceptedForms, IndexOfAOneComponentVector) {
    expectPixel("static float1 k = {2};", "float1 u = A.x; return float4((A.y ? k : u)[0], k[0], (k + u)[0], (A.z ? k : u)[0]);", {2, 2, 3, 1},
                {1, 1, 0, 0});
}

// sign of a matrix works on every component (xlate/src/rewrite/matrix_rows_intrinsics.cpp).
TEST_P(HlslAcceptedForms, SignOfAMatrix) {
    auto e = effect("float2x2 M;", "return float4(sign(M)[0], sign(M)[1]);");
    e->Parameters["M"].SetValue(std::vector<float>{-3, 0, 2, -0.5f});  // rows (-3, 0) and (2, -0.5)
    std::vector<float> px = draw(*e);
    const float expected[4] = {-1, 0, 1, -1};
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    expectPixel("", "float2x2 m = float2x2(A.x, A.y, A.z, A.w); return float4(sign(m)[1], sign(m)[0]);", {1, -1, -1, 0}, {-3, 0, 2, -0.5f});
}

// A unary minus on a bool literal negates the int it converts to (xlate/src/rewrite/negated_bool_literals.cpp).
TEST_P(HlslAcceptedForms, NegatedBoolLiterals) {
    expectPixel("", "return float4(max(-true, -2), min(-1, -2), -false, A.x - true);", {-1, -2, 0, -0.5f}, {0.5f, 0, 0, 0});
}

// `!(a <= b)` is fxc's `a > b`: false when a is NaN (xlate/src/spirv/spirv_negated_comparisons.cpp); a
// plain comparison and `!(a == b)` keep their meaning. SM4 and later, where 0 / 0 is NaN.
TEST_P(HlslAcceptedFormsSm4, NegatedComparisonsOfNaN) {
    expectPixel("", "float n = A.x / A.w; return float4(!(n <= A.y) ? 1 : 0, !(n > A.y) ? 2 : 0, (n < A.y) ? 4 : 0, !(n == A.y) ? 8 : 0);",
                {0, 0, 0, 8}, {0, 1, 0, 0});
    expectPixel("", "float n = A.x / A.w; return float4(!(n <= A.y) ? 1 : 0, !(n > A.y) ? 2 : 0, (n < A.y) ? 4 : 0, !(n == A.y) ? 8 : 0);",
                {1, 0, 0, 8}, {3, 1, 0, 1});
}

// Intel AOIT's AOIT.hlsl loads and stores its per-pixel data as structured-buffer elements of a
// struct holding one array, to and from arrays of that array's type (fxc converts componentwise-
// equal aggregates): `data.color = B[i];`, `uint4 a[2] = B[i];`, `RWB[i] = a;`. A compute shader
// does each and the buffer read back holds the values moved, element by element.
TEST(HlslAcceptedFormsCompute, StructuredBufferElementsConvertToAndFromArrays) {
    const char* const source = R"(struct C { uint4 color[2]; };
struct D { float4 depth[1]; uint4 color[2]; };
StructuredBuffer<C> B : register(t0);
RWStructuredBuffer<C> RWB : register(u0);
[numthreads(1, 1, 1)]
void Main()
{
    D d;
    d.depth[0] = 0;
    d.color = B[0];
    uint4 a[2] = B[1];
    a[0] += 100;
    RWB[0] = a;
    RWB[1] = d.color;
}
technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, Main())); } }
)";
    GraphicsDevice& device = testDevice();
    Effect effect(device, EffectSource{source, "aoit_buffers.fx"});
    std::vector<uint32_t> input(16);
    for (uint32_t k = 0; k < 16; ++k) input[k] = k < 8 ? k + 1 : k + 3;  // B[0] = 1..8, B[1] = 11..18
    StructuredBuffer in(device, 32, 2), out(device, 32, 2);
    in.SetData(input);
    out.SetData(std::vector<uint32_t>(16, 0));
    device.SetShaderResource(0, in);
    device.SetUnorderedAccess(0, out);
    effect.CurrentTechnique->Passes[0].Apply();
    device.DispatchCompute(1, 1, 1);
    device.SetShaderResource(0, nullptr);
    const std::vector<uint32_t> got = out.GetData<uint32_t>();
    ASSERT_EQ(got.size(), 16u);
    for (uint32_t k = 0; k < 8; ++k) {
        EXPECT_EQ(got[k], input[8 + k] + (k < 4 ? 100u : 0u)) << "RWB[0] component " << k;  // B[1], a[0] + 100
        EXPECT_EQ(got[8 + k], input[k]) << "RWB[1] component " << k;                         // B[0] through d.color
    }
}

// A RWTexture2D<float4> that a compute shader only writes, bound to an RGBA8 (Color) target: D3D
// converts each store to the view's format, so the target holds the values rounded to 8 bits
// (xlate/src/spirv/write_only_images.h). With the element type's rgba32f format GL would refuse
// the binding or leave the target unwritten. The values scale to whole numbers or far from a half
// (D3D allows 0.6 ULP in float -> UNORM: 127.5 may store 127 or 128, and the H200 stores 127).
TEST(HlslAcceptedFormsCompute, WrittenOnlyTypedUavTakesTheTargetsFormat) {
    const char* const source = R"(RWTexture2D<float4> Out : register(u0);
[numthreads(2, 2, 1)]
void Main(uint3 id : SV_DispatchThreadID)
{
    Out[id.xy] = float4(0.25, 0.75, 1, 0.2 * id.x + 0.4 * id.y);
}
technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, Main())); } }
)";
    GraphicsDevice& device = testDevice();
    Effect effect(device, EffectSource{source, "rgba8_uav.fx"});
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Color, DepthFormat::None);
    device.SetUnorderedAccess(0, target);
    effect.CurrentTechnique->Passes[0].Apply();
    device.DispatchCompute(1, 1, 1);
    device.SetUnorderedAccess(0, static_cast<Texture2D*>(nullptr));
    const std::vector<Vector4> got = target.GetDataAsVector4();
    ASSERT_EQ(got.size(), 4u);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            const Vector4& p = got[size_t(y * 2 + x)];
            const float w = 0.2f * float(x) + 0.4f * float(y);
            EXPECT_NEAR(p.X, 64 / 255.0f, 1e-6) << x << "," << y;   // 63.75
            EXPECT_NEAR(p.Y, 191 / 255.0f, 1e-6) << x << "," << y;  // 191.25
            EXPECT_NEAR(p.Z, 1.0f, 1e-6) << x << "," << y;
            EXPECT_NEAR(p.W, std::round(w * 255) / 255.0f, 1e-6) << x << "," << y;
        }
}

std::string modelName(const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; }
INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslAcceptedForms, ::testing::Values("2_0", "3_0", "4_0", "5_0"), modelName);
INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslAcceptedFormsSm4, ::testing::Values("4_0", "5_0"), modelName);
INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslAcceptedFormsSm5, ::testing::Values("5_0"), modelName);

}  // namespace
}  // namespace fxport::test
