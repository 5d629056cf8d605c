// Deferred contexts: calls recorded on a deferred context do nothing until the immediate context
// executes the command list; the list runs from D3D's default state (the immediate context's
// bindings do not leak in), a WRITE_DISCARD Map of a dynamic constant buffer is written when the
// list runs, and afterwards the immediate context's state is cleared (RestoreContextState FALSE)
// or put back (TRUE). FinishCommandList(TRUE) lets the next list start from the state the
// deferred context had. Pixels are compared with the colours the recorded calls write.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kColour = R"(
cbuffer C : register(b0) { float4 colour; };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(float2((id << 1) & 2, id & 2) * float2(2, -2) + float2(-1, 1), 0, 1); }
float4 ps() : SV_Target { return colour; }
)";

struct DeferredTest : ::testing::Test {
    Device d;
    ComPtr<ID3D11DeviceContext> deferred;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11Buffer> constants;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> rtv;

    void SetUp() override {
        ASSERT_EQ(d.device->CreateDeferredContext(0, deferred.GetAddressOf()), S_OK) << lastError();
        EXPECT_EQ(deferred->GetType(), D3D11_DEVICE_CONTEXT_DEFERRED);
        EXPECT_EQ(d.context->GetType(), D3D11_DEVICE_CONTEXT_IMMEDIATE);
        ComPtr<ID3DBlob> vsCode = compile(kColour, "vs", "vs_5_0"), psCode = compile(kColour, "ps", "ps_5_0");
        ASSERT_TRUE(vsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = 16;
        desc.Usage = D3D11_USAGE_DYNAMIC;
        desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
        desc.CPUAccessFlags = D3D11_CPU_ACCESS_WRITE;
        ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, constants.GetAddressOf()), S_OK) << lastError();
        target = makeTexture(d, 2, 2, D3D11_BIND_RENDER_TARGET);
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    }
    // Records: bind the pipeline, write `rgba` into the constants (Map on the deferred context), draw.
    void recordDraw(const float (&rgba)[4]) {
        deferred->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        D3D11_VIEWPORT viewport;
        viewport.Width = viewport.Height = 2;
        deferred->RSSetViewports(1, &viewport);
        deferred->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        deferred->VSSetShader(vs.Get(), nullptr, 0);
        deferred->PSSetShader(ps.Get(), nullptr, 0);
        deferred->PSSetConstantBuffers(0, 1, constants.GetAddressOfConst());
        D3D11_MAPPED_SUBRESOURCE mapped;
        ASSERT_EQ(deferred->Map(constants.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &mapped), S_OK) << lastError();
        std::memcpy(mapped.pData, rgba, sizeof rgba);
        deferred->Unmap(constants.Get(), 0);
        deferred->Draw(3, 0);
    }
    std::array<std::uint8_t, 4> pixel() { return readPixels(d, target.Get()).at(0); }
};

TEST_F(DeferredTest, RecordedCallsRunWhenTheListIsExecuted) {
    const FLOAT grey[4] = {0.5f, 0.5f, 0.5f, 1};
    deferred->ClearRenderTargetView(rtv.Get(), grey);
    const float green[4] = {0, 1, 0, 1};
    recordDraw(green);
    // Nothing has run yet: the target is still as made (zeros).
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
    ComPtr<ID3D11CommandList> list;
    ASSERT_EQ(deferred->FinishCommandList(FALSE, list.GetAddressOf()), S_OK) << lastError();
    d.context->ExecuteCommandList(list.Get(), FALSE);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 255, 0, 255}));
    // A list runs again, from the start.
    const FLOAT red[4] = {1, 0, 0, 1};
    d.context->ClearRenderTargetView(rtv.Get(), red);
    d.context->ExecuteCommandList(list.Get(), FALSE);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 255, 0, 255}));
}

TEST_F(DeferredTest, ImmediateStateIsClearedOrRestored) {
    const float blue[4] = {0, 0, 1, 1};
    recordDraw(blue);
    ComPtr<ID3D11CommandList> list;
    ASSERT_EQ(deferred->FinishCommandList(FALSE, list.GetAddressOf()), S_OK);
    // The immediate context has its own pipeline bound; RestoreContextState TRUE keeps it.
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 2;
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->PSSetConstantBuffers(0, 1, constants.GetAddressOfConst());
    d.context->ExecuteCommandList(list.Get(), TRUE);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 0, 255, 255}));
    const float white[4] = {1, 1, 1, 1};
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(d.context->Map(constants.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &mapped), S_OK) << lastError();
    std::memcpy(mapped.pData, white, sizeof white);
    d.context->Unmap(constants.Get(), 0);
    d.context->Draw(3, 0);  // with the restored bindings
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{255, 255, 255, 255}));
    // RestoreContextState FALSE: afterwards nothing is bound, so a draw draws nothing.
    d.context->ExecuteCommandList(list.Get(), FALSE);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 0, 255, 255}));
    const FLOAT red[4] = {1, 0, 0, 1};
    d.context->ClearRenderTargetView(rtv.Get(), red);
    d.context->Draw(3, 0);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
}

TEST_F(DeferredTest, FinishWithRestoreKeepsTheDeferredState) {
    const float green[4] = {0, 1, 0, 1};
    recordDraw(green);
    ComPtr<ID3D11CommandList> first, second;
    ASSERT_EQ(deferred->FinishCommandList(TRUE, first.GetAddressOf()), S_OK);
    deferred->Draw(3, 0);  // the pipeline recorded before Finish(TRUE) still holds
    ASSERT_EQ(deferred->FinishCommandList(FALSE, second.GetAddressOf()), S_OK);
    const FLOAT red[4] = {1, 0, 0, 1};
    d.context->ClearRenderTargetView(rtv.Get(), red);
    d.context->ExecuteCommandList(second.Get(), FALSE);
    // The second list binds what the first did and draws; the Map was in the first list, so the
    // buffer still has its initial zeros: the draw writes (0, 0, 0, 0).
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
    d.context->ExecuteCommandList(first.Get(), FALSE);
    d.context->ExecuteCommandList(second.Get(), FALSE);
    EXPECT_EQ(pixel(), (std::array<std::uint8_t, 4>{0, 255, 0, 255}));
}

TEST_F(DeferredTest, InvalidCallsAreAnswered) {
    ComPtr<ID3D11DeviceContext> other;
    EXPECT_EQ(d.device->CreateDeferredContext(1, other.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ContextFlags = 1"), std::string::npos) << lastError();
    ComPtr<ID3D11CommandList> list;
    EXPECT_EQ(d.context->FinishCommandList(FALSE, list.GetAddressOf()), DXGI_ERROR_INVALID_CALL);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(deferred->Map(target.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &mapped), E_INVALIDARG);
    EXPECT_NE(lastError().find("DYNAMIC buffers with D3D11_MAP_WRITE_DISCARD only"), std::string::npos) << lastError();
    UINT64 unused = 0;
    EXPECT_EQ(deferred->GetData(nullptr, &unused, sizeof unused, 0), DXGI_ERROR_INVALID_CALL);
}

}  // namespace
}  // namespace d3d11test
