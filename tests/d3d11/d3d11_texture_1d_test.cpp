// 1D textures through the D3D11 front end (CreateTexture1D, GL's 1D and 1D array textures): every
// texel of every level read back through Texture1D.Load, point and linear Sample/SampleLevel
// against the texels and their CPU average, a 1D array's slices and a view of part of them,
// GetDimensions, UpdateSubresource of a range and CopySubresourceRegion read back through a
// staging copy and Map READ, a DYNAMIC texture written through Map, GenerateMips against the CPU
// average of each pair, compute writes through RWTexture1D / RWTexture1DArray, and the
// descriptions and bindings fxport refuses, answered with the field or slot and what it holds.
#include <algorithm>
#include <cstring>

#include <gtest/gtest-spi.h>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kFullScreen = kFullScreenVertexShader;

using Texel = std::array<float, 4>;

// A distinct value per texel, slice and level.
Texel texelAt(int x, int slice, int level) { return {float(x) + 0.25f, float(slice) * 10.0f, float(level) + 0.5f, 1.0f}; }

std::vector<Texel> row(int width, int slice, int level) {
    std::vector<Texel> out;
    for (int x = 0; x < width; ++x) out.push_back(texelAt(x, slice, level));
    return out;
}

// An R32G32B32A32_FLOAT 1D texture (an array for `slices` > 1) of `levels` levels (0: the full
// chain), each subresource filled with row(width, slice, level).
ComPtr<ID3D11Texture1D> makeLine(Device& d, UINT width, UINT slices, UINT levels, UINT bind = D3D11_BIND_SHADER_RESOURCE) {
    D3D11_TEXTURE1D_DESC desc;
    desc.Width = width;
    desc.ArraySize = slices;
    desc.MipLevels = levels;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = bind;
    int chain = 1;
    for (UINT w = width; w > 1; w >>= 1) ++chain;
    const int count = levels == 0 ? chain : int(levels);
    std::vector<std::vector<Texel>> rows;
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    for (UINT slice = 0; slice < slices; ++slice)
        for (int level = 0; level < count; ++level) rows.push_back(row(std::max(1, int(width) >> level), int(slice), level));
    for (const auto& r : rows) data.push_back({r.data(), UINT(r.size() * sizeof(Texel)), 0});
    ComPtr<ID3D11Texture1D> t;
    EXPECT_EQ(d.device->CreateTexture1D(&desc, data.data(), t.GetAddressOf()), S_OK) << lastError();
    return t;
}

ComPtr<ID3D11SamplerState> sampler(Device& d, D3D11_FILTER filter) {
    D3D11_SAMPLER_DESC desc;
    desc.Filter = filter;
    desc.AddressU = desc.AddressV = desc.AddressW = D3D11_TEXTURE_ADDRESS_CLAMP;
    ComPtr<ID3D11SamplerState> s;
    EXPECT_EQ(d.device->CreateSamplerState(&desc, s.GetAddressOf()), S_OK) << lastError();
    return s;
}

std::vector<Texel> draw(Device& d, const std::string& ps, ID3D11ShaderResourceView* view, UINT width, UINT height, ID3D11SamplerState* s = nullptr) {
    return drawWithTexture(d, std::string(kFullScreen) + ps, view, width, height, s);
}

void expectNear(const Texel& got, const Texel& want, const char* what) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[std::size_t(c)], want[std::size_t(c)], 1e-3f) << what << " channel " << c;
}

