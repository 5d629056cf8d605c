// Compute, hull and domain shaders (issue 23 item 4, issue 24 item 6): cs_4_0..cs_5_0, hs_5_0 and
// ds_5_0 compile, as loose files and in technique11 passes (SetComputeShader / SetHullShader /
// SetDomainShader); the reflection holds what the runtime binds (numthreads, UAV and buffer-SRV
// registers with their GL bindings, tessellation attributes), survives a compiled-effect file, and
// the forms fxc rejects are located errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "compile_loose.h"
#include "shader_sources/quad_patch_stages.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

using fxport::test::compileLoose;

namespace {

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

// A loose shader file with entry `main`, compiled for `profile`.

const StorageBinding& storage(const CompiledShader& s, const std::string& name) {
    for (const auto& b : s.storage)
        if (b.name == name) return b;
    throw std::runtime_error("no storage binding " + name);
}

// The first error of a compile that must fail, as "file:line: message".
std::string firstError(const std::string& source, const std::string& virtualPath = "stages.fx") {
    try {
        CompiledEffect e = compileEffectSource(source, virtualPath, noCache());
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return d.location.file + ":" + std::to_string(d.location.line) + ": " + d.message;
    } catch (const CompileError& e) {
        for (const auto& d : e.diagnostics())
            if (d.severity == Severity::Error) return d.location.file + ":" + std::to_string(d.location.line) + ": " + d.message;
    }
    return "compiled";
}

const char* const kCompute = R"(struct Particle { float4 position; };
RWStructuredBuffer<Particle> Particles : register(u0);
StructuredBuffer<float> Weights : register(t2);
RWTexture2D<float4> Image;
RWByteAddressBuffer Raw;
[numthreads(8, 4, 2)]
void main(uint3 id : SV_DispatchThreadID)
{
    Particles[id.x].position *= Weights[id.y];
    Image[id.xy] = float4(1, 0, 0, 1);
    Raw.Store(id.x * 4, id.x);
}
)";

const std::string kTessellation = std::string(fxport::test::kQuadPatchDeclarations) + fxport::test::kQuadPatchStages;

}  // namespace

TEST(D3D11Stages, ComputeShaderReflectsThreadGroupAndStorageRegisters) {
    CompiledEffect e = compileLoose(kCompute, "cs_5_0");
    const Pass& pass = e.techniques.at(0).passes.at(0);
    ASSERT_EQ(pass.computeShader.shaders.size(), 1u);
    const CompiledShader& cs = e.shaders[size_t(pass.computeShader.shaders[0])];
    EXPECT_EQ(cs.profile.stage, ShaderStage::Compute);
    EXPECT_EQ(cs.threadGroupSize, (std::array<int, 3>{8, 4, 2}));
    EXPECT_NE(cs.glsl.find("local_size_x = 8, local_size_y = 4, local_size_z = 2"), std::string::npos) << cs.glsl;

    const StorageBinding& particles = storage(cs, "Particles");
    EXPECT_EQ(particles.kind, StorageKind::Buffer);
    EXPECT_EQ(particles.registerClass, 'u');
    EXPECT_EQ(particles.slot, 0);
    EXPECT_EQ(particles.binding, 0);
    EXPECT_EQ(particles.stride, 16);
    EXPECT_TRUE(particles.writes);
    const StorageBinding& weights = storage(cs, "Weights");
    EXPECT_EQ(weights.registerClass, 't');
    EXPECT_EQ(weights.slot, 2);
    EXPECT_EQ(weights.binding, kSrvBufferBindingBase + 2);
    EXPECT_EQ(weights.stride, 4);
    EXPECT_FALSE(weights.writes);
    // No register: the next free u registers in declaration order (u0 is taken).
    const StorageBinding& image = storage(cs, "Image");
    EXPECT_EQ(image.kind, StorageKind::Image);
    EXPECT_EQ(image.format, "");  // only written: the bound texture's format (write_only_images.h)
    const StorageBinding& raw = storage(cs, "Raw");
    EXPECT_EQ(raw.registerClass, 'u');
    EXPECT_NE(image.slot, 0);
    EXPECT_NE(raw.slot, 0);
    EXPECT_NE(image.slot, raw.slot);
}

