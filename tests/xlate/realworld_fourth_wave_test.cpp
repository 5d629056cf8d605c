// Real-world shaders, fourth wave (session 22's run over D3D11 samples: Intel ASSAO, NVIDIA
// D3DSamples, Microsoft Xbox-ATG-Samples, GameTechDev's OutdoorLightScattering): valid HLSL that fxc
// compiles and fxport refused. Each is a small source of our own in the sample's shape, compiled as
// the sample's build does, with what the construct means asserted on the reflection or the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

fs::path writeSource(const std::string& name, const std::string& source) {
    fs::path dir = fs::temp_directory_path() / ("fxport-fourth-wave-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / name) << source;
    return dir / name;
}

CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main") {
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{writeSource("shader.hlsl", source).string(), entry, profile}}, o);
}

}  // namespace

// ASSAO's vaSimpleShadowMap.hlsl: two functions each size a flat-initialised array by their own
// `const int sampleCount` (6 and 14). Each array takes its own function's constant.
TEST(RealworldFourthWave, LocalConstantSizesAreTheirFunctions) {
    CompiledEffect e = compileLoose(
        "float2 a() { const int n = 3; const float2 o[n] = {1, 2, 3, 4, 5, 6}; return o[n - 1]; }\n"
        "float2 b() { const int n = 4; const float2 o[n] = {1, 2, 3, 4, 5, 6, 7, 8}; return o[n - 1]; }\n"
        "float4 main() : SV_Target { return float4(a(), b()); }\n",
        "ps_5_0");
    EXPECT_FALSE(e.shaders.at(0).glsl.empty());
}

// NVIDIA SoftShadows' Poisson.fxh: a uniform array sized by its initializer, `float2 P[] = {...}`.
// fxc gives it the initializer's element count and keeps the values as the parameter's default,
// in $Global as `float2 P[3]` would be (two registers and a float2: 40 bytes, the block 48). A
// flat list and SM2 XNA style do the same.
TEST(RealworldFourthWave, UniformArraySizedByItsInitializer) {
    CompileOptions o;
    o.useCache = false;
    const std::string shader = "float4 PS(float2 t : TEXCOORD0) : SV_Target { return float4(P[0] + P[2], 0, 1); }\n"
                               "technique11 T { pass P0 { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
    for (const char* declaration : {"float2 P[] = { {1, 2}, {3, 4}, {5, 6} };\n", "float2 P[] = { 1, 2, 3, 4, 5, 6 };\n"}) {
        SCOPED_TRACE(declaration);
        CompiledEffect e = compileEffectSource(declaration + shader, writeSource("poisson.fx", "").string(), o);
        const Parameter* p = e.findParameter("P");
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(p->elements, 3);
        EXPECT_EQ(p->columns, 2);
        EXPECT_EQ(p->defaultValue, (std::vector<double>{1, 2, 3, 4, 5, 6}));
        EXPECT_EQ(p->offset, 0);
        ASSERT_FALSE(e.uniformBlocks.empty());
        EXPECT_EQ(e.uniformBlocks[0].size, 48);
    }
    CompiledEffect xna = compileEffectSource("float P[] = { 1, 2, 3 };\n"
                                             "float4 PS(float2 t : TEXCOORD0) : COLOR0 { return float4(P[0], P[1], P[2], 1); }\n"
                                             "technique T { pass P0 { PixelShader = compile ps_2_0 PS(); } }\n",
                                             writeSource("xna.fx", "").string(), o);
    const Parameter* p = xna.findParameter("P");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->elements, 3);
    EXPECT_EQ(p->defaultValue, (std::vector<double>{1, 2, 3}));
}
