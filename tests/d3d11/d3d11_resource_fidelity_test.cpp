// What the resource side of HLSL computes, as fxc and D3D compute it.
// Structured buffers hold D3D's layout, not std430's: every member 4-byte aligned, no padding, so a
// float3 element is 12 bytes and `struct { float2 x; float y; }` is 12 (std430 makes both 16). A
// compute shader reads two such buffers and writes a third of a 48-byte struct (a float3, an int, a
// row_major float2x3 and a float2: 64 bytes in std430), whole and then one row's component through
// a dynamic row index, and GetDimensions reports the D3D element count and stride. The words read
// back are compared with the same values placed at D3D's offsets on the CPU.
// And the t registers fxc gives around DX9 samplers (vkd3d's combined-samplers and
// register-reservations-resources): an unused texture's register(tN) still reserves tN; a
// `sampler` sampled both by tex2D and by tex.Sample gets a texture of its own for the tex2D, ahead
// of the declared textures; `sampler sam[2]` indexed by constants is one sampler per element.
// Also here, the UAV intrinsics glslang gets wrong: InterlockedCompareStore (dropped by glslang)
// stores where the comparison holds and only there, on uint and int buffers; GetDimensions takes
// a mix of uint and float out arguments, also on array elements, parameters and struct members.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kRepack = R"(
struct Banana { float2 x; float y; };
struct Mixed { float3 a; int b; row_major float2x3 m; float2 c; };
StructuredBuffer<float3> Points : register(t0);
StructuredBuffer<Banana> Bananas : register(t1);
RWStructuredBuffer<Mixed> Out : register(u0);

[numthreads(1, 1, 1)]
void Main(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    Mixed o;
    o.a = Points[i] * 2;
    o.b = int(i) - 5;
    o.m = float2x3(Bananas[i].x, Bananas[i].y, Points[i]);
    uint n, stride;
    Bananas.GetDimensions(n, stride);
    o.c = float2(n, stride);
    Out[i] = o;
    Out[i].m[i & 1].z = 100 + i;
}
)";

float asFloat(std::uint32_t w) {
    float f;
    std::memcpy(&f, &w, 4);
    return f;
}

TEST(D3D11ResourceFidelity, ElementsArePackedAsD3DPacksThem) {
    Device d;
    ComPtr<ID3DBlob> code = compile(kRepack, "Main", "cs_5_0", "repack.hlsl");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> shader;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK)
        << lastError();

    const UINT count = 5;
    std::vector<float> points, bananas;
    for (UINT i = 0; i < count; ++i) {
        points.insert(points.end(), {float(i), float(i) + 0.5f, -float(i)});
        bananas.insert(bananas.end(), {10.0f * float(i), 10.0f * float(i) + 1, 10.0f * float(i) + 2});
    }
    ComPtr<ID3D11Buffer> pointBuffer = makeBuffer(d, points.data(), count * 12, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 12);
    ComPtr<ID3D11Buffer> bananaBuffer = makeBuffer(d, bananas.data(), count * 12, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 12);
    const std::vector<std::uint32_t> sentinel(count * 12, 0xDEADBEEFu);
    ComPtr<ID3D11Buffer> out = makeBuffer(d, sentinel.data(), count * 48, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 48);
    ComPtr<ID3D11ShaderResourceView> views[2];
    ASSERT_EQ(d.device->CreateShaderResourceView(pointBuffer.Get(), nullptr, views[0].GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateShaderResourceView(bananaBuffer.Get(), nullptr, views[1].GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(out.Get(), nullptr, uav.GetAddressOf()), S_OK) << lastError();

    d.context->CSSetShader(shader.Get(), nullptr, 0);
    d.context->CSSetShaderResources(0, 1, views[0].GetAddressOfConst());
    d.context->CSSetShaderResources(1, 1, views[1].GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOfConst(), nullptr);
    d.context->Dispatch(count, 1, 1);
    ASSERT_EQ(lastError(), "");

    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, out.Get());
    ASSERT_EQ(got.size(), std::size_t(count) * 12);
    for (UINT i = 0; i < count; ++i) {
        const std::uint32_t* e = &got[std::size_t(i) * 12];
        const float* p = &points[std::size_t(i) * 3];
        const float* b = &bananas[std::size_t(i) * 3];
        float expected[12] = {2 * p[0], 2 * p[1], 2 * p[2], 0, b[0], b[1], b[2], p[0], p[1], p[2], float(count), 12.0f};
        expected[4 + (i & 1) * 3 + 2] = 100.0f + float(i);  // m[i & 1].z: row (i & 1), column 2
        for (int w = 0; w < 12; ++w) {
            if (w == 3) {
                EXPECT_EQ(std::int32_t(e[w]), std::int32_t(i) - 5) << "element " << i << " word 3 (b)";
                continue;
            }
            EXPECT_EQ(asFloat(e[w]), expected[w]) << "element " << i << " word " << w;
        }
    }
}

