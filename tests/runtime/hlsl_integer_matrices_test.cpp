// int, uint and bool matrices (xlate/src/spirv/integer_matrices.h): GLSL has none, so fxport holds them
// as arrays of columns. Each shader is drawn into one float pixel and compared with the element
// HLSL's indexing names (m[row][column]), written out here from the initializers.
#include <gtest/gtest.h>

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

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslIntegerMatrices, ::testing::Values("3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
