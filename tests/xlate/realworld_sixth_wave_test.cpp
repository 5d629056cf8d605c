// Real-world shaders, sixth wave (session 24's run 25 over Source SDK 2013 stdshaders, helix-toolkit,
// Urho3D, OGRE, FleX, d3d12book, AMD ForwardPlus11/TiledLighting11, DigitalRune): valid HLSL that
// fxc compiles and fxport refused. Each is a small source of our own in the project's shape, with
// what the construct means asserted on the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"
#include "compile_loose.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::writeLooseSource;
using fxport::test::compileLoose;

// Source SDK's common_vs_fxc.h: `mul3x3(modelNormal, (const float3x3)cModel[0])` in every vertex
// shader. The qualifier says nothing about a cast's value: the GLSL is the one of the plain cast.
TEST(RealworldSixthWave, ConstQualifiedCast) {
    const std::string body = "float4x3 cModel[2] : register(c58);\n"
                             "float4 main(float3 n : NORMAL) : POSITION {\n"
                             "    float3 r = mul(n, (CAST float3x3)cModel[0]) + mul(n, (CAST matrix<float, 3, 3>)cModel[1]);\n"
                             "    return float4(r, 1);\n"
                             "}\n";
    auto with = [&](const std::string& qualifier) {
        std::string s = body;
        for (size_t at; (at = s.find("CAST")) != std::string::npos;) s.replace(at, 4, qualifier);
        return compileLoose(s, "vs_3_0").shaders.at(0).glsl;
    };
    const std::string plain = with("");
    EXPECT_NE(plain.find("mat3"), std::string::npos) << plain;
    EXPECT_EQ(with("const"), plain);
}

// helix-toolkit's psCommon.hlsl: `#include "..\Common\Common.hlsl"` inside an include guard, the
// header included a second time (its body skipped), and such an include under `#if 0`. The taken
// include finds the file through the backslashes; the skipped ones are not read as string literals.
TEST(RealworldSixthWave, WindowsHeaderNameInSkippedGroup) {
    writeLooseSource("Common/Common.hlsl", "#ifndef COMMON_HLSL\n#define COMMON_HLSL\nstatic const float kCommon = 0.375;\n#endif\n");
    writeLooseSource("PS/psCommon.hlsl", "#ifndef PSCOMMON_HLSL\n#define PSCOMMON_HLSL\n#include \"..\\Common\\Common.hlsl\"\n"
                                    "float common() { return kCommon; }\n#endif\n");
    CompiledEffect e = compileLoose("#include \"psCommon.hlsl\"\n"
                                    "#include \"psCommon.hlsl\"\n"
                                    "#if 0\n#include \"..\\Missing\\Nothing.hlsl\"\n#endif\n"
                                    "float4 main() : SV_Target { return common(); }\n",
                                    "ps_4_0", "main", "PS/main.hlsl");
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("0.375"), std::string::npos) << glsl;
}

// OGRE's Hair.hlsl declares Buffer<> t0..t35 and its textures at t38 and on: the effect's texture
// objects take more registers than GL has units. A shader's textures still get units in range, each
// its own (the buffers it reads are texel buffers, bound apart from the units).
TEST(RealworldSixthWave, TexturesAfterMoreBuffersThanUnits) {
    std::string source;
    for (int i = 0; i < 36; ++i) source += "Buffer<float4> B" + std::to_string(i) + " : register(t" + std::to_string(i) + ");\n";
    source += "Texture2D A : register(t38);\nTexture2DArray C : register(t60);\nSamplerState S : register(s0);\n"
              "float4 main(float4 p : SV_Position) : SV_Target {\n"
              "    return A.Sample(S, p.xy) + C.Sample(S, p.xyz) + B35.Load(int(p.x));\n"
              "}\n";
    CompiledEffect e = compileLoose(source, "ps_5_0");
    const auto& samplers = e.shaders.at(0).samplers;
    ASSERT_EQ(samplers.size(), 2u);
    for (const SamplerBinding& b : samplers) {
        EXPECT_GE(b.unit, 0);
        EXPECT_LT(b.unit, 32);
    }
    EXPECT_NE(samplers[0].unit, samplers[1].unit);
}

