// Shadow maps as D3D11 programs make them: a typeless texture (R32_TYPELESS, R16_TYPELESS) with
// BIND_DEPTH_STENCIL | BIND_SHADER_RESOURCE, written through its depth-stencil view (D32_FLOAT,
// D16_UNORM) by a draw whose depth runs across the target, then read through its shader-resource
// view (R32_FLOAT, R16_UNORM) by Load and by SampleCmpLevelZero with a comparison sampler; both
// compared per pixel with the CPU's plane depth; the same through a depth-only pass (no render
// target, no pixel shader). D32_FLOAT depth buffers; the stencil of R24G8 / R32G8X24 shadow maps
// (INCR_SAT draws over narrowing viewports) read through X24_TYPELESS_G8_UINT /
// X32_TYPELESS_G8X24_UINT views as (0, stencil, 0, 1) beside their depth; the descriptions D3D
// refuses (a D24_UNORM_S8_UINT texture with SHADER_RESOURCE, a typeless texture's view without a
// format, a view of the wrong format) answered with the field and value.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

constexpr UINT kSize = 4;

// Pass 1: one triangle over the target, depth = 0.25 * u (u the horizontal position in 0..1).
const char* const kDepthPass = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), corner.x * 0.25, 1);
}
float4 ps() : SV_Target { return float4(1, 1, 1, 1); }
)";

// Pass 2: each pixel reads its own texel of the depth texture and compares 0.06 with it.
const char* const kReadPass = R"(
Texture2D<float> Depth : register(t0);
SamplerComparisonState Less : register(s0);
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
float4 ps(float4 pos : SV_Position) : SV_Target {
    float2 uv = pos.xy / 4;
    return float4(Depth.Load(int3(pos.xy, 0)), Depth.SampleCmpLevelZero(Less, uv, 0.06), 0, 1);
}
)";

float planeDepth(UINT x) { return 0.25f * (float(x) + 0.5f) / float(kSize); }

