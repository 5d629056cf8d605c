// Texture-stage states of a D3D9 pass reach an HLSL pixel shader's samplers (issue 24, the XNA 2.0
// samples' MaterialShader20.fx): `Texture[0] = <Image>; MagFilter[0] = Linear;` bind the parameter
// and set the sampler state at register s0, as D3D9's effect framework does; a stage the pass's
// shader does not sample stays on the device for a later pass. Fixture: PassSamplerStages.fx. The
// drawn pixels are compared with the texels the test wrote.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::testDevice;

// The fixture effect with its two texture parameters set to 1 x 1 textures of the given colours.
class PassSamplerStages : public test::OpaqueDrawTest {
protected:
    void setTextures(Color imageTexel, Color otherTexel) {
        image.SetData(std::vector<Color>{imageTexel});
        other.SetData(std::vector<Color>{otherTexel});
        effect.Parameters["Image"].SetValue(image);
        effect.Parameters["Other"].SetValue(other);
    }
    Effect effect{device, test::runtimeFixture("PassSamplerStages.fx")};
    Texture2D image{device, 1, 1, false, SurfaceFormat::Color};
    Texture2D other{device, 1, 1, false, SurfaceFormat::Color};
};

TEST_F(PassSamplerStages, StageStatesBindTheTextureAndGoOverTheSamplerState) {
    setTextures(Color(64, 128, 192, 255), Color(255, 255, 255, 255));
    device.SamplerStates[0] = SamplerState::PointWrap;
    device.SamplerStates[1] = SamplerState::LinearWrap;
    effect.CurrentTechnique = effect.Techniques["Stages"];
    effect.CurrentTechnique->Passes[0].Apply();

    // A filter the pass does not name keeps the device's: MipFilter[0] stays PointWrap's point.
    EXPECT_EQ(device.Textures[0].get(), &image);
    EXPECT_EQ(device.SamplerStates[0].Filter, TextureFilter::LinearMipPoint);
    EXPECT_EQ(device.SamplerStates[0].AddressU, TextureAddressMode::Clamp);
    EXPECT_EQ(device.SamplerStates[0].AddressV, TextureAddressMode::Mirror);
    EXPECT_EQ(device.Textures[1].get(), &image) << "Texture[1] goes over the sampler_state's Texture = <Other>";
    EXPECT_EQ(device.SamplerStates[1].Filter, TextureFilter::PointMipLinear);  // the sampler_state names no MipFilter: LinearWrap's
    EXPECT_EQ(device.SamplerStates[1].AddressU, TextureAddressMode::Clamp);
    EXPECT_EQ(device.SamplerStates[1].AddressV, TextureAddressMode::Wrap);

    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    const std::vector<float> px = test::readFloats(target);
    ASSERT_EQ(px.size(), 16u);
    const float want[4] = {64 / 255.0f, 128 / 255.0f, 192 / 255.0f, 1.0f};  // Image's rg from s0, Image's ba from s1
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(px[std::size_t(c)], want[c], 1e-6f) << "channel " << c;
}

TEST_F(PassSamplerStages, AStageNoShaderOfThePassSamplesIsKeptForLaterPasses) {
    setTextures(Color(64, 128, 192, 255), Color(0, 0, 32, 96));
    device.Textures[2] = nullptr;
    device.SamplerStates[2] = SamplerState::LinearClamp;
    effect.CurrentTechnique = effect.Techniques["Multipass"];
    effect.CurrentTechnique->Passes[0].Apply();
    EXPECT_EQ(device.Textures[2].get(), &other) << "First's Texture[2] is set on the device although FirstPS samples s0 only";
    EXPECT_EQ(device.SamplerStates[2].AddressU, TextureAddressMode::Mirror);
    EXPECT_EQ(device.SamplerStates[2].AddressV, TextureAddressMode::Clamp) << "a state the pass does not name stays the device's";

    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[1].Apply();
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    const std::vector<float> px = test::readFloats(target);
    ASSERT_EQ(px.size(), 16u);
    const float want[4] = {64 / 255.0f, 128 / 255.0f, 32 / 255.0f, 96 / 255.0f};  // Image's rg (s0, from First), Other's ba (s2, from First)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(px[std::size_t(c)], want[c], 1e-6f) << "channel " << c;

    xlate::CompiledEffect compiled = xlate::compileEffectFile(test::runtimeFixture("PassSamplerStages.fx"), xlate::CompileOptions{});
    for (const auto& d : compiled.diagnostics) EXPECT_EQ(d.message.find("fixed-function"), std::string::npos) << d.format();
}

}  // namespace
}  // namespace fxport
