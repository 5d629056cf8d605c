// System values of the vertex stage that GL spells otherwise, drawn and read back:
//  - SV_VertexID counts from the draw's start: Draw's StartVertexLocation and DrawIndexed's
//    BaseVertexLocation are not in it (HLSL proposal 0015, microsoft/hlsl-specs:
//    "SV_VertexID doesn't include the StartVertexLocation"), while the vertex fetched is still
//    StartVertexLocation + i / index + BaseVertexLocation. GL's gl_VertexID counts them in.
//  - SV_RenderTargetArrayIndex written by a vertex shader (D3D11.3 VPRT, as HolographicSpinningCube's
//    VPRT vertex shader does) or by a domain shader sends each primitive to that slice of an array
//    render target, and the pixel shader reads the slice back through the same semantic.
#include <cstring>
#include <functional>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Texel = std::array<float, 4>;

ComPtr<ID3D11Buffer> buffer(Device& d, const void* data, UINT bytes, UINT bind) {
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = bytes;
    desc.BindFlags = bind;
    D3D11_SUBRESOURCE_DATA init;
    init.pSysMem = data;
    ComPtr<ID3D11Buffer> b;
    EXPECT_EQ(d.device->CreateBuffer(&desc, &init, b.GetAddressOf()), S_OK) << lastError();
    return b;
}

ComPtr<ID3D11Texture2D> floatTexture(Device& d, UINT width, UINT height, UINT slices, UINT bind, D3D11_USAGE usage = D3D11_USAGE_DEFAULT) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = 1;
    desc.ArraySize = slices;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.Usage = usage;
    desc.BindFlags = bind;
    desc.CPUAccessFlags = usage == D3D11_USAGE_STAGING ? UINT(D3D11_CPU_ACCESS_READ) : 0u;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

void setViewport(Device& d, UINT width, UINT height) {
    D3D11_VIEWPORT vp{};
    vp.Width = float(width);
    vp.Height = float(height);
    vp.MaxDepth = 1;
    d.context->RSSetViewports(1, &vp);
}

void setShaders(Device& d, const char* source, const char* name, ComPtr<ID3DBlob>* vsCodeOut = nullptr) {
    ComPtr<ID3DBlob> vsCode = compile(source, "VS", "vs_5_0", name), psCode = compile(source, "PS", "ps_5_0", name);
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    if (vsCodeOut) *vsCodeOut = vsCode;
}

// One point per vertex at pixel x = SV_VertexID of a kWidth x 1 target, coloured (SV_VertexID,
// the vertex's VALUE attribute).
constexpr UINT kWidth = 8;
const char* const kVertexIdPoints = R"(
struct V { float4 p : SV_Position; float2 c : COLOR0; };
V VS(uint id : SV_VertexID, float value : VALUE) {
    V o;
    o.p = float4((id + 0.5) / 4.0 - 1.0, 0, 0, 1);
    o.c = float2(id, value);
    return o;
}
float4 PS(V i) : SV_Target { return float4(i.c, 0, 1); }
)";

struct D3D11VertexId : ::testing::Test {
    Device d;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11Buffer> values;  // vertex k's VALUE: 10 k

