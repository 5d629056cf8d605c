// 3D textures through the D3D11 front end: CreateTexture3D with padded row and slice pitches, a
// TEXTURE3D shader-resource view, every texel read back through Texture3D.Load (and a second
// level of a full chain) and compared with the texels written; Sample with a linear filter at
// the volume's centre against the CPU average of the eight texels; and the descriptions fxport
// refuses, answered with the field and value.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kFullScreen = kFullScreenVertexShader;

ComPtr<ID3D11Texture2D> floatTarget(Device& d, UINT width, UINT height) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Draws `ps` (entry "ps") over `target` with `view` at t0 and `sampler` (if any) at s0.
void drawInto(Device& d, const std::string& ps, ID3D11Texture2D* target, UINT width, UINT height, ID3D11ShaderResourceView* view,
              ID3D11SamplerState* sampler = nullptr) {
    const std::string text = std::string(kFullScreen) + ps;
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> p;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, p.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target, nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = float(width);
    viewport.Height = float(height);
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(p.Get(), nullptr, 0);
    d.context->PSSetShaderResources(0, 1, &view);
    if (sampler) d.context->PSSetSamplers(0, 1, &sampler);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
}

using Texel = std::array<float, 4>;

// A distinct value per texel and channel: (x, y, z, level) coded so no two texels are equal.
Texel texelAt(int x, int y, int z, int level) { return {float(x) + 0.25f, float(y) * 10.0f, float(z) * 100.0f, float(level) + 0.5f}; }

TEST(D3D11Texture3D, EveryTexelLoadsWhatWasWrittenThroughPaddedPitches) {
    Device d;
    constexpr int kW = 3, kH = 2, kD = 4;
    // Level 0 with rows padded to 64 bytes and slices to 3 rows; level 1 (1x1x2) tight.
    constexpr UINT kPitch = 64, kSlicePitch = 3 * kPitch;
    std::vector<std::uint8_t> level0(std::size_t(kSlicePitch) * kD, 0xee);
    for (int z = 0; z < kD; ++z)
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const Texel t = texelAt(x, y, z, 0);
                std::memcpy(&level0[std::size_t(z) * kSlicePitch + std::size_t(y) * kPitch + std::size_t(x) * sizeof(Texel)], t.data(), sizeof(Texel));
            }
    const Texel level1[2] = {texelAt(0, 0, 0, 1), texelAt(0, 0, 1, 1)};
    D3D11_TEXTURE3D_DESC desc;
    desc.Width = kW;
    desc.Height = kH;
    desc.Depth = kD;
    desc.MipLevels = 0;  // the full chain: 3x2x4, 1x1x2, 1x1x1
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    const Texel level2 = texelAt(0, 0, 0, 2);
    D3D11_SUBRESOURCE_DATA data[3] = {{level0.data(), kPitch, kSlicePitch}, {level1, sizeof(Texel), sizeof(Texel)}, {&level2, sizeof(Texel), sizeof(Texel)}};
    ComPtr<ID3D11Texture3D> volume;
    ASSERT_EQ(d.device->CreateTexture3D(&desc, data, volume.GetAddressOf()), S_OK) << lastError();
    D3D11_TEXTURE3D_DESC got;
    volume->GetDesc(&got);
    EXPECT_EQ(got.MipLevels, 3u);
    D3D11_RESOURCE_DIMENSION dimension = D3D11_RESOURCE_DIMENSION_UNKNOWN;
    volume->GetType(&dimension);
    EXPECT_EQ(dimension, D3D11_RESOURCE_DIMENSION_TEXTURE3D);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(volume.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE3D);
    EXPECT_EQ(viewDesc.Texture3D.MipLevels, 3u);

    // Row y of the target: level 0's row y, slice by slice (x = slice * kW + column); row kH: level 1's two texels.
    ComPtr<ID3D11Texture2D> target = floatTarget(d, kW * kD, kH + 1);
    drawInto(d, R"(
Texture3D<float4> Volume : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    if (p.y == 2) return p.x < 2 ? Volume.Load(int4(0, 0, p.x, 1)) : Volume.Load(int4(0, 0, 0, 2));
    return Volume.Load(int4(p.x % 3, p.y, p.x / 3, 0));
})",
             target.Get(), kW * kD, kH + 1, view.Get());
    const std::vector<Texel> pixels = readTexels<Texel>(d, target.Get());
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW * kD; ++x)
            EXPECT_EQ(pixels[std::size_t(y * kW * kD + x)], texelAt(x % kW, y, x / kW, 0)) << "pixel " << x << "," << y;
    EXPECT_EQ(pixels[std::size_t(kH * kW * kD + 0)], level1[0]);
    EXPECT_EQ(pixels[std::size_t(kH * kW * kD + 1)], level1[1]);
    EXPECT_EQ(pixels[std::size_t(kH * kW * kD + 2)], level2);
}