const char* kCompareStore = R"(
RWBuffer<uint> U : register(u0);
RWBuffer<int> S : register(u1);
Texture2D<float4> T : register(t0);

[numthreads(1, 1, 1)]
void Main()
{
    InterlockedCompareStore(U[0], 5, 3);    // holds: 5 -> 3
    InterlockedCompareStore(U[1], 7, 9);    // does not hold: stays 8
    InterlockedCompareStore(S[0], -2, 4);   // holds: -2 -> 4
    InterlockedCompareStore(S[1], 1, 6);    // does not hold: stays -1
    uint width;
    float height;
    T.GetDimensions(width, height);
    U[2] = width * 100 + uint(height);
}
)";

TEST(D3D11ResourceFidelity, CompareStoreStoresWhereTheComparisonHolds) {
    Device d;
    ComPtr<ID3DBlob> code = compile(kCompareStore, "Main", "cs_5_0", "compare_store.hlsl");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> shader;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK)
        << lastError();
    const std::uint32_t u[3] = {5, 8, 0};
    const std::int32_t s[2] = {-2, -1};
    ComPtr<ID3D11Buffer> ub = makeBuffer(d, u, sizeof u, D3D11_BIND_UNORDERED_ACCESS);
    ComPtr<ID3D11Buffer> sb = makeBuffer(d, s, sizeof s, D3D11_BIND_UNORDERED_ACCESS);
    D3D11_UNORDERED_ACCESS_VIEW_DESC desc{};
    desc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    desc.Format = DXGI_FORMAT_R32_UINT;
    desc.Buffer.NumElements = 3;
    ComPtr<ID3D11UnorderedAccessView> views[2];
    ASSERT_EQ(d.device->CreateUnorderedAccessView(ub.Get(), &desc, views[0].GetAddressOf()), S_OK) << lastError();
    desc.Format = DXGI_FORMAT_R32_SINT;
    desc.Buffer.NumElements = 2;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(sb.Get(), &desc, views[1].GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> texture = makeTexture(d, 3, 2, D3D11_BIND_SHADER_RESOURCE);
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, srv.GetAddressOf()), S_OK) << lastError();

    d.context->CSSetShader(shader.Get(), nullptr, 0);
    d.context->CSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(0, 1, views[0].GetAddressOfConst(), nullptr);
    d.context->CSSetUnorderedAccessViews(1, 1, views[1].GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    const std::vector<std::uint32_t> gotU = readBuffer<std::uint32_t>(d, ub.Get());
    const std::vector<std::int32_t> gotS = readBuffer<std::int32_t>(d, sb.Get());
    ASSERT_EQ(gotU.size(), 3u);
    ASSERT_EQ(gotS.size(), 2u);
    EXPECT_EQ(gotU[0], 3u);
    EXPECT_EQ(gotU[1], 8u);
    EXPECT_EQ(gotS[0], 4);
    EXPECT_EQ(gotS[1], -1);
    EXPECT_EQ(gotU[2], 302u) << "GetDimensions(uint, float) of a 3x2 texture";
}

// GetDimensions with float and uint out arguments mixed, on a texture that is not a plain global:
// an element of a texture array (DeferredCoarsePixelShading's GBuffer.hlsl), a function parameter
// and a struct's member, the last inside an `if`. fxc takes every such call; glslang called them
// ambiguous. The sizes read back are the ones the textures were created with.
const char* kArrayDimensions = R"(
struct Layer { Texture2D<float4> tex; float scale; };
Texture2D<float4> T[3] : register(t0);
RWBuffer<uint> Out : register(u0);

uint3 sizeOf(Texture2D<float4> t, uint mip)
{
    float w, h;
    uint levels;
    t.GetDimensions(mip, w, h, levels);
    return uint3(w, h, levels);
}