struct Shaders {
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    Shaders(Device& d, const char* source) {
        ComPtr<ID3DBlob> v = compile(source, "vs", "vs_5_0"), p = compile(source, "ps", "ps_5_0");
        if (!v || !p) return;
        EXPECT_EQ(d.device->CreateVertexShader(v->GetBufferPointer(), v->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreatePixelShader(p->GetBufferPointer(), p->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    }
    void set(Device& d) {
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
    }
};

ComPtr<ID3D11Texture2D> makeTarget(Device& d, DXGI_FORMAT format, UINT bind) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = format;
    desc.BindFlags = bind;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Renders the plane into a `typeless` shadow map through a `depthView` DSV, reads it back through
// an `sampledView` SRV: (depth read, comparison result) per pixel of the top row.
// `depthOnly`: the depth pass binds no render target and no pixel shader, as shadow-map passes do.
std::vector<std::array<float, 2>> shadowRoundTrip(DXGI_FORMAT typeless, DXGI_FORMAT depthView, DXGI_FORMAT sampledView, bool depthOnly = false) {
    Device d;
    std::vector<std::array<float, 2>> out;
    ComPtr<ID3D11Texture2D> shadow = makeTarget(d, typeless, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11Texture2D> colour = makeTarget(d, DXGI_FORMAT_R8G8B8A8_UNORM, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11Texture2D> result = makeTarget(d, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    if (!shadow || !colour || !result) return out;
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = depthView;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(shadow.Get(), &dsvDesc, dsv.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = sampledView;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    srvDesc.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(shadow.Get(), &srvDesc, srv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> colourView, resultView;
    EXPECT_EQ(d.device->CreateRenderTargetView(colour.Get(), nullptr, colourView.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateRenderTargetView(result.Get(), nullptr, resultView.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC samplerDesc;
    samplerDesc.Filter = D3D11_FILTER_COMPARISON_MIN_MAG_MIP_POINT;
    samplerDesc.ComparisonFunc = D3D11_COMPARISON_LESS;
    ComPtr<ID3D11SamplerState> sampler;
    EXPECT_EQ(d.device->CreateSamplerState(&samplerDesc, sampler.GetAddressOf()), S_OK) << lastError();
    if (!dsv || !srv || !colourView || !resultView || !sampler) return out;

    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    Shaders depthPass(d, kDepthPass), readPass(d, kReadPass);
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    d.context->OMSetRenderTargets(depthOnly ? 0 : 1, depthOnly ? nullptr : colourView.GetAddressOfConst(), dsv.Get());
    depthPass.set(d);
    if (depthOnly) d.context->PSSetShader(nullptr, nullptr, 0);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(1, resultView.GetAddressOfConst(), nullptr);  // the shadow map is read now
    readPass.set(d);
    d.context->PSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->PSSetSamplers(0, 1, sampler.GetAddressOfConst());
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");

    const std::vector<std::array<float, 4>> texels = readTexels<std::array<float, 4>>(d, result.Get());
    for (UINT x = 0; x < kSize && x < texels.size(); ++x) out.push_back({texels[x][0], texels[x][1]});  // the top row
    return out;
}

void expectPlane(const std::vector<std::array<float, 2>>& got, float tolerance) {
    ASSERT_EQ(got.size(), kSize);
    for (UINT x = 0; x < kSize; ++x) {
        EXPECT_NEAR(got[x][0], planeDepth(x), tolerance) << "depth of pixel " << x;
        // D3D's comparison: reference LESS texel passes (1), else 0.
        EXPECT_EQ(got[x][1], 0.06f < planeDepth(x) ? 1.0f : 0.0f) << "comparison at pixel " << x << " (depth " << planeDepth(x) << ")";
    }
}

TEST(D3D11DepthTexture, R32TypelessShadowMapIsWrittenAndSampled) {
    expectPlane(shadowRoundTrip(DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT, DXGI_FORMAT_R32_FLOAT), 1e-6f);
}

TEST(D3D11DepthTexture, DepthOnlyPassWithoutTargetOrPixelShader) {
    expectPlane(shadowRoundTrip(DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT, DXGI_FORMAT_R32_FLOAT, true), 1e-6f);
}

TEST(D3D11DepthTexture, R16TypelessShadowMapIsWrittenAndSampled) {
    expectPlane(shadowRoundTrip(DXGI_FORMAT_R16_TYPELESS, DXGI_FORMAT_D16_UNORM, DXGI_FORMAT_R16_UNORM), 1.0f / 65535.0f);
}

TEST(D3D11DepthTexture, R24G8TypelessShadowMapIsWrittenAndSampled) {
    expectPlane(shadowRoundTrip(DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_D24_UNORM_S8_UINT, DXGI_FORMAT_R24_UNORM_X8_TYPELESS), 1.0f / 16777215.0f);
}

TEST(D3D11DepthTexture, D32FloatDepthBufferTests) {
    Device d;
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_D32_FLOAT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    ComPtr<ID3D11Texture2D> depth;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, depth.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> colour = makeTexture(d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(colour.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const float black[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), black);
    // Depth cleared to 0.1: only pixels whose plane depth is below it pass LESS.
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 0.1f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), dsv.Get());
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    Shaders pass(d, kDepthPass);
    pass.set(d);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, colour.Get());
    for (UINT x = 0; x < kSize; ++x)
        EXPECT_EQ(pixels[x][0], planeDepth(x) < 0.1f ? 255 : 0) << "pixel " << x << " (depth " << planeDepth(x) << ")";
}

// A triangle at depth 0.1 that outputs the depth texture's own texel, drawn through a
// read-only view of that texture (deferred lighting reads the G-buffer depth this way).
const char* const kReadOnlyPass = R"(
Texture2D<float> Depth : register(t0);
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0.1, 1);
}
float4 ps(float4 pos : SV_Position) : SV_Target { return float4(Depth.Load(int3(pos.xy, 0)), 1, 0, 1); }
)";

// D3D11_DSV_READ_ONLY_DEPTH: the depth test still runs against the texture, nothing is written to
// it although the state enables depth writes, and a shader samples the texture meanwhile.
TEST(D3D11DepthTexture, ReadOnlyDepthViewTestsWithoutWritingWhileSampled) {
    Device d;
    ComPtr<ID3D11Texture2D> shadow = makeTarget(d, DXGI_FORMAT_R24G8_TYPELESS, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11Texture2D> result = makeTarget(d, DXGI_FORMAT_R32G32B32A32_FLOAT, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(shadow && result);
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11DepthStencilView> writable, readOnly;
    ASSERT_EQ(d.device->CreateDepthStencilView(shadow.Get(), &dsvDesc, writable.GetAddressOf()), S_OK) << lastError();
    dsvDesc.Flags = D3D11_DSV_READ_ONLY_DEPTH | D3D11_DSV_READ_ONLY_STENCIL;
    ASSERT_EQ(d.device->CreateDepthStencilView(shadow.Get(), &dsvDesc, readOnly.GetAddressOf()), S_OK) << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC got;
    readOnly->GetDesc(&got);
    EXPECT_EQ(got.Flags, UINT(D3D11_DSV_READ_ONLY_DEPTH | D3D11_DSV_READ_ONLY_STENCIL));
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = DXGI_FORMAT_R24_UNORM_X8_TYPELESS;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    srvDesc.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(shadow.Get(), &srvDesc, srv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(result.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();

    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    Shaders depthPass(d, kDepthPass), readOnlyPass(d, kReadOnlyPass);
    d.context->ClearDepthStencilView(writable.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), writable.Get());
    depthPass.set(d);
    d.context->Draw(3, 0);  // the plane, 0.25 * u
    const float black[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), black);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), readOnly.Get());  // default state: LESS, writes enabled
    readOnlyPass.set(d);
    d.context->PSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    const std::vector<std::array<float, 4>> texels = readTexels<std::array<float, 4>>(d, result.Get());
    ASSERT_GE(texels.size(), size_t(kSize));
    for (UINT x = 0; x < kSize; ++x) {
        const bool passes = 0.1f < planeDepth(x);
        EXPECT_NEAR(texels[x][0], passes ? planeDepth(x) : 0.0f, 1.0f / 16777215.0f) << "pixel " << x;
        EXPECT_EQ(texels[x][1], passes ? 1.0f : 0.0f) << "pixel " << x;
    }
    // The texture still holds the plane: read without a depth view, every pixel drawn.
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    d.context->Draw(3, 0);
    const std::vector<std::array<float, 4>> after = readTexels<std::array<float, 4>>(d, result.Get());
    ASSERT_GE(after.size(), size_t(kSize));
    for (UINT x = 0; x < kSize; ++x) EXPECT_NEAR(after[x][0], planeDepth(x), 1.0f / 16777215.0f) << "depth texel " << x << " after the draw";
    // Read-only stencil needs a format with stencil.
    shadow = makeTarget(d, DXGI_FORMAT_R32_TYPELESS, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    dsvDesc.Format = DXGI_FORMAT_D32_FLOAT;
    EXPECT_EQ(d.device->CreateDepthStencilView(shadow.Get(), &dsvDesc, readOnly.ReleaseAndGetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Flags = 3 for a DXGI_FORMAT_D32_FLOAT view"), std::string::npos) << lastError();
    dsvDesc.Flags = D3D11_DSV_READ_ONLY_DEPTH;
    EXPECT_EQ(d.device->CreateDepthStencilView(shadow.Get(), &dsvDesc, readOnly.ReleaseAndGetAddressOf()), S_OK) << lastError();
}

TEST(D3D11DepthTexture, RefusedDescriptionsNameTheField) {
    Device d;
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("BindFlags = 72 with Format = DXGI_FORMAT_D24_UNORM_S8_UINT"), std::string::npos) << lastError();
    desc.Format = DXGI_FORMAT_R32_TYPELESS;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("pDesc is null for a DXGI_FORMAT_R32_TYPELESS texture"), std::string::npos) << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = DXGI_FORMAT_R32_FLOAT;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(t.Get(), &dsvDesc, dsv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_DEPTH_STENCIL_VIEW_DESC.Format = DXGI_FORMAT_R32_FLOAT for a DXGI_FORMAT_R32_TYPELESS texture "
                               "(its depth-stencil view is DXGI_FORMAT_D32_FLOAT)"),
              std::string::npos)
        << lastError();
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R32_TYPELESS"), std::string::npos) << lastError();
}

TEST(D3D11DepthTexture, R32G8X24TypelessShadowMapIsWrittenAndSampled) {
    // GL_DEPTH32F_STENCIL8: the float depth is kept exactly, as D32_FLOAT's.
    expectPlane(shadowRoundTrip(DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_D32_FLOAT_S8X24_UINT, DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS), 1e-6f);
}

// A D32_FLOAT_S8X24_UINT depth-stencil buffer has stencil: a first draw over the left half writes
// 1 (REPLACE), a full-target draw then passes only where the stencil EQUALs 1.
TEST(D3D11DepthTexture, D32FloatS8X24HasStencil) {
    Device d;
    ComPtr<ID3D11Texture2D> depth = makeTarget(d, DXGI_FORMAT_D32_FLOAT_S8X24_UINT, D3D11_BIND_DEPTH_STENCIL);
    ComPtr<ID3D11Texture2D> colour = makeTexture(d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(depth && colour);
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(colour.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const float black[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), black);
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH | D3D11_CLEAR_STENCIL, 1.0f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), dsv.Get());
    D3D11_DEPTH_STENCIL_DESC write, test;
    write.DepthEnable = test.DepthEnable = FALSE;
    write.StencilEnable = test.StencilEnable = TRUE;
    write.FrontFace.StencilFunc = write.BackFace.StencilFunc = D3D11_COMPARISON_ALWAYS;
    write.FrontFace.StencilPassOp = write.BackFace.StencilPassOp = D3D11_STENCIL_OP_REPLACE;
    test.FrontFace.StencilFunc = test.BackFace.StencilFunc = D3D11_COMPARISON_EQUAL;
    ComPtr<ID3D11DepthStencilState> writing, testing;
    ASSERT_EQ(d.device->CreateDepthStencilState(&write, writing.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateDepthStencilState(&test, testing.GetAddressOf()), S_OK) << lastError();
    D3D11_VIEWPORT viewport;
    viewport.Width = float(kSize) / 2;  // the left half only
    viewport.Height = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    Shaders pass(d, kDepthPass);
    pass.set(d);
    d.context->OMSetDepthStencilState(writing.Get(), 1);
    d.context->Draw(3, 0);
    d.context->ClearRenderTargetView(rtv.Get(), black);
    viewport.Width = float(kSize);
    d.context->RSSetViewports(1, &viewport);
    d.context->OMSetDepthStencilState(testing.Get(), 1);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, colour.Get());
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) EXPECT_EQ(pixels[y * kSize + x][0], x < kSize / 2 ? 255 : 0) << "pixel (" << x << ", " << y << ")";
}

// Column x of a depth-only pass's stencil after four draws with INCR_SAT, the first over the whole
// target and each next one a column narrower: kSize - x.
UINT columnStencil(UINT x) { return kSize - x; }

// Fills a typeless depth-stencil texture's stencil with columnStencil (depth too, the plane), then
// reads it through `stencilView` in a shader (Texture2D<uint4>.Load: (r, g, b, a) into the target's
// (g, r, b, a)) and its depth through `depthView`: per pixel (stencil, r, b, a, depth).
std::vector<std::array<float, 5>> stencilRoundTrip(DXGI_FORMAT typeless, DXGI_FORMAT dsvFormat, DXGI_FORMAT stencilView, DXGI_FORMAT depthView) {
    Device d;
    std::vector<std::array<float, 5>> out;
    ComPtr<ID3D11Texture2D> t = makeTarget(d, typeless, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    if (!t) return out;
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = dsvFormat;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(t.Get(), &dsvDesc, dsv.GetAddressOf()), S_OK) << lastError();
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH | D3D11_CLEAR_STENCIL, 1.0f, 0);
    d.context->OMSetRenderTargets(0, nullptr, dsv.Get());
    D3D11_DEPTH_STENCIL_DESC incr;
    incr.DepthFunc = D3D11_COMPARISON_ALWAYS;
    incr.StencilEnable = TRUE;
    incr.FrontFace.StencilFunc = incr.BackFace.StencilFunc = D3D11_COMPARISON_ALWAYS;
    incr.FrontFace.StencilPassOp = incr.BackFace.StencilPassOp = D3D11_STENCIL_OP_INCR_SAT;
    ComPtr<ID3D11DepthStencilState> state;
    EXPECT_EQ(d.device->CreateDepthStencilState(&incr, state.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetDepthStencilState(state.Get(), 0);
    Shaders pass(d, kDepthPass);
    pass.set(d);
    d.context->PSSetShader(nullptr, nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    for (UINT width = kSize; width > 0; --width) {
        D3D11_VIEWPORT viewport{0, 0, float(width), float(kSize), 0, 1};
        d.context->RSSetViewports(1, &viewport);
        d.context->Draw(3, 0);
    }
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
    d.context->OMSetDepthStencilState(nullptr, 0);

    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = stencilView;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    srvDesc.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> stencil, depth;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &srvDesc, stencil.GetAddressOf()), S_OK) << lastError();
    srvDesc.Format = depthView;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &srvDesc, depth.GetAddressOf()), S_OK) << lastError();
    if (!stencil || !depth) return out;
    const std::string full = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
)";
    const std::vector<std::array<float, 4>> stencils = drawWithTexture(d, full + R"(
Texture2D<uint4> Stencil : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { uint4 s = Stencil.Load(int3(pos.xy, 0)); return float4(s.g, s.r, s.b, s.a); }
)",
                                                                       stencil.Get(), kSize, kSize);
    const std::vector<std::array<float, 4>> depths = drawWithTexture(d, full + R"(
Texture2D<float> Depth : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Depth.Load(int3(pos.xy, 0)); }
)",
                                                                     depth.Get(), kSize, kSize);
    for (std::size_t i = 0; i < stencils.size() && i < depths.size(); ++i)
        out.push_back({stencils[i][0], stencils[i][1], stencils[i][2], stencils[i][3], depths[i][0]});
    return out;
}

