// Bilinear filtering weights are computed in float on the headless device, as D3D9-class hardware
// filters: a 2x1 texture of 0 and 255 sampled between its texel centres gives the linear weight
// itself. llvmpipe's 8-bit fast path would round each weight to 1/256 (off by up to ~0.002 here);
// fxport's OSMesa context turns that path off unless GALLIVM_PERF is set (docs/testing.md); ctest
// runs this test with GALLIVM_PERF unset, so a developer's own setting cannot change its answer.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {
namespace {

TEST(TextureFiltering, BilinearWeightsAreNotRoundedTo8Bits) {
    GraphicsDevice& device = testDevice();
    const std::string text = "texture T; sampler S = sampler_state { Texture = <T>; MinFilter = Linear; MagFilter = Linear; "
                             "AddressU = Clamp; AddressV = Clamp; };\n"
                             "float2 U;\n"
                             "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
                             "float4 PS() : COLOR0 { return tex2D(S, float2(U.x, 0.5)); }\n"
                             "technique Tq { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    EffectOptions options;
    options.useCache = false;
    Effect effect(device, EffectSource{text, "texture_filtering.fx"}, options);
    Texture2D texture(device, 2, 1);
    texture.SetData(std::vector<Color>{Color(0, 0, 0, 255), Color(255, 255, 255, 255)});
    effect.Parameters["T"].SetValue(texture);
    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    double worst = 0;
    // u from the first texel centre (0.25) to the second (0.75): weight = (u - 0.25) * 2.
    for (int i = 1; i < 40; ++i) {
        const double weight = i / 40.0 + 0.0031;  // off any 1/256 step
        effect.Parameters["U"].SetValue(Vector2(float(0.25 + weight / 2), 0));
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        worst = std::max(worst, std::fabs(double(readFloats(target)[0]) - weight));
    }
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    EXPECT_LT(worst, 1e-3) << "bilinear weights are rounded (llvmpipe's 8-bit sampling path)";
}

}  // namespace
}  // namespace fxport::test
