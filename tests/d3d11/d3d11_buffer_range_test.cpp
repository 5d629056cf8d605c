// Buffer views of part of a buffer (D3D11_BUFFER_SRV/UAV and D3D11_BUFFEREX_SRV FirstElement and
// NumElements): element i of the view is element FirstElement + i of the buffer, the shader sees
// NumElements of them (GetDimensions, for typed and structured views), and a write through the view lands there and nowhere else.
// Typed (Buffer<T>/RWBuffer<T>), structured and raw (ByteAddressBuffer) views, each checked
// against the CPU's copy of the same arithmetic. GL starts a bound range at multiples of its
// buffer-offset alignment (16 bytes on common drivers); a view starting elsewhere is E_NOTIMPL.
#include <cstdint>
#include <numeric>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// Runs `entry` of `source` once (one group) with `srv` at t0 and `uav` at u0.
void dispatch(Device& d, const char* source, ID3D11ShaderResourceView* srv, ID3D11UnorderedAccessView* uav) {
    ComPtr<ID3DBlob> code = compile(source, "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetShaderResources(0, 1, &srv);
    d.context->CSSetUnorderedAccessViews(0, 1, &uav, nullptr);
    d.context->Dispatch(1, 1, 1);
    EXPECT_EQ(lastError(), "");
}

// A raw (ByteAddressBuffer) view of `count` words from word `first`.
ComPtr<ID3D11ShaderResourceView> rawSrv(Device& d, ID3D11Buffer* buffer, UINT first, UINT count) {
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.Format = DXGI_FORMAT_R32_TYPELESS;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFEREX;
    sd.BufferEx.FirstElement = first;
    sd.BufferEx.NumElements = count;
    sd.BufferEx.Flags = D3D11_BUFFEREX_SRV_FLAG_RAW;
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(buffer, &sd, srv.GetAddressOf()), S_OK) << lastError();
    return srv;
}
ComPtr<ID3D11UnorderedAccessView> rawUav(Device& d, ID3D11Buffer* buffer, UINT first, UINT count) {
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud;
    ud.Format = DXGI_FORMAT_R32_TYPELESS;
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.FirstElement = first;
    ud.Buffer.NumElements = count;
    ud.Buffer.Flags = D3D11_BUFFER_UAV_FLAG_RAW;
    ComPtr<ID3D11UnorderedAccessView> uav;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(buffer, &ud, uav.GetAddressOf()), S_OK) << lastError();
    return uav;
}

std::vector<std::uint32_t> counting(std::uint32_t n, std::uint32_t from) {
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), from);
    return v;
}

// Elements 4..11 of an R32_UINT buffer read through Buffer<uint>, written doubled through
// RWBuffer<uint> to elements 8..15 of another; GetDimensions says 8.
TEST(D3D11BufferRange, TypedViewsStartAtFirstElement) {
    Device d;
    const std::vector<std::uint32_t> in = counting(16, 100), zeros(24, 0);
    ComPtr<ID3D11Buffer> source = makeBuffer(d, in.data(), 64, D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11Buffer> target = makeBuffer(d, zeros.data(), 96, D3D11_BIND_UNORDERED_ACCESS);
    ASSERT_TRUE(source && target);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.Format = DXGI_FORMAT_R32_UINT;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    sd.Buffer.FirstElement = 4;
    sd.Buffer.NumElements = 8;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(source.Get(), &sd, srv.GetAddressOf()), S_OK) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud;
    ud.Format = DXGI_FORMAT_R32_UINT;
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.FirstElement = 8;
    ud.Buffer.NumElements = 8;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(target.Get(), &ud, uav.GetAddressOf()), S_OK) << lastError();
    dispatch(d, R"(
Buffer<uint> In : register(t0);
RWBuffer<uint> Out : register(u0);
[numthreads(8, 1, 1)]
void cs(uint i : SV_DispatchThreadID) {
    uint n;
    In.GetDimensions(n);
    Out[i] = In[i] * 2 + n * 1000;
})",
             srv.Get(), uav.Get());
    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, target.Get());
    ASSERT_EQ(got.size(), 24u);
    for (std::uint32_t e = 0; e < 24; ++e) {
        const std::uint32_t want = e >= 8 && e < 16 ? in[e - 4] * 2 + 8000 : 0;
        EXPECT_EQ(got[e], want) << "element " << e;
    }
}

