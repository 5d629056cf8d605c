// XNA's Effect.Clone: the clone runs the same code with its own copy of every parameter value
// (constants and textures) and the same current technique; later changes to either leave the other
// alone. Stock effects clone as their own type with their properties. Values are checked against
// the shader's arithmetic done here.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {
namespace {

const char* kTinted = R"(
float4 Tint;
float Scale;
texture Image;
sampler ImageSampler = sampler_state { Texture = <Image>; MinFilter = Point; MagFilter = Point; };
float4 VS(float4 p : POSITION0) : POSITION0 { return p; }
float4 Plain() : COLOR0 { return Tint * Scale + tex2D(ImageSampler, float2(0.5, 0.5)); }
float4 Doubled() : COLOR0 { return 2 * (Tint * Scale + tex2D(ImageSampler, float2(0.5, 0.5))); }
technique A { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Plain(); } }
technique B { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Doubled(); } }
)";

std::vector<float> drawOnePixel(GraphicsDevice& device, Effect& e) {
    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    e.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    std::vector<float> out = readFloats(target);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    return out;
}

void expectPixel(const std::vector<float>& got, float r, float g, float b, float a) {
    ASSERT_GE(got.size(), 4u);
    EXPECT_NEAR(got[0], r, 1e-3);
    EXPECT_NEAR(got[1], g, 1e-3);
    EXPECT_NEAR(got[2], b, 1e-3);
    EXPECT_NEAR(got[3], a, 1e-3);
}

TEST(EffectClone, CloneKeepsItsOwnValuesTexturesAndTechnique) {
    GraphicsDevice& device = testDevice();
    EffectOptions options;
    options.useCache = false;
    Effect original(device, EffectSource{kTinted, "Tinted.fx"}, options);
    Texture2D image(device, 1, 1);
    image.SetData(std::vector<Color>{Color(51, 102, 153, 204)});  // 0.2, 0.4, 0.6, 0.8
    original.Parameters["Tint"].SetValue(Vector4(0.1f, 0.2f, 0.3f, 0.4f));
    original.Parameters["Scale"].SetValue(0.5f);
    original.Parameters["Image"].SetValue(&image);
    original.CurrentTechnique = original.Techniques["B"];

    std::unique_ptr<Effect> clone = original.Clone();
    ASSERT_TRUE(clone);
    EXPECT_EQ(clone->CurrentTechnique->Name(), "B");
    original.Parameters["Tint"].SetValue(Vector4(0, 0, 0, 0));
    original.Parameters["Image"].SetValue(static_cast<Texture2D*>(nullptr));
    original.CurrentTechnique = original.Techniques["A"];

    // clone: 2 * (tint * 0.5 + texel); original: 0 * 0.5 + no texture (reads 0 in fxport and XNA's D3D9).
    expectPixel(drawOnePixel(device, *clone), 2 * (0.05f + 0.2f), 2 * (0.1f + 0.4f), 2 * (0.15f + 0.6f), 2 * (0.2f + 0.8f));
    EXPECT_EQ(clone->Parameters["Scale"].GetValueSingle(), 0.5f);
    clone->Parameters["Scale"].SetValue(0.0f);
    EXPECT_EQ(original.Parameters["Scale"].GetValueSingle(), 0.5f);
}

TEST(EffectClone, BasicEffectClonesAsABasicEffectWithItsProperties) {
    GraphicsDevice& device = testDevice();
    BasicEffect original(device);
    original.DiffuseColor = Vector3(0.25f, 0.5f, 0.75f);
    original.Alpha = 0.5f;
    original.FogEnabled = true;
    original.FogStart = 2;
    original.World = Matrix::CreateTranslation(1, 2, 3);
    original.EnableDefaultLighting();
    original.DirectionalLight1.Enabled = false;

    std::unique_ptr<Effect> cloned = original.Clone();
    auto* clone = dynamic_cast<BasicEffect*>(cloned.get());
    ASSERT_NE(clone, nullptr);
    original.DiffuseColor = Vector3(0, 0, 0);
    EXPECT_EQ(clone->DiffuseColor, Vector3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(clone->Alpha, 0.5f);
    EXPECT_TRUE(clone->FogEnabled);
    EXPECT_EQ(clone->FogStart, 2.0f);
    EXPECT_EQ(clone->World, Matrix::CreateTranslation(1, 2, 3));
    EXPECT_TRUE(clone->LightingEnabled);
    EXPECT_FALSE(clone->DirectionalLight1.Enabled);
    EXPECT_EQ(clone->AmbientLightColor, original.AmbientLightColor);
    EXPECT_EQ(clone->PermutationName(), original.PermutationName());  // lighting, fog: the same shader
}

// The clone draws with its own properties (unlit: the colour is DiffuseColor, alpha Alpha).
TEST(EffectClone, BasicEffectCloneDrawsWithItsOwnProperties) {
    GraphicsDevice& device = testDevice();
    BasicEffect original(device);
    original.DiffuseColor = Vector3(0.25f, 0.5f, 0.75f);
    std::unique_ptr<Effect> clone = original.Clone();
    original.DiffuseColor = Vector3(0, 0, 0);
    expectPixel(drawOnePixel(device, *clone), 0.25f, 0.5f, 0.75f, 1);
    expectPixel(drawOnePixel(device, original), 0, 0, 0, 1);
}

}  // namespace
}  // namespace fxport::test
