// Constant buffers laid out as D3D packs them (xlate/src/spirv/cbuffer_packing.h): the reflection's
// parameter offsets, array and matrix strides and struct member offsets are fxc's, written out
// here by hand from its rules; the GLSL declares them (layout(offset = N)) or, where GLSL cannot,
// reads an array of registers. The pixel checks are tests/d3d11/d3d11_cbuffer_packing_test.cpp
// and tests/runtime/struct_parameters_test.cpp.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

CompiledEffect compile(const std::string& declarations, const std::string& body, const std::string& profile = "ps_4_0") {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + "float4 PS() : SV_Target { " + body + " }\ntechnique10 T { pass P { SetPixelShader(CompileShader(" +
                                   profile + ", PS())); } }\n",
                               "virtual/CbufferPacking.fx", o);
}

const Parameter& param(const CompiledEffect& e, const std::string& name) {
    for (const auto& p : e.parameters)
        if (p.name == name) return p;
    throw std::runtime_error("no parameter " + name);
}

const UniformBlock& blockOf(const CompiledEffect& e, const std::string& name) { return e.uniformBlocks.at(std::size_t(param(e, name).block)); }

}  // namespace

TEST(CbufferPacking, ScalarsUseTheTailOfArraysMatricesAndStructs) {
    CompiledEffect e = compile("cbuffer C { float a; float b[2]; float c; float3x3 m; float s; row_major float2x3 r; float t; float3 u; float v; }\n",
                               "return float4(a + b[1] + c + m[2][2] + s + r[1][2] + t, u + v);");
    EXPECT_EQ(param(e, "a").offset, 0);
    EXPECT_EQ(param(e, "b").offset, 16);
    EXPECT_EQ(param(e, "b").arrayStride, 16);
    EXPECT_EQ(param(e, "c").offset, 36);   // b's last register, c2.y
    EXPECT_EQ(param(e, "m").offset, 48);   // matrices start a register
    EXPECT_EQ(param(e, "m").matrixStride, 16);
    EXPECT_EQ(param(e, "s").offset, 92);   // 48 + 2 * 16 + 12: m's last column, c5.w
    EXPECT_EQ(param(e, "r").offset, 96);
    EXPECT_EQ(param(e, "t").offset, 124);  // 96 + 16 + 12
    EXPECT_EQ(param(e, "u").offset, 128);  // c8.xyz
    EXPECT_EQ(param(e, "v").offset, 140);
    EXPECT_TRUE(blockOf(e, "a").d3dPacking);
    EXPECT_EQ(blockOf(e, "a").size, 144);
    // GLSL cannot declare c at 36: the block is read as registers.
    EXPECT_NE(e.shaders.at(0).glsl.find("uvec4 registers["), std::string::npos) << e.shaders.at(0).glsl;
}

TEST(CbufferPacking, PackoffsetPlacesMembersInAnyOrder) {
    CompiledEffect e = compile("cbuffer C { float4 a : packoffset(c2); float b : packoffset(c0.y); float2 c : packoffset(c1.z); }\n",
                               "return a + b + c.xyxy;");
    EXPECT_EQ(param(e, "a").offset, 32);
    EXPECT_EQ(param(e, "b").offset, 4);
    EXPECT_EQ(param(e, "c").offset, 24);
    EXPECT_TRUE(blockOf(e, "a").d3dPacking);
}

TEST(CbufferPacking, RegisterPlacesGlobalsAndTheOthersFollowTheLastPlacedOne) {
    // fxc (register-reservations-numeric): an unplaced global packs after the last placed one.
    CompiledEffect e = compile("float k : register(c1);\nfloat4 g : register(c3);\nfloat n;\n", "return g + k + n;");
    EXPECT_EQ(param(e, "g").offset, 48);
    EXPECT_EQ(param(e, "k").offset, 16);
    EXPECT_EQ(param(e, "n").offset, 64);
    EXPECT_EQ(blockOf(e, "g").name, "$Global");
    EXPECT_TRUE(blockOf(e, "g").d3dPacking);
    // Declarable offsets stay a GLSL block with explicit offsets, no register array.
    EXPECT_EQ(e.shaders.at(0).glsl.find("uvec4 registers["), std::string::npos) << e.shaders.at(0).glsl;
}

