// Vertex-shader inputs are fed by the vertex declaration's elements matched by semantic, as D3D
// and XNA match them: an `SV_Position` input takes the Position element (fxc reads it as POSITION0
// at SM2/3, and XNA's own stock shaders declare one), and an input the shader reads but the
// declaration lacks is an InvalidOperation naming it, as XNA throws -- never a silent (0, 0, 0, 1)
// that draws nothing.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {
namespace {

std::unique_ptr<Effect> effectFor(GraphicsDevice& device, const std::string& vsInput, const std::string& model) {
    const std::string text = "struct VSIn { float4 Position : " + vsInput + "; float4 Color : COLOR0; };\n"
                             "struct VSOut { float4 Position : POSITION0; float4 Color : TEXCOORD0; };\n"
                             "VSOut VS(VSIn v) { VSOut o; o.Position = v.Position; o.Color = v.Color; return o; }\n"
                             "float4 PS(VSOut i) : COLOR0 { return i.Color; }\n"
                             "technique T { pass P { VertexShader = compile vs_" + model + " VS(); PixelShader = compile ps_" + model + " PS(); } }\n";
    EffectOptions options;
    options.useCache = false;
    return std::make_unique<Effect>(device, EffectSource{text, "vertex_input_" + model + ".fx"}, options);
}

// Draws a full-target quad of VertexPositionColor with colour (0.25, 0.5, 0.75, 1) and returns the
// centre pixel.
std::vector<float> drawColouredQuad(GraphicsDevice& device, Effect& effect) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    device.RasterizerState = RasterizerState::CullNone;
    const Color c(64, 128, 191, 255);
    const VertexPositionColor quad[6] = {{Vector3(-1, 1, 0), c}, {Vector3(1, 1, 0), c}, {Vector3(-1, -1, 0), c},
                                         {Vector3(-1, -1, 0), c}, {Vector3(1, 1, 0), c}, {Vector3(1, -1, 0), c}};
    struct Unbind {
        GraphicsDevice& d;
        ~Unbind() { d.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }
    } unbind{device};
    effect.CurrentTechnique->Passes[0].Apply();
    device.DrawUserPrimitives(PrimitiveType::TriangleList, quad, 0, 2);
    std::vector<float> px = readFloats(target);
    return {px.begin() + (1 * 4 + 1) * 4, px.begin() + (1 * 4 + 1) * 4 + 4};
}

class VertexInputBinding : public ::testing::TestWithParam<const char*> {};

TEST_P(VertexInputBinding, SvPositionInputTakesThePositionElement) {
    GraphicsDevice& device = testDevice();
    auto effect = effectFor(device, "SV_Position", GetParam());
    const std::vector<float> px = drawColouredQuad(device, *effect);
    EXPECT_NEAR(px[0], 64 / 255.0, 1e-3);
    EXPECT_NEAR(px[1], 128 / 255.0, 1e-3);
    EXPECT_NEAR(px[2], 191 / 255.0, 1e-3);
    EXPECT_NEAR(px[3], 1.0, 1e-3);
}

TEST_P(VertexInputBinding, AnInputTheDeclarationLacksIsAnErrorNamingIt) {
    GraphicsDevice& device = testDevice();
    auto effect = effectFor(device, "POSITION0", GetParam());
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    effect->CurrentTechnique->Passes[0].Apply();
    const VertexPositionTexture tri[3] = {{Vector3(-1, 1, 0), Vector2(0, 0)}, {Vector3(1, 1, 0), Vector2(1, 0)}, {Vector3(-1, -1, 0), Vector2(0, 1)}};
    try {
        device.DrawUserPrimitives(PrimitiveType::TriangleList, tri, 0, 1);
        ADD_FAILURE() << "drawn without the COLOR0 the vertex shader reads";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("COLOR0 is missing"), std::string::npos) << e.what();
    }
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    // The device still draws afterwards.
    auto good = effectFor(device, "POSITION0", GetParam());
    EXPECT_NEAR(drawColouredQuad(device, *good)[1], 128 / 255.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Models, VertexInputBinding, ::testing::Values("2_0", "3_0", "4_0"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string("vs_") + i.param; });

}  // namespace
}  // namespace fxport::test