TEST(D3D11Stages, ComputeProfilesOfD3D10HardwareCompile) {
    const char* source = "RWStructuredBuffer<uint> Out : register(u0);\n[numthreads(64, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) { Out[id.x] = id.x * 2; }\n";
    for (const char* profile : {"cs_4_0", "cs_4_1", "cs_5_0"}) {
        CompiledEffect e = compileLoose(source, profile);
        ASSERT_EQ(e.shaders.size(), 1u) << profile;
        EXPECT_EQ(e.shaders[0].threadGroupSize, (std::array<int, 3>{64, 1, 1})) << profile;
    }
}

TEST(D3D11Stages, ComputeThreadGroupLimitsFollowTheProfile) {
    // 1024 threads are cs_5_0's limit; cs_4_0 has 768 and z == 1.
    const char* source = "RWStructuredBuffer<uint> Out : register(u0);\n[numthreads(32, 32, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) { Out[id.x] = 1; }\n";
    EXPECT_NO_THROW(compileLoose(source, "cs_5_0"));
    EXPECT_THROW(compileLoose(source, "cs_4_0"), CompileError);
}

TEST(D3D11Stages, HullAndDomainShadersInATechnique11Pass) {
    std::string source = std::string(kTessellation) +
                         "technique11 Tessellate { pass P0 {\n"
                         "  SetVertexShader(CompileShader(vs_5_0, VS()));\n"
                         "  SetHullShader(CompileShader(hs_5_0, HS()));\n"
                         "  SetDomainShader(CompileShader(ds_5_0, DS()));\n"
                         "  SetPixelShader(CompileShader(ps_5_0, PS()));\n"
                         "} }\n";
    CompiledEffect e = compileEffectSource(source, "tessellate.fx", noCache());
    const Pass& pass = e.techniques.at(0).passes.at(0);
    ASSERT_TRUE(pass.valid);
    ASSERT_EQ(pass.hullShader.shaders.size(), 1u);
    ASSERT_EQ(pass.domainShader.shaders.size(), 1u);
    const CompiledShader& hs = e.shaders[size_t(pass.hullShader.shaders[0])];
    const CompiledShader& ds = e.shaders[size_t(pass.domainShader.shaders[0])];
    EXPECT_EQ(hs.profile.stage, ShaderStage::Hull);
    EXPECT_EQ(ds.profile.stage, ShaderStage::Domain);
    EXPECT_EQ(hs.tessellation.domain, "quad");
    EXPECT_EQ(hs.tessellation.partitioning, "integer");
    EXPECT_EQ(hs.tessellation.outputTopology, "triangle_cw");
    EXPECT_EQ(hs.tessellation.patchConstantFunction, "Constants");
    EXPECT_EQ(hs.tessellation.inputControlPoints, 4);
    EXPECT_EQ(hs.tessellation.outputControlPoints, 4);
    EXPECT_EQ(ds.tessellation.domain, "quad");
    EXPECT_EQ(ds.tessellation.inputControlPoints, 4);
    EXPECT_NE(hs.glsl.find("layout(vertices = 4)"), std::string::npos) << hs.glsl;
    EXPECT_NE(ds.glsl.find("quads"), std::string::npos) << ds.glsl;
    // Factor is read by the patch-constant function: a parameter of the hull shader.
    ASSERT_NE(e.findParameter("Factor"), nullptr);
    EXPECT_FALSE(hs.uniformRangesRead.empty());

    // The compiled-effect file keeps the new stages and their reflection.
    CompiledEffect back = deserializeEffect(serializeEffect(e), "tessellate.fxo");
    const Pass& p2 = back.techniques.at(0).passes.at(0);
    ASSERT_EQ(p2.hullShader.shaders, pass.hullShader.shaders);
    ASSERT_EQ(p2.domainShader.shaders, pass.domainShader.shaders);
    EXPECT_EQ(back.shaders[size_t(p2.hullShader.shaders[0])].tessellation.patchConstantFunction, "Constants");
    EXPECT_EQ(back.shaders[size_t(p2.hullShader.shaders[0])].profile.stage, ShaderStage::Hull);
}

