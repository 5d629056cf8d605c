// Real-world shaders, seventh wave (session 25's run 26 over Wicked Engine's DX11 shaders, MAGE,
// RenderDoc's D3D11 shaders, Hieroglyph 3, HBAO+, TressFX, MJP's Shadows, DirectXTex, SharpDX's
// samples, Luna's DX11 book, and MonoGame/D3D11 course effects): valid HLSL that fxc compiles and
// fxport refused. Each is a small source of our own in the project's shape, with what the
// construct means asserted on the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "compile_loose.h"
#include "fxport/xlate/effect_file.h"
#include "run_cli.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::writeLooseSource;
using fxport::test::compileLoose;
using fxport::test::glslOfLoose;
using fxport::test::errorsOfLoose;

// Wicked Engine's ShaderInterop structs (`inline bool IsUsingWind() { return options & ...; }`)
// and MAGE's lights (`struct OmniLight : PointLight`, whose Contribution calls the base's
// DistanceAttenuation, and `OmniLight::Contribution(...)` from a struct that hides it): member
// functions, called on a cbuffer's struct. The GLSL computes what the methods say: the hidden base
// function scaled by the derived one, the inherited one called unqualified.
TEST(RealworldSeventhWave, StructMemberFunctions) {
    const std::string glsl = glslOfLoose(
        "struct Light {\n"
        "    float3 color;\n"
        "    uint options;\n"
        "    inline bool IsCasting() { return options & 2; }\n"
        "    float3 Scaled(float k) { return color * k; }\n"
        "};\n"
        "struct Spot : Light {\n"
        "    float angle;\n"
        "    float3 Scaled(float k) { return Light::Scaled(k) * angle; }\n"
        "    float3 Twice() { return Scaled(2.0) + color; }\n"
        "};\n"
        "cbuffer C : register(b0) { Spot spot; };\n"
        "float4 main() : SV_Target { return float4(spot.IsCasting() ? spot.Twice() : spot.Scaled(3.0), 1); }\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("spot.options & 2u"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("spot.color * 3.0) * "), std::string::npos) << glsl;   // Spot::Scaled(3)
    EXPECT_NE(glsl.find("spot.color * 2.0) * "), std::string::npos) << glsl;   // Twice: Scaled(2) + color
    EXPECT_NE(glsl.find("spot.angle) + "), std::string::npos) << glsl;
}

