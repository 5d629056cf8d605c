// Issue 23, the constants side: declarations of constants and effects fxc takes and fxport refused,
// and the one it must refuse. The rules are fxc's as vkd3d's conformance files state them
// (cbuffer.shader_test, effect-technique-fx_4.shader_test, effect-annotations-fx_2.shader_test,
// default-values.shader_test); the values these shaders compute are checked on the GPU by
// tests/runtime/hlsl_integer_matrices_test.cpp and the conformance runner.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

const char* kTechnique = "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";

CompileOptions uncached(const std::string& effectProfile = "") {
    CompileOptions o;
    o.useCache = false;
    o.effectProfile = effectProfile;
    return o;
}

// The first error as "ID: message (line N)", or "" when the effect compiled.
std::string described(const Diagnostic& d) { return d.id + ": " + d.message + " (line " + std::to_string(d.location.line) + ")"; }

std::string firstError(const std::string& source, const CompileOptions& options = uncached()) {
    try {
        CompiledEffect e = compileEffectSource(source, "virtual/Constants.fx", options);
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return described(d);
        return "";
    } catch (const CompileError& error) {
        return described(error.diagnostics().front());
    }
}

bool hasParameter(const CompiledEffect& e, const std::string& name) {
    for (const auto& p : e.parameters)
        if (p.name == name) return true;
    return false;
}

}  // namespace

// fxc /T fx_4_0 and fx_5_0 compile an effect of variables only; fx_2_0 refuses it, and so does
// the empty profile (XNA's effects, which cannot draw without a technique).
TEST(ConstantsFidelity, EffectWithoutTechniqueFollowsTheProfile) {
    for (const char* profile : {"fx_4_0", "fx_4_1", "fx_5_0"}) {
        CompiledEffect e = compileEffectSource("float4 f;\ncbuffer cb { float4 g; }\n", "virtual/Variables.fx", uncached(profile));
        EXPECT_TRUE(e.techniques.empty()) << profile;
        EXPECT_TRUE(hasParameter(e, "f")) << profile;
        EXPECT_TRUE(hasParameter(e, "g")) << profile;
    }
    for (const char* profile : {"", "fx_2_0"})
        EXPECT_EQ(firstError("float4 f;\n", uncached(profile)).rfind(std::string(diag::kEmptyEffect) + ":", 0), 0u) << profile;
}

TEST(ConstantsFidelity, UnknownEffectProfileIsNamed) {
    std::string error = firstError("float4 f;\n", uncached("fx_3_0"));
    EXPECT_EQ(error.rfind(std::string(diag::kBadProfile) + ":", 0), 0u) << error;
    EXPECT_NE(error.find("'fx_3_0'"), std::string::npos) << error;
}

// `cbuffer cb : register(b1) < int i = 1; >`: annotations on a cbuffer are taken and dropped.
TEST(ConstantsFidelity, CbufferAnnotationsCompile) {
    EXPECT_EQ(firstError("cbuffer cb : register(b1) < int i = 1; string s = \"x\"; > { float4 m1; };\n"
                         "cbuffer cb2 < int i = 2; > { float4 m2; };\n"
                         "float4 PS() : SV_Target { return m1 + m2; }\n" + std::string(kTechnique)),
              "");
}

// fx_5_0's `single` before a cbuffer is a modifier; elsewhere it is an ordinary name.
TEST(ConstantsFidelity, SingleBeforeCbufferIsAModifier) {
    EXPECT_EQ(firstError("cbuffer cb { float4 single; };\nsingle cbuffer cb2 { float4 var; };\n"
                         "float4 PS() : SV_Target { return single + var; }\n" + std::string(kTechnique)),
              "");
}

// fxc checks packoffset overlaps (X4019) only in a cbuffer the shader reads.
TEST(ConstantsFidelity, PackoffsetOverlapIsAnErrorOnlyWhenTheCbufferIsRead) {
    const std::string buffer = "cbuffer buffer { float4 a[2] : packoffset(c1); float4 b[2] : packoffset(c2); }\n";
    EXPECT_EQ(firstError(buffer + "float4 PS() : SV_Target { return 0; }\n" + kTechnique), "");
    std::string read = firstError(buffer + "float4 PS() : SV_Target { return b[1]; }\n" + kTechnique);
    EXPECT_NE(read.find("overlaps 'a'"), std::string::npos) << read;
}