void expectStencilColumns(const std::vector<std::array<float, 5>>& got) {
    ASSERT_EQ(got.size(), std::size_t(kSize * kSize));
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) {
            const std::array<float, 5>& p = got[y * kSize + x];
            EXPECT_EQ(p[0], float(columnStencil(x))) << "stencil of pixel (" << x << ", " << y << ")";
            EXPECT_EQ(p[1], 0.0f) << "red of pixel (" << x << ", " << y << ")";
            EXPECT_EQ(p[2], 0.0f) << "blue of pixel (" << x << ", " << y << ")";
            EXPECT_EQ(p[3], 1.0f) << "alpha of pixel (" << x << ", " << y << ")";
            // The last draw to reach column x (viewport width x + 1) wrote its depth, the plane over that viewport.
            EXPECT_NEAR(p[4], 0.25f * (float(x) + 0.5f) / float(x + 1), 1e-6f) << "depth of pixel (" << x << ", " << y << ")";
        }
}

// The stencil of a D24_UNORM_S8_UINT shadow map, read as D3D reads X24_TYPELESS_G8_UINT: (0, stencil, 0, 1).
TEST(D3D11DepthTexture, R24G8StencilIsReadThroughAnX24TypelessG8UintView) {
    expectStencilColumns(
        stencilRoundTrip(DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_D24_UNORM_S8_UINT, DXGI_FORMAT_X24_TYPELESS_G8_UINT, DXGI_FORMAT_R24_UNORM_X8_TYPELESS));
}

