// XNA's EffectParameter.StructureMembers and Elements: a struct parameter's members, an array's
// elements and the members of one element of an array of structs are set one by one, before the
// first Apply (the effect's provisional layout) and after it (the compiled one), and the pixel
// shader reads what was set. Struct layouts with members in the tail of another's register, a
// struct member after an array and a scalar after the struct, at SM2..SM5.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "one_pixel_effect.h"
#include "runtime_test_support.h"

namespace fxport::test {
namespace {

class StructParameters : public OnePixelEffect {
protected:
    void expectPixel(const std::vector<float>& px, const float (&expected)[4]) {
        ASSERT_EQ(px.size(), 4u);
        for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(px[size_t(k)], expected[k]) << "channel " << k;
    }
};

const char* kGlobals =
    "struct Light { float3 color; float intensity; float w[2]; float2 dir; };\n"
    "Light light;\n"
    "Light lights[2];\n"
    "float after;\n"
    "float4 arr[3];\n";
const char* kBody = "return float4(light.color * light.intensity + arr[2].xyz, lights[1].dir.y + lights[1].w[1] + after);";

TEST_P(StructParameters, MembersAndElementsReachTheShader) {
    auto e = effect(kGlobals, kBody);
    EffectParameter& light = e->Parameters["light"];
    ASSERT_EQ(light.ParameterClass(), EffectParameterClass::Struct);
    ASSERT_EQ(light.StructureMembers().Count(), 4);
    EXPECT_EQ(light.StructureMembers()[0].Name(), "color");
    EXPECT_EQ(light.Elements().Count(), 0);
    ASSERT_EQ(e->Parameters["lights"].Elements().Count(), 2);
    EXPECT_EQ(e->Parameters["lights"].StructureMembers().Count(), 0);  // an array: its elements have members

    // Before the first Apply: the provisional layout keeps them until the compile places them.
    light.StructureMembers()["color"].SetValue(Vector3(0.25f, 0.5f, 0.75f));
    light.StructureMembers()["intensity"].SetValue(2.0f);
    EffectParameter& second = e->Parameters["lights"].Elements()[1];
    second.StructureMembers()["dir"].SetValue(Vector2(0.125f, 0.375f));
    second.StructureMembers()["w"].SetValue(std::vector<float>{100.0f, 0.0625f});
    e->Parameters["lights"].Elements()[0].StructureMembers()["dir"].SetValue(Vector2(50.0f, 60.0f));  // not read
    e->Parameters["after"].SetValue(0.5f);
    e->Parameters["arr"].Elements()[2].SetValue(Vector4(0.0625f, 0.125f, 0.25f, 9.0f));
    e->Parameters["arr"].Elements()[1].SetValue(Vector4(7, 7, 7, 7));  // not read
    const float first[4] = {0.5f + 0.0625f, 1.0f + 0.125f, 1.5f + 0.25f, 0.375f + 0.0625f + 0.5f};
    expectPixel(draw(*e), first);
    EXPECT_FLOAT_EQ(light.StructureMembers()["intensity"].GetValueSingle(), 2.0f);
    EXPECT_FLOAT_EQ(second.StructureMembers()["dir"].GetValueVector2().Y, 0.375f);

    // After it: the compiled layout.
    light.StructureMembers()["intensity"].SetValue(4.0f);
    second.StructureMembers()["w"].Elements()[1].SetValue(0.25f);
    const float later[4] = {1.0f + 0.0625f, 2.0f + 0.125f, 3.0f + 0.25f, 0.375f + 0.25f + 0.5f};
    expectPixel(draw(*e), later);
}

TEST_P(StructParameters, AMemberChecksItsTypeLikeAParameter) {
    auto e = effect(kGlobals, kBody);
    EffectParameter& color = e->Parameters["light"].StructureMembers()["color"];
    EXPECT_THROW(color.SetValue(1.0f), ArgumentError);
    EXPECT_THROW(e->Parameters["light"].StructureMembers()["nope"], ArgumentError);
    EXPECT_EQ(e->Parameters["light"].StructureMembers().find("nope"), nullptr);
}

// An array of arrays is one array of all its elements to XNA and D3D (float c[2][3]: 6, in order,
// each in its own register), set whole or element by element. fxport listed 2 elements of 48 bytes.
TEST_P(StructParameters, ArrayOfArraysIsOneArrayOfAllElements) {
    auto e = effect("float c[2][3]; float4 v[2][2];", "return float4(c[1][0], c[0][2], c[1][2], v[1][0].y);");
    ASSERT_EQ(e->Parameters["c"].Elements().Count(), 6);
    ASSERT_EQ(e->Parameters["v"].Elements().Count(), 4);
    e->Parameters["c"].SetValue(std::vector<float>{0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f});
    e->Parameters["v"].Elements()[2].SetValue(Vector4(0, 6.25f, 0, 0));
    const float first[4] = {3.5f, 2.5f, 5.5f, 6.25f};
    expectPixel(draw(*e), first);
    e->Parameters["c"].Elements()[5].SetValue(8.0f);
    const float later[4] = {3.5f, 2.5f, 8.0f, 6.25f};
    expectPixel(draw(*e), later);
}

INSTANTIATE_TEST_SUITE_P(ShaderModels, StructParameters, ::testing::Values("2_0", "3_0", "4_0", "5_0"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("sm") + p.param; });

}  // namespace
}  // namespace fxport::test
