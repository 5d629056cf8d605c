// Real-world shaders, third wave (issue 24): constructs met in the DirectX SDK samples
// (walbourn/directx-sdk-samples, compiled by the entry points and profiles their C++ names) that
// fxc takes and fxport refused. Each is a small source of our own, compiled as a loose file as
// D3DCompileFromFile would, with what the construct means asserted on the reflection or the GLSL.
#include <set>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "fxport/xlate/effect_compiler.h"
#include "compile_loose.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::compileLoose;

namespace {

const CompiledShader& onlyShader(const CompiledEffect& e) { return e.shaders.at(0); }

}  // namespace

// The SDK's Direct3D 11 tutorials 4-7 name their block `cbuffer ConstantBuffer`: an SM 5.1 type to
// glslang, a name to fxc. The block keeps its name and its members their D3D offsets.
TEST(RealworldThirdWave, ConstantBufferIsABlockName) {
    CompiledEffect e = compileLoose(
        "cbuffer ConstantBuffer : register(b0) { matrix World; matrix View; }\n"
        "float4 main(float4 p : POSITION) : SV_Position { return mul(mul(p, World), View); }\n",
        "vs_4_0");
    ASSERT_EQ(e.uniformBlocks.size(), 2u);
    EXPECT_EQ(e.uniformBlocks[1].name, "ConstantBuffer");
    EXPECT_EQ(e.uniformBlocks[1].size, 128);
    const Parameter* view = e.findParameter("View");
    ASSERT_NE(view, nullptr);
    EXPECT_EQ(view->offset, 64);
    EXPECT_EQ(view->block, 1);
}

// `ConstantBuffer<T>` keeps its meaning where a template argument follows (a name only without).
TEST(RealworldThirdWave, ConstantBufferNamesAVariableToo) {
    CompiledEffect e = compileLoose("float4 main(float4 ConstantBuffer : TEXCOORD0) : SV_Target { return ConstantBuffer * 2; }\n", "ps_5_0");
    EXPECT_FALSE(onlyShader(e).glsl.empty());
}

// OIT11's prefix sum reads `Texture2D<uint> fragmentCount` at an `int2` variable: a texel address,
// which fxc takes (only a vector or array is indexed by a scalar).
TEST(RealworldThirdWave, TextureIndexedByAnInt2Variable) {
    const std::string source =
        "Texture2D<uint> counts : register(t0);\nRWBuffer<uint> sums : register(u0);\n"
        "[numthreads(8, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    int2 uv; uv.x = id.x % 4; uv.y = id.x / 4;\n"
        "    sums[id.x] = counts[uv] + counts.mips[0][uv];\n}\n";
    EXPECT_NO_THROW(compileLoose(source, "cs_5_0"));
    // The vector case stays refused at its line (fxc X3120-like; vkd3d's vector-indexing).
    try {
        compileLoose("float4 main() : SV_Target { float4 v = {0, 1, 2, 3}; int2 i = {1, 2}; return v[i]; }\n", "ps_4_0");
        ADD_FAILURE() << "a vector indexed by an int2 compiled";
    } catch (const CompileError& err) {
        EXPECT_NE(std::string(err.what()).find("scalar"), std::string::npos) << err.what();
    }
}

// SubD11's control-point vertex shader writes no position: it feeds a hull shader. fxc takes it from
// vs_4_0 on; its outputs keep their declared types (a float3 stays a vec3), as beside a geometry or
// domain shader. A vs_3_0 shader without a position is still refused.
TEST(RealworldThirdWave, VertexShaderWithoutPositionFeedsTessellation) {
    const std::string source =
        "struct CP { float3 pos : WORLDPOS; float2 uv : TEXCOORD0; };\n"
        "CP main(float3 p : POSITION, float2 uv : TEXCOORD0) { CP o; o.pos = p * 2; o.uv = uv; return o; }\n";
    CompiledEffect e = compileLoose(source, "vs_5_0");
    const std::string& glsl = onlyShader(e).glsl;
    EXPECT_TRUE(std::regex_search(glsl, std::regex(R"(out vec3 \w+;)"))) << glsl;
    EXPECT_EQ(glsl.find("gl_Position"), std::string::npos) << glsl;
    EXPECT_THROW(compileLoose(source, "vs_3_0"), CompileError);
}

