// DX9 1D sampling reads the Texture2D of one row that an XNA program binds (D3D9 and XNA have no 1D
// textures; Nez's PaletteCycler.fx and toon-shading ramps do this): tex1D, its gradient form,
// tex1Dlod, tex1Dbias, tex1Dproj and tex1Dgrad, through a global sampler1D and through a sampler1D
// parameter. Each pixel of a 4 x 1 target samples the texel under it with point filtering and is
// compared with the texel written; a linear sampler halfway between texels with their average.
// xlate/src/rewrite/one_row_textures.h.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::testDevice;

const std::vector<Color> kRamp = {Color(10, 20, 30, 255), Color(200, 100, 50, 255), Color(0, 255, 128, 64), Color(90, 60, 30, 0)};

// `sample` is the PS's expression of `uv` and `ramp`. With D3D9's pixel centres (an SM3 vertex
// shader) the quad's TEXCOORD0 at pixel x is x / 4; `shift` is added to it: 1/8 puts pixel x on the
// centre of texel x, 1/4 halfway between texels x and x + 1.
// Draws a 4 x 1 float target with the technique of `text` (an effect named `name`), the ramp bound
// to its texture parameter `rampParameter` and `set` setting the rest; the target is unbound again
// also when the draw throws.
std::vector<float> drawEffect(const std::string& text, const std::string& name, const std::string& rampParameter,
                              const std::function<void(Effect&)>& set = {}) {
    GraphicsDevice& device = testDevice();
    EffectOptions options;
    options.useCache = false;
    Effect effect(device, EffectSource{text, name}, options);
    Texture2D texture(device, 4, 1, false, SurfaceFormat::Color);
    texture.SetData(kRamp);
    effect.Parameters[rampParameter].SetValue(texture);
    if (set) set(effect);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    RenderTarget2D target(device, 4, 1, false, SurfaceFormat::Vector4);
    struct Unbind {
        GraphicsDevice& d;
        ~Unbind() { d.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }
    } unbind{device};
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    return readFloats(target);
}

std::vector<float> drawRamp(const std::string& sample, const std::string& filter, float shift = 0) {
    const std::string text =
        "texture RampTexture;\n"
        "sampler1D ramp = sampler_state { Texture = <RampTexture>; MinFilter = " + filter + "; MagFilter = " + filter +
        "; MipFilter = Point; AddressU = Clamp; AddressV = Clamp; };\n"
        "float Shift;\n"
        "float4 fromParameter(sampler1D s, float u) { return tex1D(s, u); }\n"
        "void VS(inout float4 p : POSITION0, inout float2 uv : TEXCOORD0) {}\n"
        "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { uv.x += Shift; return " + sample + "; }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    return drawEffect(text, "OneRowTextures.fx", "RampTexture", [&](Effect& e) { e.Parameters["Shift"].SetValue(shift); });
}

std::array<float, 4> texel(size_t x) { return {kRamp[x].R / 255.0f, kRamp[x].G / 255.0f, kRamp[x].B / 255.0f, kRamp[x].A / 255.0f}; }

void expectTexels(const std::string& sample) {
    std::vector<float> px = drawRamp(sample, "Point", 0.125f);
    ASSERT_EQ(px.size(), 16u);
    for (size_t x = 0; x < 4; ++x)
        for (size_t c = 0; c < 4; ++c) EXPECT_NEAR(px[x * 4 + c], texel(x)[c], 1e-6f) << sample << ": pixel " << x << " channel " << c;
}

TEST(OneRowTextures, EveryTex1DFormReadsTheTexelUnderThePixel) {
    expectTexels("tex1D(ramp, uv.x)");
    expectTexels("tex1D(ramp, uv)");  // a float2 converts to the float tex1D takes
    expectTexels("tex1D(ramp, uv.x, 0, 0)");
    expectTexels("tex1Dgrad(ramp, uv.x, 0, 0)");
    expectTexels("tex1Dlod(ramp, float4(uv.x, 0, 0, 0))");
    expectTexels("tex1Dbias(ramp, float4(uv.x, 0, 0, 0))");
    expectTexels("tex1Dproj(ramp, float4(2 * uv.x, 7, 0, 2))");
    expectTexels("fromParameter(ramp, uv.x)");
}

// Halfway between two texels a linear filter gives their average (the row's other neighbour is
// itself, so the rows do not blend).
TEST(OneRowTextures, LinearFilterBlendsNeighboursOfTheRow) {
    std::vector<float> px = drawRamp("tex1D(ramp, uv.x)", "Linear", 0.25f);
    ASSERT_EQ(px.size(), 16u);
    for (size_t x = 0; x < 3; ++x)
        for (size_t c = 0; c < 4; ++c)
            EXPECT_NEAR(px[x * 4 + c], (texel(x)[c] + texel(x + 1)[c]) / 2, 1.5f / 255.0f) << "pixel " << x << " channel " << c;
}

// A D3D10 Texture1D object reads a 1D texture (fxport::Texture1D); given a 2D one (which GL
// would read as black) the draw names the slot and both dimensions instead.
TEST(OneRowTextures, Texture1DObjectOverA2DTextureIsRefusedAtTheDraw) {
    const std::string text =
        "Texture1D Ramp; SamplerState Linear;\n"
        "float4 VS(float4 p : POSITION0) : SV_Position { return p; }\n"
        "float4 PS(float4 p : SV_Position) : SV_Target { return Ramp.Sample(Linear, p.x / 4); }\n"
        "technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }\n";
    try {
        drawEffect(text, "Texture1DObject.fx", "Ramp");
        ADD_FAILURE() << "a Texture1D sampled from a 2D texture drew";
    } catch (const InvalidOperation& e) {
        EXPECT_NE(std::string(e.what()).find("samples a 1D texture at unit 0 but Textures[0] holds a 2D texture"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fxport
