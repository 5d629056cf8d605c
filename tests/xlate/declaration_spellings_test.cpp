// Declarations fxc takes in spellings glslang does not (fx_parser.cpp, unsigned_types.h): `f(void)`
// for no parameters, the `export` linkage modifier on a function, and `unsigned int` for uint.
// vkd3d's function and unsigned files have them; these tests make the parser's part fail here
// first.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

std::string compileError(const std::string& source) {
    CompileOptions o;
    o.useCache = false;
    try {
        CompiledEffect e = compileEffectSource(source + "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                               "virtual/Declarations.fx", o);
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return d.message;
        return e.techniques.at(0).passes.at(0).pixelShader.shaders.empty() ? "no pixel shader" : "";
    } catch (const CompileError& error) {
        return error.diagnostics().front().message;
    }
}

}  // namespace

TEST(DeclarationSpellings, VoidParameterListMeansNoParameters) {
    EXPECT_EQ(compileError("float2 halves(void);\nfloat2 twice(void) { return 2 * halves(); }\nfloat2 halves(void) { return 0.5; }\n"
                           "float4 PS() : SV_Target { return float4(twice(), 0, 1); }\n"),
              "");
}

TEST(DeclarationSpellings, ExportedFunctionCompiles) {
    EXPECT_EQ(compileError("export float helper(float x) { return x * 2; }\nexport float4 PS() : SV_Target { return helper(0.5); }\n"), "");
}

TEST(DeclarationSpellings, UnsignedIntTypesAreUintTypes) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource("typedef int2x2 Int2x2;\nunsigned int2 v;\nunsigned Int2x2 m;\n"
                                           "float4 PS() : SV_Target { unsigned int i = 3; return v.x + m[1][1] + i; }\n"
                                           "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                           "virtual/Unsigned.fx", o);
    int found = 0;
    for (const auto& p : e.parameters) {
        if (p.name != "v" && p.name != "m") continue;
        ++found;
        EXPECT_EQ(p.type, ParameterType::UInt) << p.name;
        EXPECT_EQ(p.rows, p.name == "m" ? 2 : 1) << p.name;
        EXPECT_EQ(p.columns, 2) << p.name;
    }
    EXPECT_EQ(found, 2);
}

TEST(DeclarationSpellings, UnsignedBeforeANonIntTypeIsRefused) {
    EXPECT_EQ(compileError("unsigned uint2 v;\nfloat4 PS() : SV_Target { return 0; }\n"), "'unsigned' applies to int types; 'uint2' is not one");
    EXPECT_EQ(compileError("typedef int Ints[2];\nunsigned Ints v;\nfloat4 PS() : SV_Target { return 0; }\n"),
              "'unsigned' applies to int types; 'Ints' is not one");
}

TEST(DeclarationSpellings, LocalsFxcRefusesStayRefused) {
    // Refused before only because `main(void)` was; fxc refuses the locals themselves (vkd3d's invalid file).
    EXPECT_EQ(compileError("float4 PS(void) : SV_Target { uniform float f; return 0; }\n"),
              "local variable in 'PS' declared uniform: uniforms are globals or entry parameters");
    EXPECT_EQ(compileError("struct s { float4 f; };\nfloat4 PS(void) : SV_Target { const struct s a; return 0; }\n"),
              "const variable 'a' has no initial value (fxc X3012)");
}

// texture-load-typed L56: fxc reads the texture keywords in any case, so a templated `texture2D`
// is a Texture2D and a templated `textureCUBE` a TextureCube (a DX9 texture takes no template).
TEST(DeclarationSpellings, LowerCaseTemplatedTexturesAreObjects) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource("texture2D<float> F;\ntextureCUBE<float4> C;\nSamplerState S;\n"
                                           "float4 PS() : SV_Target { return F.Load(int3(0, 0, 0)) + C.Sample(S, float3(1, 0, 0)); }\n"
                                           "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                           "virtual/LowerCaseTextures.fx", o);
    const std::string& glsl = e.shaders.at(static_cast<size_t>(e.techniques.at(0).passes.at(0).pixelShader.shaders.at(0))).glsl;
    EXPECT_NE(glsl.find("texelFetch("), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("samplerCube "), std::string::npos) << glsl;
}

