// The text transform behind compute passes (runtime/graphics/src/compute_pass_source.cpp): a pixel
// shader's inputs and outputs become globals, gl_FragCoord and discard are rewritten, what a
// compute shader cannot do is refused, and the generated main reads the captured vertices at the
// right offsets. No GL: compute_pass_test.cpp draws with the result.
#include <gtest/gtest.h>

#include "compute_pass_source.h"

namespace fxport::detail {
namespace {

const char* kPixel = R"(#version 450

layout(binding = 0, std140) uniform _Global
{
    vec4 tint;
} _12;

layout(binding = 1) uniform sampler2D Source;

layout(location = 0) in vec4 i0;
layout(location = 2) noperspective in vec2 i2;
layout(location = 3) flat in ivec2 i3;
layout(location = 0) out vec4 _entryPointOutput_o0;
layout(location = 1) out vec4 _entryPointOutput_o1;

void main()
{
    if (i0.x < 0.5)
    {
        discard;
    }
    _entryPointOutput_o0 = texture(Source, i0.xy) * _12.tint + vec4(gl_FragCoord.xy, i2);
    _entryPointOutput_o1 = vec4(float(i3.x));
}
)";

const char* kVertex = R"(#version 450

out gl_PerVertex
{
    vec4 gl_Position;
};

layout(location = 0) in vec3 a0;
layout(location = 0) out vec4 o0;
layout(location = 2) noperspective out vec2 o2;
layout(location = 3) flat out ivec2 o3;

void main()
{
    gl_Position = vec4(a0, 1.0);
    o0 = vec4(a0, 1.0);
    o2 = a0.xy;
    o3 = ivec2(1, 2);
}
)";

TEST(ComputePassSource, InputsAndOutputsBecomeGlobals) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    ASSERT_EQ(f.refusal, "");
    ASSERT_EQ(f.inputs.size(), 3u);
    EXPECT_EQ(f.inputs[0].name, "i0");
    EXPECT_EQ(f.inputs[0].components, 4);
    EXPECT_EQ(f.inputs[0].interpolation, Interpolation::Smooth);
    EXPECT_EQ(f.inputs[1].location, 2);
    EXPECT_EQ(f.inputs[1].interpolation, Interpolation::NoPerspective);
    EXPECT_EQ(f.inputs[2].scalar, 'i');
    EXPECT_EQ(f.inputs[2].interpolation, Interpolation::Flat);
    ASSERT_EQ(f.outputs.size(), 2u);
    EXPECT_EQ(f.outputs[1].location, 1);
    EXPECT_NE(f.text.find("\nvec4 i0;\n"), std::string::npos);
    EXPECT_NE(f.text.find("\nvec4 _entryPointOutput_o0;\n"), std::string::npos);
    EXPECT_EQ(f.text.find(" in "), std::string::npos);
    EXPECT_EQ(f.text.find(" out "), std::string::npos);
    EXPECT_EQ(f.text.find("#version"), std::string::npos);
    // Uniform blocks and samplers keep their bindings.
    EXPECT_NE(f.text.find("layout(binding = 0, std140) uniform _Global"), std::string::npos);
    EXPECT_NE(f.text.find("layout(binding = 1) uniform sampler2D Source;"), std::string::npos);
}

TEST(ComputePassSource, MainFragCoordAndDiscardAreRewritten) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    ASSERT_EQ(f.refusal, "");
    EXPECT_NE(f.text.find("void fxport_pixelMain()"), std::string::npos);
    EXPECT_EQ(f.text.find("void main"), std::string::npos);
    EXPECT_NE(f.text.find("vec4(fxport_FragCoord.xy, i2)"), std::string::npos);
    EXPECT_EQ(f.text.find("gl_FragCoord"), std::string::npos);
    EXPECT_NE(f.text.find("{ fxport_discarded = true; return; };"), std::string::npos);
    EXPECT_EQ(f.text.find("discard;"), std::string::npos);
}

