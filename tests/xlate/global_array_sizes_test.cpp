// A global array's size check (xlate/src/frontend/front_end_hazards.cpp, fixed on main in d2d01db)
// reads its size only: an initialised array sized by an undeclared name is fxc's X3004 (glslang
// crashed on it), whereas a semantic, register or annotation after the `]` names no global —
// `float4 C[3] : Diffuse = {...}` is how XNA-era effects declare light colours (randomchaos'
// ADCMultiLight.fx was refused with "undeclared identifier 'Diffuse' in the size of array").
#include <gtest/gtest.h>

#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

const char* const kUse = "float4 PS() : COLOR0 { return C[1] + W[0]; }\n"
                         "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";

CompiledEffect compile(const std::string& declarations) {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + kUse, "virtual/ArraySizes.fx", o);
}

}  // namespace

TEST(GlobalArraySizes, SemanticRegisterAndAnnotationAfterTheSizeAreNotSizes) {
    CompiledEffect e = compile("#define N 3\n"
                               "float4 C[N] : Diffuse = {float4(1,0,0,1), float4(0,1,0,1), float4(0,0,1,1)};\n"
                               "float W[2] : register(c8) < string UIName = \"Weights\"; > = {0.25, 0.75};\n");
    const Parameter* c = e.findParameter("C");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->elements, 3);
    EXPECT_EQ(c->semantic, "DIFFUSE");
    EXPECT_EQ(c->defaultValue, (std::vector<double>{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1}));
    const Parameter* w = e.findParameter("W");
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->elements, 2);
    EXPECT_EQ(w->defaultValue, (std::vector<double>{0.25, 0.75}));
}

TEST(GlobalArraySizes, AnUndeclaredNameInTheSizeIsStillRefused) {
    try {
        compile("float4 C[2];\nstatic const float W[Nope + 1] = {1, 2};\n");
        ADD_FAILURE() << "compiled";
    } catch (const CompileError& error) {
        const Diagnostic& d = error.diagnostics().front();
        EXPECT_EQ(d.location.line, 2);
        EXPECT_NE(d.message.find("undeclared identifier 'Nope' in the size of array 'W'"), std::string::npos) << d.message;
    }
}

// array-size-expr L71: fxc sizes an array by a constant read through a struct member, a matrix
// row, matrix and vector swizzles (a.m[1] is rows (1 1 1)(1 5 1); ._13_22_21 is (1, 5, 1), .zxy.z
// is 5), and by a vector constant's components or a constant array's element (an int: 7.9 is 7).
// The parameters have those sizes; a local array's size is a literal glslang takes.
TEST(GlobalArraySizes, SizesReadThroughStructMembersAndSwizzles) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(
        "static const struct { float f; float2x3 m[2]; } a = {0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 5, 1};\n"
        "static const int2 S = int2(3, 2);\nstatic const int w[3] = {1, 2, 7.9};\n"
        "float C[a.m[1]._13_22_21.zxy.z];\nfloat W[S.x * S.y + w[2]];\n"
        "float4 PS() : COLOR0 { float l[a.m[1][1].y + S.y]; l[6] = C[4]; return l[6] + W[12]; }\n"
        "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n",
        "virtual/ArraySizes.fx", o);
    const Parameter* c = e.findParameter("C");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->elements, 5);
    const Parameter* w = e.findParameter("W");
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->elements, 13);
}
