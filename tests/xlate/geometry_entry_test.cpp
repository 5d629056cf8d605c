// Geometry shader entries as fxc takes them (xlate/src/rewrite/geometry_output_stream.h,
// geometry_input_rules.cpp): an entry without an output stream compiles (it emits nothing), an
// unused stream beside the one written is not validated, and fxc's input rules are enforced at
// the entry's line: maxvertexcount in 1..1024, one kind of input primitive, primitive modifiers
// only on a geometry shader's parameters. vkd3d's geometry-shader-syntax pins the same cases.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

const char* const kCommon = R"(
struct V { float4 pos : SV_Position; };
V VS(float4 pos : POSITION) { V v; v.pos = pos; return v; }
float4 PS(V v) : SV_Target { return 1; }
)";

std::string effect(const std::string& gs) {
    return std::string(kCommon) + gs +
           "\ntechnique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS()));\n"
           "                         SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
}

// The first error of compiling `source` ("" when it compiles), as "line: message".
std::string firstError(const std::string& source) {
    CompileOptions o;
    o.useCache = false;
    try {
        CompiledEffect e = compileEffectSource(source, "virtual/Geometry.fx", o);
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return std::to_string(d.location.line) + ": " + d.message;
        if (e.techniques.empty() || e.techniques[0].passes.empty() || e.techniques[0].passes[0].geometryShader.shaders.empty())
            return "no geometry shader";
        return "";
    } catch (const CompileError& error) {
        const Diagnostic& d = error.diagnostics().front();
        return std::to_string(d.location.line) + ": " + d.message;
    }
}

}  // namespace

TEST(GeometryEntry, EntryWithoutOutputStreamCompiles) {
    EXPECT_EQ(firstError(effect("[maxvertexcount(4)] void GS(triangle V v[3]) { }")), "");
    EXPECT_EQ(firstError(effect("[maxvertexcount(1024)] void GS(point V v[1]) { }")), "");
}

TEST(GeometryEntry, UnusedStreamBesideTheWrittenOneIsNotValidated) {
    EXPECT_EQ(firstError(effect("[maxvertexcount(3)] void GS(triangle V v[3], inout PointStream<V> used, inout TriangleStream<V> unused)\n"
                                "{ used.Append(v[0]); }")),
              "");
    EXPECT_EQ(firstError(effect("[maxvertexcount(3)] void GS(inout TriangleStream<V> used, triangle V v[3], inout LineStream<V> unused)\n"
                                "{ used.Append(v[0]); }")),
              "");
}

TEST(GeometryEntry, MaxVertexCountOutsideItsRangeIsRefused) {
    // Line 5: the entry, after kCommon's four lines.
    EXPECT_EQ(firstError(effect("[maxvertexcount(0)] void GS(point V v[1]) { }")), "5: maxvertexcount(0) of 'GS' is outside 1..1024");
    EXPECT_EQ(firstError(effect("[maxvertexcount(1025)] void GS(point V v[1]) { }")), "5: maxvertexcount(1025) of 'GS' is outside 1..1024");
}

TEST(GeometryEntry, InputPrimitivesOfTwoKindsAreRefused) {
    std::string error = firstError(effect("[maxvertexcount(4)] void GS(line V a[2], triangle V b[3]) { }"));
    EXPECT_NE(error.find("every input primitive of a geometry shader has one kind and vertex count"), std::string::npos) << error;
}

TEST(GeometryEntry, PrimitiveModifierOutsideAGeometryEntryIsRefused) {
    std::string member = firstError(std::string("struct S { line float4 val[2]; };\nstruct S x;\n") +
                                    effect("[maxvertexcount(4)] void GS(point V v[1]) { }"));
    EXPECT_NE(member.find("'line' on member 'val' of struct 'S'"), std::string::npos) << member;
    std::string pixel = firstError(std::string(kCommon) + "float4 PS2(point V v[1]) : SV_Target { return 0; }\n"
                                   "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS2())); } }\n");
    EXPECT_NE(pixel.find("only a geometry shader takes an input primitive"), std::string::npos) << pixel;
}
