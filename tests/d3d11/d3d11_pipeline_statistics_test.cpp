// D3D11_QUERY_PIPELINE_STATISTICS between Begin and End: two triangles (6 vertices, no index
// buffer) covering the left half of an 8 x 8 target -- 32 pixel centres by D3D's top-left rule,
// counted on the CPU -- and a dispatch of 2 groups of 4 x 2 threads. Each counter is compared with
// what D3D's documentation says it counts (D3D11_QUERY_DATA_PIPELINE_STATISTICS); a driver without
// GL_ARB_pipeline_statistics_query answers CreateQuery with E_NOTIMPL naming it, and the test says so.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kShaders = R"(
static const float2 kCorners[6] = { float2(-1, 1), float2(0, 1), float2(0, -1), float2(-1, 1), float2(0, -1), float2(-1, -1) };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 ps() : SV_Target { return 1; }
RWStructuredBuffer<uint> Out : register(u0);
[numthreads(4, 2, 1)]
void cs(uint i : SV_GroupIndex, uint3 g : SV_GroupID) { Out[g.x * 8 + i] = 1; }
)";

// The number of pixel centres (x + 0.5, y + 0.5) inside the left half of an 8 x 8 target.
UINT64 pixelsCovered() {
    UINT64 n = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) n += (x + 0.5) < 4.0 ? 1 : 0;
    return n;
}

struct Statistics : ::testing::Test {
    Device d;
    ComPtr<ID3D11Query> query;
    void SetUp() override {
        D3D11_QUERY_DESC desc;
        desc.Query = D3D11_QUERY_PIPELINE_STATISTICS;
        const HRESULT hr = d.device->CreateQuery(&desc, query.GetAddressOf());
        if (hr == E_NOTIMPL) {
            EXPECT_NE(lastError().find("GL_ARB_pipeline_statistics_query"), std::string::npos) << lastError();
            GTEST_SKIP() << "the GL driver has no pipeline statistics: " << lastError();
        }
        ASSERT_EQ(hr, S_OK) << lastError();
        EXPECT_EQ(query->GetDataSize(), sizeof(D3D11_QUERY_DATA_PIPELINE_STATISTICS));
    }
    D3D11_QUERY_DATA_PIPELINE_STATISTICS result() {
        D3D11_QUERY_DATA_PIPELINE_STATISTICS s;
        HRESULT hr = S_FALSE;
        for (int i = 0; i < 1000000 && hr == S_FALSE; ++i) hr = d.context->GetData(query.Get(), &s, sizeof s, 0);
        EXPECT_EQ(hr, S_OK) << lastError();
        return s;
    }
};

TEST_F(Statistics, ADrawCountsItsVerticesPrimitivesAndPixels) {
    ComPtr<ID3DBlob> vsCode = compile(kShaders, "vs", "vs_5_0"), psCode = compile(kShaders, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
    ComPtr<ID3D11Texture2D> target = makeTexture(d, 8, 8, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 8;
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->Draw(6, 0);  // before Begin: not counted
    d.context->Begin(query.Get());
    d.context->Draw(6, 0);
    d.context->End(query.Get());
    ASSERT_EQ(lastError(), "");
    const D3D11_QUERY_DATA_PIPELINE_STATISTICS s = result();
    EXPECT_EQ(s.IAVertices, 6u);
    EXPECT_EQ(s.IAPrimitives, 2u);
    // A driver may shade a repeated vertex once; without indices none repeats, and each is shaded.
    EXPECT_GE(s.VSInvocations, 1u);
    EXPECT_LE(s.VSInvocations, 6u);
    EXPECT_EQ(s.GSInvocations, 0u);
    EXPECT_EQ(s.GSPrimitives, 0u);
    EXPECT_EQ(s.CInvocations, 2u);
    EXPECT_EQ(s.CPrimitives, 2u);  // inside the view volume: the clipper passes both as they are
    // Every covered pixel is shaded; a GPU may count helper lanes too (llvmpipe counts each 4 x 4
    // block a triangle touches: 64 here), as D3D hardware counts whole 2 x 2 quads.
    EXPECT_GE(s.PSInvocations, pixelsCovered());
    EXPECT_EQ(s.HSInvocations, 0u);
    EXPECT_EQ(s.DSInvocations, 0u);
    EXPECT_EQ(s.CSInvocations, 0u);
}

TEST_F(Statistics, ADispatchCountsItsThreads) {
    ComPtr<ID3DBlob> code = compile(kShaders, "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK);
    ComPtr<ID3D11Buffer> out = makeBuffer(d, nullptr, 64, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(out.Get(), nullptr, uav.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOfConst(), nullptr);
    d.context->Begin(query.Get());
    d.context->Dispatch(2, 1, 1);
    d.context->End(query.Get());
    ASSERT_EQ(lastError(), "");
    const D3D11_QUERY_DATA_PIPELINE_STATISTICS s = result();
    EXPECT_EQ(s.CSInvocations, 2u * 4u * 2u);
    EXPECT_EQ(s.IAVertices, 0u);
    EXPECT_EQ(s.PSInvocations, 0u);
}

TEST_F(Statistics, OneCountsAtATime) {
    D3D11_QUERY_DESC desc;
    desc.Query = D3D11_QUERY_PIPELINE_STATISTICS;
    ComPtr<ID3D11Query> other;
    ASSERT_EQ(d.device->CreateQuery(&desc, other.GetAddressOf()), S_OK) << lastError();
    d.context->Begin(query.Get());
    d.context->Begin(other.Get());
    EXPECT_NE(lastError().find("another pipeline-statistics query is counting"), std::string::npos) << lastError();
    d.context->End(query.Get());
    D3D11_QUERY_DATA_PIPELINE_STATISTICS s;
    EXPECT_EQ(d.context->GetData(other.Get(), &s, sizeof s, 0), DXGI_ERROR_INVALID_CALL);  // never begun nor ended
}

}  // namespace
}  // namespace d3d11test
