// The live bytes of uniform blocks (xlate/src/spirv/live_uniform_bytes.h, CompiledShader::
// uniformRangesLive): which components of a parameter can reach a shader's output, as HLSL's
// semantics say (a component that only feeds a dead value, or a matrix column never extracted, is
// not live; a run-time index makes every element live). fxc sizes SM 1-3 constant registers by
// that (vkd3d's sm1-const-allocation.shader_test); its pixel checks run in the conformance suite.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

CompiledEffect compile(const std::string& declarations, const std::string& body, const std::string& profile = "ps_3_0") {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + "float4 PS() : COLOR { " + body + " }\ntechnique T { pass P { PixelShader = compile " + profile +
                                   " PS(); } }\n",
                               "virtual/LiveUniforms.fx", o);
}

const Parameter& param(const CompiledEffect& e, const std::string& name) {
    for (const auto& p : e.parameters)
        if (p.name == name) return p;
    throw std::runtime_error("no parameter " + name);
}

// Whether any byte of [offset, offset + size) of the parameter's block is live in shader 0.
bool live(const CompiledEffect& e, const Parameter& p, int offset, int size) {
    for (const auto& r : e.shaders.at(0).uniformRangesLive)
        if (r.block == p.block && r.offset < offset + size && offset < r.offset + r.size) return true;
    return false;
}

// Byte of element (row r, column c) of matrix parameter p in fxport's layout.
int matrixByte(const Parameter& p, int r, int c) { return p.offset + (p.rowMajor ? r * p.matrixStride + c * 4 : c * p.matrixStride + r * 4); }

}  // namespace

// sm1-const-allocation's first case: `d[i].x` of a copy plus another matrix reads column 0 of
// each (column_major: one register each), never column 1.
TEST(LiveUniforms, OnlyTheExtractedColumnOfACopiedMatrixIsLive) {
    CompiledEffect e = compile("float4x2 a;\nfloat4x2 b;\n", "float4x2 c = a; float4x2 d = c + b; return float4(d[0].x, d[1].x, d[2].x, d[3].x);");
    ASSERT_FALSE(e.shaders.empty());
    for (const char* name : {"a", "b"}) {
        const Parameter& p = param(e, name);
        for (int r = 0; r < 4; ++r) {
            EXPECT_TRUE(live(e, p, matrixByte(p, r, 0), 4)) << name << " row " << r;
            EXPECT_FALSE(live(e, p, matrixByte(p, r, 1), 4)) << name << " row " << r;
        }
    }
    // What the shader loads is still the whole matrices.
    EXPECT_FALSE(e.shaders[0].uniformRangesRead.empty());
}

TEST(LiveUniforms, RowOfARowMajorMatrixAndOfAColumnMajorOne) {
    CompiledEffect e = compile("row_major float2x2 m1;\ncolumn_major float2x2 m2;\n", "float4 ret; ret.xy = m1[0]; ret.zw = m2[0]; return ret;");
    ASSERT_FALSE(e.shaders.empty());
    const Parameter& m1 = param(e, "m1");
    const Parameter& m2 = param(e, "m2");
    for (int c = 0; c < 2; ++c) {
        EXPECT_TRUE(live(e, m1, matrixByte(m1, 0, c), 4));
        EXPECT_FALSE(live(e, m1, matrixByte(m1, 1, c), 4));
        EXPECT_TRUE(live(e, m2, matrixByte(m2, 0, c), 4));
        EXPECT_FALSE(live(e, m2, matrixByte(m2, 1, c), 4));
    }
}

// mul(M, v).x is row 0 of M dotted with v: row 0 live, the other rows not.
TEST(LiveUniforms, ProductPassesOneRowBack) {
    CompiledEffect e = compile("float4x4 M;\nfloat4 v;\n", "return mul(M, v).x;");
    ASSERT_FALSE(e.shaders.empty());
    const Parameter& m = param(e, "M");
    for (int c = 0; c < 4; ++c) {
        EXPECT_TRUE(live(e, m, matrixByte(m, 0, c), 4)) << c;
        for (int r = 1; r < 4; ++r) EXPECT_FALSE(live(e, m, matrixByte(m, r, c), 4)) << r << "," << c;
    }
    EXPECT_TRUE(live(e, param(e, "v"), param(e, "v").offset, 16));
}

// A component overwritten before it is used, and a value only feeding a dead local, are not live.
TEST(LiveUniforms, OverwrittenAndUnusedComponentsAreDead) {
    CompiledEffect e = compile("float4 v;\nfloat4 w;\n", "float4 t = v; t.x = 1; float4 unused = w * 2; return t.xxxy;");
    ASSERT_FALSE(e.shaders.empty());
    const Parameter& v = param(e, "v");
    EXPECT_FALSE(live(e, v, v.offset, 4));     // v.x: overwritten
    EXPECT_TRUE(live(e, v, v.offset + 4, 4));  // v.y
    EXPECT_FALSE(live(e, v, v.offset + 8, 8));
    EXPECT_FALSE(live(e, param(e, "w"), param(e, "w").offset, 16));
}

// A run-time index keeps the whole array (up to its size), and only that member of the struct.
TEST(LiveUniforms, RuntimeIndexKeepsTheWholeArray) {
    CompiledEffect e = compile("float idx;\nstruct { float dyn[5]; float unused; } a;\n", "return a.dyn[idx];");
    ASSERT_FALSE(e.shaders.empty());
    const Parameter& a = param(e, "a");
    ASSERT_EQ(a.members.size(), 2u);
    const Parameter& dyn = a.members[0];
    // (A member's offset is from the start of the block, like its struct's.)
    for (int k = 0; k < 5; ++k) EXPECT_TRUE(live(e, a, dyn.offset + k * dyn.arrayStride, 4)) << k;
    EXPECT_FALSE(live(e, a, a.members[1].offset, 4));
    EXPECT_TRUE(live(e, param(e, "idx"), param(e, "idx").offset, 4));
}

// modf's whole part is written through its out parameter: the call's own result unread, v is live.
TEST(LiveUniforms, OutParameterOfAnIntrinsicKeepsItsInput) {
    CompiledEffect e = compile("float4 v;\n", "float4 ip; modf(v, ip); return ip;");
    ASSERT_FALSE(e.shaders.empty());
    EXPECT_TRUE(live(e, param(e, "v"), param(e, "v").offset, 16));
}
