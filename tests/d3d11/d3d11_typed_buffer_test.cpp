// Typed buffer views (Buffer<T> at t#, RWBuffer<T> at u#): a compute shader reads float4 elements
// of an R32G32B32A32_FLOAT view, writes float4 results through an RWBuffer<float4> view, and counts
// with InterlockedAdd into an R32_UINT RWBuffer<uint> of fewer elements than its buffer; a pixel
// shader reads an R32_SINT Buffer<int>. Read back through staging copies and compared with the
// CPU's result. Views fxport refuses name the field and value.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {



TEST(D3D11TypedBuffer, ComputeReadsAndWritesTypedViews) {
    Device d;
    const float in[4 * 4] = {1, 2, 3, 4, -1, -2, -3, -4, 0.5f, 0.25f, 8, 16, 100, 200, 300, 400};
    ComPtr<ID3D11Buffer> source = makeBuffer(d, in, sizeof in, D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11Buffer> results = makeBuffer(d, nullptr, sizeof in, D3D11_BIND_UNORDERED_ACCESS);
    const std::uint32_t zeros[16] = {};
    ComPtr<ID3D11Buffer> counts = makeBuffer(d, zeros, sizeof zeros, D3D11_BIND_UNORDERED_ACCESS);
    ASSERT_TRUE(source && results && counts);
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    srvDesc.Buffer.NumElements = 4;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(source.Get(), &srvDesc, srv.GetAddressOf()), S_OK) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC uavDesc;
    uavDesc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    uavDesc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uavDesc.Buffer.NumElements = 4;
    ComPtr<ID3D11UnorderedAccessView> resultView, countView;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(results.Get(), &uavDesc, resultView.GetAddressOf()), S_OK) << lastError();
    uavDesc.Format = DXGI_FORMAT_R32_UINT;
    uavDesc.Buffer.NumElements = 8;  // of the buffer's 16
    ASSERT_EQ(d.device->CreateUnorderedAccessView(counts.Get(), &uavDesc, countView.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> code = compile(R"(
Buffer<float4> In : register(t2);
RWBuffer<float4> Out : register(u0);
RWBuffer<uint> Counts : register(u1);
[numthreads(64, 1, 1)]
void cs(uint3 id : SV_DispatchThreadID) {
    if (id.x < 4) Out[id.x] = In.Load(id.x) * 2 + In[3 - id.x];
    InterlockedAdd(Counts[id.x % 8], id.x);
})",
                                    "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetShaderResources(2, 1, srv.GetAddressOfConst());
    ID3D11UnorderedAccessView* uavs[2] = {resultView.Get(), countView.Get()};
    d.context->CSSetUnorderedAccessViews(0, 2, uavs, nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    std::vector<float> out = readBuffer<float>(d, results.Get());
    for (int e = 0; e < 4; ++e)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(out[std::size_t(e * 4 + c)], in[e * 4 + c] * 2 + in[(3 - e) * 4 + c]) << "element " << e << "." << c;
    std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, counts.Get());
    for (std::uint32_t k = 0; k < 16; ++k) {
        std::uint32_t want = 0;
        for (std::uint32_t id = 0; id < 64 && k < 8; ++id)
            if (id % 8 == k) want += id;
        EXPECT_EQ(got[k], want) << "count " << k << (k >= 8 ? " (past the view: untouched)" : "");
    }
}

TEST(D3D11TypedBuffer, PixelShaderReadsSignedElements) {
    Device d;
    const std::int32_t values[4] = {-7, 3, 250, -100};
    ComPtr<ID3D11Buffer> source = makeBuffer(d, values, sizeof values, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(source);
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.Format = DXGI_FORMAT_R32_SINT;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    srvDesc.Buffer.NumElements = 4;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(source.Get(), &srvDesc, srv.GetAddressOf()), S_OK) << lastError();
    const char* text = R"(
Buffer<int> Values : register(t0);
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
float4 ps(float4 pos : SV_Position) : SV_Target { return float4((Values[uint(pos.x)] + 128) / 255.0, 0, 0, 1); }
)";
    ComPtr<ID3DBlob> v = compile(text, "vs", "vs_5_0"), p = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(v && p);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(v->GetBufferPointer(), v->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(p->GetBufferPointer(), p->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = makeTexture(d, 4, 1, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = 4;
    viewport.Height = 1;
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->PSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, target.Get());
    for (int x = 0; x < 4; ++x) {
        const int clamped = std::min(255, std::max(0, values[x] + 128));
        EXPECT_EQ(int(pixels[std::size_t(x)][0]), clamped) << "pixel " << x;
    }
}

TEST(D3D11TypedBuffer, RefusedViewsNameTheField) {
    Device d;
    const float data[8] = {};
    ComPtr<ID3D11Buffer> b = makeBuffer(d, data, sizeof data, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(b);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    desc.Format = DXGI_FORMAT_R32_FLOAT;
    desc.Buffer.FirstElement = 1;
    desc.Buffer.NumElements = 4;
    ComPtr<ID3D11ShaderResourceView> v;
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &desc, v.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("D3D11_SHADER_RESOURCE_VIEW_DESC.Buffer.FirstElement = 1"), std::string::npos) << lastError();
    desc.Buffer.FirstElement = 0;
    desc.Buffer.NumElements = 9;
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &desc, v.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("NumElements 9}: the buffer holds 8 elements of DXGI_FORMAT_R32_FLOAT"), std::string::npos) << lastError();
    desc.Buffer.NumElements = 2;
    desc.Format = DXGI_FORMAT_UNKNOWN;
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &desc, v.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_UNKNOWN for a typed buffer view"), std::string::npos) << lastError();
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;  // a texture format no buffer texture holds
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &desc, v.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R8G8B8A8_UNORM_SRGB (29): not a typed-buffer format"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
