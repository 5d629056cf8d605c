// Real-world effects, second wave (issue 24): constructs met in public XNA, MonoGame, FNA and
// D3D9-11 effects that fxc takes, each on a small fixture of our own under
// tests/fixtures/realworld2/ or an inline source. Each translates, its passes link on the GL driver
// (OSMesa), and what the construct means is asserted on the reflection or the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "gl_link_check.h"
#include "run_cli.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

const std::string kDir = "tests/fixtures/realworld2/";

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

const Parameter& param(const CompiledEffect& e, const std::string& name) {
    const Parameter* p = e.findParameter(name);
    if (!p) throw std::runtime_error("no parameter " + name + " in " + e.sourcePath);
    return *p;
}

const CompiledShader& pixelShader(const CompiledEffect& e, size_t technique = 0, size_t pass = 0) {
    return e.shaders[size_t(e.techniques.at(technique).passes.at(pass).pixelShader.shaders.at(0))];
}

const SamplerBinding& samplerOf(const CompiledShader& s, const std::string& samplerName) {
    for (const auto& b : s.samplers)
        if (b.samplerName == samplerName) return b;
    throw std::runtime_error("no sampler " + samplerName);
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// Every valid pass: its shaders compile and link together (and each alone, separable).
void expectAllPassesLink(const CompiledEffect& e) {
    fxport::test::sharedTestContext();
    int linked = 0;
    for (const auto& t : e.techniques)
        for (const auto& p : t.passes) {
            if (!p.valid) continue;
            std::vector<fxport::test::GlslStageSource> stages;
            if (!p.vertexShader.shaders.empty() && p.vertexShader.shaders[0] >= 0)
                stages.push_back({fxport::test::GlslStageSource::Vertex, e.shaders[size_t(p.vertexShader.shaders[0])].glsl});
            if (!p.pixelShader.shaders.empty() && p.pixelShader.shaders[0] >= 0)
                stages.push_back({fxport::test::GlslStageSource::Fragment, e.shaders[size_t(p.pixelShader.shaders[0])].glsl});
            if (stages.empty()) continue;
            EXPECT_EQ(fxport::test::compileAndLinkSeparable(stages), "") << e.sourcePath << " " << t.name << "/" << p.name;
            ++linked;
        }
    EXPECT_GT(linked, 0) << e.sourcePath;
}

CompiledEffect compileFixture(const std::string& file, CompileOptions options = noCache()) {
    CompiledEffect e = compileEffectFile(kDir + file, options);
    expectAllPassesLink(e);
    return e;
}

}  // namespace

