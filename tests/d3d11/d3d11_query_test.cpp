// ID3D11Query: an occlusion query counts the samples a draw writes (a rectangle of 4 x 8 pixel
// centres on an 8 x 8 target without multisampling: 32, counted on the CPU from D3D's top-left
// rule), its predicate says whether any passed; event and timestamp queries become ready after End
// (timestamps in order, disjoint's frequency 1e9, never disjoint); GetData's S_FALSE/S_OK protocol
// and the invalid calls D3D answers with E_INVALIDARG / DXGI_ERROR_INVALID_CALL.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// x in [-1, 0] (the left half) over the whole height: pixels x = 0..3 of 8.
const char* kHalf = R"(
static const float2 kCorners[6] = { float2(-1, 1), float2(0, 1), float2(0, -1), float2(-1, 1), float2(0, -1), float2(-1, -1) };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 ps() : SV_Target { return 1; }
)";

struct QueryTest : ::testing::Test {
    Device d;
    ComPtr<ID3D11Texture2D> target;
    void SetUp() override {
        ComPtr<ID3DBlob> vsCode = compile(kHalf, "vs", "vs_5_0"), psCode = compile(kHalf, "ps", "ps_5_0");
        ASSERT_TRUE(vsCode && psCode);
        ComPtr<ID3D11VertexShader> vs;
        ComPtr<ID3D11PixelShader> ps;
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
        target = makeTexture(d, 8, 8, D3D11_BIND_RENDER_TARGET);
        ComPtr<ID3D11RenderTargetView> rtv;
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
        d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        D3D11_VIEWPORT viewport;
        viewport.Width = viewport.Height = 8;
        d.context->RSSetViewports(1, &viewport);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
    }
    ComPtr<ID3D11Query> query(D3D11_QUERY kind) {
        D3D11_QUERY_DESC desc;
        desc.Query = kind;
        ComPtr<ID3D11Query> q;
        EXPECT_EQ(d.device->CreateQuery(&desc, q.GetAddressOf()), S_OK) << lastError();
        return q;
    }
    // GetData until the result is there (S_FALSE meanwhile), at most a few seconds' worth of polls.
    template <class T>
    HRESULT wait(ID3D11Query* q, T& out) {
        HRESULT hr = S_FALSE;
        for (int i = 0; i < 1000000 && hr == S_FALSE; ++i) hr = d.context->GetData(q, &out, sizeof out, 0);
        return hr;
    }
};

TEST_F(QueryTest, OcclusionCountsTheSamplesADrawWrites) {
    ComPtr<ID3D11Query> occlusion = query(D3D11_QUERY_OCCLUSION), empty = query(D3D11_QUERY_OCCLUSION);
    ComPtr<ID3D11Query> some = query(D3D11_QUERY_OCCLUSION_PREDICATE), none = query(D3D11_QUERY_OCCLUSION_PREDICATE);
    d.context->Begin(occlusion.Get());
    d.context->Draw(6, 0);
    d.context->End(occlusion.Get());
    d.context->Begin(empty.Get());
    d.context->End(empty.Get());
    d.context->Begin(some.Get());
    d.context->Draw(3, 0);  // one of the two triangles: half the rectangle's pixels
    d.context->End(some.Get());
    d.context->Begin(none.Get());
    d.context->End(none.Get());
    ASSERT_EQ(lastError(), "");
    UINT64 samples = 99;
    ASSERT_EQ(wait(occlusion.Get(), samples), S_OK) << lastError();
    EXPECT_EQ(samples, 32u);  // 4 columns x 8 rows of pixel centres
    ASSERT_EQ(wait(empty.Get(), samples), S_OK);
    EXPECT_EQ(samples, 0u);
    BOOL any = FALSE;
    ASSERT_EQ(wait(some.Get(), any), S_OK);
    EXPECT_EQ(any, TRUE);
    ASSERT_EQ(wait(none.Get(), any), S_OK);
    EXPECT_EQ(any, FALSE);
    // Asking only whether it is ready: DataSize 0, pData null.
    EXPECT_EQ(d.context->GetData(occlusion.Get(), nullptr, 0, 0), S_OK);
}

