// Out and inout arguments through conversions write back as fxc does
// (xlate/src/rewrite/out_argument_casts.cpp): an inout of another type converts in and back, a cast on an
// argument applies as if on the left of an assignment. Drawn into one float pixel at SM2..SM5 and
// compared with the same steps written in C++.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "one_pixel_effect.h"

namespace fxport::test {
namespace {

class HlslOutArguments : public OnePixelEffect {};

// `void f(inout float4 a)` on an int4: in as float, back truncated to int.
TEST_P(HlslOutArguments, InoutOfAnotherTypeIsWrittenBack) {
    const int in[4] = {-2, 0, 1, 7};
    auto e = effect("int4 I; void add(inout float4 a) { a += 0.6; }", "int4 x = I; add(x); return x;");
    e->Parameters["I"].SetValue(std::vector<int>(in, in + 4));
    std::vector<float> px = draw(*e);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], float(int(float(in[k]) + 0.6f))) << "channel " << k;
}

// `f((float4)x)` of an int4 x and `f((int4)p)` of a float4 p: the value written goes back through
// the cast (x = (int4)v; p = (float4)(int4)v).
TEST_P(HlslOutArguments, CastArgumentIsWrittenBackThroughTheCast) {
    const float v[4] = {-1.9f, -1.0f, 2.9f, 4.3f};
    auto e = effect("float4 V; void put(out float4 o) { o = V; }",
                    "int4 x; put((float4)x); float4 p; put((int4)p); return x + p * 10;");
    e->Parameters["V"].SetValue(Vector4(v[0], v[1], v[2], v[3]));
    std::vector<float> px = draw(*e);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], float(int(v[k])) + float(int(v[k])) * 10) << "channel " << k;
}

// `f((float2)p)` of a float4 p writes p.xy and keeps p.zw.
TEST_P(HlslOutArguments, NarrowingCastWritesTheFirstComponents) {
    auto e = effect("void two(out float2 f) { f = float2(1, 2); }", "float4 p = {-1, -2, -3, -4}; two((float2)p); return p;");
    std::vector<float> px = draw(*e);
    const float expected[4] = {1, 2, -3, -4};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, HlslOutArguments, ::testing::Values("2_0", "3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