TEST(CbufferPacking, StructMembersHaveTheirOffsetsInTheBlock) {
    CompiledEffect e = compile("struct S { float b; float2 c; row_major float2x2 m; };\ncbuffer C { float a; S p; float d; S q[2]; float e; }\n",
                               "return float4(a + p.b + p.c.y + d + q[1].c.x + q[1].m[1][0] + e, 0, 0, 0);");
    const Parameter& p = param(e, "p");
    EXPECT_EQ(p.offset, 16);
    ASSERT_EQ(p.members.size(), 3u);
    EXPECT_EQ(p.members[0].offset, 16);
    EXPECT_EQ(p.members[1].offset, 20);
    EXPECT_EQ(p.members[2].offset, 32);  // a matrix starts a register
    EXPECT_TRUE(p.members[2].rowMajor);
    EXPECT_EQ(p.members[2].matrixStride, 16);
    EXPECT_EQ(param(e, "d").offset, 56);  // S is 16 + 24 = 40 bytes: d in its last register, c3.z
    const Parameter& q = param(e, "q");
    EXPECT_EQ(q.offset, 64);
    EXPECT_EQ(q.arrayStride, 48);
    ASSERT_EQ(q.members.size(), 3u);
    EXPECT_EQ(q.members[1].offset, 68);  // element 0's; element i is arrayStride further
    EXPECT_EQ(param(e, "e").offset, 64 + 48 + 40);
}

TEST(CbufferPacking, OverlappingPackoffsetsAreRefusedWhereDeclared) {
    try {
        compile("cbuffer C { float4 a[2] : packoffset(c1); float4 b : packoffset(c2); }\n", "return a[1] + b;");
        FAIL() << "compiled";
    } catch (const CompileError& err) {
        const Diagnostic& d = err.diagnostics().front();
        EXPECT_NE(d.message.find("packoffset(c2.x) of 'b' overlaps 'a'"), std::string::npos) << d.message;
        EXPECT_EQ(d.location.line, 1);
        EXPECT_NE(d.location.file.find("CbufferPacking.fx"), std::string::npos) << d.location.file;
    }
}

// Objects declared in a cbuffer are the resources they would be outside it and take no room in it
// (vkd3d's cbuffer tests; rewrite/cbuffer_objects.h): the numbers pack as if the objects were not
// there, a packoffset on a texture changes nothing, and the GLSL declares the texture and the
// sampler outside the block (GLSL refuses opaque members).
TEST(CbufferPacking, ObjectsInACbufferAreResourcesOutsideIt) {
    CompiledEffect e = compile("cbuffer C { float4 a; Texture2D tex; SamplerState sam; float4 b; }\ncbuffer D { Texture2D other : packoffset(c5); }\n",
                               "return a + b + tex.Sample(sam, float2(0, 0)) + other.Load(int3(0, 0, 0));");
    EXPECT_EQ(param(e, "a").offset, 0);
    EXPECT_EQ(param(e, "b").offset, 16);
    EXPECT_EQ(blockOf(e, "a").size, 32);
    int textures = 0, samplers = 0;
    for (const auto& r : e.resources) {
        textures += r.kind == ResourceDeclaration::Kind::Texture && (r.name == "tex" || r.name == "other");
        samplers += r.kind == ResourceDeclaration::Kind::Sampler && r.name == "sam";
    }
    EXPECT_EQ(textures, 2);
    EXPECT_EQ(samplers, 1);
}

// fxc's rules about objects in a cbuffer are judged where they were written: a sampler placed by
// packoffset() alone that a shader uses is refused; with a register() too it compiles.
TEST(CbufferPacking, ASamplerUsedWithOnlyAPackoffsetIsRefused) {
    try {
        compile("Texture2D tex;\ncbuffer C { sampler sam : packoffset(c1); }\n", "return tex.Sample(sam, float2(0, 0));");
        FAIL() << "compiled";
    } catch (const CompileError& err) {
        const Diagnostic& d = err.diagnostics().front();
        EXPECT_NE(d.message.find("sampler 'sam' is placed in its cbuffer by packoffset() only"), std::string::npos) << d.message;
        EXPECT_EQ(d.location.line, 2);
    }
    CompiledEffect e = compile("Texture2D tex;\ncbuffer C { sampler sam : packoffset(c1) : register(s0); }\n", "return tex.Sample(sam, float2(0, 0));");
    EXPECT_EQ(e.shaders.size(), 1u);
}

