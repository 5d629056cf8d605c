// Entry signatures as fxc lays them out (xlate/src/entry/signature_layout.h): a semantic on a struct
// cascades over its members with consecutive indices, arrays of structs take indices element after
// element, a matrix takes one semantic per column unless row_major, one-row and one-column matrix
// results map onto their registers, and an unused resource member of an input struct is no input.
// vkd3d's semantic-cascading, entry-point-semantics and matrix-semantics files check the values
// on the GPU; these tests pin the layout so a change to it fails here first.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>
#include <tuple>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "gl_link_check.h"

using namespace fxport::xlate;

namespace {

CompiledEffect compile(const std::string& source) {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(source, "virtual/EntrySignature.fx", o);
}

const CompiledShader& vertexShader(const CompiledEffect& e) {
    return e.shaders[size_t(e.techniques[0].passes[0].vertexShader.shaders[0])];
}

const CompiledShader& pixelShader(const CompiledEffect& e) {
    return e.shaders[size_t(e.techniques[0].passes[0].pixelShader.shaders[0])];
}

std::vector<std::string> inputSemantics(const CompiledShader& vs) {
    std::vector<std::string> out;
    for (const auto& in : vs.inputs) out.push_back(in.semantic + "/" + std::to_string(in.components));
    std::sort(out.begin(), out.end());
    return out;
}

bool hasLine(const std::string& glsl, const std::string& pattern) { return std::regex_search(glsl, std::regex(pattern)); }

const char* const kPassthroughPs = "float4 PS(float4 c : TEXCOORD0) : COLOR0 { return c; }\n";

std::string technique(const char* vs, const char* ps) {
    return std::string("technique T { pass P { VertexShader = compile vs_4_0 ") + vs + "(); PixelShader = compile ps_4_0 " + ps + "(); } }\n";
}

}  // namespace

