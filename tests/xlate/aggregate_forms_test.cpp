// Aggregates fxc fills component by component (session 23's real-world run): a struct and an array
// whose components match one for one in type assigned and initialized from each other (Intel AOIT's
// structured-buffer loads and stores, xlate/src/rewrite/aggregate_conversions.cpp), and flat brace
// lists of expressions that are not literals (BakingLab's SH.hlsl, initializer_lists.cpp). Each
// shader computes from constants, so the GLSL returns the folded value, which is compared with the
// value worked out by hand from fxc's rules; what fxc refuses stays refused at its line.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

CompiledEffect compilePixel(const std::string& source) {
    fs::path dir = fs::temp_directory_path() / ("fxport-aggregate-forms-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "shader.hlsl";
    std::ofstream(file) << source;
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{file.string(), "main", "ps_5_0"}}, o);
}

std::string pixelGlsl(const std::string& source) { return compilePixel(source).shaders.at(0).glsl; }

// The compile's first diagnostic's line; 0 when it compiled.
int refusedAtLine(const std::string& source) {
    try {
        compilePixel(source);
    } catch (const CompileError& err) {
        if (err.diagnostics().empty()) return -1;
        EXPECT_NE(err.diagnostics().front().location.file.find("shader.hlsl"), std::string::npos);
        return err.diagnostics().front().location.line;
    }
    return 0;
}

const char* const kAoitStructs = "struct C { uint4 color[2]; };\nstruct D { float4 depth[1]; uint4 color[2]; };\n";

}  // namespace

// AOIT.hlsl's shapes: `data.color = B[addr];` (struct to an array member), `uint4 a[2] = B[i];`
// (initialization) and `RWB[addr] = a;` (array to struct, the store) compile against structured
// buffers; the same conversions between locals hold the values moved (d.color = c, a = c, e = a,
// h = d.color: c.color[1].x, c.color[0].y, a[1].w, d.color[0].z).
TEST(AggregateForms, StructsAndArraysConvertBothWays) {
    const std::string buffers = std::string(kAoitStructs) +
                                "StructuredBuffer<C> B;\nRWStructuredBuffer<C> RWB;\n"
                                "float4 main(float4 p : SV_Position) : SV_Target\n{\n"
                                "    D d;\n    d.color = B[0];\n    uint4 a[2] = B[1];\n    RWB[0] = a;\n    RWB[1] = d.color;\n"
                                "    return d.color[1] + a[0];\n}\n";
    EXPECT_NE(pixelGlsl(buffers).find("_data[1]"), std::string::npos);
    const std::string locals = std::string(kAoitStructs) +
                               "float4 main() : SV_Target\n{\n"
                               "    C c; c.color[0] = uint4(1, 2, 3, 4); c.color[1] = uint4(5, 6, 7, 8);\n"
                               "    D d; d.depth[0] = 0; d.color = c;\n    uint4 a[2] = c;\n    C e = a;\n    C h; h = d.color;\n"
                               "    return float4(d.color[1].x, a[0].y, e.color[1].w, h.color[0].z);\n}\n";
    const std::string glsl = pixelGlsl(locals);
    EXPECT_NE(glsl.find("vec4(5.0, 2.0, 8.0, 3.0)"), std::string::npos) << glsl;
}

// fxc converts only where the counts and component types match: a uint4[1] from a struct of two
// uint4 (count), an int4[2] from it (type) and a struct from a shorter array stay refused, each at
// its line.
TEST(AggregateForms, MismatchedAggregatesStayRefused) {
    const std::string head = std::string(kAoitStructs) + "StructuredBuffer<C> B;\nfloat4 main() : SV_Target\n{\n";
    EXPECT_EQ(refusedAtLine(head + "    uint4 a[1] = B[0];\n    return a[0];\n}\n"), 6);
    EXPECT_EQ(refusedAtLine(head + "    int4 a[2] = B[0];\n    return a[0];\n}\n"), 6);
    EXPECT_EQ(refusedAtLine(head + "    uint4 a[1] = {1, 2, 3, 4};\n    C c;\n    c = a;\n    return c.color[0];\n}\n"), 8);
}