// ---- 1. declarations fxc accepts ------------------------------------------------------------------
// NVIDIA HBAO+'s ConstantBuffers.hlsl: `#define REGISTER(SLOT) : register(##SLOT##)` pastes a
// parenthesis with the argument, which fxc's preprocessor leaves side by side (glslang's refused
// the paste), and `PAD_FLOAT;` with an empty PAD_FLOAT is an empty declaration in the cbuffer
// (glslang refused the lone ';'). The cbuffer lands in slot b3 and keeps both members.
TEST(Declarations, ImpossiblePastesAndEmptyCbufferDeclarations) {
    CompiledEffect e = compileEffectSource("#define REGISTER(SLOT) : register(##SLOT##)\n#define PAD_FLOAT\n"
                                           "#define DECLARE_CONSTANT(TYPE, VARIABLE) TYPE g_##VARIABLE\n"
                                           "cbuffer Global REGISTER(b3)\n{\n    DECLARE_CONSTANT(float4, Color);\n    PAD_FLOAT;\n    float Scale;\n};\n"
                                           "float4 PS() : SV_Target { return g_Color * Scale; }\n"
                                           "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                           "virtual/Hbao.fx", noCache());
    EXPECT_EQ(param(e, "g_Color").offset, 0);
    EXPECT_EQ(param(e, "Scale").offset, 16);
    bool slot = false;
    for (const auto& r : e.resources) slot = slot || (r.name == "Global" && r.explicitRegister == 3);
    EXPECT_TRUE(slot);
    expectAllPassesLink(e);
}


TEST(Declarations, SeveralTexturesAndSamplersInOneStatement) {
    CompiledEffect e = compileFixture("declarations/SeveralDeclarators.fx");
    EXPECT_EQ(param(e, "BaseTex").type, ParameterType::Texture);
    EXPECT_EQ(param(e, "DetailTex").type, ParameterType::Texture);
    EXPECT_EQ(param(e, "ObjB").type, ParameterType::Texture2D);
    const CompiledShader& ps = pixelShader(e);
    EXPECT_EQ(samplerOf(ps, "BaseSampler").textureParameter, "BaseTex");
    EXPECT_EQ(samplerOf(ps, "BaseSampler").state.minFilter, TextureFilter::Point);
    EXPECT_EQ(samplerOf(ps, "DetailSampler").textureParameter, "DetailTex");
    EXPECT_EQ(samplerOf(ps, "DetailSampler").state.addressU, TextureAddress::Clamp);
    EXPECT_EQ(samplerOf(ps, "PlainB").unit, 3);  // register(s3) belongs to the declarator it follows
    EXPECT_NE(samplerOf(ps, "PlainA").unit, 3);
    EXPECT_EQ(pixelShader(e, 1).samplers.size(), 2u);
}

TEST(Declarations, ConstStaticIsAConstantForArraySizes) {
    CompiledEffect e = compileFixture("declarations/ConstStaticArraySize.fx");
    EXPECT_EQ(param(e, "Offsets").elements, 5);
    EXPECT_EQ(e.findParameter("Radius"), nullptr);
}

// A size may read a constant array by a constant index (`static float b[w[i]]`), as fxc takes it
// (vkd3d's array-size-expr): the size is the element, truncated. The shader must compile and read
// the sized array's last element.
TEST(Declarations, ArraySizeReadsAConstantArray) {
    const std::string src = "static const float w[4] = { 0.5, 1.5, 3.7, 2.0 };\n"
                            "static const int i = 2;\n"
                            "static const float b[w[i]] = { 1, 2, 0.25 };\n"
                            "float4 PS() : COLOR0 { return b[2]; }\n"
                            "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    CompiledEffect e = compileEffectSource(src, "virtual/ArrayIndexSize.fx", noCache());
    ASSERT_EQ(e.shaders.size(), 1u);
    EXPECT_NE(e.shaders[0].glsl.find("0.25"), std::string::npos) << e.shaders[0].glsl;
}

TEST(Declarations, ArraySizesBelowOneAreRefusedAtTheirLine) {
    // glslang takes them and lays the array out with a negative size; fxc says X3059.
    const std::string src = "static const int N = -4;\n"
                            "float Weights[N + 2];\n"
                            "float4 PS() : COLOR0 { return Weights[0]; }\n"
                            "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    try {
        compileEffectSource(src, "virtual/NegativeSize.fx", noCache());
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& e) {
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.id, std::string(diag::kArrayTooLarge));
        EXPECT_EQ(d.location.line, 2);
        EXPECT_NE(d.message.find("X3059"), std::string::npos) << d.message;
    }
}

TEST(Declarations, LowercaseDx9TexturesUsedAsObjectsBecomeObjects) {
    CompiledEffect e = compileFixture("declarations/LowercaseTextureObjects.fx");
    EXPECT_EQ(param(e, "Albedo").type, ParameterType::Texture2D);
    EXPECT_EQ(param(e, "Sky").type, ParameterType::TextureCube);
    EXPECT_EQ(param(e, "Mask").type, ParameterType::Texture2D);
    const CompiledShader& ps = pixelShader(e);
    ASSERT_EQ(ps.samplers.size(), 3u);
    for (const auto& s : ps.samplers) {
        if (s.textureParameter == "Albedo") {
            EXPECT_EQ(s.unit, 1);  // register(t1)
        }
        if (s.textureParameter == "Sky") {
            EXPECT_EQ(s.kind, TextureKind::TextureCube);
        }
    }
}

