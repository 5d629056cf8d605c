// Shader assembly (asm { } blocks) in the translator: what the pass states bind (constant
// registers, texture stages), what the compiled shaders read, and a diagnostic at the asm's own
// file:line (also inside an #include) for every instruction, register or modifier that is not
// translated. Compiling and linking every asm fixture is RealWorldFixture's job
// (translation_test.cpp); the pixels are tests/runtime/asm_shader_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

const std::string kDir = "tests/fixtures/realworld/asm_sm1/";

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

int parameter(const CompiledEffect& e, const std::string& name) {
    for (std::size_t i = 0; i < e.parameters.size(); ++i)
        if (e.parameters[i].name == name) return int(i);
    return -1;
}

bool reads(const CompiledEffect& e, const CompiledShader& s, const std::string& name) {
    return std::find(s.parametersRead.begin(), s.parametersRead.end(), parameter(e, name)) != s.parametersRead.end();
}

const CompiledShader& shaderOf(const CompiledEffect& e, const ShaderChoice& c) {
    EXPECT_EQ(c.shaders.size(), 1u);
    return e.shaders.at(std::size_t(c.shaders.at(0)));
}

// The first diagnostic with this id (nullptr if none).
const Diagnostic* find(const std::vector<Diagnostic>& ds, const std::string& id) {
    for (const auto& d : ds)
        if (d.id == id) return &d;
    return nullptr;
}

std::vector<Diagnostic> errorsOf(const std::string& source, const std::string& name = "asm_inline.fx") {
    try {
        compileEffectSource(source, name, noCache());
    } catch (const CompileError& e) {
        return e.diagnostics();
    }
    ADD_FAILURE() << "expected a compile error";
    return {};
}

TEST(AsmTranslation, ConstantsAndTextureStagesComeFromPassStates) {
    CompiledEffect e = compileEffectFile(kDir + "AsmVs11Ps20.fx", noCache());
    ASSERT_FALSE(e.hasErrors());
    const Pass& pass = e.techniques.at(0).passes.at(0);
    const CompiledShader& vs = shaderOf(e, pass.vertexShader);
    const CompiledShader& ps = shaderOf(e, pass.pixelShader);
    EXPECT_EQ(vs.profile.name, "vs_1_1");
    EXPECT_EQ(ps.profile.name, "ps_2_0");
    EXPECT_TRUE(vs.needsD3D9PixelOffset);
    EXPECT_TRUE(reads(e, vs, "WorldViewProj"));
    EXPECT_TRUE(reads(e, vs, "Scale"));
    EXPECT_FALSE(reads(e, vs, "Gain"));
    EXPECT_TRUE(reads(e, ps, "Gain"));
    // Texture[0] = <Tex> with MinFilter[0]/MagFilter[0]/AddressU[0]: stage 0 is texture unit 0.
    ASSERT_EQ(ps.samplers.size(), 1u);
    EXPECT_EQ(ps.samplers[0].unit, 0);
    EXPECT_EQ(ps.samplers[0].textureParameter, "Tex");
    EXPECT_EQ(ps.samplers[0].state.minFilter, TextureFilter::Point);
    EXPECT_EQ(ps.samplers[0].state.addressU, TextureAddress::Clamp);
    // The register states were consumed, not reported as ignored fixed-function states.
    for (const auto& d : e.diagnostics) EXPECT_NE(d.id, "FX1303") << d.format();
}

TEST(AsmTranslation, SamplerStateNamesTheStagesTexture) {
    CompiledEffect e = compileEffectFile(kDir + "AsmPs11Modifiers.fx", noCache());
    const CompiledShader& ps = shaderOf(e, e.techniques.at(0).passes.at(0).pixelShader);
    EXPECT_EQ(ps.profile.name, "ps_1_1");
    ASSERT_EQ(ps.samplers.size(), 1u);
    EXPECT_EQ(ps.samplers[0].unit, 0);
    EXPECT_EQ(ps.samplers[0].textureParameter, "Tex");  // from TexSampler's sampler_state
    EXPECT_EQ(ps.samplers[0].state.magFilter, TextureFilter::Point);
    EXPECT_TRUE(reads(e, ps, "Tint"));
    EXPECT_TRUE(reads(e, ps, "Dir"));
}

TEST(AsmTranslation, ShaderVariablesArraysAndCubeSamplers) {
    CompiledEffect e = compileEffectFile(kDir + "AsmShaderVariables.fx", noCache());
    ASSERT_FALSE(e.hasErrors());
    const Pass& array = e.techniques.at(1).passes.at(0);
    ASSERT_EQ(array.pixelShader.shaders.size(), 2u);
    const CompiledShader& cube = e.shaders.at(std::size_t(array.pixelShader.shaders[0]));
    ASSERT_EQ(cube.samplers.size(), 1u);
    EXPECT_EQ(cube.samplers[0].kind, TextureKind::TextureCube);
    EXPECT_EQ(cube.samplers[0].textureParameter, "EnvMap");
    EXPECT_EQ(e.shaders.at(std::size_t(array.pixelShader.shaders[1])).profile.name, "ps_1_1");
    EXPECT_EQ(shaderOf(e, e.techniques.at(0).passes.at(0).pixelShader).profile.name, "ps_1_4");  // written ps.1.4
}