[numthreads(1, 1, 1)]
void Main()
{
    float w;
    uint h, levels;
    T[1].GetDimensions(1, w, h, levels);
    Out[0] = uint(w);
    Out[1] = h;
    Out[2] = levels;
    uint3 p = sizeOf(T[2], 0);
    Out[3] = p.x;
    Out[4] = p.y;
    Out[5] = p.z;
    Layer layer;
    layer.tex = T[0];
    layer.scale = 1;
    uint lw = 0;
    float lh = 0;
    if (w > 0)
        layer.tex.GetDimensions(lw, lh);
    Out[6] = lw;
    Out[7] = uint(lh);
}
)";

// `levels` 0 is the full chain (fxport makes one level or all of them).
ComPtr<ID3D11ShaderResourceView> mippedTexture(Device& d, UINT width, UINT height, UINT levels) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = levels;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> texture;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, texture.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    return view;
}

TEST(D3D11ResourceFidelity, GetDimensionsMixedOutputsOfArrayElementsParametersAndMembers) {
    Device d;
    ComPtr<ID3DBlob> code = compile(kArrayDimensions, "Main", "cs_5_0", "array_dimensions.hlsl");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> shader;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK)
        << lastError();
    // T[0] 5x3 (one level), T[1] 12x10 (full chain: 12x10, 6x5, 3x2, 1x1), T[2] 7x4 (7x4, 3x2, 1x1).
    ComPtr<ID3D11ShaderResourceView> views[3] = {mippedTexture(d, 5, 3, 1), mippedTexture(d, 12, 10, 0), mippedTexture(d, 7, 4, 0)};
    const std::vector<std::uint32_t> sentinel(8, 0xDEADBEEFu);
    ComPtr<ID3D11Buffer> out = makeBuffer(d, sentinel.data(), 8 * 4, D3D11_BIND_UNORDERED_ACCESS);
    D3D11_UNORDERED_ACCESS_VIEW_DESC desc{};
    desc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    desc.Format = DXGI_FORMAT_R32_UINT;
    desc.Buffer.NumElements = 8;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(out.Get(), &desc, uav.GetAddressOf()), S_OK) << lastError();

    d.context->CSSetShader(shader.Get(), nullptr, 0);
    for (UINT i = 0; i < 3; ++i) d.context->CSSetShaderResources(i, 1, views[i].GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");
    const std::vector<std::uint32_t> got = readBuffer<std::uint32_t>(d, out.Get());
    const std::vector<std::uint32_t> expected = {6, 5, 4, 7, 4, 3, 5, 3};
    EXPECT_EQ(got, expected) << "T[1] at level 1 (w, h, levels), sizeOf(T[2], 0), layer.tex (T[0])";
}

UINT bindPoint(ID3DBlob* code, const char* name) {
    ComPtr<ID3D11ShaderReflection> r;
    EXPECT_EQ(D3DReflect(code->GetBufferPointer(), code->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_INPUT_BIND_DESC b{};
    if (!r || r->GetResourceBindingDescByName(name, &b) != S_OK) return ~0u;
    return b.BindPoint;
}

TEST(D3D11ResourceFidelity, TextureRegistersAroundSamplersAsFxcGivesThem) {
    ComPtr<ID3DBlob> reserved = compile(R"(
Texture2D unused : register(t0);
Texture2D tex;
float4 main() : SV_Target { return tex.Load(int3(0, 0, 0)); }
)", "main", "ps_4_0", "reserved.hlsl");
    ASSERT_TRUE(reserved);
    EXPECT_EQ(bindPoint(reserved.Get(), "tex"), 1u) << "register(t0) of an unused texture still takes t0";

    ComPtr<ID3DBlob> both = compile(R"(
Texture2D tex;
sampler sam;
float4 main() : SV_Target { return 10 * tex.Sample(sam, float2(0, 0)) + tex2D(sam, float2(0, 0)); }
)", "main", "ps_4_0", "both.hlsl");
    ASSERT_TRUE(both) << "tex2D and .Sample on one sampler";
    EXPECT_EQ(bindPoint(both.Get(), "tex"), 1u) << "the tex2D's texture comes first, at t0";

    ComPtr<ID3DBlob> array = compile(R"(
sampler sam[2] : register(s1);
float4 main() : SV_Target { return 10 * tex2D(sam[0], float2(0, 0)) + tex1D(sam[1], 0); }
)", "main", "ps_4_0", "array.hlsl");
    ASSERT_TRUE(array) << "a sampler array indexed by constants";
}

}  // namespace
}  // namespace d3d11test
