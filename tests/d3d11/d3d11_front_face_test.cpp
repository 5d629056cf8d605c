// SV_IsFrontFace, culling and the stencil ops against D3D11_RASTERIZER_DESC.FrontCounterClockwise.
// D3D's front faces are the triangles clockwise as seen unless FrontCounterClockwise is TRUE, then
// the counter-clockwise ones, whatever the cull mode; CULL_BACK culls the other winding, and the
// depth-stencil state's FrontFace ops apply to front faces, BackFace ops to the rest
// (D3D11_RASTERIZER_DESC and D3D11_DEPTH_STENCIL_DESC docs; vkd3d's is-front-face.shader_test).
// A triangle over the whole target drawn clockwise, or the same one counter-clockwise, shows which.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kFaces = R"(
// NDC, +y up: (-1,-1) (-1,3) (3,-1) turns clockwise as seen; the reverse order counter-clockwise.
static const float2 kCorners[3] = { float2(-1, -1), float2(-1, 3), float2(3, -1) };
float4 vsClockwise(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 vsCounterClockwise(uint id : SV_VertexID) : SV_Position { return float4(kCorners[2 - id], 0, 1); }
float4 ps(float4 p : SV_Position, bool front : SV_IsFrontFace) : SV_Target { return front ? float4(1, 0, 0, 1) : float4(0, 0, 1, 1); }
)";

constexpr std::uint32_t kRed = 0xff0000ffu;   // the pixel shader saw a front face
constexpr std::uint32_t kBlue = 0xffff0000u;  // a back face
constexpr std::uint32_t kNone = 0;            // nothing drawn (the target starts zeroed)

struct Faces {
    Device d;
    ComPtr<ID3D11VertexShader> clockwise, counterClockwise;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11Texture2D> target, depth;
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11DepthStencilView> dsv;

    Faces() {
        ComPtr<ID3DBlob> cw = compile(kFaces, "vsClockwise", "vs_5_0"), ccw = compile(kFaces, "vsCounterClockwise", "vs_5_0");
        ComPtr<ID3DBlob> psCode = compile(kFaces, "ps", "ps_5_0");
        if (!cw || !ccw || !psCode) return;
        EXPECT_EQ(d.device->CreateVertexShader(cw->GetBufferPointer(), cw->GetBufferSize(), nullptr, clockwise.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreateVertexShader(ccw->GetBufferPointer(), ccw->GetBufferSize(), nullptr, counterClockwise.GetAddressOf()), S_OK)
            << lastError();
        EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        target = makeTexture(d, 2, 2, D3D11_BIND_RENDER_TARGET);
        EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
        D3D11_TEXTURE2D_DESC td;
        td.Width = td.Height = 2;
        td.MipLevels = td.ArraySize = 1;
        td.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
        td.BindFlags = D3D11_BIND_DEPTH_STENCIL;
        EXPECT_EQ(d.device->CreateTexture2D(&td, nullptr, depth.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();
        D3D11_VIEWPORT viewport;
        viewport.Width = viewport.Height = 2;
        d.context->RSSetViewports(1, &viewport);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
    }

    // The colour of texel (0, 0) after clearing the target and drawing one triangle.
    std::uint32_t draw(bool clockwiseTriangle, D3D11_CULL_MODE cull, BOOL frontCounterClockwise, ID3D11DepthStencilState* stencil = nullptr) {
        D3D11_RASTERIZER_DESC rd;
        rd.CullMode = cull;
        rd.FrontCounterClockwise = frontCounterClockwise;
        ComPtr<ID3D11RasterizerState> rs;
        EXPECT_EQ(d.device->CreateRasterizerState(&rd, rs.GetAddressOf()), S_OK) << lastError();
        const FLOAT zero[4] = {0, 0, 0, 0};
        d.context->ClearRenderTargetView(rtv.Get(), zero);
        d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH | D3D11_CLEAR_STENCIL, 1.0f, 0);
        d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), stencil ? dsv.Get() : nullptr);
        d.context->OMSetDepthStencilState(stencil, 0);
        d.context->RSSetState(rs.Get());
        d.context->VSSetShader(clockwiseTriangle ? clockwise.Get() : counterClockwise.Get(), nullptr, 0);
        d.context->Draw(3, 0);
        EXPECT_EQ(lastError(), "");
        const auto pixel = readPixels(d, target.Get()).at(0);
        return std::uint32_t(pixel[0]) | std::uint32_t(pixel[1]) << 8 | std::uint32_t(pixel[2]) << 16 | std::uint32_t(pixel[3]) << 24;
    }
};

TEST(D3D11FrontFace, ClockwiseIsFrontWithCullingOff) {
    Faces f;
    EXPECT_EQ(f.draw(true, D3D11_CULL_NONE, FALSE), kRed);
    EXPECT_EQ(f.draw(false, D3D11_CULL_NONE, FALSE), kBlue);
}

TEST(D3D11FrontFace, FrontCounterClockwiseMakesCounterClockwiseFrontWithCullingOff) {
    Faces f;
    EXPECT_EQ(f.draw(true, D3D11_CULL_NONE, TRUE), kBlue);
    EXPECT_EQ(f.draw(false, D3D11_CULL_NONE, TRUE), kRed);
    // Back to the default on the same device: only the winding changed, the cull mode did not.
    EXPECT_EQ(f.draw(true, D3D11_CULL_NONE, FALSE), kRed);
    EXPECT_EQ(f.draw(false, D3D11_CULL_NONE, FALSE), kBlue);
}

TEST(D3D11FrontFace, CullBackAndFrontFollowTheFrontWinding) {
    Faces f;
    EXPECT_EQ(f.draw(true, D3D11_CULL_BACK, FALSE), kRed);
    EXPECT_EQ(f.draw(false, D3D11_CULL_BACK, FALSE), kNone);
    EXPECT_EQ(f.draw(true, D3D11_CULL_BACK, TRUE), kNone);
    EXPECT_EQ(f.draw(false, D3D11_CULL_BACK, TRUE), kRed);
    EXPECT_EQ(f.draw(true, D3D11_CULL_FRONT, TRUE), kBlue);
    EXPECT_EQ(f.draw(false, D3D11_CULL_FRONT, TRUE), kNone);
}

// FrontFace's stencil test refuses every pixel, BackFace's passes them: only back faces draw.
TEST(D3D11FrontFace, FrontFaceStencilOpsFollowFrontCounterClockwise) {
    Faces f;
    D3D11_DEPTH_STENCIL_DESC dd;
    dd.DepthEnable = FALSE;
    dd.StencilEnable = TRUE;
    dd.FrontFace.StencilFunc = D3D11_COMPARISON_NEVER;
    dd.BackFace.StencilFunc = D3D11_COMPARISON_ALWAYS;
    ComPtr<ID3D11DepthStencilState> ds;
    ASSERT_EQ(f.d.device->CreateDepthStencilState(&dd, ds.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(f.draw(true, D3D11_CULL_NONE, FALSE, ds.Get()), kNone);
    EXPECT_EQ(f.draw(false, D3D11_CULL_NONE, FALSE, ds.Get()), kBlue);
    EXPECT_EQ(f.draw(true, D3D11_CULL_NONE, TRUE, ds.Get()), kBlue);
    EXPECT_EQ(f.draw(false, D3D11_CULL_NONE, TRUE, ds.Get()), kNone);
}

}  // namespace
}  // namespace d3d11test