TEST(D3D11Texture1D, EveryLevelLoadsWhatWasWritten) {
    Device d;
    ComPtr<ID3D11Texture1D> t = makeLine(d, 8, 1, 0);  // 8, 4, 2, 1
    ASSERT_TRUE(t);
    D3D11_TEXTURE1D_DESC got;
    t->GetDesc(&got);
    EXPECT_EQ(got.MipLevels, 4u);
    D3D11_RESOURCE_DIMENSION dimension = D3D11_RESOURCE_DIMENSION_UNKNOWN;
    t->GetType(&dimension);
    EXPECT_EQ(dimension, D3D11_RESOURCE_DIMENSION_TEXTURE1D);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE1D);
    EXPECT_EQ(viewDesc.Texture1D.MipLevels, 4u);
    // Row y < 4: level y's texels; row 4: GetDimensions of levels 0 and 2 (width, level count).
    const std::vector<Texel> px = draw(d, R"(
Texture1D<float4> Line : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    if (p.y < 4) return Line.Load(int2(p.x >> p.y, p.y));
    uint w0, n0, w2, n2;
    Line.GetDimensions(0, w0, n0);
    Line.GetDimensions(2, w2, n2);
    return float4(w0, n0, w2, n2);
})",
                                       view.Get(), 8, 5);
    for (int level = 0; level < 4; ++level)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(px[std::size_t(level * 8 + x)], texelAt(x >> level, 0, level)) << "level " << level << " x " << x;
    EXPECT_EQ(px[32], (Texel{8, 4, 2, 4}));
}

// Point sampling at each texel's centre gives the texel; linear halfway between texels 1 and 2
// their average; SampleLevel 1 reads level 1; a view from MostDetailedMip 1 sees level 1 as its 0.
TEST(D3D11Texture1D, PointAndLinearSamplingMatchTheTexels) {
    Device d;
    ComPtr<ID3D11Texture1D> t = makeLine(d, 4, 1, 0);  // 4, 2, 1
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    const char* ps = R"(
Texture1D<float4> Line : register(t0);
SamplerState S : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    if (p.y == 0) return Line.Sample(S, (p.x + 0.5) / 4);
    if (p.y == 1) return Line.Sample(S, 0.5);
    return Line.SampleLevel(S, (p.x + 0.5) / 2, 1);
})";
    ComPtr<ID3D11SamplerState> point = sampler(d, D3D11_FILTER_MIN_MAG_MIP_POINT), linear = sampler(d, D3D11_FILTER_MIN_MAG_MIP_LINEAR);
    const std::vector<Texel> pointed = draw(d, ps, view.Get(), 4, 3, point.Get());
    for (int x = 0; x < 4; ++x) EXPECT_EQ(pointed[std::size_t(x)], texelAt(x, 0, 0)) << "x " << x;
    for (int x = 0; x < 2; ++x) EXPECT_EQ(pointed[std::size_t(8 + x)], texelAt(x, 0, 1)) << "level 1 x " << x;
    const std::vector<Texel> filtered = draw(d, ps, view.Get(), 4, 3, linear.Get());
    const Texel a = texelAt(1, 0, 0), b = texelAt(2, 0, 0);
    expectNear(filtered[4], Texel{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, 1}, "linear halfway");

    D3D11_SHADER_RESOURCE_VIEW_DESC from1;
    from1.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1D;
    from1.Texture1D = {1, UINT(-1)};
    ComPtr<ID3D11ShaderResourceView> lower;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), &from1, lower.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> px = draw(d, R"(
Texture1D<float4> Line : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    uint w, n;
    Line.GetDimensions(0, w, n);
    return pos.x < 2 ? Line.Load(int2(pos.x, 0)) : float4(w, n, 0, 0);
})",
                                       lower.Get(), 3, 1);
    EXPECT_EQ(px[0], texelAt(0, 0, 1));
    EXPECT_EQ(px[1], texelAt(1, 0, 1));
    EXPECT_EQ(px[2], (Texel{2, 2, 0, 0}));
}

// Slice s of a three-slice array at row s (Load and SampleLevel); GetDimensions gives width,
// elements and levels; a TEXTURE1DARRAY view of slices [1, 3) sees slice 1 as its 0.
TEST(D3D11Texture1D, ArraySlicesLoadAndSampleApart) {
    Device d;
    ComPtr<ID3D11Texture1D> t = makeLine(d, 4, 3, 1);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE1DARRAY);
    EXPECT_EQ(viewDesc.Texture1DArray.ArraySize, 3u);
    const char* ps = R"(