    void SetUp() override {
        ComPtr<ID3DBlob> vsCode;
        setShaders(d, kVertexIdPoints, "vertex_id.hlsl", &vsCode);
        ASSERT_TRUE(vsCode);
        const D3D11_INPUT_ELEMENT_DESC element = {"VALUE", 0, DXGI_FORMAT_R32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0};
        ComPtr<ID3D11InputLayout> layout;
        ASSERT_EQ(d.device->CreateInputLayout(&element, 1, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK) << lastError();
        float tens[kWidth];
        for (UINT k = 0; k < kWidth; ++k) tens[k] = 10.0f * float(k);
        values = buffer(d, tens, sizeof tens, D3D11_BIND_VERTEX_BUFFER);
        target = floatTexture(d, kWidth, 1, 1, D3D11_BIND_RENDER_TARGET);
        ComPtr<ID3D11RenderTargetView> rtv;
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
        const FLOAT clear[4] = {-1, -1, -1, -1};
        d.context->ClearRenderTargetView(rtv.Get(), clear);
        d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        setViewport(d, kWidth, 1);
        d.context->IASetInputLayout(layout.Get());
        const UINT stride = 4, offset = 0;
        d.context->IASetVertexBuffers(0, 1, values.GetAddressOfConst(), &stride, &offset);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
    }

    // Pixel x of the target: (SV_VertexID, VALUE) of the point drawn there, or the clear colour.
    std::vector<Texel> pixels() { return readTexels<Texel>(d, target.Get()); }
    static Texel point(float id, float value) { return {id, value, 0, 1}; }
    static Texel cleared() { return {-1, -1, -1, -1}; }
};

TEST_F(D3D11VertexId, DrawLeavesStartVertexLocationOutOfSvVertexId) {
    d.context->Draw(4, 3);
    ASSERT_EQ(lastError(), "");
    const std::vector<Texel> got = pixels();
    ASSERT_EQ(got.size(), std::size_t(kWidth));
    // Vertex i of the draw: SV_VertexID i, fetched from vertex 3 + i.
    for (UINT x = 0; x < kWidth; ++x)
        EXPECT_EQ(got[x], x < 4 ? point(float(x), 10.0f * float(3 + x)) : cleared()) << "pixel " << x;
}

TEST_F(D3D11VertexId, DrawInstancedLeavesStartVertexLocationOutOfSvVertexId) {
    d.context->DrawInstanced(2, 1, 5, 0);
    ASSERT_EQ(lastError(), "");
    const std::vector<Texel> got = pixels();
    ASSERT_EQ(got.size(), std::size_t(kWidth));
    for (UINT x = 0; x < kWidth; ++x) EXPECT_EQ(got[x], x < 2 ? point(float(x), 10.0f * float(5 + x)) : cleared()) << "pixel " << x;
}

TEST_F(D3D11VertexId, DrawIndexedGivesTheIndexWithoutBaseVertexLocation) {
    // Index positions 1..4 hold 0..3 (position 0 is skipped by StartIndexLocation 1).
    const std::uint16_t indices[5] = {7, 0, 1, 2, 3};
    ComPtr<ID3D11Buffer> ib = buffer(d, indices, sizeof indices, D3D11_BIND_INDEX_BUFFER);
    d.context->IASetIndexBuffer(ib.Get(), DXGI_FORMAT_R16_UINT, 0);
    d.context->DrawIndexed(4, 1, 2);
    ASSERT_EQ(lastError(), "");
    const std::vector<Texel> got = pixels();
    ASSERT_EQ(got.size(), std::size_t(kWidth));
    // SV_VertexID is the index read; the vertex fetched is index + BaseVertexLocation.
    for (UINT x = 0; x < kWidth; ++x)
        EXPECT_EQ(got[x], x < 4 ? point(float(x), 10.0f * float(x + 2)) : cleared()) << "pixel " << x;
}

TEST_F(D3D11VertexId, ANegativeBaseVertexLocationIsLeftOutToo) {
    const std::uint32_t indices[3] = {4, 5, 6};
    ComPtr<ID3D11Buffer> ib = buffer(d, indices, sizeof indices, D3D11_BIND_INDEX_BUFFER);
    d.context->IASetIndexBuffer(ib.Get(), DXGI_FORMAT_R32_UINT, 0);
    // Then a plain draw from 0 with the same shader: the start it last had must not stay.
    d.context->DrawIndexedInstanced(3, 1, 0, -3, 0);
    d.context->Draw(1, 0);
    ASSERT_EQ(lastError(), "");
    const std::vector<Texel> got = pixels();
    ASSERT_EQ(got.size(), std::size_t(kWidth));
    for (UINT x = 0; x < kWidth; ++x) {
        const Texel want = x == 0 ? point(0, 0) : x >= 4 && x <= 6 ? point(float(x), 10.0f * float(x - 3)) : cleared();
        EXPECT_EQ(got[x], want) << "pixel " << x;
    }
}

// Slice `slice` of a float array texture, through a staging copy and Map READ.
std::vector<Texel> readSlice(Device& d, ID3D11Texture2D* array, UINT slice, UINT width, UINT height) {
    ComPtr<ID3D11Texture2D> staging = floatTexture(d, width, height, 1, 0, D3D11_USAGE_STAGING);
    d.context->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, array, slice, nullptr);
    return readTexels<Texel>(d, staging.Get());
}

// Slices of a kSlices-slice kSize x kSize float array target: each pixel of slice s is `drawn(s)`.
constexpr UINT kSlices = 4, kSize = 2;
void expectSlices(Device& d, ID3D11Texture2D* array, const std::function<Texel(UINT)>& drawn) {
    for (UINT slice = 0; slice < kSlices; ++slice) {
        const std::vector<Texel> got = readSlice(d, array, slice, kSize, kSize);
        ASSERT_EQ(got.size(), std::size_t(kSize * kSize));
        for (std::size_t p = 0; p < got.size(); ++p) EXPECT_EQ(got[p], drawn(slice)) << "slice " << slice << " pixel " << p;
    }
}

