// D3D11's out-of-range accesses (xlate spirv/out_of_range_accesses.h): a Load of a texel or level
// outside the texture, a typed, structured or raw buffer read past the view's end and a typed UAV
// read past its end return 0, and structured and raw stores and atomics past the view are dropped,
// where GL leaves them undefined (a view of part of a buffer is bound as a range, so GL reads and
// writes on into the rest of the buffer). Checked against the CPU's copy of the rule.
#include <cstdint>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// Each pixel Loads its lower-left neighbour (outside the texture at the left and bottom borders)
// plus three times level 1 of a texture of one level.
TEST(D3D11OutOfRangeReads, TextureLoadOutsideTheTextureReadsZero) {
    Device d;
    std::vector<std::uint32_t> texels(16);
    for (std::uint32_t k = 0; k < 16; ++k) texels[k] = 0x80000000u | ((10 * k + 5) << 16) | ((k + 1) << 8) | (200 - k);
    ComPtr<ID3D11Texture2D> texture = makeTexture(d, 4, 4, D3D11_BIND_SHADER_RESOURCE, &texels);
    ASSERT_TRUE(texture);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    const std::string source = std::string(kTexelLoadShader).substr(0, std::string(kTexelLoadShader).find("float4 ps")) + R"(
float4 ps(float4 p : SV_Position) : SV_Target {
    return tex.Load(int3(int2(p.xy) + int2(-1, 1), 0)) + 3 * tex.Load(int3(p.xy, 1));
})";
    const auto got = drawWithTexture(d, source, view.Get(), 4, 4);
    ASSERT_EQ(got.size(), 16u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            std::array<float, 4> want{0, 0, 0, 0};
            if (x >= 1 && y + 1 < 4) {
                const std::uint32_t t = texels[std::size_t((y + 1) * 4 + x - 1)];
                for (int c = 0; c < 4; ++c) want[std::size_t(c)] = float((t >> (8 * c)) & 0xFF) / 255.0f;
            }
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(got[std::size_t(y * 4 + x)][std::size_t(c)], want[std::size_t(c)], 1e-5f) << "pixel " << x << "," << y << " channel " << c;
        }
}