// A matrix of one row or one column keeps a matrix's registers (one per column, or per row when
// row_major) although GLSL stores it as an array of registers (degenerate_matrices.h): float1x3
// takes c0.x c1.x c2.x, a scalar after it packs into c2.y; float3x1 takes c3.xyz and a scalar
// c3.w; a row_major float3x1 three registers, a row_major float1x3 one; a float1x1 starts one.
TEST(CbufferPacking, OneRowAndOneColumnMatricesTakeAMatrixRegisters) {
    CompiledEffect e = compile("cbuffer C { float1x3 a; float s; float3x1 b; float t; row_major float3x1 c; row_major float1x3 d; float1x1 u; }\n",
                               "return float4(a[0][2] + s + b[1][0] + t, c[2][0], d[0][1], determinant(u));");
    EXPECT_EQ(param(e, "a").offset, 0);
    EXPECT_EQ(param(e, "a").size, 36);
    EXPECT_EQ(param(e, "a").matrixStride, 16);
    EXPECT_FALSE(param(e, "a").rowMajor);
    EXPECT_EQ(param(e, "a").parameterClass, ParameterClass::Matrix);
    EXPECT_EQ(param(e, "a").rows, 1);
    EXPECT_EQ(param(e, "a").columns, 3);
    EXPECT_EQ(param(e, "s").offset, 36);
    EXPECT_EQ(param(e, "b").offset, 48);
    EXPECT_EQ(param(e, "b").size, 12);
    EXPECT_EQ(param(e, "t").offset, 60);
    EXPECT_EQ(param(e, "c").offset, 64);
    EXPECT_EQ(param(e, "c").size, 36);
    EXPECT_TRUE(param(e, "c").rowMajor);
    EXPECT_EQ(param(e, "d").offset, 112);
    EXPECT_EQ(param(e, "d").size, 12);
    EXPECT_EQ(param(e, "u").offset, 128);  // a matrix, even a 1x1, starts a register
    EXPECT_EQ(blockOf(e, "a").size, 144);
}

// `#pragma pack_matrix(row_major)` before the declaration decides its registers as a modifier would.
TEST(CbufferPacking, PackMatrixPragmaDecidesOneRowMatrixRegisters) {
    CompiledEffect e = compile("#pragma pack_matrix(row_major)\nfloat1x4 a;\nfloat b;\n#pragma pack_matrix(column_major)\nfloat1x2 c;\n",
                               "return float4(a[0][3] + b, c[0][1], a._m01_m02);", "ps_3_0");
    EXPECT_EQ(param(e, "a").offset, 0);
    EXPECT_TRUE(param(e, "a").rowMajor);
    EXPECT_EQ(param(e, "b").offset, 16);  // SM3: every global starts a register
    EXPECT_EQ(param(e, "c").offset, 32);
    EXPECT_FALSE(param(e, "c").rowMajor);
    EXPECT_EQ(param(e, "c").size, 20);
}

// A uniform struct holding objects and numbers, a global or a cbuffer member (vkd3d's
// object-field-offsets; xlate/src/rewrite/uniform_object_structs.h): the numbers are in the
// constant buffer at fxc's offsets (the objects take no room, an object array or a struct of
// objects only starts a register), the objects are textures and samplers of their own, sampled
// through the member and through a copy of the whole struct passed to a function.
TEST(CbufferPacking, StructsHoldingObjectsKeepTheirNumbersInTheBuffer) {
    CompiledEffect e = compile("struct O { Texture2D t; SamplerState s; };\n"
                               "struct M { float2 a; Texture2D tex; SamplerState sam; float b; Texture2D arr[2]; float c; O o; float d; };\n"
                               "cbuffer C { float x; M m; float y; }\nM g;\nfloat z;\n"
                               "float4 shade(M v) { return v.tex.Sample(v.sam, v.a) * v.b; }\n",
                               "return shade(m) + g.o.t.Sample(g.o.s, g.a) + float4(m.c, m.d, y + z, x + g.arr[1].Load(int3(0, 0, 0)).x);", "ps_5_0");
    const Parameter& m = param(e, "m");
    EXPECT_EQ(m.offset, 16);
    std::map<std::string, int> offsets;
    for (const auto& member : m.members)
        if (member.offset >= 0) offsets[member.name] = member.offset;  // the objects have none
    // a c1.xy, b c1.z; arr starts c2: c c2.x; o starts c3: d c3.x; y in m's last register.
    EXPECT_EQ(offsets, (std::map<std::string, int>{{"a", 16}, {"b", 24}, {"c", 32}, {"d", 48}}));
    EXPECT_EQ(param(e, "y").offset, 52);
    EXPECT_EQ(param(e, "g").offset, 0);
    EXPECT_EQ(param(e, "z").offset, 52 - 16);  // g is 36 bytes in $Global: z at c2.y
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_EQ(glsl.find("uniform vec2"), std::string::npos) << glsl;  // no number outside a block
    EXPECT_EQ(e.shaders.at(0).samplers.size(), 3u) << glsl;  // m.tex with m.sam, g.o.t with g.o.s, g.arr
}
