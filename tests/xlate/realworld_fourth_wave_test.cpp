// Real-world shaders, fourth wave (session 22's run over D3D11 samples: Intel ASSAO, NVIDIA
// D3DSamples, Microsoft Xbox-ATG-Samples, GameTechDev's OutdoorLightScattering): valid HLSL that fxc
// compiles and fxport refused. Each is a small source of our own in the sample's shape, compiled as
// the sample's build does, with what the construct means asserted on the reflection or the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"
#include "compile_loose.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::writeLooseSource;
using fxport::test::compileLoose;

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
        CompiledEffect e = compileEffectSource(declaration + shader, writeLooseSource("poisson.fx", "").string(), o);
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
                                             writeLooseSource("xna.fx", "").string(), o);
    const Parameter* p = xna.findParameter("P");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->elements, 3);
    EXPECT_EQ(p->defaultValue, (std::vector<double>{1, 2, 3}));
}

// GameTechDev's OutdoorLightScattering defaults THREAD_GROUP_SIZE to `max(INITIAL_SAMPLE_STEP, 32)`
// in [numthreads]: the comma inside max() separates no attribute arguments, and the size is the
// constant fxc folds (128), as is a static int's initial value (vkd3d's numthreads, which fxc takes).
TEST(RealworldFourthWave, ThreadGroupSizesFromConstantExpressions) {
    CompiledEffect e = compileLoose("#define THREAD_GROUP_SIZE max(128, 32)\n"
                                    "static const uint rows = 2; static int depth = 3;\n"
                                    "[numthreads(THREAD_GROUP_SIZE / 16, rows * 2 - 7 / 2, depth)]\n"
                                    "void main() {}\n",
                                    "cs_5_0");
    EXPECT_EQ(e.shaders.at(0).threadGroupSize, (std::array<int, 3>{8, 1, 3}));  // 7 / 2 is int division: 3
}

// A size that is no integer constant fxport evaluates is refused at its own file:line, saying so.
TEST(RealworldFourthWave, ThreadGroupSizeThatIsNoConstantIsLocated) {
    struct Case {
        const char* source;
        const char* message;
    };
    const Case cases[] = {
        {"static int x = 1;\n\n[numthreads(1, x++, 1)]\nvoid main() {}\n", "'x ++' is no integer constant fxport can evaluate"},
        {"\n\n[numthreads(float(2), 1, 1)]\nvoid main() {}\n", "'float(2)' is not an integer"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.source);
        try {
            compileLoose(c.source, "cs_5_0");
            ADD_FAILURE() << "compiled";
        } catch (const CompileError& err) {
            ASSERT_FALSE(err.diagnostics().empty());
            const Diagnostic& d = err.diagnostics().front();
            EXPECT_NE(d.message.find(c.message), std::string::npos) << d.message;
            EXPECT_EQ(d.location.line, 3) << d.message;
            EXPECT_NE(d.location.file.find("shader.hlsl"), std::string::npos);
        }
    }
}

// Xbox-ATG-Samples SimpleTexturePC / SimpleTrianglePC VertexShader.hlsl return the input struct as
// the output struct, whose members match one for one: fxc converts (componentwise-equal), so do
// an initialization, a cast and an argument of the other type. The outputs keep their semantics.
TEST(RealworldFourthWave, StructConvertsToAComponentwiseEqualStruct) {
    const std::string structs = "struct Vertex { float4 position : SV_Position; float2 texcoord : TEXCOORD0; };\n"
                                "struct Interpolants { float4 position : SV_Position; float2 texcoord : TEXCOORD0; };\n"
                                "Interpolants passOn(Interpolants x) { return x; }\n";
    for (const char* body : {"return In;", "Interpolants b = In; return b;", "return (Interpolants)In;", "return passOn(In);"}) {
        SCOPED_TRACE(body);
        CompiledEffect e = compileLoose(structs + "Interpolants main(Vertex In) { " + body + " }\n", "vs_5_0");
        const CompiledShader& vs = e.shaders.at(0);
        bool texcoord = false;
        for (const auto& out : vs.outputs) texcoord |= out.semantic == "TEXCOORD0";
        EXPECT_TRUE(texcoord);
    }
    // Component types differ (int against float): fxc refuses the implicit conversion, and so does fxport.
    EXPECT_THROW(compileLoose("struct A { float3 aa; int bb; }; struct B { float3 aa; float bb; };\n"
                              "float4 main(float4 p : POSITION) : SV_Position { A a = (A)p; B b = a; return b.aa.xyzz; }\n",
                              "vs_5_0"),
                 CompileError);
}
