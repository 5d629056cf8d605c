// State objects from descriptions: D3D's defaults and valid descriptions are taken (GetDesc gives
// them back); every invalid field is E_INVALIDARG, and what D3D allows but fxport cannot honour is
// E_NOTIMPL, each with a message naming the description's field and the value given.
#include <functional>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

struct StatesTest : ::testing::Test {
    Device d;
};

// Runs `create` and checks its result and that the message names `field` and `value`.
void expectRejected(HRESULT expected, const std::function<HRESULT()>& create, const std::string& field, const std::string& value) {
    const HRESULT hr = create();
    EXPECT_EQ(hr, expected) << field;
    const std::string message = lastError();
    EXPECT_NE(message.find(field), std::string::npos) << "message '" << message << "' should name " << field;
    EXPECT_NE(message.find(value), std::string::npos) << "message '" << message << "' should name the value " << value;
}

TEST_F(StatesTest, DefaultsAndValidDescriptionsAreTaken) {
    ComPtr<ID3D11SamplerState> s;
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    sd.AddressU = D3D11_TEXTURE_ADDRESS_WRAP;
    ASSERT_EQ(d.device->CreateSamplerState(&sd, s.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC back;
    s->GetDesc(&back);
    EXPECT_EQ(back.Filter, D3D11_FILTER_MIN_MAG_MIP_POINT);
    EXPECT_EQ(back.AddressU, D3D11_TEXTURE_ADDRESS_WRAP);
    EXPECT_EQ(back.AddressV, D3D11_TEXTURE_ADDRESS_CLAMP);

    ComPtr<ID3D11BlendState> b;
    D3D11_BLEND_DESC bd;
    bd.RenderTarget[0].BlendEnable = TRUE;
    bd.RenderTarget[0].SrcBlend = D3D11_BLEND_SRC_ALPHA;
    bd.RenderTarget[0].DestBlend = D3D11_BLEND_INV_SRC_ALPHA;
    EXPECT_EQ(d.device->CreateBlendState(&bd, b.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RasterizerState> r;
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;
    EXPECT_EQ(d.device->CreateRasterizerState(&rd, r.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11DepthStencilState> ds;
    D3D11_DEPTH_STENCIL_DESC dd;
    dd.StencilEnable = TRUE;
    dd.FrontFace.StencilPassOp = D3D11_STENCIL_OP_INCR;
    EXPECT_EQ(d.device->CreateDepthStencilState(&dd, ds.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(lastError(), "");
}

TEST_F(StatesTest, InvalidSamplerFieldsAreNamed) {
    auto with = [&](auto change) {
        return [this, change] {
            D3D11_SAMPLER_DESC sd;
            change(sd);
            ComPtr<ID3D11SamplerState> s;
            return d.device->CreateSamplerState(&sd, s.GetAddressOf());
        };
    };
    expectRejected(E_INVALIDARG, with([](auto& s) { s.Filter = D3D11_FILTER(0x2); }), "D3D11_SAMPLER_DESC.Filter", "2");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.AddressU = D3D11_TEXTURE_ADDRESS_MODE(0); }), "D3D11_SAMPLER_DESC.AddressU", "0");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.AddressW = D3D11_TEXTURE_ADDRESS_MODE(9); }), "D3D11_SAMPLER_DESC.AddressW", "9");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.MaxAnisotropy = 17; }), "D3D11_SAMPLER_DESC.MaxAnisotropy", "17");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.MipLODBias = 20; }), "D3D11_SAMPLER_DESC.MipLODBias", "20");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.MinLOD = 3, s.MaxLOD = 1; }), "D3D11_SAMPLER_DESC.MinLOD", "3");
    expectRejected(E_INVALIDARG,
                   with([](auto& s) { s.Filter = D3D11_FILTER_COMPARISON_MIN_MAG_MIP_LINEAR, s.ComparisonFunc = D3D11_COMPARISON_FUNC(0); }),
                   "D3D11_SAMPLER_DESC.ComparisonFunc", "0");
    expectRejected(E_NOTIMPL, with([](auto& s) { s.AddressV = D3D11_TEXTURE_ADDRESS_MIRROR_ONCE; }), "D3D11_SAMPLER_DESC.AddressV", "5");
}