// Views of the first 4 elements of 8-element buffers: thread i < 8 reads element i of a typed, a
// structured and a raw view and of a typed UAV; elements 4..7 lie past the views and read 0.
TEST(D3D11OutOfRangeReads, BufferReadsPastTheViewReadZero) {
    Device d;
    float in[16];
    for (int k = 0; k < 16; ++k) in[k] = float(k + 1) * 1.5f;
    ComPtr<ID3D11Buffer> typed = makeBuffer(d, in, 32, D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11Buffer> structured = makeBuffer(d, in, 64, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 8);
    ComPtr<ID3D11Buffer> raw = makeBuffer(d, in, 32, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS);
    ComPtr<ID3D11Buffer> rwTyped = makeBuffer(d, in, 32, D3D11_BIND_UNORDERED_ACCESS);
    const float zeros[32] = {};
    ComPtr<ID3D11Buffer> out = makeBuffer(d, zeros, sizeof zeros, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    ASSERT_TRUE(typed && structured && raw && rwTyped && out);
    ComPtr<ID3D11ShaderResourceView> srvs[3];
    D3D11_SHADER_RESOURCE_VIEW_DESC sd{};
    sd.Format = DXGI_FORMAT_R32_FLOAT;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    sd.Buffer.FirstElement = 0;
    sd.Buffer.NumElements = 4;
    ASSERT_EQ(d.device->CreateShaderResourceView(typed.Get(), &sd, srvs[0].GetAddressOf()), S_OK) << lastError();
    sd.Format = DXGI_FORMAT_UNKNOWN;
    ASSERT_EQ(d.device->CreateShaderResourceView(structured.Get(), &sd, srvs[1].GetAddressOf()), S_OK) << lastError();
    sd.Format = DXGI_FORMAT_R32_TYPELESS;
    sd.ViewDimension = D3D11_SRV_DIMENSION_BUFFEREX;
    sd.BufferEx.FirstElement = 0;
    sd.BufferEx.NumElements = 4;
    sd.BufferEx.Flags = D3D11_BUFFEREX_SRV_FLAG_RAW;
    ASSERT_EQ(d.device->CreateShaderResourceView(raw.Get(), &sd, srvs[2].GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11UnorderedAccessView> uavs[2];
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud{};
    ud.Format = DXGI_FORMAT_R32_FLOAT;
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.FirstElement = 0;
    ud.Buffer.NumElements = 4;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(rwTyped.Get(), &ud, uavs[0].GetAddressOf()), S_OK) << lastError();
    ud.Format = DXGI_FORMAT_UNKNOWN;
    ud.Buffer.NumElements = 32;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(out.Get(), &ud, uavs[1].GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> code = compile(R"(
Buffer<float> Typed : register(t0);
struct Pair { float a; float b; };
StructuredBuffer<Pair> Structured : register(t1);
ByteAddressBuffer Raw : register(t2);
RWBuffer<float> RwTyped : register(u0);
RWStructuredBuffer<float> Out : register(u1);
[numthreads(8, 1, 1)]
void cs(uint3 id : SV_DispatchThreadID) {
    Out[id.x * 4 + 0] = Typed[id.x];
    Out[id.x * 4 + 1] = Structured[id.x].b;
    Out[id.x * 4 + 2] = asfloat(Raw.Load(id.x * 4));
    Out[id.x * 4 + 3] = RwTyped[id.x];
})",
                                    "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    ID3D11ShaderResourceView* views[3] = {srvs[0].Get(), srvs[1].Get(), srvs[2].Get()};
    d.context->CSSetShaderResources(0, 3, views);
    ID3D11UnorderedAccessView* u[2] = {uavs[0].Get(), uavs[1].Get()};
    d.context->CSSetUnorderedAccessViews(0, 2, u, nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    const std::vector<float> got = readBuffer<float>(d, out.Get());
    ASSERT_EQ(got.size(), 32u);
    for (int i = 0; i < 8; ++i) {
        const bool inside = i < 4;
        EXPECT_EQ(got[std::size_t(i * 4 + 0)], inside ? in[i] : 0.0f) << "Buffer<float>[" << i << "]";
        EXPECT_EQ(got[std::size_t(i * 4 + 1)], inside ? in[2 * i + 1] : 0.0f) << "StructuredBuffer[" << i << "].b";
        EXPECT_EQ(got[std::size_t(i * 4 + 2)], inside ? in[i] : 0.0f) << "ByteAddressBuffer.Load(" << 4 * i << ")";
        EXPECT_EQ(got[std::size_t(i * 4 + 3)], inside ? in[i] : 0.0f) << "RWBuffer<float>[" << i << "]";
    }
}

// Views of the first 4 elements of 8-element buffers: threads 0..7 store through a structured view
// and add through a raw view; the stores and atomics past the views are dropped, so elements 4..7 of
// both buffers keep their contents.
TEST(D3D11OutOfRangeReads, BufferWritesPastTheViewAreDropped) {
    Device d;
    std::uint32_t fill[8];
    for (std::uint32_t k = 0; k < 8; ++k) fill[k] = 1000 + k;
    ComPtr<ID3D11Buffer> structured = makeBuffer(d, fill, sizeof fill, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    ComPtr<ID3D11Buffer> raw = makeBuffer(d, fill, sizeof fill, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS);
    ASSERT_TRUE(structured && raw);
    ComPtr<ID3D11UnorderedAccessView> uavs[2];
    D3D11_UNORDERED_ACCESS_VIEW_DESC ud{};
    ud.Format = DXGI_FORMAT_UNKNOWN;
    ud.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    ud.Buffer.FirstElement = 0;
    ud.Buffer.NumElements = 4;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(structured.Get(), &ud, uavs[0].GetAddressOf()), S_OK) << lastError();
    ud.Format = DXGI_FORMAT_R32_TYPELESS;
    ud.Buffer.Flags = D3D11_BUFFER_UAV_FLAG_RAW;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(raw.Get(), &ud, uavs[1].GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> code = compile(R"(
RWStructuredBuffer<uint> Structured : register(u0);
RWByteAddressBuffer Raw : register(u1);
[numthreads(8, 1, 1)]
void cs(uint3 id : SV_DispatchThreadID) {
    Structured[id.x] = 7 * id.x;
    Raw.InterlockedAdd(id.x * 4, 5);
})",
                                    "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    ID3D11UnorderedAccessView* u[2] = {uavs[0].Get(), uavs[1].Get()};
    d.context->CSSetUnorderedAccessViews(0, 2, u, nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    const std::vector<std::uint32_t> s = readBuffer<std::uint32_t>(d, structured.Get()), r = readBuffer<std::uint32_t>(d, raw.Get());
    ASSERT_EQ(s.size(), 8u);
    ASSERT_EQ(r.size(), 8u);
    for (std::uint32_t k = 0; k < 8; ++k) {
        EXPECT_EQ(s[k], k < 4 ? 7 * k : fill[k]) << "structured element " << k;
        EXPECT_EQ(r[k], k < 4 ? fill[k] + 5 : fill[k]) << "raw word " << k;
    }
}

}  // namespace
}  // namespace d3d11test
