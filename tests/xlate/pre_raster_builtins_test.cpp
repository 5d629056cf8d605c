// System values of the stages before the rasteriser that GL spells otherwise (glsl/pre_raster_builtins.h),
// as the GLSL xlate writes: a vertex shader's SV_RenderTargetArrayIndex / SV_ViewportArrayIndex is
// gl_Layer / gl_ViewportIndex behind the extensions that allow it there, with an #error naming the
// semantic and the extension for a driver without them, and also the varying a geometry shader reads;
// next to a geometry shader (a technique's pass) only the varying. SV_VertexID subtracts the start
// vertex the runtime sets. The draws themselves are tests/d3d11/d3d11_vertex_system_values_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

std::string looseGlsl(const std::string& source, const std::string& profile) {
    fs::path dir = fs::temp_directory_path() / ("fxport-pre-raster-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "shader.hlsl";
    std::ofstream(file) << source;
    CompiledEffect e = compileShaderFiles({{file.string(), "main", profile}}, noCache());
    EXPECT_EQ(e.shaders.size(), 1u);
    return e.shaders.empty() ? "" : e.shaders[0].glsl;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const char* const kVprt = R"(
struct V { float4 p : SV_Position; uint slice : SV_RenderTargetArrayIndex; };
V main(float4 p : POSITION, uint instance : SV_InstanceID) { V o; o.p = p; o.slice = instance; return o; })";

TEST(PreRasterBuiltins, AVertexShaderWritesGlLayerBehindTheExtensionOrStopsNamingIt) {
    const std::string glsl = looseGlsl(kVprt, "vs_5_0");
    EXPECT_TRUE(has(glsl, "gl_Layer = ")) << glsl;
    EXPECT_TRUE(has(glsl, "#extension GL_ARB_shader_viewport_layer_array : require")) << glsl;
    EXPECT_TRUE(has(glsl, "#extension GL_AMD_vertex_shader_layer : require")) << glsl;
    EXPECT_TRUE(has(glsl, "#error fxport: this vertex shader writes SV_RenderTargetArrayIndex: that needs GL_ARB_shader_viewport_layer_array")) << glsl;
    // The varying a geometry shader after it reads (D3D11 links stages compiled apart).
    EXPECT_TRUE(has(glsl, "flat out uint")) << glsl;
}

TEST(PreRasterBuiltins, ADomainShaderAsksForTheArbOrNvExtensionOnly) {
    const std::string glsl = looseGlsl(R"(
struct CP { float4 p : POS; };
struct PC { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; uint viewport : SV_ViewportArrayIndex; };
[domain("tri")]
D main(PC pc, float3 uvw : SV_DomainLocation, const OutputPatch<CP, 3> patch) {
    D o; o.p = patch[0].p * uvw.x + patch[1].p * uvw.y + patch[2].p * uvw.z; o.viewport = 1; return o;
})",
                                       "ds_5_0");
    EXPECT_TRUE(has(glsl, "gl_ViewportIndex = ")) << glsl;
    EXPECT_TRUE(has(glsl, "#extension GL_NV_viewport_array2 : require")) << glsl;
    EXPECT_FALSE(has(glsl, "GL_AMD")) << glsl;
    EXPECT_TRUE(has(glsl, "#error fxport: this domain shader writes SV_ViewportArrayIndex")) << glsl;
}

TEST(PreRasterBuiltins, NextToAGeometryShaderTheVertexShaderWritesOnlyTheVarying) {
    CompiledEffect e = compileEffectSource(R"(
struct V { float4 p : SV_Position; uint slice : SV_RenderTargetArrayIndex; };
V VS(float4 p : POSITION, uint instance : SV_InstanceID) { V o; o.p = p; o.slice = instance; return o; }
[maxvertexcount(3)] void GS(triangle V v[3], inout TriangleStream<V> s) { for (int k = 0; k < 3; k++) s.Append(v[k]); }
float4 PS(float4 p : SV_Position) : SV_Target { return 1; }
technique11 T { pass P {
    SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(CompileShader(gs_5_0, GS())); SetPixelShader(CompileShader(ps_5_0, PS()));
} })",
                                           "vprt_gs.fx", noCache());
    bool sawVertex = false, sawGeometry = false;
    for (const CompiledShader& s : e.shaders) {
        if (s.profile.stage == ShaderStage::Vertex) {
            sawVertex = true;
            EXPECT_FALSE(has(s.glsl, "gl_Layer")) << s.glsl;
            EXPECT_FALSE(has(s.glsl, "GL_ARB_shader_viewport_layer_array")) << s.glsl;
        }
        if (s.profile.stage == ShaderStage::Geometry) {
            sawGeometry = true;
            EXPECT_TRUE(has(s.glsl, "gl_Layer = ")) << s.glsl;
        }
    }
    EXPECT_TRUE(sawVertex && sawGeometry);
}

TEST(PreRasterBuiltins, SvVertexIdLeavesOutTheStartVertexTheRuntimeSets) {
    const std::string glsl = looseGlsl("float4 main(uint id : SV_VertexID) : SV_Position { return float4(id, 0, 0, 1); }", "vs_5_0");
    EXPECT_TRUE(has(glsl, std::string("uniform int ") + kStartVertexUniform + ";")) << glsl;
    EXPECT_TRUE(has(glsl, std::string("(gl_VertexID - ") + kStartVertexUniform + ")")) << glsl;
    EXPECT_FALSE(has(looseGlsl(kVprt, "vs_5_0"), kStartVertexUniform));
}

}  // namespace
