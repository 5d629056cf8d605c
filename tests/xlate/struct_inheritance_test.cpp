// `struct b : a { ... }` as fxc takes it (fx_parser.cpp parseStructBase / inheritMembers): the
// base's members come first in the layout, a member the derived struct shadows keeps its place,
// and the base must be exactly one struct declared before. vkd3d's struct-inheritance file has the
// same shaders; its probes set a struct uniform, which the conformance runner skips, so the layout
// is pinned here.
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

CompiledEffect compile(const std::string& declarations, const std::string& body) {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + "float4 PS() : SV_Target { " + body +
                                   " }\ntechnique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                               "virtual/StructInheritance.fx", o);
}

const char* const kChain = R"(
struct a { float4 aa; float4 bb; };
struct b : a { float4 cc; };
struct c : b { float4 bb; };  // shadows a.bb
)";

std::string errorOf(const std::string& declarations) {
    try {
        compile(declarations, "return 0;");
    } catch (const CompileError& e) {
        return e.diagnostics().front().message;
    }
    return "";
}

}  // namespace

// `d.bb = 2` assigns a member named like a swizzle (no X3018 for it).
TEST(StructInheritance, BaseMembersComeFirstAndShadowedOnesKeepTheirPlace) {
    CompiledEffect e = compile(std::string(kChain) + "c data;\n", "c d = data; d.aa.x = -1; d.bb = 2; return d.aa + d.bb + d.cc;");
    const Parameter* data = nullptr;
    for (const auto& p : e.parameters)
        if (p.name == "data") data = &p;
    ASSERT_NE(data, nullptr);
    ASSERT_EQ(data->members.size(), 4u);
    EXPECT_EQ(data->members[0].name, "aa");
    EXPECT_EQ(data->members[2].name, "cc");
    EXPECT_EQ(data->members[3].name, "bb");  // c's own, read by data.bb
    EXPECT_EQ(data->size, 64);
}

TEST(StructInheritance, BaseMustBeOneStructDeclaredBefore) {
    EXPECT_EQ(errorOf("struct a : float4 { float4 aa; };\n"), "the base of struct 'a' must be a struct declared before it; 'float4' is not");
    EXPECT_EQ(errorOf("struct a { float4 aa; };\nstruct b { float4 bb; };\nstruct c : a, b { float4 cc; };\n"),
              "struct 'c' names more than one base struct; fxc takes one");
}