// The array target, cleared to -1 and bound with a viewport over it.
ComPtr<ID3D11Texture2D> bindArrayTarget(Device& d) {
    ComPtr<ID3D11Texture2D> array = floatTexture(d, kSize, kSize, kSlices, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(array.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const FLOAT clear[4] = {-1, -1, -1, -1};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    setViewport(d, kSize, kSize);
    return array;
}

TEST(D3D11SystemValues, AVertexShaderSendsEachInstanceToTheSliceItsRenderTargetArrayIndexNames) {
    Device d;
    // VPRT: instance i draws a full-screen triangle into slice i + 1; the pixel shader reads the
    // slice it is drawing (SV_RenderTargetArrayIndex as an input) and the instance.
    setShaders(d, R"(
struct V { float4 p : SV_Position; nointerpolation uint instance : INSTANCE; uint slice : SV_RenderTargetArrayIndex; };
V VS(uint id : SV_VertexID, uint instance : SV_InstanceID) {
    V o;
    o.p = float4(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0, 0, 1);
    o.instance = instance;
    o.slice = instance + 1;
    return o;
}
float4 PS(float4 p : SV_Position, uint instance : INSTANCE, uint slice : SV_RenderTargetArrayIndex) : SV_Target {
    return float4(slice, instance, 7, 1);
})",
               "vprt.hlsl");
    ComPtr<ID3D11Texture2D> array = bindArrayTarget(d);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->DrawInstanced(3, 2, 0, 0);
    ASSERT_EQ(lastError(), "");
    // Slices 1 and 2 hold instances 0 and 1; 0 and 3 keep the clear colour.
    expectSlices(d, array.Get(), [](UINT slice) { return slice == 1 || slice == 2 ? Texel{float(slice), float(slice - 1), 7, 1} : Texel{-1, -1, -1, -1}; });
}

TEST(D3D11SystemValues, ADomainShaderSendsItsPatchToTheSliceItsRenderTargetArrayIndexNames) {
    Device d;
    const char* source = R"(
struct P { float4 p : POS; };
struct C { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; uint slice : SV_RenderTargetArrayIndex; };
P VS(uint id : SV_VertexID) { P o; o.p = float4(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0, 0, 1); return o; }
C Constants() { C c; c.e[0] = c.e[1] = c.e[2] = 1; c.i = 1; return c; }
[domain("tri")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(3)] [patchconstantfunc("Constants")]
P HS(InputPatch<P, 3> patch, uint i : SV_OutputControlPointID) { return patch[i]; }
[domain("tri")]
D DS(C c, float3 uvw : SV_DomainLocation, const OutputPatch<P, 3> patch) {
    D o; o.p = patch[0].p * uvw.x + patch[1].p * uvw.y + patch[2].p * uvw.z; o.slice = 2; return o;
}
float4 PS(float4 p : SV_Position, uint slice : SV_RenderTargetArrayIndex) : SV_Target { return float4(slice, 5, 0, 1); })";
    setShaders(d, source, "vprt_domain.hlsl");
    ComPtr<ID3DBlob> hsCode = compile(source, "HS", "hs_5_0", "vprt_domain.hlsl"), dsCode = compile(source, "DS", "ds_5_0", "vprt_domain.hlsl");
    ASSERT_TRUE(hsCode && dsCode);
    ComPtr<ID3D11HullShader> hs;
    ComPtr<ID3D11DomainShader> ds;
    ASSERT_EQ(d.device->CreateHullShader(hsCode->GetBufferPointer(), hsCode->GetBufferSize(), nullptr, hs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateDomainShader(dsCode->GetBufferPointer(), dsCode->GetBufferSize(), nullptr, ds.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> array = bindArrayTarget(d);
    d.context->HSSetShader(hs.Get(), nullptr, 0);
    d.context->DSSetShader(ds.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_3_CONTROL_POINT_PATCHLIST);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    expectSlices(d, array.Get(), [](UINT slice) { return slice == 2 ? Texel{2, 5, 0, 1} : Texel{-1, -1, -1, -1}; });
}

}  // namespace
}  // namespace d3d11test