// A structured SRV of elements 1..2 (of 4, 16-byte float4 elements) and a structured UAV of
// elements 2..3 (BUFFEREX for the SRV, as D3D also allows).
TEST(D3D11BufferRange, StructuredViewsStartAtFirstElement) {
    Device d;
    std::vector<float> in(16), zeros(16, 0.0f);
    for (std::size_t i = 0; i < in.size(); ++i) in[i] = float(i) + 0.5f;
    ComPtr<ID3D11Buffer> source = makeBuffer(d, in.data(), 64, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 16);
    ComPtr<ID3D11Buffer> target = makeBuffer(d, zeros.data(), 64, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 16);
    ASSERT_TRUE(source && target);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFEREX;
    sd.BufferEx.FirstElement = 1;
    sd.BufferEx.NumElements = 2;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(source.Get(), &sd, srv.GetAddressOf()), S_OK) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud;
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.FirstElement = 2;
    ud.Buffer.NumElements = 2;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(target.Get(), &ud, uav.GetAddressOf()), S_OK) << lastError();
    dispatch(d, R"(
StructuredBuffer<float4> In : register(t0);
RWStructuredBuffer<float4> Out : register(u0);
[numthreads(2, 1, 1)]
void cs(uint i : SV_DispatchThreadID) {
    uint n, stride;
    In.GetDimensions(n, stride);
    Out[i] = In[i] * 2 + float(n * 100 + stride);
})",
             srv.Get(), uav.Get());
    const std::vector<float> got = readBuffer<float>(d, target.Get());
    ASSERT_EQ(got.size(), 16u);
    for (std::size_t f = 0; f < 16; ++f) {
        const std::size_t element = f / 4;
        const float want = element >= 2 ? in[f - 4] * 2 + 216.0f : 0.0f;  // view element i = buffer element 1 + i
        EXPECT_EQ(got[f], want) << "float " << f;
    }
}

// Raw views count 4-byte words: words 4..7 read through ByteAddressBuffer, written to words 8..11
// through RWByteAddressBuffer (address 0 of each view is its FirstElement's word).
TEST(D3D11BufferRange, RawViewsStartAtFirstElement) {
    Device d;
    const std::vector<std::uint32_t> in = counting(16, 7), zeros(16, 0);
    const UINT rawMisc = D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
    ComPtr<ID3D11Buffer> source = makeBuffer(d, in.data(), 64, D3D11_BIND_SHADER_RESOURCE, rawMisc);
    ComPtr<ID3D11Buffer> target = makeBuffer(d, zeros.data(), 64, D3D11_BIND_UNORDERED_ACCESS, rawMisc);
    ASSERT_TRUE(source && target);
    ComPtr<ID3D11ShaderResourceView> srv = rawSrv(d, source.Get(), 4, 4);
    ComPtr<ID3D11UnorderedAccessView> uav = rawUav(d, target.Get(), 8, 4);
    dispatch(d, R"(
ByteAddressBuffer In : register(t0);
RWByteAddressBuffer Out : register(u0);
[numthreads(4, 1, 1)]
void cs(uint i : SV_DispatchThreadID) { Out.Store(i * 4, In.Load(i * 4) + 1000); })",
             srv.Get(), uav.Get());
    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, target.Get());
    ASSERT_EQ(got.size(), 16u);
    for (std::uint32_t w = 0; w < 16; ++w) EXPECT_EQ(got[w], w >= 8 && w < 12 ? in[w - 4] + 1000 : 0u) << "word " << w;
}