TEST(D3D11Stages, SetComputeShaderInATechnique11PassAndTheFileKeepsIt) {
    std::string source = std::string(kCompute).replace(std::string(kCompute).find("void main"), 9, "void Main") +
                         "technique11 Simulate { pass P0 { SetComputeShader(CompileShader(cs_5_0, Main())); } }\n";
    CompiledEffect e = compileEffectSource(source, "simulate.fx", noCache());
    const Pass& pass = e.techniques.at(0).passes.at(0);
    ASSERT_TRUE(pass.valid);
    ASSERT_EQ(pass.computeShader.shaders.size(), 1u);
    EXPECT_TRUE(pass.vertexShader.shaders.empty());
    for (const auto& d : e.diagnostics) EXPECT_NE(d.severity, Severity::Error) << d.format();
    CompiledEffect back = deserializeEffect(serializeEffect(e), "simulate.fxo");
    const CompiledShader& cs = back.shaders[size_t(back.techniques[0].passes[0].computeShader.shaders.at(0))];
    EXPECT_EQ(cs.threadGroupSize, (std::array<int, 3>{8, 4, 2}));
    EXPECT_EQ(storage(cs, "Weights").binding, kSrvBufferBindingBase + 2);
    EXPECT_EQ(storage(cs, "Image").format, "");
}

TEST(D3D11Stages, FormsFxcRejectsAreLocatedErrors) {
    const std::string pass = "technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, CS())); } }\n";
    // Line 2 holds the entry point in each of these.
    EXPECT_EQ(firstError("RWStructuredBuffer<uint> Out;\nvoid CS(uint3 id : SV_DispatchThreadID) { Out[id.x] = 1; }\n" + pass).substr(0, 12), "stages.fx:2:");
    EXPECT_NE(firstError("RWStructuredBuffer<uint> Out;\nvoid CS(uint3 id : SV_DispatchThreadID) { Out[id.x] = 1; }\n" + pass).find("numthreads"),
              std::string::npos);
    std::string zero = firstError("RWStructuredBuffer<uint> Out;\n[numthreads(0, 1, 1)] void CS(uint3 id : SV_DispatchThreadID) { Out[id.x] = 1; }\n" + pass);
    EXPECT_EQ(zero.substr(0, 12), "stages.fx:2:") << zero;
    EXPECT_NE(zero.find("at least 1"), std::string::npos) << zero;

    std::string hull = kTessellation;
    hull.replace(hull.find("[patchconstantfunc(\"Constants\")]"), 32, "[patchconstantfunc(\"Nope\")]     ");
    std::string bad = firstError(hull + "technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS()));"
                                        " SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }\n");
    EXPECT_EQ(bad.substr(0, 13), "stages.fx:21:") << bad;
    EXPECT_NE(bad.find("Nope"), std::string::npos) << bad;

    // A hull shader without a domain shader can never draw.
    std::string alone = firstError(std::string(kTessellation) +
                                   "technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS()));"
                                   " SetPixelShader(CompileShader(ps_5_0, PS())); } }\n");
    EXPECT_NE(alone.find("no domain shader"), std::string::npos) << alone;

    // Hull and domain profiles start at 5.0.
    EXPECT_NE(firstError(std::string(kTessellation) + "technique11 T { pass P { SetHullShader(CompileShader(hs_4_0, HS())); } }\n").find("hs_4_0"),
              std::string::npos);
}

// The suite's (and fxc's usual) form: the patch-constant function writes through an out
// parameter, and the control point holds SV_Position. glslang 12 refuses that form; fxport hands
// it a function that returns the values (patch_constant_wrapper.h).
TEST(D3D11Stages, PatchConstantFunctionWithAnOutParameter) {
    const char* hull = R"(struct data { float4 position : SV_Position; float r : RED; };
struct patch_constant_data { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
void patch_constant(InputPatch<data, 3> input, out patch_constant_data output)
{
    output.edges[0] = output.edges[1] = output.edges[2] = 2.0f;
    output.inside = 3.0f;
}
[domain("tri")] [outputcontrolpoints(3)] [partitioning("fractional_odd")] [outputtopology("triangle_ccw")]
[patchconstantfunc("patch_constant")]
data main(InputPatch<data, 3> input, uint i : SV_OutputControlPointID) { return input[i]; }
)";
    CompiledEffect e = compileLoose(hull, "hs_5_0");
    ASSERT_EQ(e.shaders.size(), 1u);
    const CompiledShader& hs = e.shaders[0];
    EXPECT_EQ(hs.tessellation.patchConstantFunction, "patch_constant");
    EXPECT_EQ(hs.tessellation.partitioning, "fractional_odd");
    EXPECT_NE(hs.glsl.find("gl_TessLevelInner[0] = 3.0"), std::string::npos) << hs.glsl;
    EXPECT_NE(hs.glsl.find("gl_TessLevelOuter[2] = 2.0"), std::string::npos) << hs.glsl;
    // Several out parameters with their own semantics go the same way.
    const char* split = R"(struct data { float4 position : SV_Position; };
void pc(InputPatch<data, 4> input, out float edges[4] : SV_TessFactor, out float inside[2] : SV_InsideTessFactor)
{
    edges[0] = edges[1] = edges[2] = edges[3] = 5.0f;
    inside[0] = inside[1] = 6.0f;
}
[domain("quad")] [outputcontrolpoints(4)] [partitioning("integer")] [outputtopology("triangle_cw")] [patchconstantfunc("pc")]
data main(InputPatch<data, 4> input, uint i : SV_OutputControlPointID) { return input[i]; }
)";
    CompiledEffect s = compileLoose(split, "hs_5_0");
    ASSERT_EQ(s.shaders.size(), 1u);
    EXPECT_NE(s.shaders[0].glsl.find("gl_TessLevelInner[1] = 6.0"), std::string::npos) << s.shaders[0].glsl;
}

