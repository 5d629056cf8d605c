// Render states an effect reads from its parameters at Apply() (D3D9's effect framework):
// `ZWriteEnable = <ZWrites[Mode]>` picks an element by another parameter's value, and a parameter
// that no shader reads keeps the value the host sets (XNA lets any parameter be set). Fixture:
// ParameterStates.fx. Expectations are the D3D9 codes the fixture's arrays hold.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::testDevice;

class ParameterStates : public test::OpaqueDrawTest {
protected:
    void apply() { effect.CurrentTechnique->Passes[0].Apply(); }
    Effect effect{device, test::runtimeFixture("ParameterStates.fx")};
};

TEST_F(ParameterStates, AnElementChosenByAnotherParameterIsReadAtEachApply) {
    effect.Parameters["Mode"].SetValue(0);
    apply();
    EXPECT_TRUE(device.DepthStencilState.DepthBufferWriteEnable);  // ZWrites[0] = true
    EXPECT_EQ(device.RasterizerState.CullMode, CullMode::None);    // Culls[0] = D3DCULL_NONE

    effect.Parameters["Mode"].SetValue(1);
    apply();
    EXPECT_FALSE(device.DepthStencilState.DepthBufferWriteEnable);               // ZWrites[1] = false
    EXPECT_EQ(device.RasterizerState.CullMode, CullMode::CullClockwiseFace);    // Culls[1] = D3DCULL_CW

    const std::vector<int> writes = {0, 1};
    effect.Parameters["ZWrites"].SetValue(writes);
    apply();
    EXPECT_TRUE(device.DepthStencilState.DepthBufferWriteEnable);  // the array's new element 1
}

TEST_F(ParameterStates, AnIndexOutsideTheArrayIsAnErrorNamingIt) {
    effect.Parameters["Mode"].SetValue(2);  // Culls has 3 elements, ZWrites 2
    try {
        apply();
        FAIL() << "Apply() with ZWrites[2] succeeded";
    } catch (const InvalidOperation& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("'ZWrites'"), std::string::npos) << what;
        EXPECT_NE(what.find("0..1"), std::string::npos) << what;
    }
}

// Tint's alpha is 0.5 (127.5 of 255): AlphaRef 77 keeps the pixel, 150 discards it. Reference is
// read by no shader; its value is set before the first Apply (when the technique compiles and the
// parameter's provisional storage goes away) and after.
TEST_F(ParameterStates, AParameterNoShaderReadsKeepsItsValueForTheState) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color);
    device.SetRenderTarget(target);
    effect.Parameters["Reference"].SetValue(77);
    for (int reference : {77, 150, 20}) {
        SCOPED_TRACE("AlphaRef " + std::to_string(reference));
        if (reference != 77) effect.Parameters["Reference"].SetValue(reference);
        EXPECT_EQ(effect.Parameters["Reference"].GetValueInt32(), reference);
        device.Clear(Color(0, 0, 255, 255));
        apply();
        drawQuad(device);
        std::vector<Color> pixels(16);
        target.GetData(pixels.data(), pixels.size());
        bool kept = 127.5 > reference;
        for (const Color& c : pixels) EXPECT_EQ(c.R, kept ? 255 : 0);
    }
}

}  // namespace
// Sampler states from parameters: the filters and AddressU follow Mode at each Apply() (D3D9's
// codes: Filters = {POINT, LINEAR}, Addresses = {CLAMP, WRAP}); AddressV, given as a value, stays.
TEST_F(ParameterStates, SamplerStatesReadTheirParameterAtEachApply) {
    effect.CurrentTechnique = effect.Techniques["SamplerFromParameters"];
    device.SamplerStates[0] = SamplerState::LinearWrap;
    effect.Parameters["Mode"].SetValue(0);
    apply();
    EXPECT_EQ(device.SamplerStates[0].Filter, TextureFilter::Point);
    EXPECT_EQ(device.SamplerStates[0].AddressU, TextureAddressMode::Clamp);
    EXPECT_EQ(device.SamplerStates[0].AddressV, TextureAddressMode::Mirror);
    effect.Parameters["Mode"].SetValue(1);
    apply();
    EXPECT_EQ(device.SamplerStates[0].Filter, TextureFilter::LinearMipPoint);
    EXPECT_EQ(device.SamplerStates[0].AddressU, TextureAddressMode::Wrap);
    EXPECT_EQ(device.SamplerStates[0].AddressV, TextureAddressMode::Mirror);
    // The parameter itself changes too: Filters[1] = D3DTEXF_POINT.
    effect.Parameters["Filters"].SetValue(std::vector<int>{1, 1});
    apply();
    EXPECT_EQ(device.SamplerStates[0].Filter, TextureFilter::Point);
}

}  // namespace fxport
