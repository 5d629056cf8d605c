// Render-target and depth-stencil views of 1D textures (D3D11_RTV/DSV_DIMENSION_TEXTURE1D and
// TEXTURE1DARRAY): draws into a row one texel high, read back through staging copies and compared
// with the shader's value at each texel centre computed here; 1D shadow maps (R32_TYPELESS,
// R16_TYPELESS) drawn into through their depth view and sampled through their depth SRV.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// A triangle over the viewport; each texel is (its centre's u, 0.5, depth, 1), depth 0.5 * u.
const char* const kRamp = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), corner.x * 0.5, 1);
}
cbuffer Size : register(b0) { float Width; };
float4 ps(float4 pos : SV_Position) : SV_Target { return float4(pos.x / Width, 0.5, pos.z, 1); }
)";

struct Pipeline {
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11Buffer> size;
    // Binds the shaders and a viewport `width` texels wide, one high.
    Pipeline(Device& d, UINT width) {
        ComPtr<ID3DBlob> v = compile(kRamp, "vs", "vs_5_0"), p = compile(kRamp, "ps", "ps_5_0");
        if (!v || !p) return;
        EXPECT_EQ(d.device->CreateVertexShader(v->GetBufferPointer(), v->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreatePixelShader(p->GetBufferPointer(), p->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        const float constants[4] = {float(width), 0, 0, 0};
        size = makeBuffer(d, constants, sizeof constants, D3D11_BIND_CONSTANT_BUFFER);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->PSSetConstantBuffers(0, 1, size.GetAddressOfConst());
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        D3D11_VIEWPORT viewport;
        viewport.Width = float(width);
        viewport.Height = 1;
        d.context->RSSetViewports(1, &viewport);
    }
};

ComPtr<ID3D11Texture1D> makeLine(Device& d, DXGI_FORMAT format, UINT width, UINT slices, UINT levels, UINT bind) {
    D3D11_TEXTURE1D_DESC desc;
    desc.Width = width;
    desc.ArraySize = slices;
    desc.MipLevels = levels;
    desc.Format = format;
    desc.BindFlags = bind;
    ComPtr<ID3D11Texture1D> t;
    EXPECT_EQ(d.device->CreateTexture1D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Subresource `sub` of an RGBA8 1D texture, read through a staging copy.
std::vector<std::array<std::uint8_t, 4>> readRow(Device& d, ID3D11Texture1D* t, UINT sub) {
    D3D11_TEXTURE1D_DESC desc;
    t->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = desc.MiscFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture1D> staging;
    EXPECT_EQ(d.device->CreateTexture1D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    if (!staging) return {};
    d.context->CopyResource(staging.Get(), t);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), sub, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    std::vector<std::array<std::uint8_t, 4>> out(std::max(1u, desc.Width >> (sub % desc.MipLevels)));
    std::memcpy(out.data(), mapped.pData, out.size() * 4);
    d.context->Unmap(staging.Get(), sub);
    return out;
}

std::uint8_t unorm(float v) { return std::uint8_t(std::lround(v * 255.0f)); }

// Texel x of a `width`-texel ramp drawn by kRamp.
void expectRamp(const std::vector<std::array<std::uint8_t, 4>>& row, UINT width, bool (*drawn)(UINT x, UINT width)) {
    ASSERT_EQ(row.size(), width);
    for (UINT x = 0; x < width; ++x) {
        const float u = (float(x) + 0.5f) / float(width);
        const std::array<std::uint8_t, 4> want = drawn(x, width) ? std::array<std::uint8_t, 4>{unorm(u), 128, unorm(0.5f * u), 255}
                                                                 : std::array<std::uint8_t, 4>{0, 0, 0, 0};
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(row[x][std::size_t(c)], want[std::size_t(c)], 1) << "texel " << x << " channel " << c;
    }
}

bool everyTexel(UINT, UINT) { return true; }

TEST(D3D11LineTargets, ADrawWritesEveryTexelOfA1DTarget) {
    Device d;
    constexpr UINT kWidth = 16;
    ComPtr<ID3D11Texture1D> t = makeLine(d, DXGI_FORMAT_R8G8B8A8_UNORM, kWidth, 1, 1, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    rtv->GetDesc(&desc);
    EXPECT_EQ(desc.ViewDimension, D3D11_RTV_DIMENSION_TEXTURE1D);
    const float clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    Pipeline pipeline(d, kWidth);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    expectRamp(readRow(d, t.Get(), 0), kWidth, everyTexel);
}

TEST(D3D11LineTargets, AViewOfOneSliceAndLevelWritesOnlyThere) {
    Device d;
    constexpr UINT kWidth = 8, kSlices = 3, kLevels = 2;
    ComPtr<ID3D11Texture1D> t = makeLine(d, DXGI_FORMAT_R8G8B8A8_UNORM, kWidth, kSlices, kLevels, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(t);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE1DARRAY;
    const float clear[4] = {0, 0, 0, 0};
    for (UINT level = 0; level < kLevels; ++level) {  // every slice of every level cleared (a layered view clears all its slices)
        desc.Texture1DArray = {level, 0, kSlices};
        ComPtr<ID3D11RenderTargetView> all;
        ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, all.GetAddressOf()), S_OK) << lastError();
        d.context->ClearRenderTargetView(all.Get(), clear);
    }
    desc.Texture1DArray = {1, 1, 1};  // level 1 of slice 1
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    Pipeline pipeline(d, kWidth / 2);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    for (UINT slice = 0; slice < kSlices; ++slice)
        expectRamp(readRow(d, t.Get(), 1 + slice * kLevels), kWidth / 2, slice == 1 ? everyTexel : [](UINT, UINT) { return false; });
    expectRamp(readRow(d, t.Get(), 1 * kLevels), kWidth, [](UINT, UINT) { return false; });  // level 0 of slice 1
}

TEST(D3D11LineTargets, A1DDepthViewTestsEachTexel) {
    // Depth cleared to 0.25; the ramp's depth 0.5 * u passes LESS where u < 0.5: the left half.
    Device d;
    constexpr UINT kWidth = 16;
    ComPtr<ID3D11Texture1D> colour = makeLine(d, DXGI_FORMAT_R8G8B8A8_UNORM, kWidth, 1, 1, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11Texture1D> depth = makeLine(d, DXGI_FORMAT_D32_FLOAT, kWidth, 1, 1, D3D11_BIND_DEPTH_STENCIL);
    ASSERT_TRUE(colour && depth);
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateRenderTargetView(colour.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC desc;
    dsv->GetDesc(&desc);
    EXPECT_EQ(desc.ViewDimension, D3D11_DSV_DIMENSION_TEXTURE1D);
    const float clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 0.25f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), dsv.Get());
    Pipeline pipeline(d, kWidth);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    expectRamp(readRow(d, colour.Get(), 0), kWidth, [](UINT x, UINT width) { return 0.5f * (float(x) + 0.5f) / float(width) < 0.25f; });
}

// A 1D shadow map: an R32_TYPELESS 1D texture drawn into through a D32_FLOAT view (the ramp's
// depth 0.5 * u) and read through an R32_FLOAT view by Load and SampleLevel: each texel the CPU's
// 0.5 * u at its centre. An R16_TYPELESS one (D16_UNORM / R16_UNORM) to 16-bit precision.
void expectShadowRow(DXGI_FORMAT typeless, DXGI_FORMAT depthView, DXGI_FORMAT sampledView, float tolerance) {
    Device d;
    constexpr UINT kWidth = 16;
    ComPtr<ID3D11Texture1D> depth = makeLine(d, typeless, kWidth, 1, 1, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(depth);
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = depthView;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE1D;
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), &dsvDesc, dsv.GetAddressOf()), S_OK) << lastError();
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);
    d.context->OMSetRenderTargets(0, nullptr, dsv.Get());
    Pipeline pipeline(d, kWidth);
    d.context->PSSetShader(nullptr, nullptr, 0);  // depth only
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);

    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = sampledView;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1D;
    srvDesc.Texture1D = {0, 1};
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(depth.Get(), &srvDesc, srv.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC pointDesc;
    pointDesc.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> point;
    ASSERT_EQ(d.device->CreateSamplerState(&pointDesc, point.GetAddressOf()), S_OK) << lastError();
    const std::vector<std::array<float, 4>> got = drawWithTexture(d, R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
Texture1D<float> Depth : register(t0);
SamplerState Point : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target { return float4(Depth.Load(int2(pos.x, 0)), Depth.SampleLevel(Point, pos.x / 16, 0), 0, 1); }
)",
                                                                  srv.Get(), kWidth, 1, point.Get());
    ASSERT_EQ(got.size(), std::size_t(kWidth));
    for (UINT x = 0; x < kWidth; ++x) {
        const float want = 0.5f * (float(x) + 0.5f) / float(kWidth);
        EXPECT_NEAR(got[x][0], want, tolerance) << "Load at texel " << x;
        EXPECT_NEAR(got[x][1], want, tolerance) << "SampleLevel at texel " << x;
    }
}

TEST(D3D11LineTargets, AR32Typeless1DShadowMapIsDrawnAndSampled) {
    expectShadowRow(DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT, DXGI_FORMAT_R32_FLOAT, 1e-6f);
}

TEST(D3D11LineTargets, AR16Typeless1DShadowMapIsDrawnAndSampled) {
    expectShadowRow(DXGI_FORMAT_R16_TYPELESS, DXGI_FORMAT_D16_UNORM, DXGI_FORMAT_R16_UNORM, 1.0f / 65535.0f);
}

TEST(D3D11LineTargets, ATypeless1DDepthTexturesViewsNameTheirFormats) {
    Device d;
    ComPtr<ID3D11Texture1D> depth = makeLine(d, DXGI_FORMAT_R24G8_TYPELESS, 8, 1, 1, D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(depth);
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(depth.Get(), nullptr, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("pDesc is null for a DXGI_FORMAT_R24G8_TYPELESS texture"), std::string::npos) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = DXGI_FORMAT_R32_FLOAT;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1D;
    srvDesc.Texture1D = {0, 1};
    EXPECT_EQ(d.device->CreateShaderResourceView(depth.Get(), &srvDesc, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R32_FLOAT for a DXGI_FORMAT_R24G8_TYPELESS 1D texture (its shader-resource view is "
                               "DXGI_FORMAT_R24_UNORM_X8_TYPELESS"),
              std::string::npos)
        << lastError();
    D3D11_DEPTH_STENCIL_VIEW_DESC dsvDesc;
    dsvDesc.Format = DXGI_FORMAT_D32_FLOAT;
    dsvDesc.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE1D;
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(depth.Get(), &dsvDesc, dsv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_D32_FLOAT for a DXGI_FORMAT_R24G8_TYPELESS 1D texture (its depth-stencil view is "
                               "DXGI_FORMAT_D24_UNORM_S8_UINT)"),
              std::string::npos)
        << lastError();
    dsvDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    dsvDesc.Flags = D3D11_DSV_READ_ONLY_STENCIL;
    EXPECT_EQ(d.device->CreateDepthStencilView(depth.Get(), &dsvDesc, dsv.GetAddressOf()), S_OK) << lastError();
}

TEST(D3D11LineTargets, BadViewsAreRefusedNamingTheField) {
    Device d;
    ComPtr<ID3D11Texture1D> t = makeLine(d, DXGI_FORMAT_R8G8B8A8_UNORM, 8, 2, 1, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(t);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE1D;  // of an array
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, rtv.GetAddressOf()), E_INVALIDARG);
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE1DARRAY;
    desc.Texture1DArray = {0, 1, 2};
    EXPECT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, rtv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("FirstArraySlice + ArraySize = 1 + 2"), std::string::npos) << lastError();
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(t.Get(), nullptr, dsv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_BIND_DEPTH_STENCIL"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
