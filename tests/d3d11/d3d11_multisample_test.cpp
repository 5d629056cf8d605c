// Multisampled render targets through the D3D11 front end (SampleDesc.Count = 4): a pixel shader
// run per sample (SV_SampleIndex) writes 2^sample into each sample; ResolveSubresource averages
// them (3.75, the CPU mean of 1, 2, 4, 8); a second pass reads every sample back through
// Texture2DMS.Load and GetDimensions' sample count from a TEXTURE2DMS view; a one-sample texture
// read as Texture2DMS gives its texels as sample 0; and the descriptions
// and copies D3D refuses for multisampled textures, answered with the field and value.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kFullScreen = kFullScreenVertexShader;

using Texel = std::array<float, 4>;
constexpr UINT kSize = 4, kSamples = 4;

D3D11_TEXTURE2D_DESC targetDesc(UINT samples) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = samples;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    return desc;
}

// Draws `ps` (entry "ps") over the whole of `rtv` (kSize x kSize) with `view` at t0 if given.
void draw(Device& d, const std::string& ps, ID3D11RenderTargetView* rtv, ID3D11ShaderResourceView* view = nullptr) {
    const std::string text = std::string(kFullScreen) + ps;
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> p;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, p.GetAddressOf()), S_OK) << lastError();
    ID3D11ShaderResourceView* none = nullptr;
    d.context->PSSetShaderResources(0, 1, &none);  // the target of the last pass may be read now
    d.context->OMSetRenderTargets(1, &rtv, nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(p.Get(), nullptr, 0);
    if (view) d.context->PSSetShaderResources(0, 1, &view);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
}

TEST(D3D11Multisample, PerSampleValuesResolveToTheirMeanAndLoadOneByOne) {
    Device d;
    D3D11_TEXTURE2D_DESC desc = targetDesc(kSamples);
    ComPtr<ID3D11Texture2D> samples;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, samples.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> samplesRtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(samples.Get(), nullptr, samplesRtv.GetAddressOf()), S_OK) << lastError();
    D3D11_RENDER_TARGET_VIEW_DESC rtvDesc;
    samplesRtv->GetDesc(&rtvDesc);
    EXPECT_EQ(rtvDesc.ViewDimension, D3D11_RTV_DIMENSION_TEXTURE2DMS);
    draw(d, R"(
float4 ps(float4 pos : SV_Position, uint id : SV_SampleIndex) : SV_Target { return float4(1u << id, pos.x, pos.y, id); }
)",
         samplesRtv.Get());

    // The resolve: each pixel's four samples averaged.
    D3D11_TEXTURE2D_DESC singleDesc = targetDesc(1);
    singleDesc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> single;
    ASSERT_EQ(d.device->CreateTexture2D(&singleDesc, nullptr, single.GetAddressOf()), S_OK) << lastError();
    d.context->ResolveSubresource(single.Get(), 0, samples.Get(), 0, DXGI_FORMAT_R32G32B32A32_FLOAT);
    EXPECT_EQ(lastError(), "");
    const std::vector<Texel> mean = readTexels<Texel>(d, single.Get());
    const float expectedMean = (1.0f + 2.0f + 4.0f + 8.0f) / 4.0f, meanIndex = (0.0f + 1.0f + 2.0f + 3.0f) / 4.0f;
    ASSERT_EQ(mean.size(), std::size_t(kSize * kSize));
    for (UINT i = 0; i < kSize * kSize; ++i) {
        EXPECT_EQ(mean[i][0], expectedMean) << "pixel " << i;
        EXPECT_EQ(mean[i][3], meanIndex) << "pixel " << i;
    }

    // Each sample on its own, through a TEXTURE2DMS view: sample s of pixel (x, y) into pixel (x, y) of target s.
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(samples.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE2DMS);
    ComPtr<ID3D11RenderTargetView> singleRtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(single.Get(), nullptr, singleRtv.GetAddressOf()), S_OK) << lastError();
    for (UINT s = 0; s < kSamples; ++s) {
        draw(d, R"(
Texture2DMS<float4> Samples : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    uint w, h, n;
    Samples.GetDimensions(w, h, n);
    float4 v = Samples.Load(int2(pos.xy), )" + std::to_string(s) + R"();
    return float4(v.x, v.w, n, w * 100 + h);
})",
             singleRtv.Get(), view.Get());
        const std::vector<Texel> got = readTexels<Texel>(d, single.Get());
        for (UINT i = 0; i < kSize * kSize; ++i)
            EXPECT_EQ(got[i], (Texel{float(1u << s), float(s), float(kSamples), float(kSize * 100 + kSize)})) << "sample " << s << ", pixel " << i;
    }
}