TEST_F(StatesTest, InvalidBlendFieldsAreNamed) {
    auto with = [&](auto change) {
        return [this, change] {
            D3D11_BLEND_DESC bd;
            bd.RenderTarget[0].BlendEnable = TRUE;
            change(bd);
            ComPtr<ID3D11BlendState> b;
            return d.device->CreateBlendState(&bd, b.GetAddressOf());
        };
    };
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].SrcBlend = D3D11_BLEND(12); }), "RenderTarget[0].SrcBlend", "12");
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].DestBlend = D3D11_BLEND(0); }), "RenderTarget[0].DestBlend", "0");
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].SrcBlendAlpha = D3D11_BLEND_SRC_COLOR; }),
                   "RenderTarget[0].SrcBlendAlpha", "3");
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].BlendOp = D3D11_BLEND_OP(6); }), "RenderTarget[0].BlendOp", "6");
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].BlendOpAlpha = D3D11_BLEND_OP(0); }), "RenderTarget[0].BlendOpAlpha", "0");
    expectRejected(E_INVALIDARG, with([](auto& b) { b.RenderTarget[0].RenderTargetWriteMask = 0x1F; }),
                   "RenderTarget[0].RenderTargetWriteMask", "31");
    expectRejected(E_INVALIDARG,
                   with([](auto& b) { b.IndependentBlendEnable = TRUE, b.RenderTarget[2].BlendOp = D3D11_BLEND_OP(7); }),
                   "RenderTarget[2].BlendOp", "7");
    expectRejected(E_NOTIMPL, with([](auto& b) { b.RenderTarget[0].SrcBlend = D3D11_BLEND_SRC1_COLOR; }), "RenderTarget[0].SrcBlend", "16");
    expectRejected(E_NOTIMPL, with([](auto& b) { b.AlphaToCoverageEnable = TRUE; }), "AlphaToCoverageEnable", "TRUE");
}

TEST_F(StatesTest, InvalidRasterizerFieldsAreNamed) {
    auto with = [&](auto change) {
        return [this, change] {
            D3D11_RASTERIZER_DESC rd;
            change(rd);
            ComPtr<ID3D11RasterizerState> r;
            return d.device->CreateRasterizerState(&rd, r.GetAddressOf());
        };
    };
    expectRejected(E_INVALIDARG, with([](auto& r) { r.FillMode = D3D11_FILL_MODE(1); }), "D3D11_RASTERIZER_DESC.FillMode", "1");
    expectRejected(E_INVALIDARG, with([](auto& r) { r.CullMode = D3D11_CULL_MODE(4); }), "D3D11_RASTERIZER_DESC.CullMode", "4");
    expectRejected(E_NOTIMPL, with([](auto& r) { r.DepthBiasClamp = 0.5f; }), "D3D11_RASTERIZER_DESC.DepthBiasClamp", "0.5");
    expectRejected(E_NOTIMPL, with([](auto& r) { r.DepthClipEnable = FALSE; }), "D3D11_RASTERIZER_DESC.DepthClipEnable", "FALSE");
}

TEST_F(StatesTest, InvalidDepthStencilFieldsAreNamed) {
    auto with = [&](auto change) {
        return [this, change] {
            D3D11_DEPTH_STENCIL_DESC dd;
            change(dd);
            ComPtr<ID3D11DepthStencilState> s;
            return d.device->CreateDepthStencilState(&dd, s.GetAddressOf());
        };
    };
    expectRejected(E_INVALIDARG, with([](auto& s) { s.DepthWriteMask = D3D11_DEPTH_WRITE_MASK(2); }), "D3D11_DEPTH_STENCIL_DESC.DepthWriteMask", "2");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.DepthFunc = D3D11_COMPARISON_FUNC(0); }), "D3D11_DEPTH_STENCIL_DESC.DepthFunc", "0");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.FrontFace.StencilFunc = D3D11_COMPARISON_FUNC(9); }), "FrontFace.StencilFunc", "9");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.FrontFace.StencilPassOp = D3D11_STENCIL_OP(0); }), "FrontFace.StencilPassOp", "0");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.BackFace.StencilFailOp = D3D11_STENCIL_OP(9); }), "BackFace.StencilFailOp", "9");
    expectRejected(E_INVALIDARG, with([](auto& s) { s.BackFace.StencilDepthFailOp = D3D11_STENCIL_OP(0); }), "BackFace.StencilDepthFailOp", "0");
}

TEST_F(StatesTest, NullDescriptionsAreInvalid) {
    ComPtr<ID3D11BlendState> b;
    EXPECT_EQ(d.device->CreateBlendState(nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("CreateBlendState"), std::string::npos);
}

}  // namespace
}  // namespace d3d11test
