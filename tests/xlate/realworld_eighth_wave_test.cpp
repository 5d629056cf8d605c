// Real-world shaders, eighth wave (session 26's run 27 over OpenXRay's r5 shaders, Torque3D, AMD's
// ShadowFX / GeometryFX / DepthOfFieldFX, Intel's CloudsGPUPro6 and DeferredCoarsePixelShading,
// Nez, penumbra, Aether.Extras, MonoGame.Extended and FlatRedBall): HLSL that fxport refused or
// crashed on, or compiled to GLSL whose result differs from fxc's. Each is a small source of our
// own in the project's shape, with what the construct means asserted on the GLSL or the error.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "compile_loose.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::glslOfLoose;
using fxport::test::errorsOfLoose;

// OpenXRay's particle.ps: `#define DEPTH_EPSILON 0.1h` and `spaceDepth < -2*DEPTH_EPSILON`. fxc
// computes half as float, so the product is the float 0.2; glslang refused an int beside the
// half literal ("Could not perform requested binary operation"). The folded constant is float32's
// 2 * 0.1.
TEST(RealworldEighthWave, HalfLiteralsAreFloats) {
    const std::string glsl = glslOfLoose(
        "#define EPSILON 0.1h\n"
        "float4 main(float4 c : COLOR0) : SV_Target {\n"
        "    float d = c.x;\n"
        "    if (d < -2 * EPSILON) d = 100000.0h;\n"
        "    return d * (2 * 0.25H);\n"
        "}\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("-0.20000000298023223876953125"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("100000.0"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("0.5"), std::string::npos) << glsl;
}

// OpenXRay's pda_overlay.ps calls `noise(tc)` in a ps_5_0 shader: an intrinsic of texture shaders
// (tx_1_0) only, which no shader profile has an instruction for. glslang crashed on it (SIGSEGV,
// FX9001); it is now fxc's refusal, at the call. A call no compiled shader reaches compiles
// (vkd3d's noise.shader_test), and a function of the shader's own named noise is called instead.
TEST(RealworldEighthWave, NoiseIsATextureShaderIntrinsic) {
    const std::vector<Diagnostic> errors = errorsOfLoose(
        "float4 main(float2 tc : TEXCOORD0) : SV_Target {\n"
        "    return tc.x - noise(tc) * 0.5;\n"
        "}\n",
        "ps_5_0");
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].message.find("'noise' is a texture-shader (tx_1_0) intrinsic: ps_5_0"), std::string::npos) << errors[0].message;
    EXPECT_EQ(errors[0].location.line, 2);
    EXPECT_FALSE(glslOfLoose("float4 unused(float2 tc) { return noise(tc); }\n"
                        "float4 main(float2 tc : TEXCOORD0) : SV_Target { return float4(tc, 0, 1); }\n",
                        "ps_5_0")
                     .empty());
    const std::string own = glslOfLoose("float noise(float2 p) { return frac(sin(dot(p, float2(12.9898, 78.233))) * 43758.5453); }\n"
                                   "float4 main(float2 tc : TEXCOORD0) : SV_Target { return noise(tc); }\n",
                                   "ps_5_0");
    EXPECT_NE(own.find("43758.546875"), std::string::npos) << own;
}

