// Declarations fxc takes in spellings glslang does not (fx_parser.cpp): `f(void)` for no
// parameters, and the `export` linkage modifier on a function. vkd3d's function file has both,
// with probes; these tests make the parser's part fail here first.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

std::string compileError(const std::string& source) {
    CompileOptions o;
    o.useCache = false;
    try {
        CompiledEffect e = compileEffectSource(source + "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                                               "virtual/Declarations.fx", o);
        for (const auto& d : e.diagnostics)
            if (d.severity == Severity::Error) return d.message;
        return e.techniques.at(0).passes.at(0).pixelShader.shaders.empty() ? "no pixel shader" : "";
    } catch (const CompileError& error) {
        return error.diagnostics().front().message;
    }
}

}  // namespace

TEST(DeclarationSpellings, VoidParameterListMeansNoParameters) {
    EXPECT_EQ(compileError("float2 halves(void);\nfloat2 twice(void) { return 2 * halves(); }\nfloat2 halves(void) { return 0.5; }\n"
                           "float4 PS() : SV_Target { return float4(twice(), 0, 1); }\n"),
              "");
}

TEST(DeclarationSpellings, ExportedFunctionCompiles) {
    EXPECT_EQ(compileError("export float helper(float x) { return x * 2; }\nexport float4 PS() : SV_Target { return helper(0.5); }\n"), "");
}