// helix-toolkit's gsLineArrowHead.hlsl: `transform._m00_m11_m22 *= d;`, a compound assignment to
// matrix elements in several rows (glslang writes such a swizzle only with `=`). The elements read
// the matrix's own values, then take the result.
TEST(RealworldSixthWave, CompoundAssignmentToMatrixSwizzle) {
    CompiledEffect e = compileLoose("float4x4 M;\nfloat d;\n"
                                    "float4 main() : SV_Target {\n"
                                    "    float4x4 m = M;\n"
                                    "    m._m00_m11_m22 *= d;\n"
                                    "    m._11_42 += float2(2, (d + 1) * 3);\n"
                                    "    return m[0] + m[1] + m[2] + m[3];\n"
                                    "}\n",
                                    "ps_4_0");
    // The three diagonal elements are read as one vector and scaled together (values: the runtime's
    // realworld_sixth_wave_render_test).
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("vec3("), std::string::npos) << glsl;
}

// OGRE's HLSL_SM4Support.hlsl (OGRE_HLSL >= 4): `#define sampler2D Sampler2D`, a struct of that name
// holding a Texture2D and a SamplerState, `static Sampler2D Tex0 = {Tex0Tex, Tex0State};` and a
// user tex2D taking the struct. The struct is the source's type, not the sampler2D keyword in
// another case; the static variable is its objects: one texture/sampler pair in the GLSL.
TEST(RealworldSixthWave, StructNamedLikeASamplerType) {
    CompiledEffect e = compileLoose("#define sampler2D Sampler2D\n"
                                    "struct Sampler1D { Texture1D t; SamplerState s; };\n"
                                    "struct Sampler2D { Texture2D t; SamplerState s; };\n"
                                    "float4 tex1D(Sampler1D s, float v) { return s.t.Sample(s.s, v); }\n"
                                    "float4 tex2D(Sampler2D s, float2 v) { return s.t.Sample(s.s, v); }\n"
                                    "Texture2D Tex0Tex : register(t0);\nSamplerState Tex0State : register(s0);\n"
                                    "static sampler2D Tex0 = {Tex0Tex, Tex0State};\n"
                                    "float4 main(float2 uv : TEXCOORD0) : SV_Target { return tex2D(Tex0, uv) + Tex0.t.Sample(Tex0.s, uv); }\n",
                                    "ps_4_0");
    const auto& samplers = e.shaders.at(0).samplers;
    ASSERT_EQ(samplers.size(), 1u);
    EXPECT_EQ(samplers[0].textureParameter, "Tex0Tex");
    EXPECT_EQ(samplers[0].samplerName, "Tex0State");
}

// OGRE's Cg-era HLSL (Bloom2_ps20.cg, ssao.cg, Grass.cg): `uniform sampler RT : register(s0)` and
// `uniform sampler2D diffuseMap` as parameters of the entry point, compiled without values as
// D3DCompile does. Each is a sampler of the shader on the register written (else the next free one).
TEST(RealworldSixthWave, UniformSamplerParametersOfTheEntry) {
    CompiledEffect e = compileLoose("float4 main(float2 uv : TEXCOORD0, uniform sampler RT : register(s1),\n"
                                    "            uniform sampler2D diffuseMap, uniform float weight) : COLOR {\n"
                                    "    return tex2D(RT, uv) * weight + tex2D(diffuseMap, uv);\n"
                                    "}\n",
                                    "ps_2_0");
    const auto& samplers = e.shaders.at(0).samplers;
    ASSERT_EQ(samplers.size(), 2u);
    for (const SamplerBinding& b : samplers) {
        if (b.samplerName == "RT") EXPECT_EQ(b.samplerRegister, 1);
        else EXPECT_EQ(b.samplerName, "diffuseMap");
    }
    EXPECT_NE(samplers[0].unit, samplers[1].unit);
    CompiledEffect sm4 = compileLoose("SamplerState S : register(s0);\n"
                                      "float4 main(float2 uv : TEXCOORD0, uniform Texture2D map : register(t3)) : SV_Target {\n"
                                      "    return map.Sample(S, uv);\n"
                                      "}\n",
                                      "ps_4_0");
    ASSERT_EQ(sm4.shaders.at(0).samplers.size(), 1u);
    EXPECT_EQ(sm4.shaders.at(0).samplers[0].textureParameter, "map");
    EXPECT_EQ(sm4.shaders.at(0).samplers[0].textureRegister, 3);
}

