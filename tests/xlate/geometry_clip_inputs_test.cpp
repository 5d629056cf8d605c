// A geometry shader whose per-vertex input struct carries SV_ClipDistance / SV_CullDistance
// (D3D10's FixedFuncEMU passes its user clip planes through its flat-shading GS so): glslang 12
// crashed on it (SIGSEGV); fxport moves the built-ins to parameters of their own
// (xlate/src/rewrite/geometry_clip_inputs.h) and spells the reads as gl_in[v].gl_ClipDistance[i]
// (xlate/src/glsl/arrayed_clip_inputs.h). The VS -> GS -> PS pass must compile and link on the GL
// driver (OSMesa), the GS reading the VS's clip distances and passing them on.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"
#include "gl_link_check.h"

using namespace fxport::xlate;

namespace {

std::string effect(const std::string& builtin, const std::string& type) {
    return "struct V { float4 pos : SV_Position; float3 wPos : TEXCOORD1; float4 color : COLOR0;\n"
           "           " + type + " planes : " + builtin + "0; };\n"
           "float4 Plane0, Plane1, Plane2;\n"
           "V VS(float4 pos : POSITION) {\n"
           "    V v = (V)0; v.pos = pos; v.wPos = pos.xyz; v.color = 1;\n"
           "    v.planes = (" + type + ")float4(dot(pos, Plane0), dot(pos, Plane1), dot(pos, Plane2), 1);\n"
           "    return v; }\n"
           "[maxvertexcount(3)]\n"
           "void GS(triangle V input[3], inout TriangleStream<V> stream) {\n"
           "    float3 n = normalize(cross(input[1].wPos - input[0].wPos, input[2].wPos - input[0].wPos));\n"
           "    for (int i = 0; i < 3; i++) { V o = input[i]; o.color = float4(n, 1); stream.Append(o); }\n"
           "    stream.RestartStrip(); }\n"
           "float4 PS(V v) : SV_Target { return v.color; }\n"
           "technique10 Flat { pass P { SetVertexShader(CompileShader(vs_4_0, VS()));\n"
           "    SetGeometryShader(CompileShader(gs_4_0, GS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
}

void expectCompilesAndLinks(const std::string& builtin, const std::string& type, const std::string& glslName) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(effect(builtin, type), "virtual/GsClip.fx", o);
    const Pass& p = e.techniques.at(0).passes.at(0);
    ASSERT_TRUE(p.valid);
    const std::string& gs = e.shaders.at(size_t(p.geometryShader.shaders.at(0))).glsl;
    EXPECT_NE(gs.find("gl_in[0]." + glslName + "["), std::string::npos) << gs;
    EXPECT_EQ(gs.find(glslName + "[0]["), std::string::npos) << gs;  // the output's float[] indexed twice
    fxport::test::sharedTestContext();
    using S = fxport::test::GlslStageSource;
    EXPECT_EQ(fxport::test::compileAndLinkSeparable({{S::Vertex, e.shaders.at(size_t(p.vertexShader.shaders.at(0))).glsl},
                                                    {S::Geometry, gs},
                                                    {S::Fragment, e.shaders.at(size_t(p.pixelShader.shaders.at(0))).glsl}}),
              "");
}

}  // namespace

TEST(GeometryClipInputs, ClipDistancesInTheInputStructCompileAndLink) {
    expectCompilesAndLinks("SV_ClipDistance", "float3", "gl_ClipDistance");
    expectCompilesAndLinks("SV_ClipDistance", "float", "gl_ClipDistance");
    expectCompilesAndLinks("SV_ClipDistance", "float2", "gl_ClipDistance");  // 2 per vertex, 3 vertices
    expectCompilesAndLinks("SV_ClipDistance", "float4", "gl_ClipDistance");
}

TEST(GeometryClipInputs, CullDistancesInTheInputStructCompileAndLink) {
    expectCompilesAndLinks("SV_CullDistance", "float3", "gl_CullDistance");
}

TEST(GeometryClipInputs, OneComponentCullDistanceCompilesAndLinks) {
    expectCompilesAndLinks("SV_CullDistance", "float1", "gl_CullDistance");
}

// Clip and cull distances under several semantic indices in one struct: the GS reads each from
// the place the VS's packed outputs put it (clip_distance_packing.h: in order of semantic index).
TEST(GeometryClipInputs, SeveralClipAndCullSemanticsReadFromThePackedPlaces) {
    const std::string text =
        "struct V { float4 pos : SV_Position; float2 c0 : SV_ClipDistance0; float3 c1 : SV_ClipDistance1;\n"
        "           float2 k1 : SV_CullDistance1; float1 k0 : SV_CullDistance0; };\n"
        "V VS(float4 pos : POSITION) { V v; v.pos = pos; v.c0 = pos.xy; v.c1 = pos.xyz; v.k1 = pos.zw; v.k0 = pos.w; return v; }\n"
        "[maxvertexcount(3)]\n"
        "void GS(triangle V input[3], inout TriangleStream<V> stream) {\n"
        "    for (int i = 0; i < 3; i++) { V o = input[i]; stream.Append(o); } }\n"
        "float4 PS(V v) : SV_Target { return 1; }\n"
        "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS()));\n"
        "    SetGeometryShader(CompileShader(gs_4_0, GS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(text, "virtual/GsClips.fx", o);
    const Pass& p = e.techniques.at(0).passes.at(0);
    ASSERT_TRUE(p.valid);
    const std::string& vs = e.shaders.at(size_t(p.vertexShader.shaders.at(0))).glsl;
    const std::string& gs = e.shaders.at(size_t(p.geometryShader.shaders.at(0))).glsl;
    // Five clip and three cull distances per vertex on both sides of the link, no holes.
    EXPECT_NE(vs.find("float gl_ClipDistance[5]"), std::string::npos) << vs;
    EXPECT_NE(vs.find("float gl_CullDistance[3]"), std::string::npos) << vs;
    EXPECT_NE(gs.find("gl_in[2].gl_ClipDistance[4]"), std::string::npos) << gs;
    EXPECT_NE(gs.find("gl_in[2].gl_CullDistance[2]"), std::string::npos) << gs;
    EXPECT_EQ(gs.find("gl_ClipDistance[6]"), std::string::npos) << gs;
    fxport::test::sharedTestContext();
    using S = fxport::test::GlslStageSource;
    EXPECT_EQ(fxport::test::compileAndLinkSeparable({{S::Vertex, vs},
                                                    {S::Geometry, gs},
                                                    {S::Fragment, e.shaders.at(size_t(p.pixelShader.shaders.at(0))).glsl}}),
              "");
}