TEST(AsmTranslation, UntranslatedInstructionIsAnErrorAtItsLine) {
    auto ds = errorsOf("float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                       "technique T { pass P {\n"
                       "  VertexShader = compile vs_2_0 VS();\n"
                       "  PixelShader = asm {\n"
                       "    ps_1_3\n"
                       "    tex t0\n"
                       "    texm3x2depth t1, t0\n"
                       "    mov r0, t1\n"
                       "  };\n"
                       "} }\n");
    const Diagnostic* d = find(ds, "FX1404");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.line, 7);
    EXPECT_NE(d->message.find("texm3x2depth"), std::string::npos) << d->message;
    EXPECT_NE(d->sourceLine.find("texm3x2depth"), std::string::npos);
}

TEST(AsmTranslation, UnknownModifierAndRegisterAreErrorsAtTheirLines) {
    auto ds = errorsOf("technique T { pass P {\n"
                       "  PixelShader = asm {\n"
                       "    ps_2_0\n"
                       "    dcl t0\n"
                       "    mov r0, t0_x8\n"
                       "    mov oC0, r0\n"
                       "  };\n"
                       "} }\n");
    const Diagnostic* d = find(ds, "FX1404");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.line, 5);
    EXPECT_NE(d->message.find("_x8"), std::string::npos) << d->message;

    ds = errorsOf("technique T { pass P {\n"
                  "  PixelShader = asm { ps_2_0\n"
                  "    mov oC0, q3\n"
                  "  };\n"
                  "} }\n");
    d = find(ds, "FX1201");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.line, 3);
    EXPECT_NE(d->message.find("q3"), std::string::npos) << d->message;
}

TEST(AsmTranslation, VersionMustMatchTheStageAndBeSupported) {
    auto ds = errorsOf("technique T { pass P { VertexShader = asm { ps_2_0 mov oC0, c0 }; } }\n");
    ASSERT_FALSE(ds.empty());
    EXPECT_EQ(ds.front().id, "FX1401");
    ds = errorsOf("technique T { pass P {\n PixelShader = asm { ps_3_0 mov oC0, c0 }; } }\n");
    ASSERT_FALSE(ds.empty());
    EXPECT_EQ(ds.front().id, "FX1404");
    EXPECT_EQ(ds.front().location.line, 2);
}