// Annotation values may carry a majority modifier (`row_major float3x2 m = {...}`).
TEST(ConstantsFidelity, AnnotationWithMajorityModifier) {
    EXPECT_EQ(firstError("float4 PS() : SV_Target { return 0; }\n"
                         "technique10 T < row_major float3x2 m = {1, 2, 3, 4, 5, 6}; > { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n"),
              "");
}

// GLSL has no integer or bool matrices: the translated shader holds none (integer_matrices.h).
TEST(ConstantsFidelity, IntegerMatricesLeaveNoMatrixTypeGlslLacks) {
    for (const char* profile : {"ps_3_0", "ps_4_0"}) {
        const std::string entry = std::string("technique T { pass P { PixelShader = compile ") + profile + " PS(); } }\n";
        CompiledEffect e = compileEffectSource("struct apple { float3 a[2]; int2x2 b; } ap = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};\n"
                                               "uint2x3 u; bool2x2 flags;\n"
                                               "float4 PS() : COLOR0 { int3x2 t = transpose((int2x3)u); return float4(ap.b) + t[2].y + flags[1].x; }\n" +
                                                   entry,
                                               "virtual/IntMatrices.fx", uncached());
        ASSERT_FALSE(e.shaders.empty()) << profile;
        for (const auto& s : e.shaders)
            for (const char* missing : {"imat", "umat", "bmat"}) EXPECT_EQ(s.glsl.find(missing), std::string::npos) << profile << "\n" << s.glsl;
    }
}

// fx_4_0 and later: a struct holding an object may be declared, not made a variable.
TEST(ConstantsFidelity, StructVariableHoldingAnObjectIsRefusedFromFx4) {
    const std::string type = "struct s { Texture t; float4 f; };\n";
    EXPECT_EQ(firstError(type, uncached("fx_4_0")), "");
    std::string error = firstError(type + "s var;\n", uncached("fx_5_0"));
    EXPECT_NE(error.find("'var'"), std::string::npos) << error;
    EXPECT_NE(error.find("(line 2)"), std::string::npos) << error;
}

// D3D10's BlendState indexes only BlendEnable and RenderTargetWriteMask; fx_4_1 indexes all.
TEST(ConstantsFidelity, PerTargetBlendStatesNeedFx41) {
    const std::string state = "BlendState bs\n{\n    BlendEnable[1] = true;\n    SrcBlend[0] = one;\n};\n";
    std::string error = firstError(state, uncached("fx_4_0"));
    EXPECT_NE(error.find("SrcBlend[0]"), std::string::npos) << error;
    EXPECT_NE(error.find("(line 4)"), std::string::npos) << error;
    EXPECT_EQ(firstError(state, uncached("fx_4_1")), "");
}

// An fxgroup has a name of its own and holds a technique.
TEST(ConstantsFidelity, FxgroupNeedsANameAndATechnique) {
    EXPECT_NE(firstError("fxgroup group\n{\n}\n", uncached("fx_5_0")), "");
    EXPECT_NE(firstError("fxgroup\n{\n    technique11 {}\n}\n", uncached("fx_5_0")), "");
    EXPECT_NE(firstError("float4 group;\nfxgroup group\n{\n    technique11 {}\n}\n", uncached("fx_5_0")), "");
    EXPECT_EQ(firstError("fxgroup group\n{\n    technique11 {}\n}\n", uncached("fx_5_0")), "");
}

// fxc takes two cbuffers of one name; each keeps its own members (and block).
TEST(ConstantsFidelity, TwoCbuffersOfOneName) {
    CompiledEffect e = compileEffectSource("cbuffer cb : register(b1) { float4 m1; };\ncbuffer cb { float4 m2; };\n"
                                           "float4 PS() : SV_Target { return m1 + m2; }\n" + std::string(kTechnique),
                                           "virtual/TwoCbuffers.fx", uncached());
    int m1 = -1, m2 = -1;
    for (const auto& p : e.parameters) {
        if (p.name == "m1") m1 = p.block;
        if (p.name == "m2") m2 = p.block;
    }
    EXPECT_GT(m1, 0);
    EXPECT_GT(m2, 0);
    EXPECT_NE(m1, m2);
}