// A static global initialized by calling the effect's functions, read by a compute shader (which
// runs without fxport's entry wrapper): fxc runs the initializer before the entry; glslang crashed
// (FX9001) where the entry did not reach the functions the initializer calls.
TEST(D3D11BufferRange, StaticInitializersCallingFunctionsRunBeforeAComputeEntry) {
    Device d;
    const std::vector<std::uint32_t> zeros(4, 0);
    ComPtr<ID3D11Buffer> target = makeBuffer(d, zeros.data(), 16, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS);
    ASSERT_TRUE(target);
    ComPtr<ID3D11UnorderedAccessView> uav = rawUav(d, target.Get(), 0, 4);
    dispatch(d, R"(
RWByteAddressBuffer Out : register(u0);
uint twice(uint x) { return x * 2; }
static uint Base = twice(20) + 1;
static uint Step = twice(Base);
[numthreads(4, 1, 1)]
void cs(uint i : SV_DispatchThreadID) { Out.Store(i * 4, Base + Step * i); })",
             nullptr, uav.Get());
    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, target.Get());
    ASSERT_EQ(got.size(), 4u);
    for (std::uint32_t i = 0; i < 4; ++i) EXPECT_EQ(got[i], 41u + 82u * i) << "word " << i;
}

// D3D's GetDimensions of a byte-address buffer is its view's size in bytes, not in words (glslang
// answers the count of uints); through a function parameter too.
TEST(D3D11BufferRange, RawViewsReportTheirSizeInBytes) {
    Device d;
    const std::vector<std::uint32_t> in = counting(16, 7), zeros(16, 0);
    const UINT rawMisc = D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
    ComPtr<ID3D11Buffer> source = makeBuffer(d, in.data(), 64, D3D11_BIND_SHADER_RESOURCE, rawMisc);
    ComPtr<ID3D11Buffer> target = makeBuffer(d, zeros.data(), 64, D3D11_BIND_UNORDERED_ACCESS, rawMisc);
    ASSERT_TRUE(source && target);
    ComPtr<ID3D11ShaderResourceView> srv = rawSrv(d, source.Get(), 4, 8);
    ComPtr<ID3D11UnorderedAccessView> uav = rawUav(d, target.Get(), 0, 16);
    dispatch(d, R"(
ByteAddressBuffer In : register(t0);
RWByteAddressBuffer Out : register(u0);
uint sizeOf(ByteAddressBuffer b) { uint n; b.GetDimensions(n); return n; }
[numthreads(1, 1, 1)]
void cs() {
    uint a, b;
    In.GetDimensions(a);
    Out.GetDimensions(b);
    Out.Store3(0, uint3(a, b, sizeOf(In)));
})",
             srv.Get(), uav.Get());
    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, target.Get());
    ASSERT_EQ(got.size(), 16u);
    EXPECT_EQ(got[0], 32u) << "the SRV's 8 words";
    EXPECT_EQ(got[1], 64u) << "the UAV's 16 words";
    EXPECT_EQ(got[2], 32u) << "through a function parameter";
}

// A first element off GL's alignment: E_NOTIMPL naming the field, its byte offset and the rule.
TEST(D3D11BufferRange, UnalignedFirstElementIsRefusedByName) {
    Device d;
    const std::vector<std::uint32_t> in = counting(16, 0);
    ComPtr<ID3D11Buffer> b = makeBuffer(d, in.data(), 64, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    ASSERT_TRUE(b);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    sd.Buffer.FirstElement = 1;
    sd.Buffer.NumElements = 3;
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &sd, srv.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("D3D11_SHADER_RESOURCE_VIEW_DESC.Buffer.FirstElement = 1: the view starts at byte 4"), std::string::npos) << lastError();
    sd.Buffer.FirstElement = 0;
    sd.Buffer.NumElements = 0;  // D3D: a view of no elements is invalid
    EXPECT_EQ(d.device->CreateShaderResourceView(b.Get(), &sd, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("NumElements 0}"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
