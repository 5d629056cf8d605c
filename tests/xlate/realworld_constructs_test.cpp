// Constructs of effects found in public XNA, MonoGame and D3D10/11 projects (issue 14), each on a
// small fixture under tests/fixtures/realworld/wild/ or an inline source: it translates, its
// programs link on the GL driver (OSMesa), and diagnostics name the original file and line.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
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

using fxport::test::RunResult;
using fxport::test::runCli;

const std::string kWild = "tests/fixtures/realworld/wild/";

CompileOptions noCache() {
    CompileOptions o;
    o.useCache = false;
    return o;
}

const Parameter& param(const CompiledEffect& e, const std::string& name) {
    const Parameter* p = e.findParameter(name);
    if (!p) throw std::runtime_error("no parameter " + name);
    return *p;
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

Diagnostic firstError(const std::string& source, const std::string& virtualPath, CompileOptions options = noCache()) {
    try {
        compileEffectSource(source, virtualPath, options);
    } catch (const CompileError& e) {
        return e.diagnostics().front();
    }
    ADD_FAILURE() << virtualPath << " compiled";
    return {};
}

fs::path freshTempDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("fxport_rw_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

// ---- 1. encodings -------------------------------------------------------------------------------

TEST(Encodings, ByteOrderMarksAndUtf16Translate) {
    for (const char* name : {"Utf8Bom.fx", "Utf8NoBom.fx", "Utf16LE.fx", "Utf16BE.fx"}) {
        SCOPED_TRACE(name);
        CompiledEffect e = compileEffectFile(kWild + "encodings/" + name, noCache());
        ASSERT_EQ(e.techniques.size(), 1u);
        EXPECT_EQ(e.techniques[0].name, "Encoded");
        EXPECT_EQ(param(e, "Tint").defaultValue, (std::vector<double>{1, 0.5, 0.25, 1}));
        EXPECT_EQ(param(e, "Tint").declaredAt.line, 3);
        EXPECT_EQ(param(e, "Tint").declaredAt.column, 8);
        expectAllPassesLink(e);
    }
}

TEST(Encodings, DiagnosticsKeepLinesAndColumnsThroughBomAndUtf16) {
    // A UTF-16 LE header (with BOM) holding an error on its line 4, column 12, included from a
    // UTF-8 file with a BOM: the diagnostic names the header, the line and the column.
    std::string src = "\xEF\xBB\xBF// BOM\n#include \"Utf16Error.fxh\"\n"
                      "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return Broken(uv); }\n"
                      "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    Diagnostic d = firstError(src, kWild + "encodings/Includer.fx");
    EXPECT_EQ(d.location.file, kWild + "encodings/Utf16Error.fxh");
    EXPECT_EQ(d.location.line, 4);
    EXPECT_EQ(d.location.column, 12);
    EXPECT_NE(d.sourceLine.find("undeclared_thing"), std::string::npos) << d.format();

    // An error in the BOM'd file itself: line 1 column 1 is the first character after the BOM.
    Diagnostic first = firstError("\xEF\xBB\xBF<bad\ntechnique T { pass P { } }\n", "virtual/Bom.fx");
    EXPECT_EQ(first.location.line, 1);
    EXPECT_EQ(first.location.column, 1);
    EXPECT_EQ(first.sourceLine, "<bad");
}

TEST(Encodings, ClassicMacLineEndsAndDosEndOfFileMark) {
    Diagnostic d = firstError("float4 PS() : COLOR0\r{ return undefined_x; }\rtechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\r",
                              "virtual/Mac.fx");
    EXPECT_EQ(d.location.line, 2);
    EXPECT_EQ(d.location.column, 10);
    CompiledEffect e = compileEffectSource("float4 PS() : COLOR0 { return 1; }\r\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\r\n\x1a",
                                           "virtual/Dos.fx", noCache());
    EXPECT_EQ(e.shaders.size(), 1u);
}

// ---- 10. end-of-file and #line diagnostics carry file(line,col) ----------------------------------

TEST(EndOfFileDiagnostics, EveryErrorNamesFileLineAndColumn) {
    const char* sources[] = {
        "technique T { pass P {} }\nfloat4 x = \n\n",                      // declaration cut by end of file
        "technique T { pass P {} }\nfloat4 f() {\n",                       // body never closed
        "float4 x;\n#if 1\nfloat y;\n",                                   // missing #endif
        "float4 x;\n#define F(a) a\nF(\n",                                 // end of input in a macro call
        "#line 0\n#error stop\n",                                         // #line 0: line 0 before
        "#line 0 \"elsewhere.fx\"\n#error stop\n",                        // ... and a file that does not exist
        "#line 2147483647\nfloat4 x;\n#error stop\n",                     // wraps to negative in glslang
        "#line 1 \"\"\n#error stop\n",                                    // empty file name
        "technique T { pass P { VertexShader = compile",                  // ends inside a pass, no newline
        "float4 x;\n/* never closed\n",
    };
    for (const char* src : sources) {
        SCOPED_TRACE(src);
        Diagnostic d = firstError(src, "virtual/Eof.fx");
        EXPECT_EQ(d.location.file, "virtual/Eof.fx");
        EXPECT_GE(d.location.line, 1);
        EXPECT_GE(d.location.column, 1);
        EXPECT_TRUE(std::regex_search(d.format(), std::regex(R"(^virtual/Eof\.fx\(\d+,\d+\): error FX\d{4}: )"))) << d.format();
    }
    // The #error after `#line 0` is reported where it is in the file: line 2.
    EXPECT_EQ(firstError("#line 0\n#error stop\n", "virtual/Eof.fx").location.line, 2);
}

TEST(EndOfFileDiagnostics, MalformedLineDirectiveIsAWarningAtItsLine) {
    CompiledEffect e = compileEffectSource("float4 PS() : COLOR0 { return 1; }\n#line abc\n"
                                           "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n",
                                           "virtual/Line.fx", noCache());
    ASSERT_EQ(e.diagnostics.size(), 1u);
    EXPECT_EQ(e.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(e.diagnostics[0].location.line, 2);
    EXPECT_EQ(e.diagnostics[0].location.column, 1);
}

TEST(EndOfFileDiagnostics, IncludeAsTheLastBytesOfAFile) {
    // glslang wants a newline after `#include "x"`; editors leave it out.
    fs::path dir = freshTempDir("lastinclude");
    std::ofstream(dir / "Part.fxh") << "float4 PS() : COLOR0 { return 1; }";
    std::ofstream(dir / "Last.fx") << "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n#include \"Part.fxh\"";
    CompiledEffect e = compileEffectFile((dir / "Last.fx").string(), noCache());
    EXPECT_EQ(e.shaders.size(), 1u);
    fs::remove_all(dir);
}

// ---- 9. directory scans ------------------------------------------------------------------------

TEST(DirectoryScan, TakesEffectsInAnyCaseAndNeverHeadersAlone) {
    fs::path dir = freshTempDir("scan");
    const char* effect = "float4 PS() : COLOR0 { return 1; }\ntechnique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    for (const char* name : {"Lower.fx", "Mixed.Fx", "Upper.FX"}) std::ofstream(dir / name) << effect;
    for (const char* name : {"Shared.fxh", "Shared.FXH", "Common.hlsli"}) std::ofstream(dir / name) << "float4 Helper() { return 1; }\n";
    RunResult r = runCli("check --no-cache '" + dir.string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("Mixed.Fx: ok"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Upper.FX: ok"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("3 passed, 0 failed"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Shared"), std::string::npos) << r.output;
    // Named explicitly, a header is skipped with a reason, not failed as "no technique".
    r = runCli("check --no-cache '" + (dir / "Common.hlsli").string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("skipped: a header"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

// ---- 2. texture objects named in sampler blocks ---------------------------------------------------

TEST(TextureObjectsInSamplers, StayObjectsAndTakeTheSamplersState) {
    CompiledEffect e = compileEffectFile(kWild + "texture_objects/TextureInSampler.fx", noCache());
    EXPECT_EQ(param(e, "Tex").type, ParameterType::Texture2D);
    EXPECT_EQ(param(e, "Env").type, ParameterType::TextureCube);
    const CompiledShader& ps = e.shaders[size_t(e.techniques[0].passes[0].pixelShader.shaders[0])];
    bool texPoint = false, envCube = false;
    for (const auto& s : ps.samplers) {
        if (s.textureParameter == "Tex" && s.samplerName == "PointClamp")
            texPoint = s.state.minFilter == TextureFilter::Point && s.state.addressU == TextureAddress::Clamp;
        if (s.textureParameter == "Env" && s.samplerName == "EnvSampler") envCube = s.kind == TextureKind::TextureCube;
    }
    EXPECT_TRUE(texPoint) << reflectionJson(e);
    EXPECT_TRUE(envCube) << reflectionJson(e);
    expectAllPassesLink(e);
}

// ---- 5. pixel shaders without outputs -------------------------------------------------------------

TEST(PixelShaderWithoutOutput, DepthOnlyPassesTranslateForPs3AndSm4) {
    CompiledEffect e = compileEffectFile(kWild + "depth_only/DepthOnlyClip.fx", noCache());
    for (const auto& t : e.techniques) {
        const CompiledShader& ps = e.shaders[size_t(t.passes[0].pixelShader.shaders[0])];
        EXPECT_EQ(ps.outputTargets, 0) << t.name;
        EXPECT_NE(ps.glsl.find("discard"), std::string::npos) << t.name;
    }
    expectAllPassesLink(e);
    // ps_2_0 must write COLOR0 (fxc X4530): still FX1403, with fxc's reason.
    Diagnostic d = firstError("void PS(float2 uv : TEXCOORD0) { clip(uv.x); }\n"
                              "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n",
                              "virtual/Ps2.fx");
    EXPECT_EQ(d.id, diag::kBadEntrySignature);
    EXPECT_NE(d.message.find("X4530"), std::string::npos) << d.message;
}

// ---- 6. ColorWriteEnable spellings --------------------------------------------------------------

TEST(ColorWriteEnable, MonoGameAndFxcSpellingsBecomeMasks) {
    CompiledEffect e = compileEffectFile(kWild + "states/ColorWriteSpellings.fx", noCache());
    auto masks = [&](const std::string& pass) {
        std::vector<std::pair<int, int>> out;  // (target, mask)
        for (const auto& p : e.techniques[0].passes)
            if (p.name == pass)
                for (const auto& s : p.states)
                    if (s.state == RenderState::ColorWriteEnable) out.push_back({s.index, std::get<int>(s.value)});
        return out;
    };
    using M = std::vector<std::pair<int, int>>;
    EXPECT_EQ(masks("AllOn"), (M{{0, 15}}));
    EXPECT_EQ(masks("AllOff"), (M{{0, 0}}));
    EXPECT_EQ(masks("NoneOff"), (M{{0, 0}}));
    EXPECT_EQ(masks("RedGreen"), (M{{0, 3}}));
    EXPECT_EQ(masks("Numeric"), (M{{0, 8}}));
    EXPECT_EQ(masks("Targets"), (M{{0, 15}, {1, 0}, {2, 0}, {3, 15}}));
    expectAllPassesLink(e);
    Diagnostic d = firstError("float4 PS() : COLOR0 { return 1; }\n"
                              "technique T { pass P { PixelShader = compile ps_2_0 PS(); ColorWriteEnable = Purple; } }\n",
                              "virtual/Cwe.fx");
    EXPECT_EQ(d.id, diag::kBadStateValue);
    EXPECT_EQ(d.location.line, 2);
}

// ---- 3. #include "../x.fxh" inside an include root ------------------------------------------------

TEST(IncludeRoot, UpwardIncludesResolveInsideTheRootOnly) {
    const std::string root = "tests/fixtures/include_root";
    const std::string effect = root + "/Effects/Water/Water.fx";
    CompileOptions options = noCache();
    options.includeRoot = root;
    CompiledEffect e = compileEffectFile(effect, options);
    EXPECT_EQ(param(e, "LightDirection").declaredAt.file, root + "/Effects/Shared/Lighting.fxh");
    EXPECT_EQ(param(e, "LightDirection").declaredAt.line, 3);
    expectAllPassesLink(e);

    // No root (the default): the includes resolve wherever they lead, as with fxc.
    CompiledEffect unconfined = compileEffectFile(effect, noCache());
    EXPECT_EQ(param(unconfined, "LightDirection").declaredAt.file, root + "/Effects/Shared/Lighting.fxh");

    // The effect's own folder as the root: FX1103 at the #include, naming the resolved file and the option.
    options.includeRoot = root + "/Effects/Water";
    try {
        compileEffectFile(effect, options);
        FAIL() << "compiled outside its root";
    } catch (const CompileError& err) {
        const Diagnostic& d = err.diagnostics().front();
        EXPECT_EQ(d.id, diag::kIncludeOutside);
        EXPECT_EQ(d.location.file, effect);
        EXPECT_EQ(d.location.line, 2);
        EXPECT_NE(d.message.find(fs::absolute(root + "/Effects/Shared/Lighting.fxh").lexically_normal().string()), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("--root"), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("includeRoot"), std::string::npos) << d.message;
    }
    // A root that holds the sibling folder but not Common/: the second hop fails, in the header.
    options.includeRoot = root + "/Effects";
    try {
        compileEffectFile(effect, options);
        FAIL() << "compiled with a root that lacks Common/";
    } catch (const CompileError& err) {
        EXPECT_EQ(err.diagnostics().front().location.file, root + "/Effects/Shared/Lighting.fxh");
        EXPECT_EQ(err.diagnostics().front().location.line, 2);
    }
}

TEST(IncludeRoot, SymbolicLinksLeavingTheRootAreRefused) {
    fs::path dir = freshTempDir("symlink");
    fs::create_directories(dir / "root" / "fx");
    fs::create_directories(dir / "elsewhere");
    std::ofstream(dir / "elsewhere" / "Secret.fxh") << "float4 Secret() { return 1; }\n";
    fs::create_symlink(dir / "elsewhere" / "Secret.fxh", dir / "root" / "Linked.fxh");
    std::ofstream(dir / "root" / "fx" / "Uses.fx") << "#include \"../Linked.fxh\"\nfloat4 PS() : COLOR0 { return Secret(); }\n"
                                                     "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
    CompileOptions options = noCache();
    options.includeRoot = (dir / "root").string();
    try {
        compileEffectFile((dir / "root" / "fx" / "Uses.fx").string(), options);
        FAIL() << "a symbolic link out of the root was followed";
    } catch (const CompileError& err) {
        EXPECT_EQ(err.diagnostics().front().id, diag::kIncludeOutside);
        EXPECT_NE(err.diagnostics().front().message.find("elsewhere"), std::string::npos) << err.what();
    }
    fs::remove_all(dir);
}

TEST(IncludeRoot, CheckConfinesOnlyWithARoot) {
    RunResult r = runCli("check --no-cache tests/fixtures/include_root");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("Water.fx: ok"), std::string::npos) << r.output;
    r = runCli("check --no-cache tests/fixtures/include_root/Effects/Water/Water.fx");
    EXPECT_EQ(r.status, 0) << r.output;
    r = runCli("check --no-cache --root tests/fixtures/include_root/Effects/Water tests/fixtures/include_root/Effects/Water/Water.fx");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("Water.fx(2,11): error FX1103"), std::string::npos) << r.output;
    r = runCli("check --no-cache --root tests/fixtures/include_root tests/fixtures/include_root/Effects/Water/Water.fx");
    EXPECT_EQ(r.status, 0) << r.output;
}

// ---- 4. implicit conversions in calls -----------------------------------------------------------

TEST(ImplicitConversions, VectorToScalarTruncationAndPromotionTranslateWithFxcWarnings) {
    const std::string path = kWild + "conversions/ImplicitConversions.fx";
    CompiledEffect e = compileEffectFile(path, noCache());
    std::vector<std::pair<int, std::string>> warnings;
    for (const auto& d : e.diagnostics)
        if (d.id == diag::kImplicitConversion) {
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_EQ(d.location.file, path);
            EXPECT_NE(d.message.find("implicit truncation of vector type"), std::string::npos) << d.message;
            EXPECT_NE(d.message.find("X3206"), std::string::npos) << d.message;
            warnings.push_back({d.location.line, d.message.substr(d.message.find("argument"))});
        }
    using W = std::vector<std::pair<int, std::string>>;
    EXPECT_EQ(warnings, (W{{27, "argument 1 of 'HalfOf' is float4, parameter 'x' is float; its first component is used"},
                           {28, "argument 1 of 'Scale' is float3, parameter 'v' is float2; its first components are used"},
                           {28, "argument 2 of 'Scale' is float4, parameter 's' is float; its first component is used"}}));
    expectAllPassesLink(e);
}

// fxc warns X3206 where an initialization truncates too (`float2 uv = input.TexCoord4;`), at the
// variable; a swizzle of as many components, or a wider target, is no truncation.
TEST(ImplicitConversions, TruncatingInitializationsGetFxcWarning) {
    CompiledEffect e = compileEffectSource("struct VSIn { float4 TexCoord4 : TEXCOORD0; float3 n : NORMAL; };\nfloat4 Tint;\n"
                                           "float4 PS(VSIn input) : COLOR0 {\n    float2 uv = input.TexCoord4;\n    float s = Tint, k = 2;\n"
                                           "    float4 wide = input.n.xyzz; float2 fine = input.TexCoord4.xy;\n"
                                           "    return float4(uv, s, wide.x + fine.x + k);\n}\n"
                                           "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n",
                                           "virtual/Truncation.fx", noCache());
    std::vector<std::pair<int, std::string>> warnings;
    for (const auto& d : e.diagnostics)
        if (d.id == diag::kImplicitConversion) warnings.push_back({d.location.line, d.message});
    using W = std::vector<std::pair<int, std::string>>;
    EXPECT_EQ(warnings, (W{{4, "implicit truncation of vector type (fxc X3206): 'uv' is float2, initialised from float4; its first components are used"},
                           {5, "implicit truncation of vector type (fxc X3206): 's' is float, initialised from float4; its first component is used"}}));
    expectAllPassesLink(e);
}

TEST(ImplicitConversions, CallsThatResolvedBeforeAreUntouchedAndRealErrorsStay) {
    // An overload the effect declares itself is chosen, not a generated one: no warning.
    CompiledEffect e = compileEffectSource("float f(float x) { return x; }\nfloat f(float4 x) { return x.w; }\n"
                                           "float4 PS(float4 c : COLOR0) : COLOR0 { return f(c); }\n"
                                           "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n",
                                           "virtual/Own.fx", noCache());
    for (const auto& d : e.diagnostics) EXPECT_NE(d.id, diag::kImplicitConversion) << d.format();
    EXPECT_NE(e.shaders[0].glsl.find(".w"), std::string::npos) << e.shaders[0].glsl;
    // A call no conversion can fix (a struct where a float goes) is still FX2001 at its line.
    Diagnostic d = firstError("struct S { float a; };\nfloat f(float x) { return x; }\n"
                              "float4 PS(float4 c : COLOR0) : COLOR0 { S s; s.a = 1; return f(s); }\n"
                              "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n",
                              "virtual/Bad.fx");
    EXPECT_EQ(d.id, diag::kHlsl);
    EXPECT_EQ(d.location.line, 3);
}

// ---- 8. loose shader files by entry point and profile -------------------------------------------

TEST(LooseShaderFiles, EntryPointsOfOneFileShareItsCBuffer) {
    const std::string path = kWild + "loose/Combined.hlsl";
    CompiledEffect e = compileShaderFiles({{path, "VSMain", "vs_4_0"}, {path, "PSMain", "ps_4_0"}}, noCache());
    ASSERT_EQ(e.techniques.size(), 1u);
    EXPECT_EQ(e.techniques[0].name, "VSMain+PSMain");
    ASSERT_EQ(e.techniques[0].passes.size(), 1u);
    EXPECT_EQ(e.shaders.size(), 2u);
    const Parameter& color = param(e, "Color");
    EXPECT_EQ(e.uniformBlocks[size_t(color.block)].name, "PerFrame");
    EXPECT_GE(color.offset, 0);
    expectAllPassesLink(e);
}

TEST(LooseShaderFiles, SeparateFilesMergeIntoOnePassWithEveryCBufferMember) {
    CompiledEffect e = compileShaderFiles({{kWild + "loose/Textured.vs", "TexturedVertexShader", "vs_5_0"},
                                           {kWild + "loose/Textured.ps", "TexturedPixelShader", "ps_5_0"}},
                                          noCache());
    const Pass& pass = e.techniques.at(0).passes.at(0);
    ASSERT_EQ(pass.vertexShader.shaders.size(), 1u);
    ASSERT_EQ(pass.pixelShader.shaders.size(), 1u);
    EXPECT_EQ(e.shaders[size_t(pass.vertexShader.shaders[0])].profile.name, "vs_5_0");
    EXPECT_EQ(e.shaders[size_t(pass.pixelShader.shaders[0])].profile.name, "ps_5_0");
    for (const char* name : {"worldMatrix", "viewMatrix", "projectionMatrix", "vertexTint", "diffuseColor"}) {
        const Parameter& p = param(e, name);
        EXPECT_GE(p.offset, 0) << name;
        EXPECT_GT(e.uniformBlocks.at(size_t(p.block)).size, 0) << name;
    }
    EXPECT_EQ(e.uniformBlocks[size_t(param(e, "diffuseColor").block)].name, "LightBuffer");
    // Round trip through the compiled-effect file, as `fxport compile` writes it.
    CompiledEffect back = deserializeEffect(serializeEffect(e), "memory");
    EXPECT_EQ(reflectionJson(back), reflectionJson(e));
    expectAllPassesLink(e);
}

// fxc /T ps_4_0 parses a variable's state block and ignores it: fxport compiles such a file, with a
// warning at each state it cannot honour there, and keeps the state it can (the sampler's filter).
TEST(LooseShaderFiles, StateBlocksAreIgnoredWithALocatedWarning) {
    CompiledEffect e = compileShaderFiles({{kWild + "loose/StateBlocks.ps", "ShadePixel", "ps_4_0"}}, noCache());
    bool unknownState = false, ignoredBlock = false;
    for (const auto& d : e.diagnostics) {
        if (d.severity != Severity::Warning) continue;
        unknownState |= d.message.find("unknown sampler state 'BorderTint'") != std::string::npos && d.location.line == 7;
        ignoredBlock |= d.message.find("state block of 'Tint' is ignored") != std::string::npos && d.location.line == 10;
    }
    EXPECT_TRUE(unknownState) << "no warning at line 7 for BorderTint";
    EXPECT_TRUE(ignoredBlock) << "no warning at line 10 for Tint's block";
    expectAllPassesLink(e);
}

// What fxc still checks in an ignored state block stays an error, at its line.
TEST(LooseShaderFiles, StateBlockValuesFxcRefusesAreErrors) {
    try {
        compileShaderFiles({{kWild + "loose/StateBlockCall.ps", "ShadePixel", "ps_4_0"}}, noCache());
        FAIL() << "compiled a state block that calls Weights with one argument";
    } catch (const CompileError& err) {
        const Diagnostic& d = err.diagnostics().front();
        EXPECT_EQ(d.location.line, 8) << d.message;
        EXPECT_NE(d.message.find("no overload of 'Weights' takes 1 parameters"), std::string::npos) << d.message;
    }
}

TEST(LooseShaderFiles, OptionErrorsNameTheOptionAndLooseFilesWithoutEntrySayIt) {
    const std::string ps = kWild + "loose/Textured.ps";
    auto firstOf = [](const std::vector<ShaderEntry>& entries) {
        try {
            compileShaderFiles(entries, noCache());
        } catch (const CompileError& e) {
            return e.diagnostics().front();
        }
        return Diagnostic{};
    };
    Diagnostic missing = firstOf({{ps, "NoSuchFunction", "ps_5_0"}});
    EXPECT_EQ(missing.id, diag::kMissingEntry);
    EXPECT_NE(missing.message.find("'NoSuchFunction' (--entry, fxc /E)"), std::string::npos) << missing.message;
    Diagnostic profile = firstOf({{ps, "TexturedPixelShader", "ps_9_9"}});
    EXPECT_EQ(profile.id, diag::kBadProfile);
    EXPECT_NE(profile.message.find("'ps_9_9' (--profile, fxc /T)"), std::string::npos) << profile.message;
    // Without an entry point: a loose file says so and lists its candidates.
    try {
        compileEffectFile(ps, noCache());
        FAIL() << "compiled without an entry point";
    } catch (const CompileError& err) {
        const Diagnostic& d = err.diagnostics().front();
        EXPECT_NE(d.message.find("loose shader file"), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("--entry NAME --profile"), std::string::npos) << d.message;
        EXPECT_NE(d.message.find("TexturedPixelShader"), std::string::npos) << d.message;
        EXPECT_EQ(d.message.find("no technique: it looks like a header"), std::string::npos) << d.message;
    }
    // Two files whose globals of one name sit at different places: one parameter cannot feed both.
    fs::path dir = freshTempDir("loose");
    std::ofstream(dir / "a.vs") << "float4 Shared; float4 OnlyA;\nfloat4 VS(float4 p : POSITION) : SV_Position { return p * OnlyA * Shared; }\n";
    std::ofstream(dir / "b.ps") << "float4 Shared;\nfloat4 PS() : SV_Target { return Shared; }\n";
    Diagnostic clash = firstOf({{(dir / "a.vs").string(), "VS", "vs_4_0"}, {(dir / "b.ps").string(), "PS", "ps_4_0"}});
    EXPECT_NE(clash.message.find("'Shared'"), std::string::npos) << clash.message;
    fs::remove_all(dir);
}

TEST(LooseShaderFiles, CommandLineTakesEntryAndProfile) {
    const std::string path = kWild + "loose/Combined.hlsl";
    RunResult r = runCli("check --no-cache '" + path + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("loose shader file"), std::string::npos) << r.output;
    fs::path out = freshTempDir("loosecli") / "Combined.json";
    r = runCli("compile --no-cache --entry VSMain --profile vs_4_0 --entry PSMain --profile ps_4_0 '" + path + "' -o '" + out.string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    CompiledEffect e = loadEffectFile(out.string());
    EXPECT_EQ(e.techniques.at(0).name, "VSMain+PSMain");
    r = runCli("check --no-cache --entry VSMain '" + path + "'");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("needs a --profile"), std::string::npos) << r.output;
    fs::remove_all(out.parent_path());
}

// `#include <..\Shared\Lighting.fxh>`: backslashes are folder separators, as on Windows.
TEST(IncludeRoot, BackslashSeparatorsAreFolders) {
    const std::string root = "tests/fixtures/include_root";
    CompileOptions options = noCache();
    options.includeRoot = root;
    CompiledEffect e = compileEffectFile(root + "/Effects/Windows/BackslashPaths.fx", options);
    EXPECT_EQ(param(e, "LightDirection").declaredAt.file, root + "/Effects/Shared/Lighting.fxh");
    expectAllPassesLink(e);
}