// Source SDK's portal_ps2x.fxc: `#define USESTATICTEXTURE (((ADDSTATIC == 1) && (HASSTATICTEXTURE ==
// 1))?(1):(0))` tested by `#if( ... || (USESTATICTEXTURE == 1) )`. The #if takes the branch the
// ?: selects; in code the macro is the same integer.
TEST(RealworldSixthWave, ConditionalOperatorInAnIfExpression) {
    auto glslWith = [](int b) {
        return compileLoose("#define A 1\n#define B " + std::to_string(b) + "\n"
                            "#define USE (((A == 1) && (B == 1))?(1):(0))\n"
                            "#if( (A == 2) || (USE == 1) )\n"
                            "float4 main() : COLOR { return 0.75 + USE * 0.125; }\n"
                            "#else\n"
                            "float4 main() : COLOR { return 0.25 + USE * 0.125; }\n"
                            "#endif\n",
                            "ps_2_0")
            .shaders.at(0)
            .glsl;
    };
    const std::string taken = glslWith(1), skipped = glslWith(0);
    EXPECT_NE(taken.find("0.875"), std::string::npos) << taken;
    EXPECT_NE(skipped.find("0.25"), std::string::npos) << skipped;
    EXPECT_EQ(skipped.find("0.75"), std::string::npos) << skipped;
}

// Source SDK's skin_vs20.fxc / vertexlit_and_unlit_generic_bump_vs20.fxc: `float3 vTangentS : TANGENT;`
// and `float4 vUserData : TANGENT;` in one VS_INPUT. Both read the one vertex element: one vec4
// attribute, the float3 member its first three components.
TEST(RealworldSixthWave, TwoVertexInputsOnOneSemanticOfDifferentWidths) {
    CompiledEffect e = compileLoose("struct VS_INPUT { float4 p : POSITION; float3 t : TANGENT; float4 u : TANGENT; };\n"
                                    "float4 main(const VS_INPUT v) : POSITION { return v.p + float4(v.t, 0) * v.u.w; }\n",
                                    "vs_2_0");
    const auto& inputs = e.shaders.at(0).inputs;
    int tangents = 0;
    for (const auto& in : inputs)
        if (in.semantic == "TANGENT0") {
            ++tangents;
            EXPECT_EQ(in.components, 4);
        }
    EXPECT_EQ(tangents, 1);
}

// OGRE's Instancing_ps.cg: `float calcDepthShadow(sampler2D shadowMap, float4 uv)` before the
// static struct `shadowMap` the SM4 support header's SAMPLER2D declares. The parameter is its own.
TEST(RealworldSixthWave, StaticStructOfObjectsBesideAParameterOfItsName) {
    CompiledEffect e = compileLoose("struct Sampler2D { Texture2D t; SamplerState s; };\n"
                                    "float4 tex2D(Sampler2D s, float2 v) { return s.t.Sample(s.s, v); }\n"
                                    "float shade(Sampler2D shadowMap, float2 uv) { return tex2D(shadowMap, uv).x; }\n"
                                    "Texture2D shadowMapTex : register(t1);\nSamplerState shadowMapState : register(s1);\n"
                                    "static Sampler2D shadowMap = {shadowMapTex, shadowMapState};\n"
                                    "float4 main(float2 uv : TEXCOORD0) : SV_Target { return shade(shadowMap, uv); }\n",
                                    "ps_4_0");
    ASSERT_EQ(e.shaders.at(0).samplers.size(), 1u);
    EXPECT_EQ(e.shaders.at(0).samplers[0].textureParameter, "shadowMapTex");
}