// VarianceShadows11 declares a `static` inside its cbuffer, initialised from a member before it. It
// is no member (the members after it keep D3D offsets as if it were not there) and its initializer
// reads the block.
TEST(RealworldThirdWave, StaticInsideACbufferIsNoMember) {
    CompiledEffect e = compileLoose(
        "cbuffer CB : register(b0) {\n    float4 data[2];\n    static float d[8] = (float[8])data;\n    float3 dir;\n};\n"
        "float4 main(uint i : TEXCOORD0) : SV_Target { return d[i] + dir.x; }\n",
        "ps_5_0");
    const Parameter* dir = e.findParameter("dir");
    ASSERT_NE(dir, nullptr);
    EXPECT_EQ(dir->offset, 32);
    EXPECT_EQ(e.uniformBlocks.at(1).size, 48);  // 44 bytes, rounded to whole registers as D3D sizes a block
    const Parameter* d = e.findParameter("d");
    EXPECT_TRUE(d == nullptr || d->offset < 0) << "the static became a member at " << d->offset;
}

// SubD11's hull shader: `static const uint Val[4] = (uint[4])uint4(4, 4, 4, 4);` (a vector cast to
// an array of its components). The GLSL holds the components, in order.
TEST(RealworldThirdWave, VectorCastToAnArrayInAnInitializer) {
    CompiledEffect e = compileLoose(
        "uint4 v;\nstatic const uint G[3] = (uint[3])v;\n"
        "float4 main(uint i : TEXCOORD0) : SV_Target {\n"
        "    static const uint Val[4] = (uint[4])uint4(7, 10, 13, 16);\n    float f[2] = (float[2])v;\n"
        "    return Val[i] + G[i] + f[i % 2];\n}\n",
        "ps_5_0");
    const std::string& glsl = onlyShader(e).glsl;
    EXPECT_TRUE(std::regex_search(glsl, std::regex(R"(7u, 10u, 13u, 16u)"))) << glsl;
}

// The DirectX SDK's skinning idiom (SkinnedMesh, MultiAnimation, LocalDeformablePRT): a vector cast
// to an array in a local declaration, from a struct member or a call. The value is converted once
// (float to int truncates, as fxc's cast does) and the array's elements are its components.
TEST(RealworldThirdWave, VectorCastToAnArrayFromAnyExpression) {
    CompiledEffect e = compileLoose(
        "struct VSIn { float4 pos : POSITION; float4 weights : BLENDWEIGHT; float4 indices : BLENDINDICES; };\n"
        "float4x4 Bones[4];\n"
        "float4 main(VSIn i) : SV_Position {\n"
        "    float w[3] = (float[3])i.weights;\n"
        "    int idx[4] = (int[4])i.indices;\n"
        "    return mul(i.pos, Bones[idx[1]]) * w[2];\n}\n",
        "vs_4_0");
    const std::string& glsl = onlyShader(e).glsl;
    EXPECT_TRUE(std::regex_search(glsl, std::regex(R"(ivec4\()"))) << glsl;  // the indices converted to int, once
}

