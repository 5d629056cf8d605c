// Stream output in xlate (issue 24/25): ConstructGSWithSO's declaration strings parsed as the D3D10/11
// effect runtimes parse them, resolved to the GLSL variables the geometry (or vertex) shader writes,
// kept through the compiled-effect file, and bad declarations refused at their file:line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "fxport/xlate/stream_output.h"

using namespace fxport::xlate;

namespace {

// A geometry shader whose output has a float4, a float, a uint and SV_Position.
const char* kShaders = R"(struct VSOut { float3 pos : POSITION; float counter : COUNTER; };
struct GSOut { float4 pos : POSITION; float counter : COUNTER; uint id : ID; float4 sv : SV_Position; };
VSOut VS(VSOut v) { return v; }
[maxvertexcount(2)]
void GS(point VSOut input[1], inout PointStream<GSOut> stream) {
    GSOut o;
    o.pos = float4(input[0].pos * 2 + 1, 1);
    o.counter = input[0].counter + 1;
    o.id = 7;
    o.sv = float4(0, 0, 0, 1);
    stream.Append(o);
}
)";

// The effect with `gs` as the geometry-shader variable's initializer (line 13).
std::string effectWith(const std::string& gs) {
    return std::string(kShaders) + "GeometryShader gsSO = " + gs + ";\n" +
           "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(gsSO); SetPixelShader(NULL); } }\n";
}

const CompiledShader& passGeometryShader(const CompiledEffect& e) {
    const Pass& p = e.techniques.at(0).passes.at(0);
    EXPECT_TRUE(p.valid);
    return e.shaders.at(static_cast<size_t>(p.geometryShader.shaders.at(0)));
}

// The first error of compiling `source` (fatal or confined to a pass).
Diagnostic firstError(const std::string& source) {
    try {
        CompiledEffect e = compileEffectSource(source, "so.fx");
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return d;
    } catch (const CompileError& error) {
        return error.diagnostics().at(0);
    }
    return {};
}

}  // namespace

TEST(StreamOutputDeclaration, ParsesSlotsSemanticIndicesMasksAndGaps) {
    std::vector<StreamOutputEntry> entries;
    std::string error;
    ASSERT_TRUE(parseStreamOutputDeclaration(" POSITION.xyz; TEXCOORD3.y;$SKIP.xy; 2:COLOR.rgba ; NORMAL;", 1, entries, error)) << error;
    ASSERT_EQ(entries.size(), 5u);
    auto is = [&](size_t i, const char* name, int index, int start, int count, int slot) {
        SCOPED_TRACE(i);
        EXPECT_EQ(entries[i].semanticName, name);
        EXPECT_EQ(entries[i].semanticIndex, index);
        EXPECT_EQ(entries[i].startComponent, start);
        EXPECT_EQ(entries[i].componentCount, count);
        EXPECT_EQ(entries[i].outputSlot, slot);
        EXPECT_EQ(entries[i].stream, 1);
    };
    is(0, "POSITION", 0, 0, 3, 0);
    is(1, "TEXCOORD", 3, 1, 1, 0);
    is(2, "", 0, 0, 2, 0);  // $SKIP
    is(3, "COLOR", 0, 0, 4, 2);
    is(4, "NORMAL", 0, 0, 4, 0);  // no mask: four components
}