// D3D reads a one-sample texture bound where a shader declares Texture2DMS: Load(p, 0) is its texel
// (vkd3d's suite relies on it). A Texture2D declaration reading a multisampled texture is refused.
TEST(D3D11Multisample, SingleSampleTextureLoadsAsSampleZeroOfATexture2DMS) {
    Device d;
    std::vector<Texel> texels(kSize * kSize);
    for (UINT i = 0; i < kSize * kSize; ++i) texels[i] = {float(i), float(i % kSize) * 0.5f, float(i / kSize) * 0.25f, 1.0f};
    D3D11_TEXTURE2D_DESC sourceDesc = targetDesc(1);
    sourceDesc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    D3D11_SUBRESOURCE_DATA data = {texels.data(), kSize * sizeof(Texel), 0};
    ComPtr<ID3D11Texture2D> source, target;
    ASSERT_EQ(d.device->CreateTexture2D(&sourceDesc, &data, source.GetAddressOf()), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC targetDescription = targetDesc(1);
    targetDescription.BindFlags = D3D11_BIND_RENDER_TARGET;
    ASSERT_EQ(d.device->CreateTexture2D(&targetDescription, nullptr, target.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(source.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    draw(d, R"(
Texture2DMS<float4, 1> Source : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Source.Load(int2(pos.xy), 0); }
)",
         rtv.Get(), view.Get());
    EXPECT_EQ(readTexels<Texel>(d, target.Get()), texels);

    // The other way round: a multisampled texture where the shader declares a Texture2D.
    D3D11_TEXTURE2D_DESC samplesDesc = targetDesc(kSamples);
    ComPtr<ID3D11Texture2D> samples;
    ASSERT_EQ(d.device->CreateTexture2D(&samplesDesc, nullptr, samples.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> samplesView;
    ASSERT_EQ(d.device->CreateShaderResourceView(samples.Get(), nullptr, samplesView.GetAddressOf()), S_OK) << lastError();
    const std::string text = std::string(kFullScreen) + "Texture2D Source : register(t0);\n"
                             "float4 ps(float4 pos : SV_Position) : SV_Target { return Source.Load(int3(pos.xy, 0)); }\n";
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->PSSetShaderResources(0, 1, samplesView.GetAddressOfConst());
    d.context->Draw(3, 0);
    EXPECT_NE(lastError().find("holds the multisampled texture"), std::string::npos) << lastError();
}

TEST(D3D11Multisample, RefusedDescriptionsCopiesAndResolvesNameTheField) {
    Device d;
    ComPtr<ID3D11Texture2D> t;
    D3D11_TEXTURE2D_DESC desc = targetDesc(3);
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("SampleDesc.Count = 3"), std::string::npos) << lastError();
    desc = targetDesc(kSamples);
    desc.MipLevels = 0;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MipLevels = 0 for a multisampled texture"), std::string::npos) << lastError();
    desc.MipLevels = 1;
    const float texels[kSize * kSize * 4] = {};
    D3D11_SUBRESOURCE_DATA data = {texels, kSize * 16, 0};
    EXPECT_EQ(d.device->CreateTexture2D(&desc, &data, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("with pInitialData"), std::string::npos) << lastError();
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("BindFlags = 8 with SampleDesc.Count = 4"), std::string::npos) << lastError();

    desc = targetDesc(kSamples);
    ComPtr<ID3D11Texture2D> samples, single;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, samples.GetAddressOf()), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC singleDesc = targetDesc(1);
    ASSERT_EQ(d.device->CreateTexture2D(&singleDesc, nullptr, single.GetAddressOf()), S_OK) << lastError();
    // A single-sample view of a multisampled texture, and the other way round.
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    viewDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(samples.Get(), &viewDesc, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_SRV_DIMENSION_TEXTURE2DMS"), std::string::npos) << lastError();
    viewDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DMS;
    EXPECT_EQ(d.device->CreateShaderResourceView(single.Get(), &viewDesc, view.GetAddressOf()), E_INVALIDARG);
    // Copies keep the sample count; a resolve goes from many samples to one, in the textures' format.
    d.context->CopyResource(single.Get(), samples.Get());
    EXPECT_NE(lastError().find("differ in SampleDesc.Count"), std::string::npos) << lastError();
    d.context->ResolveSubresource(samples.Get(), 0, single.Get(), 0, DXGI_FORMAT_R32G32B32A32_FLOAT);
    EXPECT_NE(lastError().find("the source was not made with SampleDesc.Count > 1"), std::string::npos) << lastError();
    d.context->ResolveSubresource(single.Get(), 0, samples.Get(), 0, DXGI_FORMAT_R8G8B8A8_UNORM);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R8G8B8A8_UNORM"), std::string::npos) << lastError();
}

// A 4x multisampled swap chain drawn with a 4x depth buffer (what a D3D11 game asks for when it
// turns MSAA on): three full-screen triangles at depths 0.5 (red), 0.7 (blue, behind it: hidden
// everywhere) and 0.3 (green, the left half only, in front). The resolved back buffer is green on
// the left and red on the right, which only a depth test of every sample gives.
TEST(D3D11Multisample, MultisampledSwapChainAndDepthBufferTestDepthPerSample) {
    DXGI_SWAP_CHAIN_DESC sd;
    sd.BufferCount = 1;
    sd.BufferDesc.Width = sd.BufferDesc.Height = 8;
    sd.BufferDesc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    sd.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    sd.SampleDesc.Count = kSamples;
    Device d;
    d.device.Reset();
    d.context.Reset();
    ComPtr<IDXGISwapChain> swapChain;
    ASSERT_EQ(D3D11CreateDeviceAndSwapChain(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, &sd,
                                            swapChain.GetAddressOf(), d.device.GetAddressOf(), nullptr, d.context.GetAddressOf()),
              S_OK)
        << lastError();
    UINT levels = 0;
    ASSERT_EQ(d.device->CheckMultisampleQualityLevels(DXGI_FORMAT_D24_UNORM_S8_UINT, kSamples, &levels), S_OK);
    EXPECT_EQ(levels, 1u);
    ComPtr<ID3D11Texture2D> backBuffer, depth;
    ASSERT_EQ(swapChain->GetBuffer(0, IID_ID3D11Texture2D, reinterpret_cast<void**>(backBuffer.GetAddressOf())), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC desc;
    backBuffer->GetDesc(&desc);
    EXPECT_EQ(desc.SampleDesc.Count, kSamples);
    desc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, depth.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateRenderTargetView(backBuffer.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsv->GetDesc(&dsvDesc);
    EXPECT_EQ(dsvDesc.ViewDimension, D3D11_DSV_DIMENSION_TEXTURE2DMS);
    const FLOAT black[4] = {0, 0, 0, 1};
    d.context->ClearRenderTargetView(rtv.Get(), black);
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), dsv.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    struct Layer { const char* z; const char* colour; float width; };
    for (const Layer& layer : {Layer{"0.5", "float4(1, 0, 0, 1)", 8}, Layer{"0.7", "float4(0, 0, 1, 1)", 8}, Layer{"0.3", "float4(0, 1, 0, 1)", 4}}) {
        const std::string text = std::string(R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), )") + layer.z + R"(, 1);
}
float4 ps() : SV_Target { return )" + layer.colour + "; }\n";
        ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
        ASSERT_TRUE(vsCode && psCode);
        ComPtr<ID3D11VertexShader> vs;
        ComPtr<ID3D11PixelShader> ps;
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
        D3D11_VIEWPORT viewport;
        viewport.Width = layer.width;
        viewport.Height = 8;
        d.context->RSSetViewports(1, &viewport);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->Draw(3, 0);  // D3D's default depth state: test LESS, write
        EXPECT_EQ(lastError(), "");
    }
    EXPECT_EQ(swapChain->Present(0, 0), S_OK);
    D3D11_TEXTURE2D_DESC singleDesc = desc;
    singleDesc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    singleDesc.SampleDesc.Count = 1;
    singleDesc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> single;
    ASSERT_EQ(d.device->CreateTexture2D(&singleDesc, nullptr, single.GetAddressOf()), S_OK) << lastError();
    d.context->ResolveSubresource(single.Get(), 0, backBuffer.Get(), 0, DXGI_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(lastError(), "");
    const auto pixels = readPixels(d, single.Get());
    ASSERT_EQ(pixels.size(), 64u);
    for (int i = 0; i < 64; ++i) {
        const bool left = i % 8 < 4;
        EXPECT_EQ(pixels[std::size_t(i)], (std::array<std::uint8_t, 4>{std::uint8_t(left ? 0 : 255), std::uint8_t(left ? 255 : 0), 0, 255}))
            << "pixel " << i;
    }
}

}  // namespace
}  // namespace d3d11test
