// Real-world shaders, third wave (issue 24): constructs met in the DirectX SDK samples
// (walbourn/directx-sdk-samples, compiled by the entry points and profiles their C++ names) that
// fxc takes and fxport refused. Each is a small source of our own, compiled as a loose file as
// D3DCompileFromFile would, with what the construct means asserted on the reflection or the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main") {
    fs::path dir = fs::temp_directory_path() / ("fxport-third-wave-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "shader.hlsl";
    std::ofstream(file) << source;
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{file.string(), entry, profile}}, o);
}

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