TEST(D3D11DepthTexture, R32G8X24StencilIsReadThroughAnX32TypelessG8X24UintView) {
    expectStencilColumns(stencilRoundTrip(DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_D32_FLOAT_S8X24_UINT, DXGI_FORMAT_X32_TYPELESS_G8X24_UINT,
                                          DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS));
}

TEST(D3D11DepthTexture, AStencilViewOfAnotherFamilyIsRefusedNamingTheFormat) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeTarget(d, DXGI_FORMAT_R32G8X24_TYPELESS, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(t);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_X24_TYPELESS_G8_UINT;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_X24_TYPELESS_G8_UINT for a DXGI_FORMAT_R32G8X24_TYPELESS texture (its shader-resource view is "
                               "DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, or DXGI_FORMAT_X32_TYPELESS_G8X24_UINT for the stencil)"),
              std::string::npos)
        << lastError();
    // A stencil view of an R32_TYPELESS texture (no stencil) names the format too.
    ComPtr<ID3D11Texture2D> plain = makeTarget(d, DXGI_FORMAT_R32_TYPELESS, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(plain);
    EXPECT_EQ(d.device->CreateShaderResourceView(plain.Get(), &desc, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_X24_TYPELESS_G8_UINT for a DXGI_FORMAT_R32_TYPELESS texture"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