TEST(AsmTranslation, UnboundConstantIsAWarningAtItsLine) {
    CompiledEffect e = compileEffectSource("float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                           "technique T { pass P {\n"
                                           "  VertexShader = compile vs_2_0 VS();\n"
                                           "  PixelShader = asm {\n"
                                           "    ps_2_0\n"
                                           "    mov oC0, c7\n"
                                           "  };\n"
                                           "} }\n",
                                           "unbound.fx", noCache());
    const Diagnostic* d = find(e.diagnostics, "FX1404");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, Severity::Warning);
    EXPECT_EQ(d->location.line, 6);
    EXPECT_NE(d->message.find("c7"), std::string::npos) << d->message;
}

// `;` starts a comment in shader assembly; an apostrophe there must not reach the preprocessor
// as an unclosed character literal.
TEST(AsmTranslation, SemicolonCommentsMayHoldQuotes) {
    CompiledEffect e = compileEffectSource("float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                           "technique T { pass P {\n"
                                           "  VertexShader = compile vs_2_0 VS();\n"
                                           "  PixelShader = asm {\n"
                                           "    ps_1_1          ; it's the \"version\" (don't care)\n"
                                           "    def c0, 1.0f, 0.5f, -0.25, 1e-1\n"
                                           "    mov r0, c0      ; copy\n"
                                           "  };\n"
                                           "} }\n",
                                           "quotes.fx", noCache());
    EXPECT_FALSE(e.hasErrors());
    EXPECT_EQ(e.shaders.size(), 2u);
}

// DX8-era spellings met in public effects: `c[1]` for c1, a shader variable named as `<PS>`.
TEST(AsmTranslation, Dx8Spellings) {
    CompiledEffect e = compileEffectSource("float4 Color;\n"
                                           "PixelShader PS = asm { ps.1.1 mov r0, c[1] };\n"
                                           "technique T { pass P {\n"
                                           "  VertexShader = asm { vs.1.1 dcl_position v0 mov oPos, v0 mov oD0, c[2] };\n"
                                           "  VertexShaderConstant[2] = <Color>;\n"
                                           "  PixelShaderConstant[1] = <Color>;\n"
                                           "  PixelShader = <PS>;\n"
                                           "} }\n",
                                           "dx8.fx", noCache());
    ASSERT_FALSE(e.hasErrors());
    const Pass& p = e.techniques.at(0).passes.at(0);
    EXPECT_TRUE(reads(e, shaderOf(e, p.pixelShader), "Color"));
    EXPECT_TRUE(reads(e, shaderOf(e, p.vertexShader), "Color"));
}

TEST(AsmTranslation, Dx8DeclBlockIsNamed) {
    auto ds = errorsOf("technique T { pass P {\n"
                       "  VertexShader = decl { float v0[3]; } asm { vs.1.0 mov oPos, v0 };\n"
                       "} }\n");
    ASSERT_FALSE(ds.empty());
    EXPECT_EQ(ds.front().id, "FX1404");
    EXPECT_EQ(ds.front().location.line, 2);
    EXPECT_NE(ds.front().message.find("decl"), std::string::npos) << ds.front().message;
}

// Malformed assembly is a diagnostic on the asm's line, never a crash or generated code glslang
// rejects.
TEST(AsmTranslation, MalformedAssemblyIsADiagnosticAtItsLine) {
    const char* const bodies[] = {"",
                                  "ps_1_1 mov",
                                  "ps_1_1 mov r0,",
                                  "ps_1_1 def c0, 1",
                                  "ps_1_1 mov r0, c4000000000",
                                  "ps_2_0 m4x4 oC0, r0, c2147483647",
                                  "ps_2_0 mov oC0.q, r0",
                                  "ps_2_0 mov oC0, r0.xyzwx",
                                  "ps_1_1 + + mov r0, t0",
                                  "ps_2_0 texld r0, t0, c0 mov oC0, r0",
                                  "ps_2_0 dcl_foo s0 mov oC0, c0",
                                  "ps_1_1 mov r0, t0_foo",
                                  "ps_2_0 mov_x9 oC0, c0",
                                  "ps_2_0 mov oC0, b0",
                                  "ps_1_1 mov oC0, c0",
                                  "vs_1_1 dcl_position v0 mov oPos, v0 mov oC0, v0",
                                  "vs_1_1 dcl_bogus v0 mov oPos, v0",
                                  "vs_1_1 dcl_position v0 mov oD0, v0"};
    for (const char* body : bodies) {
        SCOPED_TRACE(body);
        bool vertex = body[0] == 'v';
        std::string source = std::string("float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                         "float4 PS() : COLOR { return 0; }\n"
                                         "technique T { pass P {\n") +
                             (vertex ? "  PixelShader = compile ps_2_0 PS();\n  VertexShader = asm { " : "  VertexShader = compile vs_2_0 VS();\n  PixelShader = asm { ") +
                             body + " };\n} }\n";
        auto ds = errorsOf(source);
        ASSERT_FALSE(ds.empty());
        EXPECT_EQ(ds.front().location.line, 5) << ds.front().format();
        EXPECT_NE(ds.front().id, "FX2001") << ds.front().format();  // not glslang choking on generated code
    }
}

TEST(AsmTranslation, BadConstantBindingNamesTheState) {
    auto ds = errorsOf("struct S { float4 a; };\nS s;\n"
                       "technique T { pass P {\n"
                       "  PixelShaderConstantF[0] = <s>;\n"
                       "  PixelShader = asm { ps_2_0 mov oC0, c0 };\n"
                       "} }\n");
    const Diagnostic* d = find(ds, "FX1302");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.line, 4);
}

// An asm block inside an #include: the diagnostic names the header and the line there.
TEST(AsmTranslation, DiagnosticsPointIntoIncludes) {
    fs::path dir = fs::temp_directory_path() / ("fxport_asm_include_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(dir);
    std::ofstream(dir / "shaders.fxh") << "// asm shaders\n"
                                          "PixelShader Ps = asm\n"
                                          "{\n"
                                          "    ps_1_1\n"
                                          "    tex t0\n"
                                          "    bem r0.rg, t0, t0\n"
                                          "};\n";
    std::ofstream(dir / "main.fx") << "#include \"shaders.fxh\"\n"
                                      "technique T { pass P { PixelShader = (Ps); } }\n";
    try {
        compileEffectFile((dir / "main.fx").string(), noCache());
        ADD_FAILURE() << "bem is not translated";
    } catch (const CompileError& e) {
        const Diagnostic* d = find(e.diagnostics(), "FX1404");
        ASSERT_NE(d, nullptr);
        EXPECT_NE(d->location.file.find("shaders.fxh"), std::string::npos) << d->format();
        EXPECT_EQ(d->location.line, 6);
    }
    fs::remove_all(dir);
}

}  // namespace