TEST(ComputePassSource, WhatAComputeShaderCannotDoIsRefused) {
    const std::string base = kPixel;
    auto refusalOf = [&](const std::string& from, const std::string& to) {
        std::string glsl = base;
        glsl.replace(glsl.find(from), from.size(), to);
        return pixelFunctionFromShader(glsl).refusal;
    };
    EXPECT_EQ(refusalOf("texture(Source, i0.xy)", "vec4(dFdx(i0.x))"), "uses dFdx");
    EXPECT_EQ(refusalOf("texture(Source, i0.xy)", "vec4(fwidthFine(i0.x))"), "uses fwidthFine");
    EXPECT_EQ(refusalOf("texture(Source, i0.xy)", "vec4(float(gl_FrontFacing))"), "uses gl_FrontFacing");
    EXPECT_EQ(refusalOf("texture(Source, i0.xy)", "interpolateAtCentroid(i0)"), "uses interpolateAtCentroid");
    EXPECT_EQ(refusalOf("_entryPointOutput_o1 = vec4(float(i3.x));", "gl_FragDepth = 0.5;"), "uses gl_FragDepth");
    // An output other than vec4 leaves channels GL does not define.
    EXPECT_EQ(refusalOf("layout(location = 1) out vec4 _entryPointOutput_o1;", "layout(location = 1) out float _entryPointOutput_o1;"),
              "writes float to render target 1");
    // An interface declaration it does not understand.
    EXPECT_NE(refusalOf("layout(location = 0) in vec4 i0;", "layout(location = 0) in vec4 i0[2];"), "");
    // discard in a function other than main cannot end the invocation.
    EXPECT_EQ(refusalOf("void main()\n{", "void helper() { discard; }\nvoid main()\n{"), "discards outside main()");
    // A shader without them is accepted; identifiers merely containing a refused word are not refused.
    EXPECT_EQ(refusalOf("texture(Source, i0.xy)", "vec4(i0.x + 1.0)"), "");
    EXPECT_EQ(refusalOf("vec4 tint;", "vec4 dFdxScale;"), "");
}

TEST(ComputePassSource, VertexOutputsInCaptureOrder) {
    VertexOutputs v = parseVertexOutputs(kVertex);
    ASSERT_EQ(v.refusal, "");
    ASSERT_EQ(v.varyings.size(), 3u);
    EXPECT_EQ(v.varyings[0].name, "o0");
    EXPECT_EQ(v.varyings[1].location, 2);
    EXPECT_EQ(v.varyings[2].type, "ivec2");
    EXPECT_EQ(capturedFloatsPerVertex(v.varyings), 4 + 4 + 2 + 2);
}

TEST(ComputePassSource, GeneratedMainReadsEachInputAtItsCapturedOffset) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    VertexOutputs v = parseVertexOutputs(kVertex);
    std::vector<ComputeTarget> targets(2);
    targets[0].imageFormat = "rgba8";
    targets[0].normalized = true;
    targets[0].color = targets[0].alpha = BlendOp::Min;
    targets[1].imageFormat = "rgba32f";
    targets[1].writeMask = 1 | 8;
    std::string refusal;
    std::string source = computeShaderSource(f, v.varyings, targets, refusal);
    ASSERT_EQ(refusal, "");
    // i0 after gl_Position (offset 4), perspective-correct; i2 at 8, screen-linear; i3 flat at 10
    // from the last (provoking) vertex.
    EXPECT_NE(source.find("i0 = vec4((p.x * fxport_read(t * 3 + 0, 4) + p.y * fxport_read(t * 3 + 1, 4) + p.z * fxport_read(t * 3 + 2, 4)))"),
              std::string::npos)
        << source;
    EXPECT_NE(source.find("i2 = vec2((l.x * fxport_read(t * 3 + 0, 8)"), std::string::npos);
    EXPECT_NE(source.find("i3 = ivec2((floatBitsToInt(fxport_read(t * 3 + 2, 10))).xy)"), std::string::npos);
    EXPECT_NE(source.find("int b = vertex * 12 + offset;"), std::string::npos);
    // Min on a unorm target clamps the source first; the masked float target keeps g and b.
    EXPECT_NE(source.find("vec4 src = clamp(_entryPointOutput_o0, 0.0, 1.0);"), std::string::npos);
    EXPECT_NE(source.find("min(src.rgb, fxport_dst0.rgb), min(src.a, fxport_dst0.a)"), std::string::npos);
    EXPECT_NE(source.find("mix(fxport_dst1, blended, bvec4(true, false, false, true))"), std::string::npos);
    EXPECT_NE(source.find("layout(binding = 1, rgba32f) uniform image2D fxport_target1;"), std::string::npos);
    EXPECT_NE(source.find("layout(local_size_x = 8, local_size_y = 8) in;"), std::string::npos);
}

TEST(ComputePassSource, AnInputWithoutAVertexOutputIsRefused) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    VertexOutputs v = parseVertexOutputs(kVertex);
    v.varyings.pop_back();  // no output at location 3
    std::vector<ComputeTarget> targets(1);
    targets[0].imageFormat = "rgba8";
    std::string refusal;
    EXPECT_EQ(computeShaderSource(f, v.varyings, targets, refusal), "");
    EXPECT_EQ(refusal, "pixel input 'i3' (location 3) has no vertex output");
}

}  // namespace
}  // namespace fxport::detail
