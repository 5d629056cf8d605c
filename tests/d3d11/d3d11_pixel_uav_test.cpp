// A pixel shader's UAVs (OMSetRenderTargetsAndUnorderedAccessViews), written as D3D11 code writes
// them: every covered pixel of a 4x2 target stores its own coordinates into a RWStructuredBuffer
// at u1 (after the render target at slot 0), read back through a staging copy and compared with
// what each pixel must write; misuse: UAVs over the render targets' slots, and a draw whose pixel
// shader's u# holds no view (nothing drawn, the message naming the register).
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kShaders = R"(
RWStructuredBuffer<uint> Written : register(u1);
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);  // one triangle over the whole target
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
float4 ps(float4 pos : SV_Position) : SV_Target {
    uint x = uint(pos.x), y = uint(pos.y);
    Written[y * 4 + x] = 100 + x * 10 + y;
    return float4(1, 0, 0, 1);
}
)";

struct PixelUavScene {
    Device d;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11Buffer> buffer;
    ComPtr<ID3D11UnorderedAccessView> uav;

    PixelUavScene() {
        ComPtr<ID3DBlob> vsCode = compile(kShaders, "vs", "vs_5_0"), psCode = compile(kShaders, "ps", "ps_5_0");
        EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        target = makeTexture(d, 4, 2, D3D11_BIND_RENDER_TARGET);
        EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = 8 * 4;
        desc.BindFlags = D3D11_BIND_UNORDERED_ACCESS;
        desc.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
        desc.StructureByteStride = 4;
        const std::uint32_t zeros[8] = {};
        D3D11_SUBRESOURCE_DATA init;
        init.pSysMem = zeros;
        EXPECT_EQ(d.device->CreateBuffer(&desc, &init, buffer.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(d.device->CreateUnorderedAccessView(buffer.Get(), nullptr, uav.GetAddressOf()), S_OK) << lastError();
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        D3D11_VIEWPORT viewport;
        viewport.Width = 4;
        viewport.Height = 2;
        d.context->RSSetViewports(1, &viewport);
    }

    std::vector<std::uint32_t> written() {
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = 8 * 4;
        desc.Usage = D3D11_USAGE_STAGING;
        desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
        ComPtr<ID3D11Buffer> staging;
        EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
        std::vector<std::uint32_t> out(8, 0);
        if (!staging) return out;
        d.context->CopyResource(staging.Get(), buffer.Get());
        D3D11_MAPPED_SUBRESOURCE mapped;
        EXPECT_EQ(d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
        if (mapped.pData) std::memcpy(out.data(), mapped.pData, 32);
        d.context->Unmap(staging.Get(), 0);
        return out;
    }
};

TEST(D3D11PixelUav, EveryPixelWritesItsElement) {
    PixelUavScene s;
    s.d.context->OMSetRenderTargetsAndUnorderedAccessViews(1, s.rtv.GetAddressOfConst(), nullptr, 1, 1, s.uav.GetAddressOfConst(), nullptr);
    s.d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    std::vector<std::uint32_t> got = s.written();
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 4; ++x) EXPECT_EQ(got[y * 4 + x], 100 + x * 10 + y) << "pixel (" << x << ", " << y << ")";
    // The target was drawn too.
    EXPECT_EQ(readPixels(s.d, s.target.Get())[5], (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
}

TEST(D3D11PixelUav, UavsOverTheTargetsAreRefusedAndAMissingOneDrawsNothing) {
    PixelUavScene s;
    // u0 is the render target's slot: nothing is set, the message says why.
    s.d.context->OMSetRenderTargetsAndUnorderedAccessViews(1, s.rtv.GetAddressOfConst(), nullptr, 0, 1, s.uav.GetAddressOfConst(), nullptr);
    EXPECT_NE(lastError().find("UAVStartSlot 0"), std::string::npos) << lastError();
    // Targets only (the UAV slots emptied): the draw needs u1 and draws nothing.
    s.d.context->OMSetRenderTargetsAndUnorderedAccessViews(1, s.rtv.GetAddressOfConst(), nullptr, 1, 0, nullptr, nullptr);
    s.d.context->Draw(3, 0);
    EXPECT_NE(lastError().find("(u1)"), std::string::npos) << lastError();
    EXPECT_NE(lastError().find("OMSetRenderTargetsAndUnorderedAccessViews"), std::string::npos) << lastError();
    EXPECT_EQ(s.written(), std::vector<std::uint32_t>(8, 0));
    // D3D11_KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL keeps the target while the UAV is set.
    s.d.context->OMSetRenderTargetsAndUnorderedAccessViews(D3D11_KEEP_RENDER_TARGETS_AND_DEPTH_STENCIL, nullptr, nullptr, 1, 1,
                                                           s.uav.GetAddressOfConst(), nullptr);
    s.d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    EXPECT_EQ(s.written()[7], 100u + 3 * 10 + 1);
}

}  // namespace
}  // namespace d3d11test
