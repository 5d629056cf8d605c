// The text transform behind compute passes (runtime/graphics/src/compute_pass_source.cpp): a pixel
// shader's inputs and outputs become globals, gl_FragCoord and discard are rewritten, what a
// compute shader cannot do is refused, and the generated main and fill shader agree on the layers
// of the replay store. No GL: compute_pass_test.cpp draws with the result.
#include <gtest/gtest.h>

#include "gl/passes/compute_pass_source.h"

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

TEST(ComputePassSource, GeneratedMainReadsEachInputFromTheReplayStore) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    ASSERT_EQ(f.refusal, "");
    EXPECT_TRUE(f.readsFragCoord);
    // Read components only: i0.x and i0.xy, i2 whole, i3.x.
    ASSERT_EQ(f.inputs.size(), 3u);
    EXPECT_EQ(f.inputs[0].readMask, 3u);
    EXPECT_EQ(f.inputs[1].readMask, 3u);
    EXPECT_EQ(f.inputs[2].readMask, 1u);
    // Stamp, i0.xy, i2.xy, i3.x, gl_FragCoord's z and w.
    EXPECT_EQ(replayLayers(f), 1 + 2 + 2 + 1 + 2);
    EXPECT_TRUE(hasPerspectiveInput(f));
    std::vector<ComputeTarget> targets(2);
    targets[0].imageFormat = "rgba8";
    targets[0].normalized = true;
    targets[0].color = targets[0].alpha = BlendOp::Min;
    targets[1].imageFormat = "rgba32f";
    targets[1].writeMask = 1 | 8;
    std::string refusal;
    std::string source = computeShaderSource(f, targets, refusal);
    ASSERT_EQ(refusal, "");
    // Coverage is the fill's stamp; each read component one layer, bits as the fill stored them,
    // components never read 0.
    EXPECT_NE(source.find("if (fxport_stored(pixel, 0) != fxport_currentStamp) return;"), std::string::npos) << source;
    EXPECT_NE(source.find("i0 = vec4(uintBitsToFloat(fxport_stored(pixel, 1)), uintBitsToFloat(fxport_stored(pixel, 2)), 0.0, 0.0);"),
              std::string::npos);
    EXPECT_NE(source.find("i2 = vec2(uintBitsToFloat(fxport_stored(pixel, 3)), uintBitsToFloat(fxport_stored(pixel, 4)));"),
              std::string::npos);
    EXPECT_NE(source.find("i3 = ivec2(int(fxport_stored(pixel, 5)), 0);"), std::string::npos);
    EXPECT_NE(source.find("fxport_FragCoord = vec4(vec2(pixel) + 0.5, uintBitsToFloat(fxport_stored(pixel, 6)), "
                          "uintBitsToFloat(fxport_stored(pixel, 7)));"),
              std::string::npos);
    // Min on a unorm target clamps the source first; the masked float target keeps g and b.
    EXPECT_NE(source.find("vec4 src = clamp(_entryPointOutput_o0, 0.0, 1.0);"), std::string::npos);
    EXPECT_NE(source.find("min(src.rgb, dst.rgb), min(src.a, dst.a)"), std::string::npos);
    EXPECT_NE(source.find("blended = mix(dst, blended, bvec4(true, false, false, true))"), std::string::npos);
    EXPECT_NE(source.find("layout(binding = 1, rgba32f) uniform image2D fxport_target1;"), std::string::npos);
    EXPECT_NE(source.find("layout(local_size_x = 8, local_size_y = 8) in;"), std::string::npos);
}

// The fill shader declares the pixel shader's inputs as it does (location and qualifiers) and
// stores the same layers the compute shader reads.
TEST(ComputePassSource, FillShaderRepeatsTheInputDeclarations) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    const std::string fill = fillShaderSource(f);
    EXPECT_NE(fill.find("layout(location = 0) in vec4 i0;"), std::string::npos) << fill;
    EXPECT_NE(fill.find("layout(location = 2) noperspective in vec2 i2;"), std::string::npos);
    EXPECT_NE(fill.find("layout(location = 3) flat in ivec2 i3;"), std::string::npos);
    EXPECT_NE(fill.find("imageStore(fxport_store, ivec3(pixel, 1), uvec4(floatBitsToUint(i0.x)));"), std::string::npos);
    EXPECT_NE(fill.find("imageStore(fxport_store, ivec3(pixel, 5), uvec4(uint(i3.x)));"), std::string::npos);
    EXPECT_EQ(fill.find("i3.y"), std::string::npos);  // never read, not stored
    EXPECT_NE(fill.find("imageStore(fxport_store, ivec3(pixel, 7), uvec4(floatBitsToUint(gl_FragCoord.w)));"), std::string::npos);
    EXPECT_NE(fill.find("imageStore(fxport_store, ivec3(pixel, 0), uvec4(fxport_stamp));"), std::string::npos);
    EXPECT_EQ(fill.find("out "), std::string::npos);  // no colour output
    EXPECT_NE(inputSignature(f).find("2noperspective vec2:3"), std::string::npos);
}

TEST(ComputePassSource, AnInputWithoutAVertexOutputIsRefused) {
    PixelFunction f = pixelFunctionFromShader(kPixel);
    VertexOutputs v = parseVertexOutputs(kVertex);
    EXPECT_EQ(inputsRefusal(f, v.varyings), "");
    v.varyings.pop_back();  // no output at location 3
    EXPECT_EQ(inputsRefusal(f, v.varyings), "pixel input 'i3' (location 3) has no vertex output");
}

}  // namespace
}  // namespace fxport::detail
