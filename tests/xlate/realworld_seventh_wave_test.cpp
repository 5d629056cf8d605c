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
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

fs::path writeSource(const std::string& name, const std::string& source) {
    fs::path dir = fs::temp_directory_path() / ("fxport-seventh-wave-" + std::to_string(::getpid()));
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name) << source;
    return dir / name;
}

CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main") {
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{writeSource("shader.hlsl", source).string(), entry, profile}}, o);
}

std::string glslOf(const std::string& source, const std::string& profile) {
    try {
        return compileLoose(source, profile).shaders.at(0).glsl;
    } catch (const CompileError& err) {
        ADD_FAILURE() << err.what();
        return {};
    }
}

std::vector<Diagnostic> errorsOf(const std::string& source, const std::string& profile) {
    try {
        compileLoose(source, profile);
    } catch (const CompileError& err) {
        return err.diagnostics();
    }
    ADD_FAILURE() << "compiled";
    return {};
}

}  // namespace

// Wicked Engine's ShaderInterop structs (`inline bool IsUsingWind() { return options & ...; }`)
// and MAGE's lights (`struct OmniLight : PointLight`, whose Contribution calls the base's
// DistanceAttenuation, and `OmniLight::Contribution(...)` from a struct that hides it): member
// functions, called on a cbuffer's struct. The GLSL computes what the methods say: the hidden base
// function scaled by the derived one, the inherited one called unqualified.
TEST(RealworldSeventhWave, StructMemberFunctions) {
    const std::string glsl = glslOf(
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
    const std::string glsl = glslOf(
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
    const std::string glsl = glslOf(shared + "float4 main() : SV_Target { return s5 * 0.25 + f3; }\n", "ps_5_0");
    EXPECT_NE(glsl.find("s5 * 0.25"), std::string::npos) << glsl;

    std::string distinct;
    for (int i = 0; i < 15; ++i)
        distinct += "cbuffer B" + std::to_string(i) + " : register(b" + std::to_string(i) + ") { float4 b" + std::to_string(i) + "; };\n";
    auto errors = errorsOf(distinct + "float4 main() : SV_Target { return b0; }\n", "ps_5_0");
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors[0].message.find("X4567"), std::string::npos) << errors[0].message;
}