TEST(Declarations, AssignedUniformsGetTheShadersOwnCopy) {
    CompiledEffect e = compileFixture("declarations/AssignedUniforms.fx");
    EXPECT_EQ(param(e, "Scale").defaultValue, std::vector<double>{2});
    EXPECT_EQ(param(e, "Counter").type, ParameterType::Float);
    EXPECT_EQ(e.findParameter("fxport_copy_Scale"), nullptr);
    const std::string& glsl = pixelShader(e).glsl;
    for (const char* name : {"Scale", "Tint", "Counter"})
        EXPECT_NE(glsl.find(std::string("fxport_copy_") + name + " = "), std::string::npos) << name << "\n" << glsl;
}

TEST(Declarations, LoopVariablesUsedAfterTheirLoopCompile) {
    CompiledEffect e = compileFixture("declarations/LoopVariableScope.fx");
    EXPECT_FALSE(pixelShader(e).glsl.empty());  // values: runtime.RealWorld2Render.LoopVariablesLiveInTheEnclosingScope
}

TEST(Declarations, ConstructorAsAssignmentTargetCompiles) {
    CompiledEffect e = compileFixture("declarations/ConstructorAssignment.fx");
    EXPECT_FALSE(pixelShader(e).glsl.empty());  // values: runtime.RealWorld2Render.ConstructorTargetsAssignTheirParts
}

TEST(Declarations, ASamplerSampledWithTwoDimensionsByDifferentShaders) {
    CompiledEffect e = compileFixture("declarations/SamplerTwoDimensions.fx");
    EXPECT_EQ(param(e, "LightTexture").type, ParameterType::Texture);
    const CompiledShader& cube = pixelShader(e, 0);
    const CompiledShader& flat = pixelShader(e, 1);
    ASSERT_EQ(cube.samplers.size(), 1u);
    ASSERT_EQ(flat.samplers.size(), 1u);
    EXPECT_EQ(cube.samplers[0].kind, TextureKind::TextureCube);
    EXPECT_EQ(flat.samplers[0].kind, TextureKind::Texture2D);
    EXPECT_EQ(cube.samplers[0].unit, flat.samplers[0].unit);
    for (const auto* s : {&cube.samplers[0], &flat.samplers[0]}) {
        EXPECT_EQ(s->textureParameter, "LightTexture");
        EXPECT_EQ(s->state.minFilter, TextureFilter::Point);
    }
}

// ---- 5. FXAA 3.11's needs: gather on a texture in a struct, no GLSL macros ------------------------

TEST(Gather, ChannelsThroughAStructAndNoGlslPredefines) {
    CompiledEffect e = compileFixture("gather/GatherChannels.fx");
    const std::string& glsl = pixelShader(e).glsl;
    // Taken only when GL_ARB_gpu_shader5 is undefined, as under fxc: Gather (red), GatherGreen, GatherAlpha+offset.
    EXPECT_EQ(count(glsl, "textureGather("), 2u) << glsl;
    EXPECT_EQ(count(glsl, "textureGatherOffset("), 1u) << glsl;
    EXPECT_NE(glsl.find(", 1)"), std::string::npos) << glsl;  // green
    EXPECT_NE(glsl.find(", 3)"), std::string::npos) << glsl;  // alpha
}

// ---- 2. MonoGame's dialect ------------------------------------------------------------------------

