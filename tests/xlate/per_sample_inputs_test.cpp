// A pixel shader that runs once per sample (an SV_SampleIndex or `sample` input) reads its other
// inputs where D3D evaluates them, not where GL does: GL evaluates every input and gl_FragCoord of
// such a shader at the sample's position, D3D only the `sample` ones (entry_wrapper.cpp,
// evaluatedAsD3D). The values are checked by vkd3d's eval-attrib (tests/conformance); here the
// translation is checked for its form and that the GL driver takes it, with D3D's
// EvaluateAttribute* intrinsics (intrinsic_spellings.h, spirv_fixups.cpp interpolateAtSampleTakesInt).
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"
#include "gl_link_check.h"

using namespace fxport::xlate;

namespace {

// The GLSL of the pixel shader of `ps` (the body of PS, its inputs in `signature`), after a VS
// that writes ATTR and ATTR1; linked with it on the GL driver (an empty string when it links).
struct Linked {
    std::string pixel, linkLog;
};
Linked compileAndLink(const std::string& signature, const std::string& body) {
    const std::string text =
        "void VS(float4 p : POSITION, out float4 pos : SV_Position, out float2 a : ATTR, out float2 c : ATTR1) {\n"
        "    pos = p; a = p.xy; c = p.yx; }\n"
        "float4 PS(" + signature + ") : SV_Target {\n" + body + "\n}\n"
        "technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }\n";
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(text, "virtual/PerSample.fx", o);
    const Pass& p = e.techniques.at(0).passes.at(0);
    EXPECT_TRUE(p.valid);
    if (!p.valid) return {};
    Linked l;
    l.pixel = e.shaders.at(size_t(p.pixelShader.shaders.at(0))).glsl;
    fxport::test::sharedTestContext();
    using S = fxport::test::GlslStageSource;
    l.linkLog = fxport::test::compileAndLinkSeparable({{S::Vertex, e.shaders.at(size_t(p.vertexShader.shaders.at(0))).glsl}, {S::Fragment, l.pixel}});
    return l;
}

}  // namespace

TEST(PerSampleInputs, PlainInputsAndThePositionStayAtThePixelCentre) {
    Linked l = compileAndLink("float4 pos : SV_Position, float2 a : ATTR, centroid float2 c : ATTR1, uint s : SV_SampleIndex",
                              "return float4(pos.xy + a + c, s, 1);");
    EXPECT_EQ(l.linkLog, "");
    EXPECT_NE(l.pixel.find("interpolateAtOffset("), std::string::npos) << l.pixel;    // a: the centre
    EXPECT_NE(l.pixel.find("interpolateAtCentroid("), std::string::npos) << l.pixel;  // c: the centroid
    EXPECT_NE(l.pixel.find("floor("), std::string::npos) << l.pixel;                  // pos: the centre
}

TEST(PerSampleInputs, SampleInputsStayAtTheSample) {
    // Not linked: the link check's whole program wants the VS output declared `sample` as well,
    // the runtime's separate stage programs do not (vkd3d's eval-attrib draws such a pair).
    Linked l = compileAndLink("float4 pos : SV_Position, sample float2 a : ATTR", "return float4(pos.xy + a, 0, 1);");
    EXPECT_NE(l.pixel.find("sample in"), std::string::npos) << l.pixel;
    EXPECT_EQ(l.pixel.find("interpolateAtOffset("), std::string::npos) << l.pixel;
}

TEST(PerSampleInputs, PixelRateShadersReadTheirInputsAsDeclared) {
    Linked l = compileAndLink("float4 pos : SV_Position, float2 a : ATTR", "return float4(pos.xy + a, 0, 1);");
    EXPECT_EQ(l.linkLog, "");
    EXPECT_EQ(l.pixel.find("interpolateAt"), std::string::npos) << l.pixel;
    EXPECT_EQ(l.pixel.find("floor("), std::string::npos) << l.pixel;
}

TEST(PerSampleInputs, EvaluateAttributeIntrinsicsReachTheInput) {
    Linked l = compileAndLink("float2 a : ATTR, uint s : SV_SampleIndex",
                              "return float4(EvaluateAttributeAtSample(a, s) + EvaluateAttributeCentroid(a)\n"
                              "              + EvaluateAttributeSnapped(a, int2(1, 0)), 0, 1);");
    EXPECT_EQ(l.linkLog, "");
    EXPECT_NE(l.pixel.find("interpolateAtSample("), std::string::npos) << l.pixel;
    EXPECT_NE(l.pixel.find("interpolateAtCentroid("), std::string::npos) << l.pixel;
}
