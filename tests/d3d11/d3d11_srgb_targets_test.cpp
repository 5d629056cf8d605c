// D3D10+'s _SRGB render-target views store what is written sRGB-encoded: ClearRenderTargetView's
// colour and a pixel shader's output (linear values) land as the CPU's linear-to-sRGB encoding of
// them, through an R8G8B8A8_UNORM_SRGB texture's own view and through an _SRGB view of an
// R8G8B8A8_TYPELESS texture; an R8G8B8A8_UNORM view of the same texture stores the values as given.
#include <cmath>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

int encodedByte(float linear) {
    const float s = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return int(std::lround(s * 255.0f));
}

ComPtr<ID3D11Texture2D> target(Device& d, DXGI_FORMAT format) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = format;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

ComPtr<ID3D11RenderTargetView> targetViewAs(Device& d, ID3D11Texture2D* t, DXGI_FORMAT format) {
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.Format = format;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(t, &desc, rtv.GetAddressOf()), S_OK) << lastError();
    return rtv;
}

void draw(Device& d, ID3D11RenderTargetView* rtv) {
    const char* text = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
float4 ps() : SV_Target { return float4(0.5, 0.2, 0.01, 0.75); }
)";
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, &rtv, nullptr);
    D3D11_VIEWPORT viewport{0, 0, 2, 2, 0, 1};
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
}

void expectEvery(const std::vector<Rgba>& got, const std::array<int, 4>& want, const char* what) {
    ASSERT_EQ(got.size(), 4u) << what;
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(int(got[i][c]), want[c], 1) << what << ": texel " << i << " channel " << c;
}

// The clear (0.5, 0.25, 1, 0.5) and the draw (0.5, 0.2, 0.01, 0.75): colour channels encoded, alpha as given.
void expectEncoded(Device& d, ID3D11Texture2D* t, ID3D11RenderTargetView* rtv, const char* what) {
    const float clear[4] = {0.5f, 0.25f, 1.0f, 0.5f};
    d.context->ClearRenderTargetView(rtv, clear);
    expectEvery(readPixels(d, t), {encodedByte(0.5f), encodedByte(0.25f), 255, 128}, what);
    draw(d, rtv);
    expectEvery(readPixels(d, t), {encodedByte(0.5f), encodedByte(0.2f), encodedByte(0.01f), 191}, what);
}

TEST(D3D11SrgbTargets, AnSrgbTextureStoresClearsAndDrawsEncoded) {
    Device d;
    ComPtr<ID3D11Texture2D> t = target(d, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB);
    ASSERT_TRUE(t);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    expectEncoded(d, t.Get(), rtv.Get(), "R8G8B8A8_UNORM_SRGB");
}

TEST(D3D11SrgbTargets, AnSrgbViewOfATypelessTextureEncodesAndAUnormViewDoesNot) {
    Device d;
    ComPtr<ID3D11Texture2D> t = target(d, DXGI_FORMAT_R8G8B8A8_TYPELESS);
    ASSERT_TRUE(t);
    ComPtr<ID3D11RenderTargetView> srgb = targetViewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UNORM_SRGB), unorm = targetViewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UNORM);
    ASSERT_TRUE(srgb && unorm);
    expectEncoded(d, t.Get(), srgb.Get(), "R8G8B8A8_UNORM_SRGB view");
    const float clear[4] = {0.5f, 0.25f, 1.0f, 0.5f};
    d.context->ClearRenderTargetView(unorm.Get(), clear);
    expectEvery(readPixels(d, t.Get()), {128, 64, 255, 128}, "R8G8B8A8_UNORM view, cleared");
    draw(d, unorm.Get());
    expectEvery(readPixels(d, t.Get()), {128, 51, 3, 191}, "R8G8B8A8_UNORM view, drawn");
}

}  // namespace
}  // namespace d3d11test