// OpenXRay's gas-mask drops and rain shaders fade with reversed edges: `smoothstep(0.5, 0.0, d)`,
// `smoothstep(250, 200, p_len)`. GLSL's smoothstep is undefined for edge0 >= edge1; fxc's is
// t * t * (3 - 2t) with t = saturate((x - a) / (b - a)), which falls from 1 to 0 there. The GLSL
// spells fxc's arithmetic; edges that are constants in order keep smoothstep (defined, the same).
TEST(RealworldEighthWave, ReversedSmoothstepEdgesComputeFxcsCurve) {
    const std::string glsl = glslOfLoose(
        "cbuffer C : register(b0) { float near; float far; };\n"
        "float4 main(float4 c : COLOR0) : SV_Target {\n"
        "    return float4(smoothstep(far, near, c.x), smoothstep(0.5, 0.0, c.y), smoothstep(0.2, 0.8, c.z), 1);\n"
        "}\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("(i0.x - _"), std::string::npos) << glsl;                  // x - a over b - a
    EXPECT_NE(glsl.find(".near - _"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("clamp((i0.y - 0.5) * (-2.0), 0.0, 1.0)"), std::string::npos) << glsl;  // (x - 0.5) / -0.5
    EXPECT_NE(glsl.find("smoothstep(0.20000000298023223876953125, 0.800000011920928955078125, i0.z)"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("smoothstep(0.5"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("smoothstep(_"), std::string::npos) << glsl;
}

// clamp(x, a, b) is min(max(x, a), b) to fxc, so reversed bounds (OpenXRay's pda_overlay.ps:
// `clamp(0.1, sin(4 * n), 0.4)`) give b; GLSL's clamp is undefined when min > max. Bounds that are
// not constants in order are written as fxc computes them; saturate stays a clamp to 0..1.
TEST(RealworldEighthWave, ReversedClampBoundsGiveTheMaximum) {
    const std::string glsl = glslOfLoose(
        "cbuffer C : register(b0) { float lo; float hi; int ilo; int ihi; };\n"
        "float4 main(float4 c : COLOR0, int4 k : TEXCOORD1) : SV_Target {\n"
        "    return float4(clamp(0.1, sin(c.x), 0.4), clamp(c.y, lo, hi), clamp(k.x, ilo, ihi), saturate(c.w));\n"
        "}\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("min(max(0.100000001490116119384765625, sin(i0.x)), 0.4000000059604644775390625)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("min(max(i0.y, _"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("min(max(i1.x, _"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("clamp(i0.w, 0.0, 1.0)"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("clamp(i0.y"), std::string::npos) << glsl;
}

// Torque3D's MLAA blend weights (DX9-style: sampler2D, tex2Dlod, COLOR0) are compiled at ps_5_0,
// where fxc's round() is round_ne: halves to the even integer. With glslang's DX9 switch the GLSL
// was `round`, whose halves GLSL leaves to the implementation; it is `roundEven` as for a
// Texture2D source (the GLSL before the fix: `vec4(round(vec2(...`).
TEST(RealworldEighthWave, RoundOfDx9StyleSourceRoundsHalvesToEven) {
    const std::string source =
        "sampler2D edges : register(s0);\n"
        "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n"
        "    float e = tex2Dlod(edges, float4(uv, 0, 0)).r;\n"
        "    return float4(33 * round(4.0 * float2(e, uv.y)), round(uv.x), 1);\n"
        "}\n";
    const std::string glsl = glslOfLoose(source, "ps_5_0");
    EXPECT_NE(glsl.find("roundEven(vec2("), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("roundEven(i0.x)"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find(" round("), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("(round("), std::string::npos) << glsl;
}

// Seen while reading this sample's GLSL (CloudsGPUPro6 and Torque3D scale sign(); none divides
// sign() itself): HLSL's sign() is an int, so `sign(d) / 2` divides integers (0), `sign(d) & 1` and
// `sign(v) >> 1` are integer operations. glslang typed sign as float: the division gave ±0.5, the
// `&` a float operand (GLSL the driver refuses) and the shift moved the float's bits. The calls
// are cast to fxc's int type; a constant folds as fxc folds it (sign(-3.0) / 2 + 0.25 is 0.25).
TEST(RealworldEighthWave, SignIsAnInt) {
    const std::string glsl = glslOfLoose(
        "cbuffer C : register(b0) { float d; float3 v; };\n"
        "float4 main() : SV_Target {\n"
        "    int a = sign(d) & 1;\n"
        "    float b = sign(d) / 2;\n"
        "    int3 c = sign(v) >> 1;\n"
        "    return float4(a, b, c.y, sign(-3.0) / 2 + 0.25);\n"
        "}\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("float(int(sign(_"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(")) & 1)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(")) / 2)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("(ivec3(sign(_"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(", 0.25);"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("& 1.0"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("floatBitsToInt(sign"), std::string::npos) << glsl;
}

// Two blocks of one function each declare an array of the same name and size (Wicked Engine's
// depth-of-field post-filter: `float p[9]` then `float3 p[9]`; Luna's GS subdivision: `v[12]`, then
// `v[6]` ...). The deferral of out-of-range literal indices read the second declaration's size `9`
// as an index past the first array's end and wrapped it in a call: glslang refused the declaration.
TEST(RealworldEighthWave, ArraysOfOneNameInTwoBlocksKeepTheirSizes) {
    const std::string glsl = glslOfLoose(
        "RWTexture2D<float4> output : register(u0);\n"
        "[numthreads(8, 8, 1)]\n"
        "void main(uint3 id : SV_DispatchThreadID) {\n"
        "    float alpha = 0;\n"
        "    { float p[9]; p[0] = id.x; p[8] = id.y; alpha = p[4] + p[8]; }\n"
        "    { float3 p[9]; p[0] = id.x; p[8] = id.y; alpha += p[4].x + p[8].y; }\n"
        "    output[id.xy] = alpha;\n"
        "}\n",
        "cs_5_0");
    EXPECT_NE(glsl.find("void main()"), std::string::npos) << glsl;
}
