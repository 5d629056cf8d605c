// Real-world shaders, fifth wave (session 23's run 24 over CMAA2, MiniEngine, Windows-universal-
// samples, FidelityFX): valid HLSL that fxc compiles and fxport refused. Each is a small source of
// our own in the project's shape, with what the construct means asserted on the GLSL or reflection.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "fxport/xlate/effect_compiler.h"
#include "compile_loose.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::writeLooseSource;
using fxport::test::compileLoose;
using fxport::test::errorsOfLoose;

// CMAA2.hlsl's `#error ... it's likely not valid anymore` and FXAA 3.11's `#error ... can't be
// enabled together` sit in groups that #if skips; a C preprocessor only looks for the next
// directive there. The taken branch is the one compiled (its constant in the GLSL), also when the
// quote is unmatched in a skipped #define, a text line or an included header.
TEST(RealworldFifthWave, UnmatchedQuotesInSkippedGroups) {
    writeLooseSource("fxaa.h", "#if 0\n#error FXAA_GREEN_AS_LUMA and FXAA_LUMA_SEPARATE_R8 can't be enabled together\n#endif\n");
    CompiledEffect e = compileLoose("#include \"fxaa.h\"\n"
                                    "#if (0 != 0)\n"
                                    "#error this codepath needs testing - it's likely not valid anymore\n"
                                    "#define BROKEN it's\n"
                                    "the \"open string and don't\n"
                                    "float4 main() : SV_Target { return 0.75; }\n"
                                    "#else\n"
                                    "float4 main() : SV_Target { return 0.25; }\n"
                                    "#endif\n",
                                    "ps_4_0");
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("0.25"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("0.75"), std::string::npos) << glsl;
}

// A taken #error reports its text as written (apostrophe and quotes kept), once: no second
// "missing #endif" for the group glslang stopped in. Quotes in taken code are still errors.
TEST(RealworldFifthWave, TakenErrorKeepsItsText) {
    std::vector<Diagnostic> errors = errorsOfLoose("#if 1\n#error can't do \"this\"\n#endif\nfloat4 main() : SV_Target { return 1; }\n", "ps_4_0");
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].message.find("can't do \"this\""), std::string::npos) << errors[0].message;
    EXPECT_EQ(errors[0].location.line, 2);
    errors = errorsOfLoose("#if 1\n#if foo(TEST)\n#endif\n#endif\nfloat4 main() : SV_Target { return 1; }\n", "ps_4_0");
    ASSERT_EQ(errors.size(), 1u) << errors.back().message;
    EXPECT_EQ(errors[0].location.line, 2);
    errors = errorsOfLoose("float4 main() : SV_Target {\n return it's;\n}\n", "ps_4_0");
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].location.line, 2);
}

// HolographicSpatialMapping's `min16float4x4 normalToWorld` in a cbuffer, and local minimum-precision
// matrices: each is its 32-bit matrix (fxc keeps 32-bit storage in constant buffers), so the
// members after them sit where float4x4 and int2x2 would put them.
TEST(RealworldFifthWave, MinimumPrecisionMatrixNames) {
    CompiledEffect e = compileLoose("cbuffer C : register(b0) { min16float4x4 m; min16int2x2 k; float4 after; };\n"
                                    "float4 main(float4 p : SV_Position) : SV_Target {\n"
                                    "    min16float3x3 r = (min16float3x3)m;\n"
                                    "    matrix<min16uint, 2, 2> u = (matrix<min16uint, 2, 2>)k;\n"
                                    "    min10float2x2 h = min10float2x2(1, 2, 3, 4);\n"
                                    "    return float4(mul(p.xyz, r), h[1][0]) + mul(p, m) + after + u[1][1];\n"
                                    "}\n",
                                    "ps_5_0");
    auto offsetOf = [&](const std::string& name) {
        for (const auto& p : e.parameters)
            if (p.name == name) return p.offset;
        return -2;
    };
    EXPECT_EQ(offsetOf("m"), 0);
    EXPECT_EQ(offsetOf("k"), 64);
    EXPECT_EQ(offsetOf("after"), 96);  // int2x2: two registers, the second half used
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("mat3"), std::string::npos) << glsl;
}