TEST(MonoGameDialect, RedefinedShaderModelUndeclaredTextureAndUniformsWithoutValues) {
    CompiledEffect e = compileFixture("monogame/PlatformTemplate.fx");
    // The header's later `#define VS_SHADERMODEL` wins, with fxc's warning at the redefinition.
    const CompiledShader& vs = e.shaders[size_t(e.techniques[0].passes[0].vertexShader.shaders[0])];
    EXPECT_EQ(vs.profile.name, "vs_4_0_level_9_3");
    bool warned = false;
    for (const auto& d : e.diagnostics)
        warned |= d.severity == Severity::Warning && d.id == std::string(diag::kPreprocessor) &&
                  d.location.file.find("ShaderModels.fxh") != std::string::npos && d.location.line == 10 &&
                  d.message.find("VS_SHADERMODEL") != std::string::npos;
    EXPECT_TRUE(warned);
    // `Texture = <SpriteTexture>` with no declaration: the parameter MonoGame makes.
    EXPECT_EQ(param(e, "SpriteTexture").type, ParameterType::Texture);
    EXPECT_EQ(samplerOf(pixelShader(e), "SpriteSampler").textureParameter, "SpriteTexture");
    EXPECT_NE(e.findParameter("DepthMap"), nullptr);  // named by a SamplerState block, as MonoGame reads it
    // `PS()` is the overload without uniforms; `PS(true, 2)` fills both; `PS(true)` leaves Gain to the
    // application, as a parameter of the constant buffer read by that shader only.
    EXPECT_EQ(e.findParameter("Invert"), nullptr);
    const Parameter& gain = param(e, "Gain");
    EXPECT_EQ(gain.type, ParameterType::Float);
    EXPECT_GE(gain.offset, 0);
    auto reads = [&](const CompiledShader& s, const std::string& name) {
        for (int i : s.parametersRead)
            if (e.parameters[size_t(i)].name == name) return true;
        return false;
    };
    EXPECT_FALSE(reads(pixelShader(e, 0), "Gain"));
    EXPECT_FALSE(reads(pixelShader(e, 1), "Gain"));
    EXPECT_TRUE(reads(pixelShader(e, 2), "Gain"));
    EXPECT_EQ(pixelShader(e, 1).arguments, "true , 2");
}

// ---- 3. includes as games write them --------------------------------------------------------------

const std::string kGame = kDir + "includes/Game";
const std::string kWater = kGame + "/Content/Shaders/Effects/Water/Water.fx";

TEST(GameIncludes, FromTheGameFolderWithWindowsPathsGuardsAndATechniqueInAHeader) {
    CompileOptions options = noCache();
    options.includeRoot = kGame;
    CompiledEffect e = compileFixture("includes/Game/Content/Shaders/Effects/Water/Water.fx", options);
    ASSERT_EQ(e.techniques.size(), 1u);
    EXPECT_EQ(e.techniques[0].name, "Main");  // defined in Common/Techniques.fx
    for (const char* name : {"FogDensity", "LightDir", "ShadowStrength"}) EXPECT_NE(e.findParameter(name), nullptr) << name;
    // Every header is a dependency of the compile (the cache rebuilds when one changes).
    std::vector<std::string> deps = effectDependencies(kWater, options);
    for (const char* file : {"Fog.inc", "Lighting.hpp", "Shadows.h", "Techniques.fx"})
        EXPECT_TRUE(std::any_of(deps.begin(), deps.end(), [&](const std::string& d) { return d.find(file) != std::string::npos; })) << file;
}

// Without a root the folders above the effect stand in for the game's working folder all the way
// up (fxc resolves against the current directory); a root ends the search there.
TEST(GameIncludes, WithoutARootTheFoldersAboveAreSearched) {
    CompiledEffect e = compileEffectFile(kWater, noCache());
    EXPECT_EQ(e.techniques.at(0).name, "Main");
}

TEST(GameIncludes, ARootEndsTheSearchOfTheFoldersAbove) {
    CompileOptions options = noCache();
    options.includeRoot = fs::path(kWater).parent_path().string();
    try {
        compileEffectFile(kWater, options);
        ADD_FAILURE() << "compiled with the effect's folder as the include root";
    } catch (const CompileError& e) {
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.id, std::string(diag::kIncludeNotFound));
        EXPECT_EQ(d.location.line, 4);
    }
}

TEST(GameIncludes, NamesMatchingSeveralFilesByCaseAreRefusedNamingThem) {
    fs::path dir = fs::temp_directory_path() / ("fxport_rw2_case_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "Shared.fxh") << "float A;\n";
    std::ofstream(dir / "SHARED.fxh") << "float B;\n";
    std::ofstream(dir / "Uses.fx") << "// x\n#include \"shared.fxh\"\nfloat4 PS() : COLOR0 { return 1; }\n"
                                      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    try {
        compileEffectFile((dir / "Uses.fx").string(), noCache());
        ADD_FAILURE() << "an ambiguous include compiled";
    } catch (const CompileError& e) {
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.id, std::string(diag::kIncludeNotFound));
        EXPECT_EQ(d.location.line, 2);
        EXPECT_NE(d.message.find("Shared.fxh"), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("SHARED.fxh"), std::string::npos) << d.message;
    }
    // Named exactly, either one is taken.
    std::ofstream(dir / "Uses.fx") << "#include \"SHARED.fxh\"\nfloat4 PS() : COLOR0 { return B; }\n"
                                      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    EXPECT_NE(compileEffectFile((dir / "Uses.fx").string(), noCache()).findParameter("B"), nullptr);
    fs::remove_all(dir);
}