Texture1DArray<float4> Lines : register(t0);
SamplerState S : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    int2 p = int2(pos.xy);
    if (p.y == 3) { uint w, e, n; Lines.GetDimensions(0, w, e, n); return float4(w, e, n, 0); }
    return p.x < 4 ? Lines.Load(int3(p.x, p.y, 0)) : Lines.SampleLevel(S, float2((p.x - 4 + 0.5) / 4, p.y), 0);
})";
    ComPtr<ID3D11SamplerState> point = sampler(d, D3D11_FILTER_MIN_MAG_MIP_POINT);
    std::vector<Texel> px = draw(d, ps, view.Get(), 8, 4, point.Get());
    for (int slice = 0; slice < 3; ++slice)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(px[std::size_t(slice * 8 + x)], texelAt(x % 4, slice, 0)) << "slice " << slice << " x " << x;
    EXPECT_EQ(px[24], (Texel{4, 3, 1, 0}));

    D3D11_SHADER_RESOURCE_VIEW_DESC part;
    part.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1DARRAY;
    part.Texture1DArray = {0, 1, 1, 2};
    ComPtr<ID3D11ShaderResourceView> partView;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), &part, partView.GetAddressOf()), S_OK) << lastError();
    px = draw(d, ps, partView.Get(), 8, 4, point.Get());
    for (int slice = 0; slice < 2; ++slice) EXPECT_EQ(px[std::size_t(slice * 8)], texelAt(0, slice + 1, 0)) << "view slice " << slice;
    EXPECT_EQ(px[24], (Texel{4, 2, 1, 0}));
}

std::vector<std::uint32_t> readLine(Device& d, ID3D11Texture1D* t, UINT subresource) {
    D3D11_TEXTURE1D_DESC desc;
    t->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = desc.MiscFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture1D> staging;
    EXPECT_EQ(d.device->CreateTexture1D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    d.context->CopyResource(staging.Get(), t);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), subresource, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    const UINT width = std::max(1u, desc.Width >> (subresource % desc.MipLevels));
    std::vector<std::uint32_t> out(width);
    std::memcpy(out.data(), mapped.pData, width * 4);
    d.context->Unmap(staging.Get(), subresource);
    return out;
}

ComPtr<ID3D11Texture1D> uintLine(Device& d, UINT width, UINT slices, UINT bind, const std::uint32_t* initial) {
    D3D11_TEXTURE1D_DESC desc;
    desc.Width = width;
    desc.ArraySize = slices;
    desc.MipLevels = 1;
    desc.Format = DXGI_FORMAT_R32_UINT;
    desc.BindFlags = bind;
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    for (UINT s = 0; s < slices; ++s) data.push_back({initial + s * width, width * 4, 0});
    ComPtr<ID3D11Texture1D> t;
    EXPECT_EQ(d.device->CreateTexture1D(&desc, initial ? data.data() : nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// UpdateSubresource of texels [2, 5) of slice 1 changes those and nothing else; CopySubresourceRegion
// of source texels [1, 3) to DstX 5 of slice 0 likewise.
TEST(D3D11Texture1D, UpdatedAndCopiedRangesReadBackThroughStaging) {
    Device d;
    const std::uint32_t initial[16] = {0, 1, 2, 3, 4, 5, 6, 7, 10, 11, 12, 13, 14, 15, 16, 17};
    ComPtr<ID3D11Texture1D> t = uintLine(d, 8, 2, D3D11_BIND_SHADER_RESOURCE, initial);
    const std::uint32_t update[3] = {100, 101, 102};
    D3D11_BOX box{2, 0, 0, 5, 1, 1};
    d.context->UpdateSubresource(t.Get(), 1, &box, update, sizeof update, 0);
    EXPECT_EQ(lastError(), "");
    EXPECT_EQ(readLine(d, t.Get(), 1), (std::vector<std::uint32_t>{10, 11, 100, 101, 102, 15, 16, 17}));
    EXPECT_EQ(readLine(d, t.Get(), 0), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));

    const std::uint32_t other[8] = {50, 51, 52, 53, 54, 55, 56, 57};
    ComPtr<ID3D11Texture1D> source = uintLine(d, 8, 1, D3D11_BIND_SHADER_RESOURCE, other);
    D3D11_BOX range{1, 0, 0, 3, 1, 1};
    d.context->CopySubresourceRegion(t.Get(), 0, 5, 0, 0, source.Get(), 0, &range);
    EXPECT_EQ(lastError(), "");
    EXPECT_EQ(readLine(d, t.Get(), 0), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 51, 52, 7}));
}

