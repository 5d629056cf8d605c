// XNA 4's vertex textures: GraphicsDevice::VertexTextures and VertexSamplerStates feed an SM 1-3
// vertex shader's samplers by their s# (D3D9's vertex texture samplers), apart from the pixel
// samplers' Textures[]. A vs_3_0 terrain-style shader raises four columns of an 8x8 target to the
// heights it reads with tex2Dlod from a 4x1 Single texture; the rows each column fills are
// compared with the CPU's count from the same heights -- with the texture set by the effect's
// parameter (which lands in VertexTextures[0], as XNA's effects put it), and set by the host in
// VertexTextures[0] while Textures[0] holds a decoy of other heights.
#include <gtest/gtest.h>

#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {
namespace {

// Each column's top vertices (z = 1) rise to -1 + 2h of the height h under their uv; the bottom
// ones (z = 0) stay at the target's bottom edge. The colour is the height read.
const char* const kDisplaced = R"(
texture HeightMap;
sampler FromParameter = sampler_state { Texture = <HeightMap>; MinFilter = Point; MagFilter = Point; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };
sampler FromDevice;
struct VSOut { float4 pos : POSITION0; float4 colour : COLOR0; };
VSOut Raise(float h, float3 pos) {
    VSOut o;
    o.pos = float4(pos.x, -1 + 2 * h * pos.z, 0, 1);
    o.colour = float4(h, 1, 0, 1);
    return o;
}
VSOut ParameterVS(float3 pos : POSITION0, float2 uv : TEXCOORD0) { return Raise(tex2Dlod(FromParameter, float4(uv, 0, 0)).r, pos); }
VSOut DeviceVS(float3 pos : POSITION0, float2 uv : TEXCOORD0) { return Raise(tex2Dlod(FromDevice, float4(uv, 0, 0)).r, pos); }
float4 PS(float4 colour : COLOR0) : COLOR0 { return colour; }
technique Parameter { pass P { VertexShader = compile vs_3_0 ParameterVS(); PixelShader = compile ps_3_0 PS(); } }
technique Device { pass P { VertexShader = compile vs_3_0 DeviceVS(); PixelShader = compile ps_3_0 PS(); } }
)";

constexpr int kSize = 8, kColumns = 4;

// Column i's top edge lies a quarter pixel above row boundary rows[i] from the bottom: it fills
// that many rows under D3D9's and D3D10's pixel centres alike.
std::vector<float> heightsFilling(const std::vector<int>& rows) {
    std::vector<float> h;
    for (int r : rows) h.push_back((float(r) + 0.25f) / float(kSize));
    return h;
}

// Column i spans pixels 2i + 0.25 .. 2i + 1.75; pixel column 2i + 1 is inside it under either
// convention. Two triangles per column, uv at the texel's centre.
std::vector<VertexPositionTexture> columns() {
    std::vector<VertexPositionTexture> v;
    for (int i = 0; i < kColumns; ++i) {
        const float left = -1 + 2 * (2 * i + 0.25f) / kSize, right = -1 + 2 * (2 * i + 1.75f) / kSize;
        const Vector2 uv((float(i) + 0.5f) / kColumns, 0.5f);
        const VertexPositionTexture bl(Vector3(left, -1, 0), uv), br(Vector3(right, -1, 0), uv), tl(Vector3(left, 0, 1), uv),
            tr(Vector3(right, 0, 1), uv);
        for (const VertexPositionTexture& p : {tl, tr, bl, bl, tr, br}) v.push_back(p);
    }
    return v;
}

// Draws the columns with `technique` and returns, per column, the rows filled (from the bottom)
// and the height colour of its bottom pixel.
std::vector<std::pair<int, float>> drawColumns(GraphicsDevice& device, Effect& effect, const char* technique) {
    RenderTarget2D target(device, kSize, kSize, false, SurfaceFormat::Vector4);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect.CurrentTechnique = effect.Techniques[technique];
    effect.CurrentTechnique->Passes[0].Apply();
    const std::vector<VertexPositionTexture> v = columns();
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v.data(), 0, int(v.size() / 3));
    const std::vector<float> rgba = readFloats(target);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<std::pair<int, float>> out;
    for (int i = 0; i < kColumns; ++i) {
        const int x = 2 * i + 1;
        int filled = 0;
        for (int y = 0; y < kSize; ++y) filled += rgba[std::size_t((y * kSize + x) * 4 + 1)] > 0.5f ? 1 : 0;  // green: drawn
        out.emplace_back(filled, rgba[std::size_t(((kSize - 1) * kSize + x) * 4)]);
    }
    return out;
}

void expectColumns(const std::vector<std::pair<int, float>>& got, const std::vector<int>& rows) {
    ASSERT_EQ(got.size(), rows.size());
    const std::vector<float> h = heightsFilling(rows);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(got[i].first, rows[i]) << "rows filled by column " << i;
        EXPECT_NEAR(got[i].second, h[i], 1e-6f) << "height read by column " << i;
    }
}

std::unique_ptr<Texture2D> heightTexture(GraphicsDevice& device, const std::vector<int>& rows) {
    auto t = std::make_unique<Texture2D>(device, kColumns, 1, false, SurfaceFormat::Single);
    t->SetData(heightsFilling(rows));
    return t;
}

TEST(VertexTextures, AnEffectParameterFeedsTheVertexTextureSlot) {
    GraphicsDevice& device = testDevice();
    EffectOptions options;
    options.useCache = false;
    Effect effect(device, EffectSource{kDisplaced, "Displaced.fx"}, options);
    const std::vector<int> rows = {1, 3, 5, 7};
    std::unique_ptr<Texture2D> heights = heightTexture(device, rows);
    device.Textures[0] = nullptr;
    effect.Parameters["HeightMap"].SetValue(heights.get());
    expectColumns(drawColumns(device, effect, "Parameter"), rows);
    // As XNA's effect does: the vertex shader's sampler s0 is vertex texture 0, not Textures[0].
    EXPECT_EQ(device.VertexTextures[0].get(), heights.get());
    EXPECT_EQ(device.Textures[0].get(), nullptr);
    EXPECT_EQ(device.VertexSamplerStates[0].Filter, TextureFilter::Point);
    device.VertexTextures[0] = nullptr;
}

TEST(VertexTextures, TheHostsVertexTextureIsReadNotTexturesOfTheSameIndex) {
    GraphicsDevice& device = testDevice();
    EffectOptions options;
    options.useCache = false;
    Effect effect(device, EffectSource{kDisplaced, "Displaced.fx"}, options);
    const std::vector<int> rows = {6, 2, 8, 4}, decoyRows = {1, 1, 1, 1};
    std::unique_ptr<Texture2D> heights = heightTexture(device, rows), decoy = heightTexture(device, decoyRows);
    device.VertexTextures[0] = heights.get();
    device.VertexSamplerStates[0] = SamplerState::PointClamp;
    device.Textures[0] = decoy.get();
    expectColumns(drawColumns(device, effect, "Device"), rows);
    device.VertexTextures[0] = nullptr;
    device.Textures[0] = nullptr;
}

}  // namespace
}  // namespace fxport::test
