// Several viewports and scissor rectangles (RSSetViewports / RSSetScissorRects with n > 1): a
// geometry shader's SV_ViewportArrayIndex picks the viewport, its depth range and its scissor
// rectangle. The expected pixels are the viewport transform computed here.
#include <gtest/gtest.h>

#include "d3d11_test_support.h"

namespace {

using namespace d3d11test;

// One point in; the geometry shader draws the same quad, the left half of NDC at depth 0.5, once
// to each of viewports 0 and 1 (red, then green).
const char* kTwoViewports = R"(
struct Point { float4 position : SV_Position; };
struct Corner { float4 position : SV_Position; float4 color : COLOR0; uint viewport : SV_ViewportArrayIndex; };

Point VS(uint id : SV_VertexID) { Point p; p.position = float4(0, 0, 0, 1); return p; }

[maxvertexcount(8)]
void GS(point Point p[1], inout TriangleStream<Corner> stream)
{
    const float2 corners[4] = { float2(-1, -1), float2(0, -1), float2(-1, 1), float2(0, 1) };
    for (uint v = 0; v < 2; ++v) {
        for (int i = 0; i < 4; ++i) {
            Corner c;
            c.position = float4(corners[i], 0.5, 1);
            c.color = v == 0 ? float4(1, 0, 0, 1) : float4(0, 1, 0, 1);
            c.viewport = v;
            stream.Append(c);
        }
        stream.RestartStrip();
    }
}

float4 PS(float4 position : SV_Position, float4 color : COLOR0) : SV_Target { return color; }
)";

constexpr UINT kWidth = 64, kHeight = 32;
constexpr std::uint32_t kRed = 0xff0000ffu, kGreen = 0xff00ff00u;

class ViewportsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ComPtr<ID3DBlob> vsCode = compile(kTwoViewports, "VS", "vs_5_0", "viewports.hlsl");
        ComPtr<ID3DBlob> gsCode = compile(kTwoViewports, "GS", "gs_5_0", "viewports.hlsl");
        ComPtr<ID3DBlob> psCode = compile(kTwoViewports, "PS", "ps_5_0", "viewports.hlsl");
        ASSERT_TRUE(vsCode && gsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreateGeometryShader(gsCode->GetBufferPointer(), gsCode->GetBufferSize(), nullptr, gs.GetAddressOf()), S_OK)
            << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        target = makeTexture(d, kWidth, kHeight, D3D11_BIND_RENDER_TARGET);
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
        const FLOAT clear[4] = {0, 0, 0, 0};
        d.context->ClearRenderTargetView(view.Get(), clear);
        d.context->OMSetRenderTargets(1, view.GetAddressOfConst(), nullptr);
        viewports[0].Width = viewports[1].Width = kWidth / 2;
        viewports[0].Height = viewports[1].Height = kHeight;
        viewports[1].TopLeftX = kWidth / 2;  // the right half
    }
    // The state left as it is; a point drawn through the shaders.
    void draw(ID3D11RasterizerState* rasterizer = nullptr) {
        D3D11_RASTERIZER_DESC rd;
        rd.CullMode = D3D11_CULL_NONE;  // a strip's triangles alternate winding
        ComPtr<ID3D11RasterizerState> noCull;
        ASSERT_EQ(d.device->CreateRasterizerState(&rd, noCull.GetAddressOf()), S_OK);
        d.context->RSSetState(rasterizer ? rasterizer : noCull.Get());
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->GSSetShader(gs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->Draw(1, 0);
        ASSERT_EQ(lastError(), "");
    }
    // Each pixel against `expected(x, y)`, reporting the first few that differ.
    template <class F>
    void expectPixels(F expected) {
        std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, target.Get());
        ASSERT_EQ(pixels.size(), std::size_t(kWidth) * kHeight);
        int wrong = 0;
        for (UINT y = 0; y < kHeight; ++y)
            for (UINT x = 0; x < kWidth; ++x) {
                std::uint32_t got;
                std::memcpy(&got, pixels[y * kWidth + x].data(), 4);
                const std::uint32_t want = expected(x, y);
                if (got != want && ++wrong <= 5) ADD_FAILURE() << "pixel (" << x << ", " << y << "): " << std::hex << got << ", want " << want;
            }
        EXPECT_EQ(wrong, 0);
    }

    Device d;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11GeometryShader> gs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> view;
    D3D11_VIEWPORT viewports[2];
};

// The quad covers the left half of each viewport: x 0..15 in viewport 0, 32..47 in viewport 1.
std::uint32_t quadInEach(UINT x, UINT) {
    if (x < kWidth / 4) return kRed;
    if (x >= kWidth / 2 && x < kWidth * 3 / 4) return kGreen;
    return 0;
}