// MiniEngine's `WorkCounts.Store2(0, 0);`: a scalar value is converted to the uintN parameter,
// fxc's argument conversion: replicated, a float value-converted (2.75 -> 2). The GLSL stores it in
// every word of the store (glslang folds the constant ones), and a variable likewise.
TEST(RealworldFifthWave, ByteAddressStoreOfAScalar) {
    CompiledEffect e = compileLoose("RWByteAddressBuffer C : register(u0);\n"
                                    "[numthreads(64, 1, 1)]\n"
                                    "void main(uint GI : SV_GroupIndex) { C.Store2(4, 7); C.Store3(16, 2.75); C.Store4(32, GI); }\n",
                                    "cs_5_0");
    const std::string& glsl = e.shaders.at(0).glsl;
    for (const char* store : {"._data[1] = 7u;", "._data[2] = 7u;", "._data[4] = 2u;", "._data[5] = 2u;", "._data[6] = 2u;",
                              "._data[8] = gl_LocalInvocationIndex;", "._data[11] = gl_LocalInvocationIndex;"})
        EXPECT_NE(glsl.find(store), std::string::npos) << store << "\n" << glsl;
    EXPECT_EQ(glsl.find("._data[3] ="), std::string::npos) << glsl;
}

// MiniEngine's ModelViewerPS: textures at register(t64) and on (D3D11 has t0..t127). The t register
// stays the D3D binding; the GL units are the shader's own, each texture its own unit in range.
TEST(RealworldFifthWave, TextureRegistersAboveThirtyOne) {
    CompiledEffect e = compileLoose("Texture2D<float> A : register(t64);\n"
                                    "Texture2DArray<float> B : register(t127);\n"
                                    "Texture2D<float4> C : register(t1);\n"
                                    "SamplerState S : register(s0);\n"
                                    "SamplerComparisonState Z : register(s1);\n"
                                    "float4 main(float4 p : SV_Position) : SV_Target {\n"
                                    "    return A.Sample(S, p.xy) + B.SampleCmp(Z, p.xyz, 0.5) + A.Load(int3(p.xy, 0)) + C.Sample(S, p.xy);\n"
                                    "}\n",
                                    "ps_5_0");
    std::map<int, int> unitOfRegister;
    for (const SamplerBinding& b : e.shaders.at(0).samplers) {
        EXPECT_GE(b.unit, 0);
        EXPECT_LT(b.unit, 32);
        if (unitOfRegister.count(b.textureRegister)) continue;  // A with S and A loaded may share or not
        for (const auto& [reg, unit] : unitOfRegister) EXPECT_NE(unit, b.unit) << "t" << reg << " and t" << b.textureRegister;
        unitOfRegister[b.textureRegister] = b.unit;
    }
    EXPECT_TRUE(unitOfRegister.count(64));
    EXPECT_TRUE(unitOfRegister.count(127));
    EXPECT_EQ(unitOfRegister.at(1), 1);  // a register within the units keeps its unit
}

// FidelityFX's ffx_a.h defines `AToThreeF1(AF1)` and `AToThreeF1(AH1)` (float, min16float) and the
// FSR pass calls neither: fxc keeps them apart; to glslang they are one function defined twice.
// Uncalled, the earlier is renamed; called ones still get fxc's choice (2.0 for the float
// argument, the min16float overload adding 10).
TEST(RealworldFifthWave, UncalledMinimumPrecisionOverloadTwins) {
    const std::string overloads = "float f(float c) { return c; }\nmin16float f(min16float c) { return c + 10; }\n"
                                  "int g(min16int c) { return c; }\nint g(int c) { return c; }\n";
    CompiledEffect e = compileLoose(overloads + "float4 main() : SV_Target { return 1; }\n", "ps_5_0");
    EXPECT_FALSE(e.shaders.at(0).glsl.empty());
    e = compileLoose(overloads + "float4 main(float4 p : SV_Position) : SV_Target { min16float h = p.x; return float4(f(2.0), f(h), 0, 1); }\n",
                     "ps_5_0");
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("10.0"), std::string::npos) << glsl;  // the min16float overload, called for h
}

// MiniEngine's TAAResolve.hlsl: `int offsets[1][8] = { MAKEOFFSET(-1, -1), ... }`, a 2-D array
// initialised by a flat list with a non-literal item. The values land in order (row width 10).
TEST(RealworldFifthWave, TwoDimensionalArrayFromAFlatNonLiteralList) {
    CompiledEffect e = compileLoose("#define MK(x, y) int((y) * 10 + (x))\n"
                                    "float4 main(float4 p : SV_Position) : SV_Target {\n"
                                    "    const int o[1][8] = { MK(-1, -1), MK(0, -1), MK(1, -1), MK(-1, 0), MK(1, 0), MK(-1, 1), MK(0, 1), MK(1, int(p.y)) };\n"
                                    "    int q[2][2] = { 1, 2, 3, int(p.y) };\n"
                                    "    return o[0][(uint)p.x % 8] + q[1][(uint)p.x % 2];\n"
                                    "}\n",
                                    "ps_5_0");
    const std::string& glsl = e.shaders.at(0).glsl;
    EXPECT_NE(glsl.find("(-11, -10, -9, -1, 1, 9, 10, "), std::string::npos) << glsl;
}