TEST_F(QueryTest, EventAndTimestampsBecomeReadyAfterEnd) {
    ComPtr<ID3D11Query> disjoint = query(D3D11_QUERY_TIMESTAMP_DISJOINT), before = query(D3D11_QUERY_TIMESTAMP),
                        after = query(D3D11_QUERY_TIMESTAMP), event = query(D3D11_QUERY_EVENT);
    d.context->Begin(disjoint.Get());
    d.context->End(before.Get());
    d.context->Draw(6, 0);
    d.context->End(after.Get());
    d.context->End(disjoint.Get());
    d.context->End(event.Get());
    ASSERT_EQ(lastError(), "");
    BOOL done = FALSE;
    ASSERT_EQ(wait(event.Get(), done), S_OK);
    EXPECT_EQ(done, TRUE);
    UINT64 t0 = 0, t1 = 0;
    ASSERT_EQ(wait(before.Get(), t0), S_OK);
    ASSERT_EQ(wait(after.Get(), t1), S_OK);
    EXPECT_GT(t0, 0u);
    EXPECT_GE(t1, t0);
    D3D11_QUERY_DATA_TIMESTAMP_DISJOINT frequency;
    ASSERT_EQ(wait(disjoint.Get(), frequency), S_OK);
    EXPECT_EQ(frequency.Frequency, 1000000000u);
    EXPECT_EQ(frequency.Disjoint, FALSE);
}

TEST_F(QueryTest, InvalidQueriesAndCallsAreAnswered) {
    D3D11_QUERY_DESC desc;
    ComPtr<ID3D11Query> q;
    EXPECT_EQ(d.device->CreateQuery(nullptr, q.GetAddressOf()), E_INVALIDARG);
    desc.Query = D3D11_QUERY(99);
    EXPECT_EQ(d.device->CreateQuery(&desc, q.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_QUERY_DESC.Query = 99"), std::string::npos) << lastError();
    desc.Query = D3D11_QUERY_OCCLUSION;
    desc.MiscFlags = D3D11_QUERY_MISC_PREDICATEHINT;
    EXPECT_EQ(d.device->CreateQuery(&desc, q.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MiscFlags = 1"), std::string::npos) << lastError();
    desc = {};
    desc.Query = D3D11_QUERY_SO_STATISTICS_STREAM2;  // fxport captures stream 0 only (d3d11_stream_output_test.cpp)
    EXPECT_EQ(d.device->CreateQuery(&desc, q.GetAddressOf()), E_NOTIMPL);
    desc.Query = D3D11_QUERY_OCCLUSION;
    EXPECT_EQ(d.device->CreateQuery(&desc, nullptr), S_FALSE);  // valid, nothing made

    ComPtr<ID3D11Query> occlusion = query(D3D11_QUERY_OCCLUSION);
    UINT64 samples = 0;
    EXPECT_EQ(d.context->GetData(occlusion.Get(), &samples, sizeof samples, 0), DXGI_ERROR_INVALID_CALL);  // never ended
    d.context->Begin(occlusion.Get());
    d.context->End(occlusion.Get());
    EXPECT_EQ(d.context->GetData(occlusion.Get(), &samples, 4, 0), E_INVALIDARG);
    EXPECT_NE(lastError().find("DataSize = 4"), std::string::npos) << lastError();
    EXPECT_EQ(d.context->GetData(occlusion.Get(), &samples, sizeof samples, 8), E_INVALIDARG);
    // Two occlusion queries at once: the second Begin is refused with a message (GL counts one).
    ComPtr<ID3D11Query> other = query(D3D11_QUERY_OCCLUSION);
    d.context->Begin(occlusion.Get());
    d.context->Begin(other.Get());
    EXPECT_NE(lastError().find("another occlusion query is counting"), std::string::npos) << lastError();
    d.context->End(occlusion.Get());
    // Begin on an event query: D3D ignores it (noted).
    ComPtr<ID3D11Query> event = query(D3D11_QUERY_EVENT);
    d.context->Begin(event.Get());
    EXPECT_NE(lastError().find("has no Begin"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