// The domain shader of a pass declares its hull shader's partitioning and topology (GL's TES
// layout), from a hull shader in another loose file too.
TEST(D3D11Stages, DomainShaderTakesTheHullShadersPartitioning) {
    fs::path dir = fs::temp_directory_path() / ("fxport-d3d11-stages-pair-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string source = kTessellation;
    source.replace(source.find("\"integer\""), 9, "\"fractional_even\"");
    source.replace(source.find("\"triangle_cw\""), 13, "\"point\"");
    std::ofstream(dir / "hull.hlsl") << source;
    std::ofstream(dir / "domain.hlsl") << kTessellation;
    // Domain first on purpose: the hull's file is compiled first anyway.
    CompiledEffect e = compileShaderFiles({{(dir / "domain.hlsl").string(), "DS", "ds_5_0"}, {(dir / "hull.hlsl").string(), "HS", "hs_5_0"},
                                           {(dir / "domain.hlsl").string(), "VS", "vs_5_0"}, {(dir / "domain.hlsl").string(), "PS", "ps_5_0"}},
                                          noCache());
    const Pass& pass = e.techniques.at(0).passes.at(0);
    ASSERT_EQ(pass.domainShader.shaders.size(), 1u);
    const std::string& ds = e.shaders[size_t(pass.domainShader.shaders[0])].glsl;
    EXPECT_NE(ds.find("fractional_even_spacing"), std::string::npos) << ds;
    EXPECT_NE(ds.find("point_mode"), std::string::npos) << ds;
}

// fxc gives a pixel shader's unregistered UAVs the slots after its render targets (D3D11 binds
// RTVs and UAVs in one output-merger array): one SV_Target -> the first UAV is u1.
TEST(D3D11Stages, PixelShaderUavsStartAfterItsRenderTargets) {
    CompiledEffect e = compileLoose("RWTexture2D<float> u;\nRWStructuredBuffer<float> b;\nfloat4 main() : sv_target\n"
                                    "{ u[uint2(0, 0)] = 0.5; b[0] = 1; return 0; }\n", "ps_5_0");
    ASSERT_EQ(e.shaders.size(), 1u);
    EXPECT_EQ(storage(e.shaders[0], "u").slot, 1);
    EXPECT_EQ(storage(e.shaders[0], "b").slot, 2);
}

// fxc gives a control-point function without outputs a pass-through phase (point i out = point i
// in); without it GL's outputs would stay unwritten.
TEST(D3D11Stages, HullShaderWithoutOutputsPassesControlPointsThrough) {
    const char* hull = R"(struct data { float4 position : SV_Position; float r : RED; };
struct patch_constant_data { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
void patch_constant(InputPatch<data, 3> input, out patch_constant_data output)
{
    output.edges[0] = output.edges[1] = output.edges[2] = 1.0f;
    output.inside = 1.0f;
}
[domain("tri")] [outputcontrolpoints(3)] [partitioning("integer")] [outputtopology("triangle_cw")] [patchconstantfunc("patch_constant")]
void main(InputPatch<data, 3> input) { }
)";
    CompiledEffect e = compileLoose(hull, "hs_5_0");
    ASSERT_EQ(e.shaders.size(), 1u);
    const std::string& glsl = e.shaders[0].glsl;
    EXPECT_NE(glsl.find("gl_out[gl_InvocationID].gl_Position"), std::string::npos) << glsl;
}

// [earlydepthstencil] reaches the GL program (the depth test before the shader: a hidden fragment
// writes no UAV), and SM5's conservative depth outputs are the fragment's depth. Attribute names
// keep their case, as fxc matches them (vkd3d's numthreads refuses [NumThreads(1, 1, 1)] below SM6).
TEST(D3D11Stages, EarlyDepthStencilAndConservativeDepth) {
    CompiledEffect ps = compileLoose("RWTexture2D<float4> U : register(u1);\n[earlydepthstencil]\n"
                                     "float4 main(float4 p : SV_Position) : SV_Target { U[uint2(p.xy)] = 1; return p; }\n",
                                     "ps_5_0");
    ASSERT_EQ(ps.shaders.size(), 1u);
    EXPECT_NE(ps.shaders[0].glsl.find("early_fragment_tests"), std::string::npos) << ps.shaders[0].glsl;
    CompiledEffect plain = compileLoose("float4 main(float4 p : SV_Position) : SV_Target { return p; }\n", "ps_5_0");
    EXPECT_EQ(plain.shaders.at(0).glsl.find("early_fragment_tests"), std::string::npos);
    for (const char* semantic : {"SV_DepthLessEqual", "SV_DepthGreaterEqual"}) {
        CompiledEffect depth = compileLoose(std::string("struct O { float4 c : SV_Target0; float d : ") + semantic +
                                                "; };\nO main(float4 p : SV_Position) { O o; o.c = 1; o.d = p.z * 0.5; return o; }\n",
                                            "ps_5_0");
        ASSERT_EQ(depth.shaders.size(), 1u) << semantic;
        EXPECT_NE(depth.shaders[0].glsl.find("gl_FragDepth"), std::string::npos) << semantic << "\n" << depth.shaders[0].glsl;
    }
    EXPECT_NE(firstError("RWTexture2D<float4> U;\n[NumThreads(8, 8, 1)]\nvoid main(uint3 t : SV_DispatchThreadID) { U[t.xy] = 1; }\n"
                         "technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, main())); } }\n"),
              "");
}

// Rasterizer-ordered views (uav-rwtexture L192-L336, rasteriser-ordered-views L41): each kind is
// a UAV at its register, indexed as its RW twin is (an int2 index into a 2D one), and a pixel
// shader that uses one runs its body as a critical section in primitive order: the GLSL asks for
// ARB_fragment_shader_interlock's pixel_interlock_ordered and begins the interlock before the
// first image access and ends it at the end. A shader that declares one and never touches it
// gets no interlock.
TEST(D3D11Stages, RasterizerOrderedViewsRunInPrimitiveOrder) {
    const std::string declarations =
        "RasterizerOrderedTexture2D<uint> tex : register(u1);\nRasterizerOrderedBuffer<float4> buf : register(u2);\n"
        "RasterizerOrderedStructuredBuffer<float> sb : register(u3);\nRasterizerOrderedByteAddressBuffer raw : register(u4);\n"
        "RasterizerOrderedTexture1DArray<float> arr : register(u5);\n";
    const std::string used = declarations +
                             "float4 main(float4 pos : SV_Position) : SV_Target\n{\n    int2 idx = int2(pos.xy);\n    tex[idx] = tex[idx] + 1;\n"
                             "    buf[idx.x] = 2;\n    sb[idx.y] = 3;\n    raw.Store(0, 4u);\n    arr[int2(0, 0)] = 5;\n    return 0;\n}\n";
    const CompiledShader ps = compileLoose(used, "ps_5_0").shaders.at(0);
    for (const char* name : {"tex", "buf", "sb", "raw", "arr"}) EXPECT_EQ(storage(ps, name).registerClass, 'u') << name;
    EXPECT_EQ(storage(ps, "tex").slot, 1);
    EXPECT_EQ(storage(ps, "arr").slot, 5);
    const size_t mode = ps.glsl.find("layout(pixel_interlock_ordered) in;");
    const size_t begin = ps.glsl.find("SPIRV_Cross_beginInvocationInterlock();");
    const size_t load = ps.glsl.find("imageLoad(tex");
    const size_t end = ps.glsl.find("SPIRV_Cross_endInvocationInterlock();");
    ASSERT_NE(mode, std::string::npos) << ps.glsl;
    ASSERT_NE(begin, std::string::npos) << ps.glsl;
    ASSERT_NE(load, std::string::npos) << ps.glsl;
    ASSERT_NE(end, std::string::npos) << ps.glsl;
    EXPECT_LT(begin, load);
    EXPECT_LT(load, end);
    const std::string unused = declarations + "float4 main(float4 pos : SV_Position) : SV_Target\n{\n    return pos;\n}\n";
    EXPECT_EQ(compileLoose(unused, "ps_5_0").shaders.at(0).glsl.find("Interlock"), std::string::npos);
}

// numthreads L111, L125, L208: a compute entry declared before its definition. The first
// declaration's attributes are the function's (the definition's are dropped), so a prototype
// without [numthreads] leaves the entry without one, which fxc refuses; the prototype itself does
// not reach glslang, which took it for the entry ("No function definition") or a recursion.
TEST(D3D11Stages, ComputeEntryPrototypesGiveTheAttributes) {
    const CompiledEffect bare = compileLoose("    [numthreads(1, 1, 1)]\nvoid main();\n\nvoid main() {}\n", "cs_5_0");
    EXPECT_EQ(bare.shaders.at(0).threadGroupSize, (std::array<int, 3>{1, 1, 1}));
    const CompiledEffect first = compileLoose(
        "RWTexture2D<float> u;\n[numthreads(2, 1, 1)]\nvoid main(uint2 id);\n[numthreads(1, 2, 1)]\n"
        "void main(uint2 id : sv_dispatchthreadid)\n{\n    u[id] = 2.0;\n}\n",
        "cs_5_0");
    EXPECT_EQ(first.shaders.at(0).threadGroupSize, (std::array<int, 3>{2, 1, 1}));
    EXPECT_THROW(compileLoose("void main();\n\n    [numthreads(1, 1, 1)]\nvoid main() {}\n", "cs_5_0"), CompileError);
}

// A domain shader writing SV_ClipDistance0 (Wicked Engine's objectDS.hlsl: `float clip :
// SV_ClipDistance0` in its output struct) and a hull shader reading and writing it: glslang alone
// refuses both ("clip/cull not currently implemented for this stage"). The domain shader writes
// gl_ClipDistance (the runtime enables its planes), the hull shader reads the vertex shader's
// gl_in[v].gl_ClipDistance and passes the value on as a varying of its own.
TEST(D3D11Stages, HullAndDomainShadersPassClipDistancesOn) {
    const std::string cp = "struct CP { float4 pos : SV_Position; float clip : SV_ClipDistance0; float2 uv : TEXCOORD0; };\n"
                           "struct HSConst { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };\n";
    CompiledEffect ds = compileLoose(cp + "struct DSOut { float4 pos : SV_Position; float clip : SV_ClipDistance0; float2 uv : TEXCOORD0; };\n"
                                          "float4 plane;\n"
                                          "[domain(\"tri\")]\n"
                                          "DSOut main(HSConst c, float3 b : SV_DomainLocation, const OutputPatch<CP, 3> p) {\n"
                                          "    DSOut o; o.pos = p[0].pos * b.x + p[1].pos * b.y + p[2].pos * b.z;\n"
                                          "    o.clip = dot(o.pos, plane); o.uv = b.xy; return o; }\n",
                                     "ds_5_0");
    ASSERT_EQ(ds.shaders.size(), 1u);
    const CompiledShader& d = ds.shaders[0];
    EXPECT_NE(d.glsl.find("float gl_ClipDistance[1];"), std::string::npos) << d.glsl;
    EXPECT_NE(d.glsl.find("gl_ClipDistance[0] = "), std::string::npos) << d.glsl;
    EXPECT_EQ(d.clipDistances, 1);

    CompiledEffect hs = compileLoose(cp + "HSConst pcf(InputPatch<CP, 3> p) { HSConst c; c.e[0] = c.e[1] = c.e[2] = 2; c.i = 2; return c; }\n"
                                          "[domain(\"tri\")][partitioning(\"integer\")][outputtopology(\"triangle_cw\")]\n"
                                          "[outputcontrolpoints(3)][patchconstantfunc(\"pcf\")]\n"
                                          "CP main(InputPatch<CP, 3> p, uint i : SV_OutputControlPointID) { return p[i]; }\n",
                                     "hs_5_0");
    ASSERT_EQ(hs.shaders.size(), 1u);
    const std::string& h = hs.shaders[0].glsl;
    EXPECT_NE(h.find("gl_in[2].gl_ClipDistance[0]"), std::string::npos) << h;
    EXPECT_NE(h.find("    float gl_ClipDistance[1];\n} gl_in[];"), std::string::npos) << h;  // one per vertex
}
