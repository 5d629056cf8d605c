// SetPredication with an OCCLUSION_PREDICATE (ID3D11DeviceContext::SetPredication's documentation):
// the predicated calls -- draws, dispatches, clears, copies, UpdateSubresource -- are not performed
// while the predicate's data (TRUE: some sample passed) equals PredicateValue, and are performed
// otherwise. Each call's effect is read back on the CPU: a pixel's colour, a buffer's bytes.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kShaders = R"(
static const float2 kCorners[3] = { float2(-1, -1), float2(-1, 3), float2(3, -1) };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 ps() : SV_Target { return float4(0, 1, 0, 1); }
)";

constexpr std::uint32_t kGreen = 0xff00ff00u, kRed = 0xff0000ffu, kBlack = 0;

struct Predication : ::testing::Test {
    Device d;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> rtv;
    ComPtr<ID3D11Predicate> passed, failed;  // a draw's samples passed / a draw of nothing

    void SetUp() override {
        ComPtr<ID3DBlob> vsCode = compile(kShaders, "vs", "vs_5_0"), psCode = compile(kShaders, "ps", "ps_5_0");
        ASSERT_TRUE(vsCode && psCode);
        ComPtr<ID3D11VertexShader> vs;
        ComPtr<ID3D11PixelShader> ps;
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
        target = makeTexture(d, 4, 4, D3D11_BIND_RENDER_TARGET);
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
        d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        D3D11_VIEWPORT viewport;
        viewport.Width = viewport.Height = 4;
        d.context->RSSetViewports(1, &viewport);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        D3D11_QUERY_DESC desc;
        desc.Query = D3D11_QUERY_OCCLUSION_PREDICATE;
        ASSERT_EQ(d.device->CreatePredicate(&desc, passed.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePredicate(&desc, failed.GetAddressOf()), S_OK) << lastError();
        d.context->Begin(passed.Get());
        d.context->Draw(3, 0);
        d.context->End(passed.Get());
        d.context->Begin(failed.Get());
        d.context->Draw(0, 0);
        d.context->End(failed.Get());
        ASSERT_EQ(lastError(), "");
        clear(kBlack);
    }
    void clear(std::uint32_t rgba) {
        const FLOAT c[4] = {float(rgba & 0xff) / 255, float(rgba >> 8 & 0xff) / 255, float(rgba >> 16 & 0xff) / 255, float(rgba >> 24) / 255};
        d.context->ClearRenderTargetView(rtv.Get(), c);
    }
    std::uint32_t pixel() {
        const auto p = readPixels(d, target.Get()).at(5);
        return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
    }
};

TEST_F(Predication, DrawsAreSkippedWhenThePredicateEqualsTheValue) {
    d.context->SetPredication(passed.Get(), TRUE);  // data TRUE == TRUE: skipped
    d.context->Draw(3, 0);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(pixel(), kBlack);
    d.context->SetPredication(failed.Get(), TRUE);  // data FALSE != TRUE: drawn
    d.context->Draw(3, 0);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(pixel(), kGreen);
    clear(kBlack);
    d.context->SetPredication(failed.Get(), FALSE);  // FALSE == FALSE: skipped
    d.context->Draw(3, 0);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(pixel(), kBlack);
    d.context->SetPredication(passed.Get(), FALSE);  // TRUE != FALSE: drawn
    d.context->Draw(3, 0);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(pixel(), kGreen);
}

TEST_F(Predication, ClearsCopiesAndUpdatesArePredicatedToo) {
    d.context->SetPredication(passed.Get(), TRUE);
    clear(kRed);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(pixel(), kBlack);  // the clear was skipped (the read-back copies ran unpredicated)

    const std::uint32_t ones[4] = {1, 1, 1, 1}, twos[4] = {2, 2, 2, 2};
    ComPtr<ID3D11Buffer> a = makeBuffer(d, ones, 16, D3D11_BIND_VERTEX_BUFFER), b = makeBuffer(d, twos, 16, D3D11_BIND_VERTEX_BUFFER);
    d.context->SetPredication(passed.Get(), TRUE);
    d.context->CopyResource(a.Get(), b.Get());
    d.context->UpdateSubresource(b.Get(), 0, nullptr, ones, 0, 0);
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(readBuffer<std::uint32_t>(d, a.Get()), std::vector<std::uint32_t>(4, 1u));
    EXPECT_EQ(readBuffer<std::uint32_t>(d, b.Get()), std::vector<std::uint32_t>(4, 2u));
    d.context->SetPredication(passed.Get(), FALSE);  // performed
    d.context->CopyResource(a.Get(), b.Get());
    d.context->SetPredication(nullptr, FALSE);
    EXPECT_EQ(readBuffer<std::uint32_t>(d, a.Get()), std::vector<std::uint32_t>(4, 2u));
}

TEST_F(Predication, GetPredicationClearStateAndMisuse) {
    d.context->SetPredication(passed.Get(), TRUE);
    ComPtr<ID3D11Predicate> got;
    BOOL value = FALSE;
    d.context->GetPredication(got.GetAddressOf(), &value);
    EXPECT_EQ(got.Get(), passed.Get());
    EXPECT_EQ(value, TRUE);
    d.context->Begin(passed.Get());  // invalid while it predicates
    EXPECT_NE(lastError().find("the one SetPredication set"), std::string::npos) << lastError();
    d.context->ClearState();  // predication off again
    ComPtr<ID3D11Predicate> none;
    d.context->GetPredication(none.GetAddressOf(), &value);
    EXPECT_EQ(none.Get(), nullptr);
    EXPECT_EQ(value, FALSE);

    D3D11_QUERY_DESC desc;
    desc.Query = D3D11_QUERY_OCCLUSION;
    ComPtr<ID3D11Predicate> wrong;
    EXPECT_EQ(d.device->CreatePredicate(&desc, wrong.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_QUERY_DESC.Query = 1"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
