// A fixture for HLSL value tests: an effect whose pixel shader is a few statements, compiled for
// the test's shader model (the parameter: "2_0" ... "5_0") and drawn into one float pixel.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {

class OnePixelEffect : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override {
        device.BlendState = BlendState::Opaque;
        device.DepthStencilState = DepthStencilState::None;
        device.RasterizerState = RasterizerState::CullNone;
    }
    void TearDown() override { device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }

    // An effect whose pixel shader is `body` (HLSL statements returning a float4) after `globals`.
    std::unique_ptr<Effect> effect(const std::string& globals, const std::string& body) {
        const std::string model = GetParam();
        std::string text = globals + "\n"
                           "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
                           "float4 PS() : COLOR0 {\n" + body + "\n}\n"
                           "technique T { pass P { VertexShader = compile vs_" + model + " VS(); PixelShader = compile ps_" + model + " PS(); } }\n";
        EffectOptions options;
        options.useCache = false;
        const std::string suite = ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name();
        return std::make_unique<Effect>(device, EffectSource{text, suite + "_" + model + ".fx"}, options);
    }

    // Draws one pixel with `e`; Apply() compiles the pass first (and throws what the compile does).
    std::vector<float> draw(Effect& e) {
        RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
        struct Unbind {
            GraphicsDevice& d;
            ~Unbind() { d.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }
        } unbind{device};
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        e.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        return readFloats(target);
    }

    GraphicsDevice& device = testDevice();
};

}  // namespace fxport::test
