// SV_IsFrontFace with culling off, on a device whose first draw does not cull: D3D's front faces
// are the triangles clockwise as seen (FrontCounterClockwise FALSE), whatever the cull mode. A
// triangle over the whole target drawn clockwise must read true, the same triangle counter-
// clockwise false (vkd3d's is-front-face.shader_test checks the same through the suite runner).
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

// The colour of texel (0, 0) after a draw with `vsEntry` and culling off on a fresh device.
std::uint32_t faceColour(const char* vsEntry) {
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kFaces, vsEntry, "vs_5_0"), psCode = compile(kFaces, "ps", "ps_5_0");
    if (!vsCode || !psCode) return 0;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;
    ComPtr<ID3D11RasterizerState> rs;
    EXPECT_EQ(d.device->CreateRasterizerState(&rd, rs.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = makeTexture(d, 2, 2, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 2;
    d.context->RSSetViewports(1, &viewport);
    d.context->RSSetState(rs.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    const auto pixel = readPixels(d, target.Get()).at(0);
    return std::uint32_t(pixel[0]) | std::uint32_t(pixel[1]) << 8 | std::uint32_t(pixel[2]) << 16 | std::uint32_t(pixel[3]) << 24;
}

TEST(D3D11FrontFace, ClockwiseIsFrontWithCullingOff) {
    EXPECT_EQ(faceColour("vsClockwise"), 0xff0000ffu);         // red: front
    EXPECT_EQ(faceColour("vsCounterClockwise"), 0xffff0000u);  // blue: back
}

}  // namespace
}  // namespace d3d11test