// A DYNAMIC texture written through Map WRITE_DISCARD is what the shader loads after Unmap.
TEST(D3D11Texture1D, DynamicTextureMapsForWriting) {
    Device d;
    D3D11_TEXTURE1D_DESC desc;
    desc.Width = 4;
    desc.ArraySize = desc.MipLevels = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.Usage = D3D11_USAGE_DYNAMIC;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_WRITE;
    ComPtr<ID3D11Texture1D> t;
    ASSERT_EQ(d.device->CreateTexture1D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(d.context->Map(t.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &mapped), S_OK) << lastError();
    const std::vector<Texel> texels = row(4, 7, 0);
    std::memcpy(mapped.pData, texels.data(), 4 * sizeof(Texel));
    d.context->Unmap(t.Get(), 0);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> px = draw(d, R"(
Texture1D<float4> Line : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Line.Load(int2(pos.x, 0)); })",
                                       view.Get(), 4, 1);
    for (int x = 0; x < 4; ++x) EXPECT_EQ(px[std::size_t(x)], texelAt(x, 7, 0)) << "x " << x;
}

// GenerateMips fills level 1 with the average of each pair of level 0's texels (a box filter of a
// power-of-two row).
TEST(D3D11Texture1D, GenerateMipsAveragesPairs) {
    Device d;
    D3D11_TEXTURE1D_DESC desc;
    desc.Width = 4;
    desc.ArraySize = 1;
    desc.MipLevels = 0;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS;
    ComPtr<ID3D11Texture1D> t;
    ASSERT_EQ(d.device->CreateTexture1D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    const Texel level0[4] = {{0, 2, 4, 1}, {2, 4, 8, 1}, {10, 0, 1, 1}, {20, 8, 3, 1}};
    d.context->UpdateSubresource(t.Get(), 0, nullptr, level0, sizeof level0, 0);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    d.context->GenerateMips(view.Get());
    EXPECT_EQ(lastError(), "");
    const std::vector<Texel> px = draw(d, R"(
Texture1D<float4> Line : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Line.Load(int2(pos.x, 1)); })",
                                       view.Get(), 2, 1);
    for (int x = 0; x < 2; ++x) {
        const Texel &a = level0[2 * x], &b = level0[2 * x + 1];
        expectNear(px[std::size_t(x)], Texel{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, 1}, "level 1");
    }
}

