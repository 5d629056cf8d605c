// int, uint and bool matrices (xlate/src/spirv/integer_matrices.h): GLSL has none, so fxport holds them
// as arrays of columns. Each shader is drawn into one float pixel and compared with the element
// HLSL's indexing names (m[row][column]), written out here from the initializers.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "one_pixel_effect.h"

namespace fxport::test {
namespace {

class HlslIntegerMatrices : public OnePixelEffect {};

// Constants' initial values, read by element (the values fill rows: b[0] = {7, 8}).
TEST_P(HlslIntegerMatrices, InitialValuesReadByElement) {
    auto e = effect("int2x2 b = {7, 8, 9, 10};\nuint2x3 u = {11, 12, 13, 14, 15, 16};",
                    "return float4(b[0][1], b[1][0], u[1][2], u[0][0]);");
    std::vector<float> px = draw(*e);
    const float expected[4] = {8, 9, 16, 11};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// Conversions and transpose compute column by column; the element each lands in is HLSL's.
TEST_P(HlslIntegerMatrices, ConversionsAndTransposeKeepElements) {
    auto e = effect("float4 F;",
                    "int2x3 m = int2x3((int)F.x, (int)F.y, 3, 4, 5, 6);\n"
                    "int3x2 t = transpose(m);\n"
                    "float2x3 f = (float2x3)m;\n"
                    "bool2x2 b = (bool2x2)int2x2((int)F.z, 0, 0, 1);\n"
                    "return float4(t[2][1], f[0][1], b[0][0] ? 10 : 20, b[0][1] ? 30 : 40);");
    e->Parameters["F"].SetValue(Vector4(1, 2, 0, 0));
    std::vector<float> px = draw(*e);
    const float expected[4] = {6, 2, 20, 40};  // t[2][1] = m[1][2]; f[0][1] = m[0][1]
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

// abs of an int matrix and a bool matrix converted to a float one compute column by column too
// (GLSL.std.450 SAbs and OpSelect had no array overload in the GLSL).
TEST_P(HlslIntegerMatrices, AbsAndBoolToFloatPerComponent) {
    auto e = effect("float4 F;",
                    "int2x3 m = int2x3((int)F.x, (int)F.y, 3, -4, 5, 6); int2x3 a = abs(m);\n"
                    "bool2x2 b = (bool2x2)int2x2((int)F.z, 0, 0, 1); float2x2 f = b;\n"
                    "return float4(a[0][1], a[1][0], f[0][0], f[1][1]);");
    e->Parameters["F"].SetValue(Vector4(1, -2, 0, 0));
    std::vector<float> px = draw(*e);
    const float expected[4] = {2, 4, 0, 1};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslIntegerMatrices, ::testing::Values("3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });


// Operators on int and uint matrices compute per component, as fxc does (rewrite/matrix_operators.h;
// glslang crashed on them). Integer operations are SM4's; the values come from uniforms, so the GPU
// computes, and the expected ones are the same operations on each component in C++.
class HlslIntegerMatrixOperators : public OnePixelEffect {
protected:
    static constexpr int kI[4] = {7, -3, 12, 5};
    static constexpr unsigned kU[4] = {0x80000001u, 6, 0xF0u, 9};

    std::unique_ptr<Effect> withUniforms(const std::string& body) {
        auto e = effect("int4 I; uint4 U; uint G;", body);
        e->Parameters["I"].SetValue(std::vector<int>(kI, kI + 4));
        e->Parameters["U"].SetValue(std::vector<int>{int(kU[0]), int(kU[1]), int(kU[2]), int(kU[3])});
        e->Parameters["G"].SetValue(11);
        return e;
    }

    void expectPixel(Effect& e, const float (&expected)[4]) {
        std::vector<float> px = draw(e);
        ASSERT_EQ(px.size(), 4u);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    }
};

// int2x3 e = {I.x, I.y, I.z, I.w, 9, -6} (rows of three); uint2x4 u = {U, 1, 2, 3, 4}.
const char* const kMatrices = "int2x3 e = {I.x, I.y, I.z, I.w, 9, -6}; uint2x4 u = {U.x, U.y, U.z, U.w, 1, 2, 3, 4};";

TEST_P(HlslIntegerMatrixOperators, ArithmeticBitwiseAndShiftsPerComponent) {
    auto e = withUniforms(std::string(kMatrices) +
                          "int2x3 a = 2 + e * e - 1; int2x3 b = -e / 2 % 3; int2x3 c = (e & 3) | (e ^ 1); uint2x4 v = (u << 2) >> 1;"
                          "return float4(a[1][2] * 100 + a[0][0], b[1][1] * 10 + b[0][1], c[0][1], v[0][0] + v[1][0]);");
    const int x = kI[1], y = 9, w = -6;  // e[0][1], e[1][1], e[1][2]
    auto a = [](int c) { return 2 + c * c - 1; };
    auto b = [](int c) { return -c / 2 % 3; };
    const float expected[4] = {float(a(w) * 100 + a(kI[0])), float(b(y) * 10 + b(x)), float((x & 3) | (x ^ 1)),
                               float(((kU[0] << 2) >> 1) + ((1u << 2) >> 1))};
    expectPixel(*e, expected);
}

TEST_P(HlslIntegerMatrixOperators, CompoundAssignmentsPerComponent) {
    auto e = withUniforms(std::string(kMatrices) +
                          "e += 1; e <<= 2; e &= 0x3c; e -= I.x; u |= 3; u >>= 1; u *= u;"
                          "return float4(e[0][1], e[1][2], u[0][2], u[1][3]);");
    auto ints = [](int c) { return ((((c + 1) << 2) & 0x3c) - kI[0]); };
    auto uints = [](std::uint32_t c) { return ((c | 3u) >> 1) * ((c | 3u) >> 1); };
    const float expected[4] = {float(ints(kI[1])), float(ints(-6)), float(uints(kU[2])), float(uints(4))};
    expectPixel(*e, expected);
}

// `++` and `--` on int and uint matrices, prefix (the new value) and postfix (the old one).
TEST_P(HlslIntegerMatrixOperators, IncrementsPerComponent) {
    auto e = withUniforms(std::string(kMatrices) +
                          "int2x3 g = e++; ++e; int2x3 h = --e + 10; uint2x4 v = u--; --u;"
                          "return float4(g[0][1], e[1][2] * 100 + h[0][0], v[0][3], u[1][0]);");
    const float expected[4] = {float(kI[1]), float((-6 + 1) * 100 + (kI[0] + 1 + 10)), float(kU[3]), float(std::uint32_t(1u - 2u))};
    expectPixel(*e, expected);
}

// Comparisons give bool matrices, per component; `?:` with one selects per component, with
// branches of other types (a uint scalar and an int2x3) and scalar branches (DirectXTex BC6HEncode's
// `uint2x3 s = color >= 0 ? 0 : 1;`).
TEST_P(HlslIntegerMatrixOperators, ComparisonsAndSelectionsPerComponent) {
    auto e = withUniforms(std::string(kMatrices) +
                          "bool2x3 b = e > 6; uint2x3 s = e >= 0 ? 0 : 1; int2x3 g = (e == 12) ? G : e;"
                          "int2x3 h = ((I.x >= 15) | (e == 9)) ? e : -e;"
                          "return float4(b[0][0] * 10 + b[0][1], s[0][1] * 10 + s[1][0], g[0][2] * 100 + g[1][1], h[1][1] * 100 + h[0][0]);");
    const float expected[4] = {10 * (kI[0] > 6) + (kI[1] > 6), float(10 * (kI[1] >= 0 ? 0 : 1) + (kI[3] >= 0 ? 0 : 1)),
                               float(100 * (kI[2] == 12 ? 11 : kI[2]) + 9), float(100 * 9 - kI[0])};
    expectPixel(*e, expected);
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslIntegerMatrixOperators, ::testing::Values("4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
