// Real-world constructs of the sixth wave (run 25) whose value matters, drawn into one float pixel
// and compared with the same arithmetic on the CPU.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "one_pixel_effect.h"
#include "runtime_test_support.h"

namespace fxport::test {
namespace {

class RealworldSixthWaveRender : public OnePixelEffect {};
// Constructs of DX10 objects: shader models 4 and 5 only.
class RealworldSixthWaveRenderSm4 : public OnePixelEffect {};

// helix-toolkit's gsLineArrowHead.hlsl: `transform._m00_m11_m22 *= d;` scales the diagonal in place;
// `m._11_42 += v` adds to two elements of different rows (one-based names: _11 is [0][0], _42 [3][1]).
TEST_P(RealworldSixthWaveRender, CompoundAssignmentToMatrixSwizzle) {
    auto e = effect("float4 A;",
                    "float4x4 m = float4x4(A, A.yzwx, A.zwxy, A.wxyz);\n"
                    "float d = A.x - 0.5;\n"
                    "m._m00_m11_m22 *= d;\n"
                    "m._11_42 += float2(2, (d + 1) * 3);\n"
                    "return float4(m[0][0], m[1][1], m[2][2], m[3][1]);");
    const float a[4] = {1.5f, -2.0f, 0.25f, 3.0f};
    e->Parameters["A"].SetValue(Vector4(a[0], a[1], a[2], a[3]));
    // Row r of m is A rotated left by r: m[r][c] = a[(r + c) % 4].
    auto m = [&](int r, int c) { return a[(r + c) % 4]; };
    const float d = a[0] - 0.5f;
    const float expected[4] = {m(0, 0) * d + 2, m(1, 1) * d, m(2, 2) * d, m(3, 1) + (d + 1) * 3};
    std::vector<float> px = draw(*e);
    ASSERT_EQ(px.size(), 4u);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[k], 1e-5f) << "channel " << k;
}

// OGRE's HLSL_SM4Support.hlsl on D3D11: `sampler2D` is #defined to a struct of a Texture2D and a
// SamplerState, and SAMPLER2D(name, reg) declares `static Sampler2D name = {nameTex, nameState}`,
// sampled through a user tex2D overload. The texel read is the texture's.
TEST_P(RealworldSixthWaveRenderSm4, StaticStructOfObjects) {
    auto e = effect("struct Sampler2D { Texture2D t; SamplerState s; };\n"
                    "float4 tex2D(Sampler2D s, float2 v) { return s.t.Sample(s.s, v); }\n"
                    "Texture2D Tex0Tex : register(t0);\nSamplerState Tex0State : register(s0);\n"
                    "static Sampler2D Tex0 = {Tex0Tex, Tex0State};",
                    "return tex2D(Tex0, float2(0.5, 0.5)) * 0.5 + Tex0.t.Sample(Tex0.s, float2(0.5, 0.5)) * 0.5;");
    Texture2D texture(device, 1, 1, false, SurfaceFormat::Color);
    texture.SetData(std::vector<Color>{Color(64, 128, 192, 255)});
    e->Parameters["Tex0Tex"].SetValue(texture);
    std::vector<float> px = draw(*e);
    ASSERT_EQ(px.size(), 4u);
    const float expected[4] = {64 / 255.0f, 128 / 255.0f, 192 / 255.0f, 1};
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(px[size_t(k)], expected[k], 1e-3f) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, RealworldSixthWaveRender, ::testing::Values("3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });
INSTANTIATE_TEST_SUITE_P(ShaderModels, RealworldSixthWaveRenderSm4, ::testing::Values("4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
