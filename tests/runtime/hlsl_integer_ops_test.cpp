// D3D10+'s integer instructions where SPIR-V and GLSL leave the result undefined, and SM2-3's
// integers computed as floats (xlate/src/spirv/spirv_integer_fixups.cpp): each shader is drawn into one
// float pixel and compared with the operation written in C++ with D3D's meaning. Counts and operands come as
// uniforms (the GPU computes) and as literals (glslang's and spirv-opt's folding computes).
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "one_pixel_effect.h"

namespace fxport::test {
namespace {

class HlslIntegerOps : public OnePixelEffect {};

// ishl / ishr / ushr take the count's low 5 bits: 1 << 33 is 2, x >> -1 is x >> 31.
TEST_P(HlslIntegerOps, ShiftCountsUseTheirLowFiveBits) {
    const int counts[4] = {33, -1, 32, 62};
    auto d3dShl = [](std::int32_t x, int s) { return float(std::int32_t(std::uint32_t(x) << (s & 31))); };
    auto d3dShr = [](std::int32_t x, int s) { return float(x >> (s & 31)); };
    auto d3dUshr = [](std::uint32_t x, int s) { return float(x >> (s & 31)); };
    const float expected[4] = {d3dShl(1, counts[0]), d3dShr(INT_MIN, counts[1]), d3dUshr(0xFFFFFFFFu, counts[2]),
                               d3dShl(7, counts[3])};
    auto fromUniforms = effect("int4 S; int X;", "uint u = 0xFFFFFFFF; int m = -2147483648;"
                               "return float4(X << S.x, m >> S.y, u >> S.z, (X * 7) << S.w);");
    fromUniforms->Parameters["S"].SetValue(std::vector<int>(counts, counts + 4));
    fromUniforms->Parameters["X"].SetValue(1);
    auto fromLiterals = effect("", "int x = 1; uint u = 0xFFFFFFFF; int m = -2147483648; int seven = 7;"
                               "return float4(x << 33, m >> -1, u >> 32, seven << 62);");
    for (Effect* e : {fromUniforms.get(), fromLiterals.get()}) {
        std::vector<float> px = draw(*e);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    }
}

// ftou saturates: negative floats convert to 0 (GLSL's uint() of them is undefined; llvmpipe wraps).
TEST_P(HlslIntegerOps, NegativeFloatToUintIsZero) {
    const float in[4] = {-3.6f, -0.5f, 2.6f, -1e9f};
    auto d3dFtou = [](float f) { return f <= 0 ? 0.0f : float(std::uint32_t(f)); };
    auto e = effect("float4 F;", "return float4((uint)F.x, (uint)F.y, (uint)F.z, (uint)F.w);");
    e->Parameters["F"].SetValue(Vector4(in[0], in[1], in[2], in[3]));
    auto literal = effect("", "float h = -3.6; float g = 2.6; return float4((uint)h, (uint)(h * 0.1), (uint)g, (uint)(h * 1e9));");
    const float fromLiterals[4] = {d3dFtou(-3.6f), d3dFtou(-0.36f), d3dFtou(2.6f), d3dFtou(-3.6e9f)};
    std::vector<float> px = draw(*e), lit = draw(*literal);
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(px[size_t(k)], d3dFtou(in[k])) << "channel " << k;
        EXPECT_EQ(lit[size_t(k)], fromLiterals[k]) << "channel " << k;
    }
}

// INT_MIN / -1 of constants compiles (spirv-opt's folder traps on it) and computes what D3D's
// idiv does: the quotient wraps to INT_MIN, the remainder is 0. Beside it a uniform division.
TEST_P(HlslIntegerOps, IntMinByMinusOneFolds) {
    auto e = effect("int D;", "int x = -2147483648; int y = -1; int2 v = int2(x, 9); int2 w = int2(y, 2);"
                    "return float4(x / y, x % y, (v / w).y, x / D);");
    e->Parameters["D"].SetValue(-2);
    std::vector<float> px = draw(*e);
    const float expected[4] = {float(INT_MIN), 0.0f, float(9 / 2), float(INT_MIN / -2)};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslIntegerOps, ::testing::Values("4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

// SM2-3 have no integers: fxc divides the operands as floats and truncates, so an int beyond 2^24
// loses its low bits first (16777217 is 16777216 as a float: 16777217 % 10 is 6, not 7).
class HlslSm3Integers : public OnePixelEffect {};

TEST_P(HlslSm3Integers, DivisionRoundsOperandsToFloat) {
    const int a = 16777217, b = 10, c = 16782201, d = 999;
    auto asFxc = [](int x, int y, bool remainder) {
        const float q = float(x) / float(y), r = std::fmod(float(x), float(y));
        return float(int(remainder ? r : q));
    };
    auto e = effect("float B; float D;", "int a = 16777217; int b = B; int c = 16782201; int d = D;"
                    "return float4(a % b, (-a) % b, c / d, (-c) / d);");
    e->Parameters["B"].SetValue(float(b));
    e->Parameters["D"].SetValue(float(d));
    std::vector<float> px = draw(*e);
    const float expected[4] = {asFxc(a, b, true), asFxc(-a, b, true), asFxc(c, d, false), asFxc(-c, d, false)};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// fxc folds constant ints exactly (16777217 % 10 is 7), except negation, which it folds as a
// float (-16777217 is -16777216, 16782201 comes back from two negations as 16782200; vkd3d's
// arithmetic-int pins both).
TEST_P(HlslSm3Integers, ConstantsFoldExactlyButNegateAsFloats) {
    const int a = 16777217, b = 10, c = 16782201, d = 999;
    auto negated = [](int x) { return int(-float(x)); };
    auto e = effect("", "int a = 16777217; int b = 10; int c = 16782201; int d = 999;"
                    "return float4(a % b, (-a) % b, (-c) / d, (-(-c)) + 1);");
    std::vector<float> px = draw(*e);
    const float expected[4] = {float(a % b), float(negated(a) % b), float(negated(c) / d), float(negated(negated(c)) + 1)};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// An SM2-3 int is a float, so values beyond 32-bit integers stay what they are (vkd3d's
// arithmetic-int and cast-to-int): INT_MIN / -1 is 2^31, -INT_MIN is 2^31 (a constant and a
// uniform's), (int) of the uint 0xfffffffe is 4294967294, and (int)f still truncates (-3.6 is -3).
TEST_P(HlslSm3Integers, ValuesBeyondInt32StayFloats) {
    auto e = effect("float F;", "int x = -2147483648; int y = -1; uint u = 0xfffffffe; int f = F;"
                    "return float4(x / y, -x, (float)(int)u, f);");
    e->Parameters["F"].SetValue(-3.6f);
    std::vector<float> px = draw(*e);
    const float expected[4] = {2147483648.0f, 2147483648.0f, float(0xfffffffeu), -3.0f};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    auto n = effect("float A;", "int a = A; return float4(int2(-a, a), -a, 0);");
    n->Parameters["A"].SetValue(-2147483648.0f);
    px = draw(*n);
    const float computed[4] = {2147483648.0f, -2147483648.0f, 2147483648.0f, 0.0f};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], computed[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslSm3Integers, ::testing::Values("2_0", "3_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