// A compute shader writes RWTexture1D (texel i = 3i + 1) and RWTexture1DArray (texel i of slice s
// = 100s + i) through UAVs; the staging copies read back exactly that.
TEST(D3D11Texture1D, ComputeWritesThroughUnorderedAccessViews) {
    Device d;
    ComPtr<ID3D11Texture1D> line = uintLine(d, 8, 1, D3D11_BIND_UNORDERED_ACCESS, nullptr);
    ComPtr<ID3D11Texture1D> lines = uintLine(d, 8, 2, D3D11_BIND_UNORDERED_ACCESS, nullptr);
    ComPtr<ID3D11UnorderedAccessView> uavs[2];
    ASSERT_EQ(d.device->CreateUnorderedAccessView(line.Get(), nullptr, uavs[0].GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateUnorderedAccessView(lines.Get(), nullptr, uavs[1].GetAddressOf()), S_OK) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC got;
    uavs[1]->GetDesc(&got);
    EXPECT_EQ(got.ViewDimension, D3D11_UAV_DIMENSION_TEXTURE1DARRAY);
    ComPtr<ID3DBlob> code = compile(R"(
RWTexture1D<uint> Line : register(u0);
RWTexture1DArray<uint> Lines : register(u1);
[numthreads(8, 2, 1)]
void cs(uint2 i : SV_DispatchThreadID) {
    if (i.y == 0) Line[i.x] = 3 * i.x + 1;
    Lines[i] = 100 * i.y + i.x;
})",
                                    "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    ID3D11UnorderedAccessView* bound[2] = {uavs[0].Get(), uavs[1].Get()};
    d.context->CSSetUnorderedAccessViews(0, 2, bound, nullptr);
    d.context->Dispatch(1, 1, 1);
    EXPECT_EQ(lastError(), "");
    ID3D11UnorderedAccessView* none[2] = {nullptr, nullptr};
    d.context->CSSetUnorderedAccessViews(0, 2, none, nullptr);
    EXPECT_EQ(readLine(d, line.Get(), 0), (std::vector<std::uint32_t>{1, 4, 7, 10, 13, 16, 19, 22}));
    EXPECT_EQ(readLine(d, lines.Get(), 0), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(readLine(d, lines.Get(), 1), (std::vector<std::uint32_t>{100, 101, 102, 103, 104, 105, 106, 107}));
}

TEST(D3D11Texture1D, ReflectionNamesTheDimension) {
    ComPtr<ID3DBlob> code = compile(R"(
Texture1D<float4> Line : register(t2);
float4 ps(float4 pos : SV_Position) : SV_Target { return Line.Load(int2(pos.x, 0)); })",
                                    "ps", "ps_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(code->GetBufferPointer(), code->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_INPUT_BIND_DESC b;
    ASSERT_EQ(r->GetResourceBindingDescByName("Line", &b), S_OK);
    EXPECT_EQ(b.Dimension, D3D_SRV_DIMENSION_TEXTURE1D);
    EXPECT_EQ(b.BindPoint, 2u);
}

// CheckFormatSupport reports TEXTURE1D for the formats CreateTexture1D makes, not for BC formats.
TEST(D3D11Texture1D, FormatSupportSaysWhichFormatsAre1D) {
    Device d;
    UINT bits = 0;
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_R32G32B32A32_FLOAT, &bits), S_OK);
    EXPECT_TRUE(bits & D3D11_FORMAT_SUPPORT_TEXTURE1D);
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_BC1_UNORM, &bits), S_OK);
    EXPECT_FALSE(bits & D3D11_FORMAT_SUPPORT_TEXTURE1D);
}

HRESULT create(Device& d, D3D11_TEXTURE1D_DESC desc) {
    ComPtr<ID3D11Texture1D> t;
    return d.device->CreateTexture1D(&desc, nullptr, t.GetAddressOf());
}