TEST(StreamOutputDeclaration, RefusesMasksThatAreNoRunAndSlotsOutOfRange) {
    for (const char* bad : {"POSITION.xz", "POSITION.q", "POSITION.", "4:POSITION", ":POSITION", "x1:POSITION", "POS-ITION"}) {
        std::vector<StreamOutputEntry> entries;
        std::string error;
        EXPECT_FALSE(parseStreamOutputDeclaration(bad, 0, entries, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(StreamOutputDeclaration, CapturedVaryingsInterleaveSlotsWithNextBufferAndSkips) {
    StreamOutput so;
    std::string error;
    ASSERT_TRUE(parseStreamOutputDeclaration("A.xyz; $SKIP.xyzw; $SKIP.xy; 2:B.x", 0, so.entries, error));
    std::vector<ShaderOutput> outputs{{"A0", "a_var", 3}, {"B0", "b_var", 1}};
    so.strides[2] = 8;  // a stride past its entries pads the vertex
    ASSERT_TRUE(resolveStreamOutput(outputs, so, error)) << error;
    EXPECT_EQ(so.strides[0], 36);  // 3 + 4 + 2 floats
    EXPECT_EQ(so.strides[1], 0);
    EXPECT_EQ(capturedVaryings(so), (std::vector<std::string>{"a_var", "gl_SkipComponents4", "gl_SkipComponents2", "gl_NextBuffer",
                                                               "gl_NextBuffer", "b_var", "gl_SkipComponents1"}));
}

TEST(StreamOutputEffect, GeometryShaderCarriesTheResolvedDeclaration) {
    CompiledEffect e = compileEffectSource(effectWith("ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyzw; COUNTER.x; 1:ID.x\")"),
                                           "so.fx");
    const CompiledShader& gs = passGeometryShader(e);
    ASSERT_EQ(gs.streamOutput.entries.size(), 3u);
    EXPECT_EQ(gs.outputPrimitiveVertices, 1);
    EXPECT_EQ(gs.streamOutput.strides, (std::array<int, 4>{20, 4, 0, 0}));
    for (const auto& entry : gs.streamOutput.entries) {
        EXPECT_FALSE(entry.varying.empty());
        EXPECT_NE(gs.glsl.find(" " + entry.varying + ";"), std::string::npos) << entry.varying << " is not declared in\n" << gs.glsl;
    }
    const std::vector<std::string> names = capturedVaryings(gs.streamOutput);
    ASSERT_EQ(names.size(), 4u);
    EXPECT_EQ(names[2], "gl_NextBuffer");
}

TEST(StreamOutputEffect, Effects11FormTakesFourStreamsAndTheRasterizedStream) {
    CompiledEffect e = compileEffectSource(
        effectWith("ConstructGSWithSO(CompileShader(gs_5_0, GS()), \"0:SV_POSITION.xyzw; 0:COUNTER.x\", NULL, NULL, NULL, -1)"), "so.fx");
    const CompiledShader& gs = passGeometryShader(e);
    ASSERT_EQ(gs.streamOutput.entries.size(), 2u);
    EXPECT_EQ(gs.streamOutput.entries[0].varying, "gl_Position");
    EXPECT_EQ(gs.streamOutput.rasterizedStream, kNoRasterizedStream);
}

TEST(StreamOutputEffect, StreamingAVertexShaderRunsItWithTheDeclarationAndNoGeometryShader) {
    std::string source = std::string(kShaders) +
                         "VertexShader vs = CompileShader(vs_4_0, VS());\n"
                         "GeometryShader gsSO = ConstructGSWithSO(vs, \"POSITION.xyz; COUNTER.x\");\n"
                         "technique10 T { pass P { SetVertexShader(vs); SetGeometryShader(gsSO); SetPixelShader(NULL); } }\n";
    CompiledEffect e = compileEffectSource(source, "so.fx");
    const Pass& p = e.techniques.at(0).passes.at(0);
    ASSERT_TRUE(p.valid);
    EXPECT_TRUE(p.geometryShader.shaders.empty());
    const CompiledShader& vs = e.shaders.at(static_cast<size_t>(p.vertexShader.shaders.at(0)));
    EXPECT_EQ(vs.profile.stage, ShaderStage::Vertex);
    ASSERT_EQ(vs.streamOutput.entries.size(), 2u);
    EXPECT_EQ(vs.streamOutput.strides[0], 16);
}

TEST(StreamOutputEffect, TheDeclarationSurvivesTheEffectFileAndAForgedOneIsRefused) {
    CompiledEffect e = compileEffectSource(effectWith("ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyzw; $SKIP.x; ID.x\")"), "so.fx");
    CompiledEffect back = deserializeEffect(serializeEffect(e), "so.fxeffect");
    EXPECT_EQ(passGeometryShader(back).streamOutput, passGeometryShader(e).streamOutput);
    EXPECT_EQ(passGeometryShader(back).outputs.size(), passGeometryShader(e).outputs.size());

    const int gs = e.techniques[0].passes[0].geometryShader.shaders[0];
    CompiledEffect forged = e;
    forged.shaders[static_cast<size_t>(gs)].streamOutput.entries[0].varying = "gl_Position";  // not POSITION's variable
    EXPECT_THROW(deserializeEffect(serializeEffect(forged), "forged.fxeffect"), CompileError);
    forged = e;
    forged.shaders[static_cast<size_t>(gs)].streamOutput.entries[0].componentCount = 5;
    EXPECT_THROW(deserializeEffect(serializeEffect(forged), "forged.fxeffect"), CompileError);
}

TEST(StreamOutputEffect, BadDeclarationsAreRefusedAtTheirLine) {
    struct Case {
        const char* gs;
        const char* says;
    };
    const Case cases[] = {
        {"ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyzw; NOSUCH.x\")", "no output with semantic NOSUCH0"},
        {"ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"COUNTER.xy\")", "output COUNTER0 has 1 component"},
        {"ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xw\")", "invalid component mask 'xw'"},
        {"ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"7:POSITION\")", "invalid output slot '7'"},
        {"ConstructGSWithSO(CompileShader(gs_4_0, GS()), \"POSITION.xyz\")", "captures an output whole"},
        {"ConstructGSWithSO(CompileShader(gs_5_0, GS()), NULL, \"COUNTER.x\", NULL, NULL, 0)", "stream 0 only"},
        {"ConstructGSWithSO(CompileShader(gs_5_0, GS()), \"COUNTER.x\", NULL, NULL, NULL, 9)", "rasterized stream 9"},
        {"ConstructGSWithSO(CompileShader(gs_5_0, GS()), \"COUNTER.x\", NULL, NULL, NULL, 1)", "rasterizes stream 0 only"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.gs);
        Diagnostic d = firstError(effectWith(c.gs));
        EXPECT_EQ(d.id, diag::kBadStreamOutput);
        EXPECT_NE(d.message.find(c.says), std::string::npos) << d.message;
        EXPECT_EQ(d.location.line, 13) << d.format();
        EXPECT_NE(d.location.file.find("so.fx"), std::string::npos) << d.format();
    }
}
