// fxc's choice among the effect's own overloads where glslang's differs (rewrite/overload_choices):
// half, double and the minimum-precision types ranked apart from float, int and uint, by the
// worst conversion an overload needs. Each case is a section of vkd3d's function-overload (the
// line named), whose expected value is fxc's pick: the overload fxc picks returns 0.75, the other
// 0.25, and the pixel shader's GLSL must return the one and hold no trace of the other.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

struct ChoiceCase {
    const char* name;
    const char* picked;  // the overload fxc calls: returns 0.75
    const char* other;   // returns 0.25
    const char* call;    // main's body before `return`, then the call
};

void PrintTo(const ChoiceCase& c, std::ostream* os) { *os << c.name; }

std::string source(const ChoiceCase& c, bool pickedFirst) {
    std::string picked = std::string("float4 ") + c.picked + " { return 0.75; }\n";
    std::string other = std::string("float4 ") + c.other + " { return 0.25; }\n";
    return (pickedFirst ? picked + other : other + picked) + "float4 main() : sv_target\n{\n    " + c.call + "\n}\n";
}

std::vector<ChoiceCase> cases() {
    return {
        // L283: int narrows to min16int rather than change class to float.
        {"NarrowingBeatsClassChange", "func(min16int x)", "func(float x)", "return func(int(0));"},
        // L310, L333: a sign change beats narrowing to a minimum-precision int.
        {"SignChangeBeatsIntNarrowing", "func(uint x)", "func(min16int x)", "return func(int(0));"},
        {"SignChangeBeatsUintNarrowing", "func(int x)", "func(min16uint x)", "return func(uint(0));"},
        // L355: min16int and int are two functions; the exact one wins.
        {"ExactMinimumPrecision", "f(min16int x)", "f(int x)", "return f(min16int(0));"},
        // L379: float promotes to double rather than change class to int.
        {"PromotionBeatsClassChange", "func(double x)", "func(int x)", "return func(float(0));"},
        // L401, L415, L429: promotion (with widening) beats narrowing and class change.
        {"PromotionBeatsNarrowing", "f(double x)", "f(half x)", "return f(float(0.0));"},
        {"WideningPromotionBeatsNarrowing", "f(double2 x)", "f(half x)", "return f(float(0.0));"},
        {"WideningPromotionBeatsClassChange", "f(double2 x)", "f(int x)", "return f(float(0.0));"},
        // L543: widening float to float2 beats promotion to double.
        {"WideningBeatsPromotion", "func(float2 x)", "func(double x)", "return func(float(0));"},
        // L448: the worst step decides: count narrowing (float4 -> float2) loses to narrowing to half
        // plus a class change (float -> int).
        {"WorstStepDecides", "func(half4 x, int y)", "func(float2 x, double y)", "float4 x = 0.0;\n    float y = 0.0;\n    return func(x, y);"},
        // L471: a class change (float -> int) loses to sign change plus promotion.
        {"ClassChangeLoses", "func(uint4 x, double y)", "func(int4 x, int y)", "int x = 0.0;\n    float y = 0.0;\n    return func(x, y);"},
        // L517: narrowing four arguments to half beats one count narrowing.
        {"CountNarrowingIsWorst", "func(half4 x, half y, half z, half a)", "func(float2 x, double y, double z, double a)",
         "float4 x = 0.0;\n    float y = 0.0;\n    return func(x, y, y, y);"},
        // refract L207: an intrinsic of half arguments only is half (the half4 overload takes it);
        // one float argument makes it float.
        {"HalfIntrinsicStaysHalf", "detect(half4 x)", "detect(float4 x)",
         "half4 r = 0;\n    half4 n = 0;\n    half i = 0;\n    return detect(refract(r, n, i));"},
        {"MixedIntrinsicIsFloat", "detect(float4 x)", "detect(half4 x)",
         "float4 r = 0;\n    half4 n = 0;\n    half i = 0;\n    return detect(refract(r, n, i));"},
    };
}

class OverloadChoices : public ::testing::TestWithParam<ChoiceCase> {};

TEST_P(OverloadChoices, PixelShaderReturnsFxcsPick) {
    for (bool pickedFirst : {true, false}) {
        CompileOptions options;
        options.useCache = false;
        const std::string hlsl = source(GetParam(), pickedFirst);
        CompiledEffect e = compileShaderSource(hlsl, "/tmp/overload_choices_case.hlsl", {{"/tmp/overload_choices_case.hlsl", "main", "ps_5_0"}}, options);
        ASSERT_FALSE(e.shaders.empty()) << hlsl;
        const std::string& glsl = e.shaders.back().glsl;
        EXPECT_TRUE(std::regex_search(glsl, std::regex(R"(0\.75)"))) << hlsl << glsl;
        EXPECT_FALSE(std::regex_search(glsl, std::regex(R"(0\.25)"))) << hlsl << glsl;
    }
}

INSTANTIATE_TEST_SUITE_P(FunctionOverload, OverloadChoices, ::testing::ValuesIn(cases()), [](const auto& p) { return std::string(p.param.name); });

}  // namespace