TEST(D3D11Texture1D, BadDescriptionsNameTheField) {
    Device d;
    D3D11_TEXTURE1D_DESC good;
    good.Width = 8;
    good.ArraySize = 1;
    good.MipLevels = 1;
    good.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    good.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    EXPECT_EQ(create(d, good), S_OK) << lastError();
    D3D11_TEXTURE1D_DESC bad = good;
    bad.Width = 0;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateTexture1D: D3D11_TEXTURE1D_DESC.Width = 0 (1 to 16384)");
    bad = good;
    bad.MipLevels = 5;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateTexture1D: D3D11_TEXTURE1D_DESC.MipLevels = 5 (a 8-texel texture has at most 4)");
    bad = good;
    bad.ArraySize = 0;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateTexture1D: D3D11_TEXTURE1D_DESC.ArraySize = 0 (1 to 2048)");
    bad = good;
    bad.Format = DXGI_FORMAT_BC1_UNORM;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_NE(lastError().find("CreateTexture1D: D3D11_TEXTURE1D_DESC.Format = DXGI_FORMAT_BC1_UNORM"), std::string::npos) << lastError();
    bad = good;
    bad.Usage = D3D11_USAGE_STAGING;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateTexture1D: D3D11_TEXTURE1D_DESC.BindFlags = 8 with USAGE_STAGING (must be 0)");
    bad = good;
    bad.Usage = D3D11_USAGE_DYNAMIC;
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateTexture1D: D3D11_TEXTURE1D_DESC.CPUAccessFlags = 0 with USAGE_DYNAMIC (must be D3D11_CPU_ACCESS_WRITE)");
    bad = good;
    bad.BindFlags = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE;  // render targets and depth: d3d11_line_targets_test.cpp
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R8G8B8A8_UNORM with BIND_DEPTH_STENCIL: not a depth format"), std::string::npos) << lastError();
    bad.Format = DXGI_FORMAT_D32_FLOAT;  // sampled depth is made typeless
    EXPECT_EQ(create(d, bad), E_INVALIDARG);
    EXPECT_NE(lastError().find("BindFlags = 72 with Format = DXGI_FORMAT_D32_FLOAT: a depth texture a shader samples is made typeless (DXGI_FORMAT_R32_TYPELESS)"),
              std::string::npos)
        << lastError();

    ComPtr<ID3D11Texture1D> t = makeLine(d, 4, 2, 1);
    D3D11_SHADER_RESOURCE_VIEW_DESC view;
    view.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11ShaderResourceView> v;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &view, v.GetAddressOf()), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateShaderResourceView: D3D11_SHADER_RESOURCE_VIEW_DESC.ViewDimension = 4 for a 1D texture "
                           "(D3D11_SRV_DIMENSION_TEXTURE1D or TEXTURE1DARRAY)");
    view.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1DARRAY;
    view.Texture1DArray = {0, 1, 1, 2};
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &view, v.GetAddressOf()), E_INVALIDARG);
    EXPECT_EQ(lastError(), "CreateShaderResourceView: D3D11_SHADER_RESOURCE_VIEW_DESC.Texture1DArray.FirstArraySlice + ArraySize = 1 + 2 "
                           "(the texture has 2 slices)");
}

// A shader's Texture1D given a 2D texture's view, and its Texture2D given a 1D one, are refused at
// the draw, naming the register and both dimensions (GL would read black).
TEST(D3D11Texture1D, AViewOfAnotherDimensionIsRefusedAtTheDraw) {
    Device d;
    ComPtr<ID3D11Texture1D> line = makeLine(d, 4, 1, 1);
    ComPtr<ID3D11ShaderResourceView> lineView, flatView;
    ASSERT_EQ(d.device->CreateShaderResourceView(line.Get(), nullptr, lineView.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> flat = makeTexture(d, 4, 1, D3D11_BIND_SHADER_RESOURCE);
    ASSERT_EQ(d.device->CreateShaderResourceView(flat.Get(), nullptr, flatView.GetAddressOf()), S_OK) << lastError();
    const std::string oneD = std::string(kFullScreen) + R"(
Texture1D<float4> Line : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Line.Load(int2(pos.x, 0)); })";
    const std::string twoD = std::string(kFullScreen) + R"(
Texture2D<float4> Flat : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return Flat.Load(int3(pos.xy, 0)); })";
    EXPECT_NONFATAL_FAILURE(drawWithTexture(d, oneD, flatView.Get(), 4, 1), "t0 holds a view of a 2D texture where the shader's 'Line' is a 1D texture");
    EXPECT_NONFATAL_FAILURE(drawWithTexture(d, twoD, lineView.Get(), 4, 1), "t0 holds a view of a 1D texture where the shader's 'Flat' is a 2D texture");
}

}  // namespace
}  // namespace d3d11test
