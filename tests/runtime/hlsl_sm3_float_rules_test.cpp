// SM 2-3 float arithmetic as D3D9 computes it where IEEE differs (xlate/src/spirv/legacy_division.h,
// ps2_equality.h):
// each shader is drawn into one float pixel, the operands coming from uniforms (the GPU computes;
// fxc refuses a constant divisor of 0).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "one_pixel_effect.h"

namespace fxport::test {
namespace {

class HlslSm3Floats : public OnePixelEffect {};

// fxc's a / b at SM 2-3 is a * rcp(b), and D3D9's multiply makes 0 * inf 0: 0 / 0 and inf / inf
// are 0 (vkd3d float-comparison L60), so is 0 / 0 of computed values; 1 / 0 is still inf.
TEST_P(HlslSm3Floats, ZeroOverZeroIsZero) {
    auto e = effect("float Z; float One; float Inf;", "return float4(Z / Z, One / Z, Inf / Inf, (Z * One) / (Z + Z));");
    e->Parameters["Z"].SetValue(0.0f);
    e->Parameters["One"].SetValue(1.0f);
    e->Parameters["Inf"].SetValue(INFINITY);
    std::vector<float> px = draw(*e);
    EXPECT_EQ(px[0], 0.0f);
    EXPECT_TRUE(std::isinf(px[1]) && px[1] > 0) << px[1];
    EXPECT_EQ(px[2], 0.0f);
    EXPECT_EQ(px[3], 0.0f);
    // Every other quotient is IEEE's, its sign too: -1 / inf and 1 / (1 / -0) are -0 (vkd3d rcp L52).
    auto s = effect("float Z; float One; float Inf;", "return float4(-One / Inf, One / (One / -Z), Inf / One, 0);");
    s->Parameters["Z"].SetValue(0.0f);
    s->Parameters["One"].SetValue(1.0f);
    s->Parameters["Inf"].SetValue(INFINITY);
    px = draw(*s);
    EXPECT_TRUE(px[0] == 0.0f && std::signbit(px[0])) << px[0];
    EXPECT_TRUE(px[1] == 0.0f && std::signbit(px[1])) << px[1];
    EXPECT_TRUE(std::isinf(px[2])) << px[2];
}

// ps_2_0 has no compare instruction: fxc's a == b there is (a - b)² == 0, which holds for
// differences whose square underflows (1e-37 against 0 and -1e-37), not for 1e38 against -1e38
// (the square is inf); ps_3_0 compares exactly (vkd3d float-comparison L92 and L108).
TEST_P(HlslSm3Floats, Ps2EqualityIsASquaredDifference) {
    auto e = effect("float4 A; float4 B;", "return float4(A == B) + 10 * float4(A != B);");
    e->Parameters["A"].SetValue(Vector4(1e-37f, 1e-37f, 1e38f, 1e38f));
    e->Parameters["B"].SetValue(Vector4(0.0f, -1e-37f, 1e38f, -1e38f));
    std::vector<float> px = draw(*e);
    const bool ps2 = std::string(GetParam()) == "2_0";
    const float expected[4] = {ps2 ? 1.0f : 10.0f, ps2 ? 1.0f : 10.0f, 1.0f, 10.0f};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslSm3Floats, ::testing::Values("2_0", "3_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
