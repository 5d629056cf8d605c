// D3D10+'s integer and BGRA texture formats through the D3D11 front end, each read back (a staging
// copy, Map READ) and compared with a CPU computation: a pixel shader that Loads a
// Texture2D<uint4> and writes uint4 into an R32G32B32A32_UINT target (values past 2^24, which a
// float path would round); ClearRenderTargetView on SINT and UINT targets (D3D truncates the floats
// toward zero and clamps them to the channel); InterlockedAdd on an R32_SINT RWTexture2D from many
// threads; 8- and 16-bit integer textures; B8G8R8A8_UNORM read as (r, g, b, a); and descriptions
// fxport refuses, answered with the field and value; a cube texture's six faces sampled by
// direction.
#include <climits>
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kFullScreen = kFullScreenVertexShader;

ComPtr<ID3D11Texture2D> texture(Device& d, UINT width, UINT height, DXGI_FORMAT format, UINT bind, const void* texels = nullptr,
                                UINT rowBytes = 0) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = format;
    desc.BindFlags = bind;
    D3D11_SUBRESOURCE_DATA data;
    data.pSysMem = texels;
    data.SysMemPitch = rowBytes;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, texels ? &data : nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}


template <class T>
std::vector<T> readAs(Device& d, ID3D11Texture2D* t, std::size_t texelBytes) {
    std::vector<std::uint8_t> bytes = readTexelBytes(d, t, texelBytes);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

// Draws `ps` (entry "ps", with kFullScreen's vertex shader) into `target` (width x height), with
// `source` at t0.
void drawInto(Device& d, const std::string& ps, ID3D11Texture2D* target, UINT width, UINT height, ID3D11ShaderResourceView* source) {
    const std::string text = std::string(kFullScreen) + ps;
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> p;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, p.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target, nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = float(width);
    viewport.Height = float(height);
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(p.Get(), nullptr, 0);
    if (source) d.context->PSSetShaderResources(0, 1, &source);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
}

ComPtr<ID3D11ShaderResourceView> viewOf(Device& d, ID3D11Texture2D* t) {
    ComPtr<ID3D11ShaderResourceView> v;
    EXPECT_EQ(d.device->CreateShaderResourceView(t, nullptr, v.GetAddressOf()), S_OK) << lastError();
    return v;
}

TEST(D3D11Formats, UintTextureLoadIntoUintTarget) {
    Device d;
    constexpr UINT W = 4, H = 2;
    std::vector<std::uint32_t> source(W * H * 4);
    for (std::size_t i = 0; i < source.size(); ++i) source[i] = 0xFFFFFF00u - std::uint32_t(i) * 0x01010101u;  // past 2^24: not floats
    ComPtr<ID3D11Texture2D> src = texture(d, W, H, DXGI_FORMAT_R32G32B32A32_UINT, D3D11_BIND_SHADER_RESOURCE, source.data(), W * 16);
    ComPtr<ID3D11Texture2D> target = texture(d, W, H, DXGI_FORMAT_R32G32B32A32_UINT, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(src && target);
    drawInto(d, R"(
Texture2D<uint4> Source : register(t0);
uint4 ps(float4 pos : SV_Position) : SV_Target {
    uint2 p = uint2(pos.xy);
    return Source.Load(int3(p, 0)) ^ uint4(p.x, p.y, 0x80000000u, 7u);
})",
             target.Get(), W, H, viewOf(d, src.Get()).Get());
    std::vector<std::uint32_t> got = readAs<std::uint32_t>(d, target.Get(), 16);
    for (UINT y = 0; y < H; ++y)
        for (UINT x = 0; x < W; ++x) {
            const std::size_t at = (y * W + x) * 4;
            const std::uint32_t want[4] = {source[at] ^ x, source[at + 1] ^ y, source[at + 2] ^ 0x80000000u, source[at + 3] ^ 7u};
            for (int c = 0; c < 4; ++c) EXPECT_EQ(got[at + std::size_t(c)], want[c]) << "pixel (" << x << ", " << y << ") channel " << c;
        }
}

TEST(D3D11Formats, IntegerClearsTruncateAndClamp) {
    Device d;
    ComPtr<ID3D11Texture2D> sint = texture(d, 2, 2, DXGI_FORMAT_R32G32B32A32_SINT, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11Texture2D> small = texture(d, 2, 2, DXGI_FORMAT_R8G8B8A8_UINT, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(sint && small);
    ComPtr<ID3D11RenderTargetView> a, b;
    ASSERT_EQ(d.device->CreateRenderTargetView(sint.Get(), nullptr, a.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateRenderTargetView(small.Get(), nullptr, b.GetAddressOf()), S_OK) << lastError();
    const float values[4] = {-3.75f, 1e10f, 42.9f, -1e10f};
    d.context->ClearRenderTargetView(a.Get(), values);
    d.context->ClearRenderTargetView(b.Get(), values);
    EXPECT_EQ(lastError(), "");
    const std::int32_t wantSigned[4] = {-3, INT_MAX, 42, INT_MIN};
    std::vector<std::int32_t> got = readAs<std::int32_t>(d, sint.Get(), 16);
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], wantSigned[i % 4]) << "word " << i;
    const std::uint8_t wantBytes[4] = {0, 255, 42, 0};
    std::vector<std::uint8_t> bytes = readTexelBytes(d, small.Get(), 4);
    for (std::size_t i = 0; i < bytes.size(); ++i) EXPECT_EQ(bytes[i], wantBytes[i % 4]) << "byte " << i;
}

TEST(D3D11Formats, InterlockedAddOnR32SintTexture) {
    Device d;
    constexpr UINT W = 4;
    const std::int32_t initial[W] = {10, -20, 30, INT_MAX - 100};
    ComPtr<ID3D11Texture2D> t = texture(d, W, 1, DXGI_FORMAT_R32_SINT, D3D11_BIND_UNORDERED_ACCESS, initial, W * 4);
    ASSERT_TRUE(t);
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(t.Get(), nullptr, uav.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> code = compile(R"(
RWTexture2D<int> Sums : register(u0);
[numthreads(64, 1, 1)]
void cs(uint3 id : SV_DispatchThreadID) {
    int old;
    InterlockedAdd(Sums[uint2(id.x % 4, 0)], int(id.x) - 50, old);
})",
                                    "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOfConst(), nullptr);
    d.context->Dispatch(2, 1, 1);  // 128 threads, 32 per texel
    ASSERT_EQ(lastError(), "");
    std::int64_t want[W];
    for (UINT x = 0; x < W; ++x) want[x] = initial[x];
    for (int id = 0; id < 128; ++id) want[id % 4] += id - 50;
    std::vector<std::int32_t> got = readAs<std::int32_t>(d, t.Get(), 4);
    for (UINT x = 0; x < W; ++x) {
        const std::int32_t wrapped = std::int32_t(std::uint32_t(std::uint64_t(want[x])));  // two's-complement wrap, as the GPU adds
        EXPECT_EQ(got[x], wrapped) << "texel " << x;
    }
}

TEST(D3D11Formats, SmallIntegerTexturesKeepTheirBits) {
    Device d;
    // R16G16B16A16_SINT and R8G8B8A8_SINT texels, loaded and widened into an R32G32B32A32_SINT target.
    const std::int16_t shorts[2 * 4] = {-32768, 32767, -1, 5, 1000, -1000, 0, 77};
    const std::int8_t bytes[2 * 4] = {-128, 127, -1, 3, 9, -9, 0, 100};
    ComPtr<ID3D11Texture2D> s16 = texture(d, 2, 1, DXGI_FORMAT_R16G16B16A16_SINT, D3D11_BIND_SHADER_RESOURCE, shorts, 16);
    ComPtr<ID3D11Texture2D> s8 = texture(d, 2, 1, DXGI_FORMAT_R8G8B8A8_SINT, D3D11_BIND_SHADER_RESOURCE, bytes, 8);
    ComPtr<ID3D11Texture2D> target = texture(d, 2, 1, DXGI_FORMAT_R32G32B32A32_SINT, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(s16 && s8 && target);
    ComPtr<ID3D11ShaderResourceView> v8 = viewOf(d, s8.Get());
    d.context->PSSetShaderResources(1, 1, v8.GetAddressOfConst());
    drawInto(d, R"(
Texture2D<int4> Wide : register(t0);
Texture2D<int4> Narrow : register(t1);
int4 ps(float4 pos : SV_Position) : SV_Target {
    int3 p = int3(pos.xy, 0);
    return Wide.Load(p) * 1000 + Narrow.Load(p);
})",
             target.Get(), 2, 1, viewOf(d, s16.Get()).Get());
    std::vector<std::int32_t> got = readAs<std::int32_t>(d, target.Get(), 16);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(got[i], std::int32_t(shorts[i]) * 1000 + bytes[i]) << "word " << i;
}

TEST(D3D11Formats, Bgra8IsReadAsRgba) {
    Device d;
    // Memory order B, G, R, A: the shader reads red from byte 2.
    const std::uint8_t bgra[2 * 4] = {10, 20, 30, 40, 200, 150, 100, 250};
    ComPtr<ID3D11Texture2D> src = texture(d, 2, 1, DXGI_FORMAT_B8G8R8A8_UNORM, D3D11_BIND_SHADER_RESOURCE, bgra, 8);
    ComPtr<ID3D11Texture2D> target = texture(d, 2, 1, DXGI_FORMAT_B8G8R8A8_UNORM, D3D11_BIND_RENDER_TARGET);
    ASSERT_TRUE(src && target);
    drawInto(d, R"(
Texture2D Source : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    float4 c = Source.Load(int3(pos.xy, 0));
    return float4(c.r, c.g * 0.5, 1 - c.b, c.a);  // red, half green, inverted blue
})",
             target.Get(), 2, 1, viewOf(d, src.Get()).Get());
    std::vector<std::uint8_t> got = readTexelBytes(d, target.Get(), 4);
    for (std::size_t px = 0; px < 2; ++px) {
        const std::uint8_t* in = &bgra[px * 4];
        // The target is BGRA in memory too: byte 0 blue, 1 green, 2 red, 3 alpha.
        const int want[4] = {255 - in[0], int(std::lround(in[1] * 0.5)), in[2], in[3]};
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[px * 4 + std::size_t(c)], want[c], 1) << "pixel " << px << " byte " << c;
    }
}