// Before SM 5.1 fxc takes a cbuffer's slot as register(c#) as well as b# (AMD's ShadowFX ships
// fxc's output of `cbuffer CB : register(c0)`); other letters stay refused.
TEST(ConstantsFidelity, CbufferSlotMayBeWrittenAsAConstantRegister) {
    const std::string source = "cbuffer cb : register(c2) { float4 m1; };\nfloat4 PS() : SV_Target { return m1; }\n" + std::string(kTechnique);
    EXPECT_EQ(firstError(source), "");
    CompiledEffect e = compileEffectSource(source, "virtual/CbufferC.fx", uncached());
    bool found = false;
    for (const auto& r : e.resources)
        if (r.kind == ResourceDeclaration::Kind::ConstantBuffer && r.name == "cb") found = r.explicitRegister == 2;
    EXPECT_TRUE(found);
    EXPECT_NE(firstError("cbuffer cb : register(t2) { float4 m1; };\nfloat4 PS() : SV_Target { return m1; }\n" + std::string(kTechnique)), "");
}

// Annotations belong to globals: a local's are refused at their '<'.
TEST(ConstantsFidelity, LocalVariableAnnotationsAreRefused) {
    std::string error = firstError("float4 PS() : SV_Target\n{\n    float var < int a = 1; > = 0;\n    return var;\n}\n" + std::string(kTechnique));
    EXPECT_NE(error.find("'var'"), std::string::npos) << error;
    EXPECT_NE(error.find("(line 3)"), std::string::npos) << error;
    EXPECT_EQ(firstError("float g < int a = 1; > = 0;\nfloat4 PS() : SV_Target\n{\n    float var = g < 1 ? 2 : 3;\n    return var;\n}\n" +
                         std::string(kTechnique)),
              "");
}

// Gather with four offsets is four gathers with one offset each, component k from gather k (as fxc
// compiles it and GLSL defines it): llvmpipe's textureGatherOffsets reads other texels
// (gather_offsets.h). The values are the conformance runner's (gather.shader_test,
// gather-cmp.shader_test).
TEST(ConstantsFidelity, GatherWithFourOffsetsIsFourGathers) {
    CompiledEffect e = compileEffectSource("Texture2D t; SamplerState s; SamplerComparisonState c;\n"
                                           "float4 PS() : SV_Target { return t.GatherGreen(s, float2(0.2, 0.2), int2(0, 0), int2(1, 0), int2(0, 0), int2(0, 1))\n"
                                           "  + t.GatherCmp(c, float2(0.2, 0.2), 0.5, int2(0, 0), int2(1, 0), int2(0, 0), int2(0, 1)); }\n"
                                           "technique11 T { pass P { SetPixelShader(CompileShader(ps_5_0, PS())); } }\n",
                                           "virtual/GatherOffsets.fx", uncached());
    ASSERT_FALSE(e.shaders.empty());
    const std::string& glsl = e.shaders.back().glsl;
    EXPECT_EQ(glsl.find("textureGatherOffsets"), std::string::npos) << glsl;
    size_t gathers = 0;
    for (size_t at = glsl.find("textureGatherOffset("); at != std::string::npos; at = glsl.find("textureGatherOffset(", at + 1)) ++gathers;
    EXPECT_EQ(gathers, 8u) << glsl;
}

// Load()'s offset from a swizzle of a local vector fxc folds and glslang does not: the fetch reads
// coordinate + offset, as GLSL takes no variable texelFetchOffset (fetch_offsets.h). The values
// are the conformance runner's (swizzle-constant-prop.shader_test).
TEST(ConstantsFidelity, VariableLoadOffsetMovesTheCoordinate) {
    CompiledEffect e = compileEffectSource("Texture2D tex; Texture2DArray arr; int i;\n"
                                           "float4 PS() : SV_Target { int4 a = {1, 2, i, i}; int3 c = a.wyx;\n"
                                           "  return tex.Load(int3(0, 0, 0), a.xy) + arr.Load(int4(0, 0, 1, 0), c.yz); }\n" +
                                               std::string(kTechnique),
                                           "virtual/FetchOffsets.fx", uncached());
    ASSERT_FALSE(e.shaders.empty());
    const std::string& glsl = e.shaders.back().glsl;
    EXPECT_EQ(glsl.find("texelFetchOffset"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("texelFetch("), std::string::npos) << glsl;
}

// SM 4-5: fxc discards a `register(b...)` of a numeric global, whatever follows the b.
TEST(ConstantsFidelity, BufferRegisterOfANumericGlobalIsDiscarded) {
    EXPECT_EQ(firstError("float a : register(banana);\nfloat4 PS() : SV_Target { return a; }\n" + std::string(kTechnique)), "");
    EXPECT_EQ(firstError("float a : register(b2);\nfloat4 PS() : SV_Target { return a; }\n" + std::string(kTechnique)), "");
}
