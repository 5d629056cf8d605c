// SM 2-3 float arithmetic as D3D9 computes it where IEEE differs (xlate/src/spirv/legacy_division.h):
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

// fxc's a / b at SM 2-3 is a * rcp(b), and D3D9's multiply makes 0 * inf 0: 0 / 0 and 1 / inf
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
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslSm3Floats, ::testing::Values("2_0", "3_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