// PRT.fx sizes an entry parameter by an expression of macros: `float4 w[NUM_PCA/4] : BLENDWEIGHT1`
// (NUM_PCA given by the application, here -D). The parameter has NUM_PCA/4 elements, not NUM_PCA.
TEST(RealworldThirdWave, EntryParameterSizedByAnExpression) {
    fs::path dir = fs::temp_directory_path() / ("fxport-third-wave-prt-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "prt.fx") << "float4x4 WVP;\n"
                                     "float4 VS(float4 p : POSITION, float4 w[NUM_PCA/4] : BLENDWEIGHT1, out float4 c : COLOR0) : POSITION\n"
                                     "{ c = w[0] + w[NUM_PCA/4 - 1]; return mul(p, WVP); }\n"
                                     "float4 PS(float4 c : COLOR0) : COLOR0 { return c; }\n"
                                     "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    CompileOptions o;
    o.useCache = false;
    o.defines = {{"NUM_PCA", "8"}};
    CompiledEffect e = compileEffectFile((dir / "prt.fx").string(), o);
    const CompiledShader& vs = e.shaders.at(size_t(e.techniques.at(0).passes.at(0).vertexShader.shaders.at(0)));
    int blendWeights = 0;
    for (const auto& in : vs.inputs) blendWeights += in.semantic.rfind("BLENDWEIGHT", 0) == 0 ? 1 : 0;
    EXPECT_EQ(blendWeights, 2);  // BLENDWEIGHT1 and BLENDWEIGHT2
    // Without the macro the size is no constant, and the error names the parameter as written.
    o.defines.clear();
    try {
        compileEffectFile((dir / "prt.fx").string(), o);
        ADD_FAILURE() << "compiled without NUM_PCA";
    } catch (const CompileError& err) {
        EXPECT_NE(std::string(err.what()).find("array 'w' has a size that is no constant"), std::string::npos) << err.what();
    }
    fs::remove_all(dir);
}

// `VertexShader = null;` in a pass (the DirectX SDK's ShadowVolume, PostProcess, ConfigSystem): the
// effect framework takes `null` as NULL there; elsewhere `null` stays an undeclared name (fxc X3004).
TEST(RealworldThirdWave, NullAsAPassStateValue) {
    fs::path dir = fs::temp_directory_path() / ("fxport-third-wave-null-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "null.fx") << "float4 PS() : COLOR0 { return 1; }\n"
                                      "technique T { pass P { VertexShader = null; PixelShader = compile ps_2_0 PS(); } }\n";
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectFile((dir / "null.fx").string(), o);
    EXPECT_TRUE(e.techniques.at(0).passes.at(0).vertexShader.shaders.empty());
    std::ofstream(dir / "null.fx") << "float4 PS() : COLOR0 { float4 c = null; return c; }\n"
                                      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    EXPECT_THROW(compileEffectFile((dir / "null.fx").string(), o), CompileError);
    fs::remove_all(dir);
}

// D3DX spells the counter-clockwise stencil states with an underscore (`Ccw_StencilPass = Decr;`,
// the DirectX SDK's ShadowVolume): the same states as CcwStencilPass.
TEST(RealworldThirdWave, CcwStencilStatesWithAnUnderscore) {
    fs::path dir = fs::temp_directory_path() / ("fxport-third-wave-ccw-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "ccw.fx") << "float4 PS() : COLOR0 { return 1; }\n"
                                     "technique T { pass P { TwoSidedStencilMode = true; Ccw_StencilFunc = Always; Ccw_StencilPass = Decr;\n"
                                     "    PixelShader = compile ps_2_0 PS(); } }\n";
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectFile((dir / "ccw.fx").string(), o);
    bool pass = false, func = false;
    for (const auto& s : e.techniques.at(0).passes.at(0).states) {
        pass |= s.state == RenderState::CcwStencilPass && std::get<StencilOperation>(s.value) == StencilOperation::Decrement;
        func |= s.state == RenderState::CcwStencilFunc && std::get<CompareFunction>(s.value) == CompareFunction::Always;
    }
    EXPECT_TRUE(pass);
    EXPECT_TRUE(func);
    fs::remove_all(dir);
}

// fxc reads `Matrix` and `Vector` as the type keywords (the DirectX SDK's Soldier.fx, vs_4_0:
// `Matrix m = ...;`), though not as templates (vkd3d's type-names: `Vector<float, 2> v;` fails);
// a struct the source names `Vector` stays that struct.
TEST(RealworldThirdWave, TypeKeywordsInAnyCase) {
    CompiledEffect e = compileLoose(
        "float4x4 World;\n"
        "float4 main(float4 p : POSITION) : SV_Position {\n"
        "    Matrix m = World * 2;\n    VECTOR v = p;\n    return mul(v, m);\n}\n",
        "vs_4_0");
    EXPECT_FALSE(onlyShader(e).glsl.empty());
    EXPECT_THROW(compileLoose("Vector<float, 2> v;\nfloat4 main() : SV_Target { return v.xyxy; }\n", "ps_4_0"), CompileError);
    EXPECT_NO_THROW(compileLoose("struct Vector { float4 xyzw; };\n"
                                 "float4 main(float4 p : POSITION) : SV_Position { Vector v; v.xyzw = p; return v.xyzw; }\n",
                                 "vs_4_0"));
}

// Entry attributes in another case: Intel's ZoomBox.hlsl (DynamicResolutionRendering, AOIT) writes
// `[MaxVertexCount(12)]` and fxc compiles it at run time; `[NumThreads]` stays refused, as fxc
// refuses it (vkd3d's numthreads), and an array sized by a constant of such a name is left alone.
TEST(RealworldThirdWave, EntryAttributesInAnyCase) {
    CompiledEffect gs = compileLoose("struct V { float4 p : SV_Position; };\n"
                                     "[MaxVertexCount(3)]\n"
                                     "void main(triangle V i[3], inout TriangleStream<V> s) { for (int k = 0; k < 3; ++k) s.Append(i[k]); }\n",
                                     "gs_4_0");
    EXPECT_NE(onlyShader(gs).glsl.find("max_vertices = 3"), std::string::npos) << onlyShader(gs).glsl;
    EXPECT_THROW(compileLoose("[NumThreads(1, 1, 1)]\nvoid main() {}\n", "cs_5_0"), CompileError);
    EXPECT_NO_THROW(compileLoose("static const int Domain = 2;\nfloat4 c[Domain];\n"
                                 "float4 main() : SV_Target { return c[1]; }\n",
                                 "ps_4_0"));
}

// More textures than GL's 32 units per stage (D3D11 has 128 slots): FX1404 naming the texture past
// the limit, not an inconsistent-effect FX3101; 32 of them at high registers still compile.
TEST(RealworldThirdWave, TexturesPastTheGlUnitsAreNamed) {
    auto shader = [](int count) {
        std::string s;
        for (int i = 0; i < count; ++i) s += "Texture2D t" + std::to_string(i) + " : register(t" + std::to_string(i + 40) + ");\n";
        s += "SamplerState s;\nfloat4 main(float2 uv : TEXCOORD0) : SV_Target {\n    float4 c = 0;\n";
        for (int i = 0; i < count; ++i) s += "    c += t" + std::to_string(i) + ".Sample(s, uv);\n";
        return s + "    return c;\n}\n";
    };
    EXPECT_EQ(onlyShader(compileLoose(shader(32), "ps_5_0")).samplers.size(), 32u);
    try {
        compileLoose(shader(33), "ps_5_0");
        ADD_FAILURE() << "33 textures compiled";
    } catch (const CompileError& err) {
        EXPECT_NE(std::string(err.what()).find("FX1404"), std::string::npos) << err.what();
        EXPECT_NE(std::string(err.what()).find("'t32' is its texture and sampler pair number 33"), std::string::npos) << err.what();
    }
}

// The fuzz seed written to reach the recent rewrites (tests/fuzz/seeds) compiles, so the fuzzers
// start from a compiled effect; its geometry and compute entries read a static initializer that
// calls a function (glslang crashed on them before those entries reached the callee).
TEST(RealworldThirdWave, RecentRewritesFuzzSeedCompiles) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectFile("tests/fuzz/seeds/recent_rewrites.fx", o);
    EXPECT_EQ(e.techniques.size(), 2u);
    EXPECT_EQ(e.shaders.size(), 4u);
}

// An error in a function two shaders include (glslang compiles the whole effect for each) is
// reported once.
TEST(RealworldThirdWave, AnErrorSeenByEveryShaderIsReportedOnce) {
    CompileOptions o;
    o.useCache = false;
    try {
        compileEffectSource("float4 helper(float4 c) { return c * missing; }\n"
                            "float4 VS(float4 p : POSITION) : POSITION { return helper(p); }\n"
                            "float4 PS(float4 c : COLOR0) : COLOR0 { return helper(c); }\n"
                            "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n",
                            "virtual/Repeated.fx", o);
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& err) {
        std::set<std::string> seen;
        for (const auto& d : err.diagnostics()) EXPECT_TRUE(seen.insert(d.format()).second) << d.format();
        EXPECT_FALSE(err.diagnostics().empty());
    }
}