// Flat lists of expressions fill the target's components in order: BakingLab's `SH4 shr = { ... }`
// (struct SH4 { float c[4]; }), scalars filling a struct's float2 member, scalars filling float2
// elements and float2 values each filling two floats. p = (0.5, -1.5, 2.25, 4): s.c = (4, 2.25,
// -1.5, 0.5), v = {(0.5, -1.5), 2.25}, a = {(0.5, -1.5), (2.25, 4)}, c = (0.5, -1.5, 2.25, 4).
TEST(AggregateForms, FlatListsOfExpressionsFillInOrder) {
    const std::string glsl = pixelGlsl(
        "struct SH4 { float c[4]; };\nstruct V { float2 a; float b; };\nfloat4 main() : SV_Target\n{\n"
        "    float4 p = float4(0.5, -1.5, 2.25, 4);\n    SH4 s = { p.w, p.z, p.y, p.x };\n    V v = { p.x, p.y, p.z };\n"
        "    float2 a[2] = { p.x, p.y, p.z, p.w };\n    float c[4] = { p.xy, p.zw };\n"
        "    return float4(s.c[1] + v.b, a[1].y + v.a.y, c[2] - c[0], s.c[0]);\n}\n");
    EXPECT_NE(glsl.find("vec4(4.5, 2.5, 1.75, 4.0)"), std::string::npos) << glsl;
}

// An element with a call that fills several components runs once, every element in order: with
// q = (1, 2, 3, 4), d = {q.x, bump(q).xy, q.x} is {1, 2, 3, 2} (twice would make d[2] 4 and d[3] 3;
// reading the first q.x after the call would make d[0] 2).
TEST(AggregateForms, SplitCallsRunOnceInOrder) {
    const std::string glsl = pixelGlsl(
        "float4 bump(inout float4 q) { q += 1; return q; }\nfloat4 main() : SV_Target\n{\n"
        "    float4 q = float4(1, 2, 3, 4);\n    float d[4] = { q.x, bump(q).xy, q.x };\n    return float4(d[0], d[1], d[2], d[3]);\n}\n");
    EXPECT_NE(glsl.find("vec4(1.0, 2.0, 3.0, 2.0)"), std::string::npos) << glsl;
}

// Lists fxc refuses (three components for four) stay refused at their line, and so does a list
// whose element's type the rewrite cannot tell (a call among overloads): glslang judges it as
// written rather than the rewrite guessing a count.
TEST(AggregateForms, ListsNotUnderstoodAreLeftToGlslang) {
    EXPECT_EQ(refusedAtLine("float4 main(float4 p : SV_Position) : SV_Target\n{\n    float c[4] = { p.xy, p.z };\n    return c[0];\n}\n"), 3);
    EXPECT_EQ(refusedAtLine("float2 g(float x) { return x; }\nfloat2 g(int x) { return x; }\n"
                            "float4 main(float4 p : SV_Position) : SV_Target\n{\n    float c[4] = { g(p.x), p.zw };\n    return c[0];\n}\n"),
              5);
}

// A cast to a struct of any expression a cast binds, not only of a variable: a constructor, a
// parenthesised expression and a swizzle each fill the struct's members in order, converted
// (`(Pair)float2(a, b)`, `(Quad)(p * 2)` with an int2 member truncating). With p = (0.5, -1.5,
// 2.25, 4): a = (0.5, 4), q = {(1, -3), (4, 8)}, r = (2.25, -1.5).
TEST(AggregateForms, CastsOfExpressionsToStructs) {
    const std::string glsl = pixelGlsl(
        "struct Pair { float x; float y; };\nstruct Quad { Pair lo; int2 hi; };\nfloat4 main() : SV_Target\n{\n"
        "    float4 p = float4(0.5, -1.5, 2.25, 4);\n    Pair a = (Pair)float2(p.x, p.w);\n    Quad q = (Quad)(p * 2);\n"
        "    Pair r = (Pair)p.zy;\n    return float4(a.x + a.y, q.lo.y + q.hi.x, q.hi.y, r.x - r.y);\n}\n");
    EXPECT_NE(glsl.find("vec4(4.5, 1.0, 8.0, 3.75)"), std::string::npos) << glsl;
}

// A scalar cast to an array type fills every element from the scalar, as fxc does (`(float4[4])0`;
// glslang read it as an array constructor of one argument and refused it): in a local and a global
// initializer, in an array of arrays and in an assignment, from a literal and from a scalar
// variable converted to the element type (an int array from 2.75 truncates to 2).
TEST(AggregateForms, ScalarCastToArrayFillsEveryElement) {
    const std::string glsl = pixelGlsl(
        "static const float g[2][2] = (float[2][2])-1;\nfloat4 main() : SV_Target\n{\n"
        "    float4 a[4] = (float4[4])3;\n    float s = 2.75;\n    int c[2];\n    c = (int[2])s;\n"
        "    return float4(a[3].y, a[0].w + g[1][0], c[1], g[0][1]);\n}\n");
    EXPECT_NE(glsl.find("vec4(3.0, 2.0, 2.0, -1.0)"), std::string::npos) << glsl;
}
