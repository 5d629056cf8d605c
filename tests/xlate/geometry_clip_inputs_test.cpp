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