// type-names L1: a typedef in a function may name a built-in type, which then means the alias to
// the block's end (`typedef Half2 float;` makes `float v` a float2; `typedef float float;` changes
// nothing); DWORD is dword in any case, also where a local typedef shadows `dword`. The pixel
// shader's value is folded to a literal: (v.x, v.y, w, d) = (2, 3, 1, 4).
TEST(DeclarationSpellings, LocalTypedefsMayNameBuiltinTypes) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource("typedef float2 Half2;\n"
                                           "float4 PS() : SV_Target {\n"
                                           "    float w = 1;\n"
                                           "    {\n        typedef Half2 float;\n        typedef float2 dword;\n"
                                           "        float v = {2, 3};\n        DWORD d = 4.5;\n"
                                           "        {\n            typedef float float;\n            return float4(v, w, d);\n        }\n    }\n}\n"
                                           "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                           "virtual/LocalTypedefs.fx", o);
    const std::string& glsl = e.shaders.at(static_cast<size_t>(e.techniques.at(0).passes.at(0).pixelShader.shaders.at(0))).glsl;
    EXPECT_NE(glsl.find("vec4(2.0, 3.0, 1.0, 4.0)"), std::string::npos) << glsl;
}

// null L55: `= NULL` on a resource global is fxc's spelling of no object bound, and Effects 10's
// RenderTargetView / DepthStencilView variables are nothing a shader reads; NULL stays refused as
// a numeric value and in lower case (null L1, L29).
TEST(DeclarationSpellings, NullInitializedResourcesAndViews) {
    EXPECT_EQ(compileError("Texture2D T = NULL;\nTexture2DMS<float4> M = NULL;\nStructuredBuffer<float4> B = NULL, C = NULL;\n"
                           "RenderTargetView rtv = NULL;\nDepthStencilView dsv;\nSamplerState S;\n"
                           "float4 PS() : SV_Target { return T.Sample(S, 0.5) + M.Load(int2(0, 0), 0) + B[0] + C[1]; }\n"),
              "");
    EXPECT_NE(compileError("float4 V = NULL;\nfloat4 PS() : SV_Target { return V; }\n"), "");
    EXPECT_NE(compileError("Texture2D T = null;\nfloat4 PS() : SV_Target { return 0; }\n"), "");
}

// hard-copy-prop L163: `float4 a, b;` in a struct declares two members. All of them reach the
// reflection (so `x.b` is settable through StructureMembers at its own offset) and, in an entry
// struct, the signature (each with its own semantic).
TEST(DeclarationSpellings, StructMemberListsDeclareEveryMember) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(
        "struct S { float4 a, b; float c[2], d; };\nS x;\n"
        "struct VSIn { float4 pos : POSITION0, col : COLOR0; };\n"
        "float4 VS(VSIn v) : SV_Position { return v.pos + v.col; }\n"
        "float4 PS() : SV_Target { return x.a + x.b + x.c[1] + x.d; }\n"
        "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
        "virtual/MemberLists.fx", o);
    const Parameter* x = nullptr;
    for (const auto& p : e.parameters)
        if (p.name == "x") x = &p;
    ASSERT_NE(x, nullptr);
    ASSERT_EQ(x->members.size(), 4u);
    EXPECT_EQ(x->members[1].name, "b");
    EXPECT_EQ(x->members[1].offset, 16);
    EXPECT_EQ(x->members[2].name, "c");
    EXPECT_EQ(x->members[2].elements, 2);
    EXPECT_EQ(x->members[3].name, "d");
    EXPECT_EQ(x->members[3].offset, 52);  // c[1] at 48, d packed after it in the same register
    const auto& vs = e.shaders.at(static_cast<size_t>(e.techniques.at(0).passes.at(0).vertexShader.shaders.at(0)));
    ASSERT_EQ(vs.inputs.size(), 2u);
    EXPECT_EQ(vs.inputs[1].semantic, "COLOR0");
}

// uav-rwbuffer L69, L98: a UAV of double2 elements (four 32-bit words) that no function touches
// compiles, as fxc drops it; double3 (six words) stays refused as fxc refuses it (L61).
TEST(DeclarationSpellings, UnusedDoubleUavsAreDropped) {
    auto compileSm5 = [](const std::string& declarations) {
        CompileOptions o;
        o.useCache = false;
        try {
            compileEffectSource(declarations + "float4 PS() : SV_Target1 { return 0; }\n"
                                               "technique11 T { pass P { SetPixelShader(CompileShader(ps_5_0, PS())); } }\n",
                                "virtual/DoubleUavs.fx", o);
        } catch (const CompileError& error) {
            return error.diagnostics().front().message;
        }
        return std::string();
    };
    EXPECT_EQ(compileSm5("RWBuffer<double2> u;\nRasterizerOrderedBuffer<double2> v;\nRWBuffer<double> w;\n"), "");
    EXPECT_NE(compileSm5("RWBuffer<double3> u;\n"), "");
}