TEST(EntrySignature, StructSemanticCascadesOverMembers) {
    CompiledEffect e = compile(std::string(R"(
struct apple { float aa; float bb[2] : INPLACE; float2 cc; };
struct banana { float dd; apple ap : IGNORED; };
float4 VS(float4 p : POSITION, banana ba : TEXCOORD3, out float4 c : TEXCOORD0) : SV_Position {
    c = float4(ba.dd, ba.ap.aa, ba.ap.bb[0] + ba.ap.bb[1], ba.ap.cc.y);
    return p;
}
)") + kPassthroughPs + technique("VS", "PS"));
    // dd TEXCOORD3, ap.aa 4, ap.bb[0..1] 5-6 (INPLACE and IGNORED overridden), ap.cc 7.
    EXPECT_EQ(inputSemantics(vertexShader(e)), (std::vector<std::string>{"POSITION0/4", "TEXCOORD3/1", "TEXCOORD4/1", "TEXCOORD5/1",
                                                                       "TEXCOORD6/1", "TEXCOORD7/2"}));
}

TEST(EntrySignature, ArrayOfStructsCascadesElementAfterElement) {
    CompiledEffect e = compile(std::string(R"(
struct apple { float aa; float2 bb; };
float4 VS(float4 p : POSITION, apple ap[2] : TEXCOORD1, out float4 c : TEXCOORD0) : SV_Position {
    c = float4(ap[0].aa + ap[0].bb.x, ap[1].bb, ap[1].aa);
    return p;
}
)") + kPassthroughPs + technique("VS", "PS"));
    EXPECT_EQ(inputSemantics(vertexShader(e)),
              (std::vector<std::string>{"POSITION0/4", "TEXCOORD1/1", "TEXCOORD2/2", "TEXCOORD3/1", "TEXCOORD4/2"}));
}

TEST(EntrySignature, ArrayOfStructsWithoutCascadeSharesMemberSemantics) {
    // fxc gives every element's member the member's own semantic: one input feeds them all.
    CompiledEffect e = compile(std::string(R"(
struct apple { float4 t0 : TEXCOORD0; float4 t1 : TEXCOORD1; };
float4 VS(float4 p : POSITION, apple aps[2][2], out float4 c : TEXCOORD0) : SV_Position {
    c = aps[0][0].t0 + aps[1][1].t1;
    return p;
}
)") + kPassthroughPs + technique("VS", "PS"));
    EXPECT_EQ(inputSemantics(vertexShader(e)), (std::vector<std::string>{"POSITION0/4", "TEXCOORD0/4", "TEXCOORD1/4"}));
}

TEST(EntrySignature, MatrixInputTakesOneSemanticPerColumnUnlessRowMajor) {
    CompiledEffect e = compile(std::string(R"(
float4 VS(float4 p : POSITION, float4x2 m : TEXCOORD0, row_major float3x2 r : TEXCOORD4, out float4 c : TEXCOORD0) : SV_Position {
    c = float4(m[3], r[0] + r[1] + r[2]);
    return p;
}
)") + kPassthroughPs + technique("VS", "PS"));
    // Columns of the 4x2: two 4-wide registers; rows of the row_major 3x2: three 2-wide ones.
    EXPECT_EQ(inputSemantics(vertexShader(e)), (std::vector<std::string>{"POSITION0/4", "TEXCOORD0/4", "TEXCOORD1/4", "TEXCOORD4/2",
                                                                       "TEXCOORD5/2", "TEXCOORD6/2"}));
}

TEST(EntrySignature, OneColumnAndOneRowResultsTakeTheirRegisters) {
    const char* vs = "float4 VS(float4 p : POSITION) : SV_Position { return p; }\n";
    // Column-major float4x1: one column, one target. row_major float4x1 and column-major
    // float1x4: four one-component registers, four targets.
    CompiledEffect column = compile(std::string(vs) + "float4x1 PS() : SV_Target { return float4(1, 2, 3, 4); }\n" + technique("VS", "PS"));
    EXPECT_EQ(pixelShader(column).outputTargets, 1);
    CompiledEffect rows =
        compile(std::string(vs) + "row_major float4x1 PS() : SV_Target { return float4(1, 2, 3, 4); }\n" + technique("VS", "PS"));
    EXPECT_EQ(pixelShader(rows).outputTargets, 4);
    CompiledEffect wide = compile(std::string(vs) + "float1x4 PS() : SV_Target { return float4(1, 2, 3, 4); }\n" + technique("VS", "PS"));
    EXPECT_EQ(pixelShader(wide).outputTargets, 4);
    CompiledEffect wideRow =
        compile(std::string(vs) + "row_major float1x4 PS() : SV_Target { return float4(1, 2, 3, 4); }\n" + technique("VS", "PS"));
    EXPECT_EQ(pixelShader(wideRow).outputTargets, 1);
    EXPECT_TRUE(hasLine(pixelShader(wideRow).glsl, R"(layout\(location = 0\) out vec4)")) << pixelShader(wideRow).glsl;
}

TEST(EntrySignature, UnusedResourceMemberOfAnInputStructIsNoInput) {
    CompiledEffect e = compile(std::string(R"(
struct apple { Texture2D unused; float4 c : TEXCOORD2; };
float4 VS(float4 p : POSITION, apple a, out float4 c : TEXCOORD0) : SV_Position { c = a.c; return p; }
)") + kPassthroughPs + technique("VS", "PS"));
    EXPECT_EQ(inputSemantics(vertexShader(e)), (std::vector<std::string>{"POSITION0/4", "TEXCOORD2/4"}));
}

TEST(EntrySignature, ResourceMemberWithASemanticIsRefused) {
    EXPECT_THROW(compile(std::string(R"(
struct apple { Texture2D t : TEXTURE; float4 c : TEXCOORD2; };
float4 VS(float4 p : POSITION, apple a, out float4 c : TEXCOORD0) : SV_Position { c = a.c; return p; }
)") + kPassthroughPs + technique("VS", "PS")),
                 CompileError);
}

// glslang drops an SV_Coverage pixel input (its reads became OpUndef); the wrapper's stand-in
// varying must end as gl_SampleMaskIn[0], neither a varying the runtime links nor an undefined value.
// vkd3d's coverage file checks the values on a 4-sample target.
TEST(EntrySignature, CoverageInputReadsGlSampleMaskIn) {
    CompiledEffect e = compile(std::string(R"(
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS(float4 c : TEXCOORD0, uint coverage : SV_Coverage) : SV_Target { return c * float(coverage); }
technique T { pass P { VertexShader = compile vs_5_0 VS(); PixelShader = compile ps_5_0 PS(); } }
)"));
    const CompiledShader& ps = pixelShader(e);
    EXPECT_TRUE(hasLine(ps.glsl, R"(uint\(gl_SampleMaskIn\[0\]\))")) << ps.glsl;
    EXPECT_FALSE(hasLine(ps.glsl, "SAMPLEMASKIN|in uint fxport_sampleMaskIn|uint _[0-9]+;")) << ps.glsl;
    ASSERT_EQ(ps.varyingInputs.size(), 1u);
    EXPECT_EQ(ps.varyingInputs[0].semantic, "TEXCOORD0");
}

// An interpolation modifier on a struct-typed parameter applies to its members (vkd3d's
// nointerpolation file checks the flat colour on the GPU).
TEST(EntrySignature, InterpolationModifierOfAStructParameterReachesItsMembers) {
    CompiledEffect e = compile(std::string(R"(
struct ps_input { float4 t : TEXCOORD0; };
float4 VS(float4 p : POSITION, out float4 t : TEXCOORD0) : SV_Position { t = p; return p; }
float4 PS(nointerpolation ps_input input) : SV_Target { return input.t; }
technique T { pass P { VertexShader = compile vs_4_0 VS(); PixelShader = compile ps_4_0 PS(); } }
)"));
    const CompiledShader& ps = pixelShader(e);
    EXPECT_TRUE(hasLine(ps.glsl, R"(flat in vec4 \w+;)")) << ps.glsl;
}

// An entry name with several overloads: d3dcompiler_47 (fxc) compiles the overload declared last,
// counting each overload from its first declaration, so a later prototype of an earlier overload
// changes nothing and an earlier prototype moves its overload ahead (vkd3d's
// tests/entry-point-overload.shader_test, native results, in ValveSoftware/vkd3d). Each overload
// returns its own constant, which SPIRV-Cross folds into the pixel shader's GLSL.
namespace {

std::string looseEntryGlsl(const std::string& source, const std::string& entry = "main") {
    CompileOptions o;
    o.useCache = false;
    return compileShaderSource(source, "virtual/Overloads.hlsl", {{"virtual/Overloads.hlsl", entry, "ps_4_0"}}, o).shaders.at(0).glsl;
}

const char* const kNoInputs = "float4 main() : sv_target { return 0.25; }\n";
const char* const kTexcoord = "float4 main(float tex : texcoord) : sv_target { return 0.75 + tex * 0; }\n";

}  // namespace

TEST(EntrySignature, OverloadedEntryIsTheOneDeclaredLast) {
    for (const auto& [source, chosen, other] : {std::tuple{std::string(kNoInputs) + kTexcoord, "0.75", "0.25"},
                                                std::tuple{std::string(kTexcoord) + kNoInputs, "0.25", "0.75"}}) {
        const std::string glsl = looseEntryGlsl(source);
        EXPECT_NE(glsl.find(chosen), std::string::npos) << source << glsl;
        EXPECT_EQ(glsl.find(other), std::string::npos) << source << glsl;
    }
}

TEST(EntrySignature, OverloadedEntryCountsFromItsFirstDeclaration) {
    // A later prototype of the first overload does not make it the last declared.
    std::string glsl = looseEntryGlsl(std::string(kTexcoord) + kNoInputs + "float4 main(float tex : texcoord) : sv_target;\n");
    EXPECT_NE(glsl.find("0.25"), std::string::npos) << glsl;
    // An earlier prototype of the second definition makes the first one the last declared.
    glsl = looseEntryGlsl(std::string("float4 main() : sv_target;\n") + kTexcoord + kNoInputs);
    EXPECT_NE(glsl.find("0.75"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("0.25"), std::string::npos) << glsl;
}

// MSAAFilter's and BakingLab's ToneMap: a helper overload, then the pixel shader of the same name.
TEST(EntrySignature, OverloadedEntryAfterAHelperOfItsName) {
    const std::string glsl = looseEntryGlsl(R"(
float3 ToneMap(float3 color, float exposure) { return color * exposure; }
float4 ToneMap(in float4 pos : SV_Position) : SV_Target0 { return float4(ToneMap(float3(1, 2, 4), 0.5), 1); }
)",
                                            "ToneMap");
    EXPECT_NE(glsl.find("vec4(0.5, 1.0, 2.0, 1.0)"), std::string::npos) << glsl;
}

// With the helper declared last, fxc takes the helper as the entry, whose parameters have no
// semantics: the error names the helper's parameter at the helper's line.
TEST(EntrySignature, OverloadedEntryDeclaredLastWithoutSemanticsIsRefusedAtItsLine) {
    try {
        looseEntryGlsl("float4 ToneMap(in float4 pos : SV_Position) : SV_Target0 { return pos; }\n"
                       "float3 ToneMap(float3 color, float exposure) { return color * exposure; }\n",
                       "ToneMap");
        FAIL() << "the helper overload compiled as the entry point";
    } catch (const CompileError& e) {
        const std::string text = e.diagnostics().empty() ? e.what() : e.diagnostics()[0].format();
        EXPECT_NE(text.find("Overloads.hlsl(2,"), std::string::npos) << text;
        EXPECT_NE(text.find("'color'"), std::string::npos) << text;
    }
}

// A bool vertex input (vkd3d's bool-semantics: `bool4 apple : apple` fed from a uint format): GLSL
// has no bool attribute ("vertex shader input / attribute cannot have type bvec4"), so the input
// is a uint one and nonzero reads true; the GL driver compiles and links the pass.
TEST(EntrySignature, BoolVertexInputsAreUintAttributes) {
    CompiledEffect e = compile("struct I { bool4 apple : apple; bool one : ONE; float4 pos : POSITION; };\n"
                               "struct O { float4 pos : SV_Position; nointerpolation int4 fapple : apple1; };\n"
                               "O VS(I i) { O o; o.pos = i.pos; o.fapple = i.apple + int4(i.one, 0, 0, 0); return o; }\n"
                               "float4 PS(O i) : SV_Target { return i.fapple; }\n"
                               "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }\n");
    const std::string& vs = vertexShader(e).glsl;
    EXPECT_EQ(vs.find("bvec"), std::string::npos) << vs;
    EXPECT_EQ(vs.find("in bool"), std::string::npos) << vs;
    EXPECT_NE(vs.find("in uvec4"), std::string::npos) << vs;
    fxport::test::sharedTestContext();
    using S = fxport::test::GlslStageSource;
    EXPECT_EQ(fxport::test::compileAndLinkSeparable({{S::Vertex, vs}, {S::Fragment, pixelShader(e).glsl}}), "");
}