TEST_F(ViewportsTest, TheGeometryShaderPicksTheViewport) {
    d.context->RSSetViewports(2, viewports);
    draw();
    expectPixels(quadInEach);
}

TEST_F(ViewportsTest, EachViewportHasItsDepthRange) {
    // Depth cleared to 0.7, tested LESS: depth 0.5 becomes 0.8 in viewport 0 ([0.6, 1]), which
    // fails, and 0.1 in viewport 1 ([0, 0.2]), which passes.
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = kWidth;
    desc.Height = kHeight;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    desc.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    ComPtr<ID3D11Texture2D> depth;
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, depth.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 0.7f, 0);
    d.context->OMSetRenderTargets(1, view.GetAddressOfConst(), dsv.Get());
    viewports[0].MinDepth = 0.6f;
    viewports[1].MaxDepth = 0.2f;
    d.context->RSSetViewports(2, viewports);
    draw();
    expectPixels([](UINT x, UINT) { return x >= kWidth / 2 && x < kWidth * 3 / 4 ? kGreen : 0u; });
}

TEST_F(ViewportsTest, EachViewportHasItsScissorRectangle) {
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;
    rd.ScissorEnable = TRUE;
    ComPtr<ID3D11RasterizerState> scissored;
    ASSERT_EQ(d.device->CreateRasterizerState(&rd, scissored.GetAddressOf()), S_OK);
    D3D11_RECT rects[2];
    rects[0].right = kWidth;  // all of it
    rects[0].bottom = kHeight;
    rects[1].left = 36;  // part of viewport 1's quad
    rects[1].top = 4;
    rects[1].right = 44;
    rects[1].bottom = 20;
    d.context->RSSetViewports(2, viewports);
    d.context->RSSetScissorRects(2, rects);
    draw(scissored.Get());
    expectPixels([](UINT x, UINT y) {
        if (x < kWidth / 4) return kRed;
        return x >= 36 && x < 44 && y >= 4 && y < 20 ? kGreen : 0u;
    });
}

TEST_F(ViewportsTest, AViewportNoLongerSetDrawsNothingThere) {
    // Two viewports, then one: index 1 must not keep drawing into the old viewport 1 (D3D: a
    // viewport the call did not set is off; fxport draws an index past them through viewport 0).
    d.context->RSSetViewports(2, viewports);
    draw();
    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(view.Get(), clear);
    d.context->RSSetViewports(1, viewports);
    draw();
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, target.Get());
    for (UINT y = 0; y < kHeight; ++y)
        for (UINT x = kWidth / 4; x < kWidth; ++x) ASSERT_EQ(pixels[y * kWidth + x][3], 0) << "pixel (" << x << ", " << y << ")";
    EXPECT_EQ(pixels[0][3], 0xff);  // viewport 0 still draws (red, or green over it where index 1 draws through viewport 0)
}

// The vertex shader picks the viewport too (GL_ARB_shader_viewport_layer_array): instance i draws
// the quad to viewport i.
const char* kVertexPicks = R"(
struct Corner { float4 position : SV_Position; float4 color : COLOR0; uint viewport : SV_ViewportArrayIndex; };
Corner VS(uint id : SV_VertexID, uint instance : SV_InstanceID)
{
    Corner c;
    c.position = float4(id & 1 ? 0 : -1, id & 2 ? 1 : -1, 0.5, 1);
    c.color = instance == 0 ? float4(1, 0, 0, 1) : float4(0, 1, 0, 1);
    c.viewport = instance;
    return c;
}
)";

TEST_F(ViewportsTest, TheVertexShaderPicksTheViewport) {
    ComPtr<ID3DBlob> code = compile(kVertexPicks, "VS", "vs_5_0", "vertex_viewports.hlsl");
    ASSERT_TRUE(code);
    ComPtr<ID3D11VertexShader> picking;
    ASSERT_EQ(d.device->CreateVertexShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, picking.GetAddressOf()), S_OK)
        << lastError();
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;
    ComPtr<ID3D11RasterizerState> noCull;
    ASSERT_EQ(d.device->CreateRasterizerState(&rd, noCull.GetAddressOf()), S_OK);
    d.context->RSSetState(noCull.Get());
    d.context->RSSetViewports(2, viewports);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    d.context->VSSetShader(picking.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->DrawInstanced(4, 2, 0, 0);
    ASSERT_EQ(lastError(), "");
    expectPixels(quadInEach);
}

TEST_F(ViewportsTest, MoreThanSixteenAreRefused) {
    D3D11_VIEWPORT many[17];
    d.context->RSSetViewports(17, many);
    EXPECT_NE(lastError().find("16"), std::string::npos) << lastError();
}

}  // namespace