// ---- 4. legacy encodings ---------------------------------------------------------------------------

bool isUtf8(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        auto c = static_cast<unsigned char>(s[i]);
        size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        if (n == 0 || i + n > s.size()) return false;
        for (size_t k = 1; k < n; ++k)
            if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
        i += n;
    }
    return true;
}

class LegacyEncoding : public ::testing::TestWithParam<const char*> {};

TEST_P(LegacyEncoding, CommentsAndStringsNeverStopACompile) {
    CompiledEffect e = compileFixture(std::string("encodings/") + GetParam() + ".fx");
    const Parameter& p = param(e, "Intensity");
    EXPECT_EQ(p.defaultValue, std::vector<double>{0.5});
    ASSERT_EQ(p.annotations.size(), 1u);
    EXPECT_TRUE(isUtf8(p.annotations[0].value));
    EXPECT_TRUE(isUtf8(param(e, "Description").defaultString));
    EXPECT_TRUE(isUtf8(reflectionJson(e)));
    fxport::test::RunResult r = fxport::test::runCli("dump --no-cache --reflection " + kDir + "encodings/" + GetParam() + ".fx");
    EXPECT_TRUE(r.exited && r.status == 0) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Wild, LegacyEncoding, ::testing::Values("Latin1", "Cp949", "ShiftJis"));

TEST(LegacyEncodings, ShiftJisCommentEndingInABackslashByteContinuesNoLine) {
    const std::string file = kDir + "encodings/ShiftJisError.fx";
    try {
        compileEffectFile(file, noCache());
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& e) {
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.location.line, 4);
        EXPECT_NE(d.message.find("Missing"), std::string::npos) << d.message;
        EXPECT_NE(d.sourceLine.find("return Missing;"), std::string::npos) << d.sourceLine;
    }
    fxport::test::RunResult r = fxport::test::runCli("check --no-cache " + file);
    EXPECT_TRUE(r.exited && r.status == 1) << r.output;
    EXPECT_NE(r.output.find("ShiftJisError.fx(4,"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("return Missing;"), std::string::npos) << r.output;
}

// ---- 8. what stays out, said clearly ----------------------------------------------------------------

TEST(Unsupported, InterfacesAndClassesAreNamedNotMisparsed) {
    try {
        compileEffectFile(kDir + "declarations/DynamicLinkage.fx", noCache());
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& e) {
        ASSERT_EQ(e.diagnostics().size(), 1u);
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.id, std::string(diag::kUnsupported));
        EXPECT_EQ(d.location.line, 3);
        EXPECT_NE(d.message.find("interfaces"), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("not supported"), std::string::npos) << d.message;
    }
}

TEST(Unsupported, AnEntryParameterOfAnUndeclaredTypeIsSaidToBeUndeclared) {
    // Effect fragments meant to follow a header their engine prepends.
    const std::string src = "float Progress;\n"
                            "float4 PS_Fade(VertexShaderOutput input) : COLOR { return Progress; }\n"
                            "technique Fade { pass P { PixelShader = compile ps_2_0 PS_Fade(); } }\n";
    try {
        compileEffectSource(src, "virtual/Fragment.fx", noCache());
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& e) {
        const Diagnostic& d = e.diagnostics().front();
        EXPECT_EQ(d.location.line, 2);
        EXPECT_NE(d.message.find("'VertexShaderOutput' is not declared"), std::string::npos) << d.message;
        EXPECT_EQ(d.message.find("a0"), std::string::npos) << d.message;  // no names of the generated wrapper
    }
}