TEST(D3D11Texture3D, LinearSampleAtTheCentreAveragesTheEightTexels) {
    Device d;
    Texel texels[8];
    Texel average = {0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        texels[i] = {float(i & 1), float((i >> 1) & 1) * 0.5f, float(i >> 2) * 0.25f, float(i) / 8.0f};
        for (int c = 0; c < 4; ++c) average[std::size_t(c)] += texels[i][std::size_t(c)] / 8.0f;
    }
    D3D11_TEXTURE3D_DESC desc;
    desc.Width = desc.Height = desc.Depth = 2;
    desc.MipLevels = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    D3D11_SUBRESOURCE_DATA data = {texels, 2 * sizeof(Texel), 4 * sizeof(Texel)};
    ComPtr<ID3D11Texture3D> volume;
    ASSERT_EQ(d.device->CreateTexture3D(&desc, &data, volume.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    viewDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE3D;
    viewDesc.Texture3D.MipLevels = UINT(-1);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(volume.Get(), &viewDesc, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC samplerDesc;
    samplerDesc.Filter = D3D11_FILTER_MIN_MAG_MIP_LINEAR;
    ComPtr<ID3D11SamplerState> linear;
    ASSERT_EQ(d.device->CreateSamplerState(&samplerDesc, linear.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = floatTarget(d, 1, 1);
    drawInto(d, R"(
Texture3D Volume : register(t0);
SamplerState Linear : register(s0);
float4 ps() : SV_Target { return Volume.Sample(Linear, float3(0.5, 0.5, 0.5)); }
)",
             target.Get(), 1, 1, view.Get(), linear.Get());
    const Texel got = readTexels<Texel>(d, target.Get())[0];
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[std::size_t(c)], average[std::size_t(c)], 1e-6f) << "channel " << c;
}

TEST(D3D11Texture3D, RefusedDescriptionsAndViewsNameTheField) {
    Device d;
    D3D11_TEXTURE3D_DESC desc;
    desc.Width = desc.Height = 4;
    desc.Depth = 0;
    desc.MipLevels = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture3D> volume;
    EXPECT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Width x Height x Depth = 4 x 4 x 0"), std::string::npos) << lastError();
    desc.Depth = 4;
    desc.MipLevels = 2;
    EXPECT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("MipLevels = 2"), std::string::npos) << lastError();
    desc.MipLevels = 4;
    EXPECT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MipLevels = 4 (this volume has at most 3)"), std::string::npos) << lastError();
    desc.MipLevels = 1;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    EXPECT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("BindFlags = 40"), std::string::npos) << lastError();
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    EXPECT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("USAGE_IMMUTABLE without pInitialData"), std::string::npos) << lastError();
    desc.Usage = D3D11_USAGE_DEFAULT;
    const std::uint32_t texels[4 * 4 * 4] = {};
    D3D11_SUBRESOURCE_DATA data = {texels, 16, 32};  // a slice pitch of two rows for four
    EXPECT_EQ(d.device->CreateTexture3D(&desc, &data, volume.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("pInitialData[0].SysMemSlicePitch = 32"), std::string::npos) << lastError();
    ASSERT_EQ(d.device->CreateTexture3D(&desc, nullptr, volume.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    viewDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(volume.Get(), &viewDesc, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ViewDimension = 4 for a 3D texture"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