TEST(D3D11Formats, CubeFacesAreSampledByDirection) {
    Device d;
    // Six 1x1 faces in D3D's order (+X, -X, +Y, -Y, +Z, -Z), each its own colour.
    const std::uint32_t faces[6] = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xff00ffffu, 0xffff00ffu, 0xffffff00u};
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 1;
    desc.MipLevels = 1;
    desc.ArraySize = 6;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    D3D11_SUBRESOURCE_DATA data[6];
    for (int f = 0; f < 6; ++f) {
        data[f].pSysMem = &faces[f];
        data[f].SysMemPitch = 4;
    }
    ComPtr<ID3D11Texture2D> cube;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, data, cube.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> view = viewOf(d, cube.Get());
    D3D11_SHADER_RESOURCE_VIEW_DESC viewDesc;
    view->GetDesc(&viewDesc);
    EXPECT_EQ(viewDesc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURECUBE);
    ComPtr<ID3D11Texture2D> target = texture(d, 6, 1, DXGI_FORMAT_R8G8B8A8_UNORM, D3D11_BIND_RENDER_TARGET);
    // Point sampling: a linear filter blends across the edges of 1x1 faces (D3D10+ filters cubes seamlessly).
    D3D11_SAMPLER_DESC pointDesc;
    pointDesc.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> point;
    ASSERT_EQ(d.device->CreateSamplerState(&pointDesc, point.GetAddressOf()), S_OK) << lastError();
    d.context->PSSetSamplers(0, 1, point.GetAddressOfConst());
    drawInto(d, R"(
TextureCube Sky : register(t0);
SamplerState Point : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    static const float3 directions[6] = {float3(1, 0.1, 0.2), float3(-1, 0.2, 0.1), float3(0.1, 1, 0.2),
                                         float3(0.2, -1, 0.1), float3(0.1, 0.2, 1), float3(0.2, 0.1, -1)};
    return Sky.Sample(Point, directions[uint(pos.x)]);
})",
             target.Get(), 6, 1, view.Get());
    std::vector<std::uint32_t> got = readAs<std::uint32_t>(d, target.Get(), 4);
    for (int f = 0; f < 6; ++f) EXPECT_EQ(got[std::size_t(f)], faces[f]) << "face " << f;
    // A cube is six square faces, sampled only.
    desc.Width = 2;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, cube.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ArraySize = 6, Width x Height = 2 x 1 with D3D11_RESOURCE_MISC_TEXTURECUBE"), std::string::npos) << lastError();
    desc.Width = 1;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, cube.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("BindFlags = 40, Usage = 0 for a cube texture"), std::string::npos) << lastError();
}

TEST(D3D11Formats, RefusedDescriptionsNameTheField) {
    Device d;
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 4;
    desc.MipLevels = desc.ArraySize = 1;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.Format = DXGI_FORMAT(7);  // R32G32B32_UINT: no 96-bit texels in fxport
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("D3D11_TEXTURE2D_DESC.Format = "), std::string::npos) << lastError();
    EXPECT_NE(lastError().find(" (7)"), std::string::npos) << lastError();
    // Integer texels cannot be filtered into smaller levels.
    desc.Format = DXGI_FORMAT_R32_UINT;
    desc.MipLevels = 0;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    desc.MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("MiscFlags = 1 (D3D11_RESOURCE_MISC_GENERATE_MIPS) with Format = DXGI_FORMAT_R32_UINT"), std::string::npos)
        << lastError();
}

}  // namespace
}  // namespace d3d11test