// MAGE's math.hlsli defines Max(half2) ... Max(uint4) and calls it from a light's member function,
// whose argument types fxport's overload ranking cannot read: the set is left to glslang, which
// must not see sqr(half) and sqr(float) as one function defined twice. Attributes on statements
// inside a member function are statement attributes, not attributes of a file-scope declaration.
TEST(RealworldSeventhWave, OverloadTwinsCalledFromAMemberFunction) {
    const std::string glsl = glslOfLoose(
        "half Max(half2 v) { return max(v.x, v.y); }\n"
        "half Max(half3 v) { return Max(max(v.xy, v.z)); }\n"
        "float Max(float2 v) { return max(v.x, v.y); }\n"
        "float Max(float3 v) { return Max(max(v.xy, v.z)); }\n"
        "int Max(int2 v) { return max(v.x, v.y); }\n"
        "struct Cube {\n"
        "    float3 extent;\n"
        "    float Reach(float3 p) {\n"
        "        float r = 0;\n"
        "        [unroll] for (int i = 0; i < 2; ++i) r += Max(abs(p) * extent);\n"
        "        [branch] if (r > 8) r = 8;\n"
        "        return r;\n"
        "    }\n"
        "};\n"
        "cbuffer C : register(b0) { Cube cube; };\n"
        "float4 main(float4 p : SV_Position) : SV_Target { return cube.Reach(p.xyz) + Max(p.xy); }\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("max("), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("8.0"), std::string::npos) << glsl;
}

// Wicked Engine's and RenderDoc's headers declare a dozen or more cbuffers that share registers
// (`cbuffer MeshVertexCBuffer : register(b0)`, `cbuffer TexDisplayPSCBuffer : register(b0)` ...);
// a shader reads one or two. fxc counts slots, not declarations: a register reserves its slot
// once, and a cbuffer without a register that no function reads takes none. The shader compiles
// and reads its own buffer; fifteen distinct registers are still refused (vkd3d's cbuffer.shader_test).
TEST(RealworldSeventhWave, ConstantBufferSlotsNotDeclarations) {
    std::string shared;
    for (int i = 0; i < 16; ++i)
        shared += "cbuffer Shared" + std::to_string(i) + " : register(b" + std::to_string(i % 4) + ") { float4 s" +
                  std::to_string(i) + "; };\n";
    for (int i = 0; i < 12; ++i) shared += "cbuffer Free" + std::to_string(i) + " { float4 f" + std::to_string(i) + "; };\n";
    const std::string glsl = glslOfLoose(shared + "float4 main() : SV_Target { return s5 * 0.25 + f3; }\n", "ps_5_0");
    EXPECT_NE(glsl.find("s5 * 0.25"), std::string::npos) << glsl;

    std::string distinct;
    for (int i = 0; i < 15; ++i)
        distinct += "cbuffer B" + std::to_string(i) + " : register(b" + std::to_string(i) + ") { float4 b" + std::to_string(i) + "; };\n";
    auto errors = errorsOfLoose(distinct + "float4 main() : SV_Target { return b0; }\n", "ps_5_0");
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors[0].message.find("X4567"), std::string::npos) << errors[0].message;
}

// MAGE's msaa.hlsli resolves `input_textures.m_image.sample[i][p_display]` (a Texture2DMS in a
// struct parameter) into `output_textures.m_image[p_display]` (an RWTexture2D member indexed by a
// uint2), RenderDoc's pixel history reads `copyin_stencil_ms.sample[s][uint3(...)].g` of a
// Texture2DMSArray. `.sample[s][p]` is the Load of sample s at p: texelFetch with the sample index.
TEST(RealworldSeventhWave, SampleIndexersOfMultisampleTextures) {
    const std::string glsl = glslOfLoose(
        "struct Inputs { Texture2DMS<float4> image; };\n"
        "struct Outputs { RWTexture2D<float4> image; };\n"
        "Texture2DMS<float4> image : register(t0);\n"
        "Texture2DMSArray<uint2> stencil : register(t1);\n"
        "RWTexture2D<float4> outImage : register(u0);\n"
        "void resolve(uint2 p, Inputs inputs, Outputs outputs) {\n"
        "    float4 sum = 0;\n"
        "    for (uint i = 0; i < 4; ++i) sum += inputs.image.sample[i][p] * 0.25 + stencil.sample[3][uint3(p, 1)].g;\n"
        "    outputs.image[p] = sum;\n"
        "}\n"
        "[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    Inputs inputs; inputs.image = image;\n"
        "    Outputs outputs; outputs.image = outImage;\n"
        "    resolve(id.xy, inputs, outputs);\n"
        "}\n",
        "cs_5_0");
    // (Each fetch is compared against the texture's size and samples: out_of_range_accesses.h.)
    EXPECT_NE(glsl.find(" = ivec2(gl_GlobalInvocationID.xy);"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(" = int(_"), std::string::npos) << glsl;  // sample i of image
    EXPECT_NE(glsl.find("texelFetch(fxport_image_SPIRV_Cross_DummySampler, _"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(" = ivec3(uvec3(gl_GlobalInvocationID.xy, 1u));"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find(", 3), bvec4("), std::string::npos) << glsl;  // sample 3 of stencil
    EXPECT_NE(glsl.find("imageStore(outImage"), std::string::npos) << glsl;
}

// Wicked Engine's gpusortlib_sortCS.hlsl sizes its thread group with a conditional of macro
// arithmetic: `[numthreads(N / (N > 1024 ? N / 1024 : 1), 1, 1)]`. fxc folds it; so does the
// thread-group size here: 256 x 2 for N = 256, 1024 x 1 for N = 2048.
TEST(RealworldSeventhWave, ConditionalThreadGroupSize) {
    auto sized = [](const std::string& n) {
        return glslOfLoose("#define N (" + n + ")\n"
                      "RWBuffer<uint> data : register(u0);\n"
                      "[numthreads(N / (N > 1024 ? N / 1024 : 1), N >= 512 == 1 ? 1 : 2, 1)]\n"
                      "void main(uint3 id : SV_DispatchThreadID) { data[id.x] = id.y; }\n",
                      "cs_5_0");
    };
    const std::string small = sized("512 / 2"), large = sized("1024 * 2");
    EXPECT_NE(small.find("local_size_x = 256, local_size_y = 2,"), std::string::npos) << small;
    EXPECT_NE(large.find("local_size_x = 1024, local_size_y = 1,"), std::string::npos) << large;
}

// Luna's DX11 book builds every .fx with `fxc /T fx_5_0 /Fo X.fxo X.fx`, LightHelper.fx (structs
// and functions, no technique) included: the same command line compiles with fxport, the effect
// profile taken from /T, and a technique-less file is then a compiled effect, as with fxc; with no
// profile (XNA's rules) it stays FX1003.
TEST(RealworldSeventhWave, EffectProfileFromTheCommandLine) {
    const fs::path header = writeLooseSource("FX/LightHelper.fx", "struct Material { float4 Ambient; float4 Diffuse; };\n"
                                                              "float4 Lit(Material m, float k) { return m.Ambient + m.Diffuse * k; }\n");
    const std::string out = (header.parent_path() / "LightHelper.fxo").string();
    auto fxc = fxport::test::runCli("compile /T fx_5_0 /Fo '" + out + "' '" + header.string() + "' --no-cache");
    EXPECT_EQ(fxc.status, 0) << fxc.output;
    EXPECT_TRUE(fs::exists(out)) << fxc.output;
    auto plain = fxport::test::runCli("compile '" + header.string() + "' -o '" + out + "' --no-cache");
    EXPECT_EQ(plain.status, 1) << plain.output;
    EXPECT_NE(plain.output.find("FX1003"), std::string::npos) << plain.output;
}

// A D3D11 course's fx_5_0 effects (compiled with D3D10_SHADER_ENABLE_BACKWARDS_COMPATIBILITY)
// include a header of twenty cbuffers, and each technique's shaders read a few: fxc counts the
// slots per shader. Its instancing vertex shaders assign a cbuffer member (`World =
// input.Transform;`): the shader works on its own copy, as with a $Globals uniform, the copy
// declared after the cbuffer (glslang takes no static inside it). The GLSL transforms by the
// modified copy.
TEST(RealworldSeventhWave, EffectCbuffersPerShaderAndWrittenMembers) {
    std::string source;
    for (int i = 0; i < 20; ++i) source += "cbuffer CB_" + std::to_string(i) + " { float4 v" + std::to_string(i) + "; };\n";
    source += "cbuffer CB_World { matrix World; };\n"
              "float4 VS(float4 p : POSITION) : SV_Position { World = World * 2.0; return mul(p, World) + v0 + v1; }\n"
              "float4 PS1() : SV_Target { return v2 + v3 + v4 + v5 + v6 + v7 + v8 + v9; }\n"
              "float4 PS2() : SV_Target { return v10 + v11 + v12 + v13 + v14 + v15 + v16 + v17 + v18 + v19; }\n"
              "technique11 A { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS1())); } }\n"
              "technique11 B { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS2())); } }\n";
    CompileOptions o;
    o.useCache = false;
    o.effectProfile = "fx_5_0";
    CompiledEffect e;
    try {
        e = compileEffectFile(writeLooseSource("Course.fx", source).string(), o);
    } catch (const CompileError& err) {
        FAIL() << err.what();
    }
    bool copied = false;
    for (const auto& s : e.shaders)
        if (s.entryPoint == "VS") copied = s.glsl.find("* 2.0") != std::string::npos && s.glsl.find("World") != std::string::npos;
    EXPECT_TRUE(copied);
}

// MAGE's voxel cone tracer: `GetRadianceAndAO(Cone cone)` calls its sibling
// `GetRadianceAndAO(cone, m_max_cone_distance)`, whose parameter is a float4, with a float; a
// derived struct calls an inherited one with an int. fxc converts the arguments as in any call;
// the GLSL reads the float replicated and the int as 2.0.
TEST(RealworldSeventhWave, MemberFunctionCallsConvertArguments) {
    const std::string glsl = glslOfLoose(
        "struct Tracer {\n"
        "    float4 weights;\n"
        "    float reach;\n"
        "    float Trace(float4 distances) { return dot(weights, distances); }\n"
        "    float Trace() { return Trace(reach); }\n"
        "    float Scaled(float k) { return reach * k; }\n"
        "};\n"
        "struct Wide : Tracer { float Twice() { return Scaled(2) + Trace(); } };\n"
        "cbuffer C : register(b0) { Wide w; };\n"
        "float4 main() : SV_Target { return w.Twice(); }\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("w.weights, vec4("), std::string::npos) << glsl;  // Trace(reach): the float replicated
    EXPECT_NE(glsl.find("w.reach, 2.0,"), std::string::npos) << glsl;     // Scaled(2): reach * 2.0 (an fma)
}
