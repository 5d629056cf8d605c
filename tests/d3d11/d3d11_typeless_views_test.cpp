// Typeless colour textures written and read in members of their family other than the one fxport
// stores them in, through GL texture views of the same texels: an R8G8B8A8_TYPELESS texture drawn
// into through an R8G8B8A8_UINT render-target view and written by a compute shader through an
// R8G8B8A8_UINT unordered-access view (its bytes read back and compared with the integers written,
// then read as UNORM); the wider families -- R16G16B16A16_TYPELESS read as UINT and UNORM and drawn
// into as UINT, R32G32_TYPELESS floats read as their UINT bits, R8_TYPELESS written as R8_UINT and
// read as R8_UNORM -- each compared with the CPU's reading of the same bytes; and an R8G8B8A8_TYPELESS
// array read through a UINT TEXTURE2DARRAY view of two slices and drawn into through a UINT
// render-target view of one; typeless cubes and cube arrays read through sRGB cube views.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Texel = std::array<float, 4>;

const char* const kFullScreen = kFullScreenVertexShader;

ComPtr<ID3D11RenderTargetView> targetAs(Device& d, ID3D11Texture2D* texture, DXGI_FORMAT format) {
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.Format = format;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(texture, &desc, rtv.GetAddressOf()), S_OK) << lastError();
    return rtv;
}

// A full-screen triangle into `rtv` (width x height) with `ps` (entry "ps", after kFullScreen).
void drawInto(Device& d, ID3D11RenderTargetView* rtv, UINT width, UINT height, const std::string& ps) {
    const std::string text = std::string(kFullScreen) + ps;
    ComPtr<ID3DBlob> vsCode = compile(text, "vs", "vs_5_0"), psCode = compile(text, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> p;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, p.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, &rtv, nullptr);
    D3D11_VIEWPORT viewport{0, 0, float(width), float(height), 0, 1};
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(p.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    d.context->OMSetRenderTargets(0, nullptr, nullptr);
}

// `cs` (entry "cs") once, one group, with `uav` at u0.
void dispatch(Device& d, ID3D11UnorderedAccessView* uav, const std::string& cs) {
    ComPtr<ID3DBlob> code = compile(cs, "cs", "cs_5_0");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> shader;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(shader.Get(), nullptr, 0);
    d.context->CSSetUnorderedAccessViews(0, 1, &uav, nullptr);
    d.context->Dispatch(1, 1, 1);
    EXPECT_EQ(lastError(), "");
    ID3D11UnorderedAccessView* none = nullptr;
    d.context->CSSetUnorderedAccessViews(0, 1, &none, nullptr);
}

constexpr UINT kW = 4, kH = 2;

TEST(D3D11TypelessViews, Rgba8TypelessIsDrawnAndWrittenAsUintAndReadAsUnorm) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R8G8B8A8_TYPELESS, kW, kH, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    ASSERT_TRUE(t);
    // The render-target view writes integers: the bytes are those integers.
    ComPtr<ID3D11RenderTargetView> rtv = targetAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UINT);
    ASSERT_TRUE(rtv);
    drawInto(d, rtv.Get(), kW, kH, "uint4 ps(float4 pos : SV_Position) : SV_Target { uint2 p = uint2(pos.xy); return uint4(p.x * 16 + 1, p.y * 32 + 2, 200, 255 - p.x); }");
    std::vector<std::uint8_t> bytes = readTexelBytes(d, t.Get(), 4);
    ASSERT_EQ(bytes.size(), std::size_t(kW * kH * 4));
    for (UINT y = 0; y < kH; ++y)
        for (UINT x = 0; x < kW; ++x) {
            const std::uint8_t* b = &bytes[(y * kW + x) * 4];
            EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{int(x * 16 + 1), int(y * 32 + 2), 200, int(255 - x)}))
                << "drawn texel (" << x << ", " << y << ")";
        }
    // Read as UNORM: byte / 255.
    std::vector<Texel> unorm = drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UNORM).Get(), kW, kH);
    ASSERT_EQ(unorm.size(), std::size_t(kW * kH));
    for (UINT i = 0; i < kW * kH; ++i)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(unorm[i][c], float(bytes[i * 4 + c]) / 255.0f, 1e-6f) << "texel " << i << " channel " << c;

    // The unordered-access view writes integers too.
    D3D11_UNORDERED_ACCESS_VIEW_DESC uavDesc;
    uavDesc.Format = DXGI_FORMAT_R8G8B8A8_UINT;
    uavDesc.ViewDimension = D3D11_UAV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(t.Get(), &uavDesc, uav.GetAddressOf()), S_OK) << lastError();
    dispatch(d, uav.Get(), R"(
RWTexture2D<uint4> Out : register(u0);
[numthreads(4, 2, 1)] void cs(uint3 id : SV_DispatchThreadID) { Out[id.xy] = uint4(id.x + 100, id.y + 50, 7, 9 + id.x * id.y); }
)");
    bytes = readTexelBytes(d, t.Get(), 4);
    ASSERT_EQ(bytes.size(), std::size_t(kW * kH * 4));
    for (UINT y = 0; y < kH; ++y)
        for (UINT x = 0; x < kW; ++x) {
            const std::uint8_t* b = &bytes[(y * kW + x) * 4];
            EXPECT_EQ((std::array<int, 4>{b[0], b[1], b[2], b[3]}), (std::array<int, 4>{int(x + 100), int(y + 50), 7, int(9 + x * y)}))
                << "written texel (" << x << ", " << y << ")";
        }
}

TEST(D3D11TypelessViews, Rgba16TypelessReadsAsUintAndUnormAndIsDrawnAsUint) {
    Device d;
    std::array<std::uint16_t, kW * kH * 4> texels{};
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint16_t(i * 4099 + 17);
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R16G16B16A16_TYPELESS, kW, kH, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE, texels.data(), kW * 8);
    ASSERT_TRUE(t);
    const std::vector<Texel> asUint = drawWithTexture(d, std::string(kFullScreen) + R"(
Texture2D<uint4> T : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { return float4(T.Load(int3(pos.xy, 0))); }
)",
                                                      viewAs(d, t.Get(), DXGI_FORMAT_R16G16B16A16_UINT).Get(), kW, kH);
    const std::vector<Texel> asUnorm = drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R16G16B16A16_UNORM).Get(), kW, kH);
    ASSERT_EQ(asUint.size(), std::size_t(kW * kH));
    ASSERT_EQ(asUnorm.size(), std::size_t(kW * kH));
    for (UINT i = 0; i < kW * kH; ++i)
        for (int c = 0; c < 4; ++c) {
            EXPECT_EQ(asUint[i][c], float(texels[i * 4 + c])) << "UINT texel " << i << " channel " << c;
            EXPECT_NEAR(asUnorm[i][c], float(texels[i * 4 + c]) / 65535.0f, 1e-6f) << "UNORM texel " << i << " channel " << c;
        }
    ComPtr<ID3D11RenderTargetView> rtv = targetAs(d, t.Get(), DXGI_FORMAT_R16G16B16A16_UINT);
    ASSERT_TRUE(rtv);
    drawInto(d, rtv.Get(), kW, kH, "uint4 ps(float4 pos : SV_Position) : SV_Target { uint2 p = uint2(pos.xy); return uint4(1000 + p.x, 2000 + p.y, 3, 65535); }");
    const std::vector<std::uint16_t> drawn = readTexels<std::uint16_t>(d, t.Get(), 4);
    ASSERT_EQ(drawn.size(), std::size_t(kW * kH * 4));
    for (UINT y = 0; y < kH; ++y)
        for (UINT x = 0; x < kW; ++x) {
            const std::uint16_t* v = &drawn[(y * kW + x) * 4];
            EXPECT_EQ((std::array<int, 4>{v[0], v[1], v[2], v[3]}), (std::array<int, 4>{int(1000 + x), int(2000 + y), 3, 65535}))
                << "drawn texel (" << x << ", " << y << ")";
        }
}

TEST(D3D11TypelessViews, Rg32TypelessFloatsReadAsTheirUintBits) {
    Device d;
    const float texels[kW * kH * 2] = {1.5f, -2.25f, 0.1f, 1e30f, -0.0f, 3.0e-38f, 65504.0f, -1.0f, 0.5f, 2.0f, 7.75f, -8.5f, 1.0f / 3.0f, 100.0f, 0.0f, 42.0f};
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R32G32_TYPELESS, kW, kH, D3D11_BIND_SHADER_RESOURCE, texels, kW * 8);
    ASSERT_TRUE(t);
    // The bits in 16-bit halves, which a float holds exactly.
    const std::vector<Texel> bits = drawWithTexture(d, std::string(kFullScreen) + R"(
Texture2D<uint2> T : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { uint2 v = T.Load(int3(pos.xy, 0)); return float4(v.x >> 16, v.x & 0xffff, v.y >> 16, v.y & 0xffff); }
)",
                                                    viewAs(d, t.Get(), DXGI_FORMAT_R32G32_UINT).Get(), kW, kH);
    ASSERT_EQ(bits.size(), std::size_t(kW * kH));
    for (UINT i = 0; i < kW * kH; ++i) {
        std::uint32_t x = 0, y = 0;
        std::memcpy(&x, &texels[i * 2], 4);
        std::memcpy(&y, &texels[i * 2 + 1], 4);
        EXPECT_EQ(bits[i], (Texel{float(x >> 16), float(x & 0xffff), float(y >> 16), float(y & 0xffff)})) << "texel " << i;
    }
}

TEST(D3D11TypelessViews, R8TypelessIsWrittenAsUintAndReadAsUnorm) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R8_TYPELESS, kW, kH, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
    ASSERT_TRUE(t);
    D3D11_UNORDERED_ACCESS_VIEW_DESC uavDesc;
    uavDesc.Format = DXGI_FORMAT_R8_UINT;
    uavDesc.ViewDimension = D3D11_UAV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11UnorderedAccessView> uav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(t.Get(), &uavDesc, uav.GetAddressOf()), S_OK) << lastError();
    dispatch(d, uav.Get(), R"(
RWTexture2D<uint> Out : register(u0);
[numthreads(4, 2, 1)] void cs(uint3 id : SV_DispatchThreadID) { Out[id.xy] = id.x * 60 + id.y * 7 + 3; }
)");
    const std::vector<Texel> unorm = drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R8_UNORM).Get(), kW, kH);
    ASSERT_EQ(unorm.size(), std::size_t(kW * kH));
    for (UINT y = 0; y < kH; ++y)
        for (UINT x = 0; x < kW; ++x) {
            const Texel want{float(x * 60 + y * 7 + 3) / 255.0f, 0, 0, 1};
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(unorm[y * kW + x][c], want[c], 1e-6f) << "texel (" << x << ", " << y << ") channel " << c;
        }
}

TEST(D3D11TypelessViews, ViewsOutsideTheFamilyAreRefusedNamingTheFormat) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R16G16_TYPELESS, kW, kH, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE);
    ASSERT_TRUE(t);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R32_FLOAT;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, rtv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R32_FLOAT for a DXGI_FORMAT_R16G16_TYPELESS texture"), std::string::npos) << lastError();
    // A multisampled typeless texture is drawn into in its stored format only.
    D3D11_TEXTURE2D_DESC msDesc;
    msDesc.Width = kW;
    msDesc.Height = kH;
    msDesc.MipLevels = msDesc.ArraySize = 1;
    msDesc.Format = DXGI_FORMAT_R8G8B8A8_TYPELESS;
    msDesc.SampleDesc.Count = 4;
    msDesc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> samples;
    ASSERT_EQ(d.device->CreateTexture2D(&msDesc, nullptr, samples.GetAddressOf()), S_OK) << lastError();
    desc.Format = DXGI_FORMAT_R8G8B8A8_UINT;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DMS;
    EXPECT_EQ(d.device->CreateRenderTargetView(samples.Get(), &desc, rtv.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R8G8B8A8_UINT of a multisampled DXGI_FORMAT_R8G8B8A8_TYPELESS texture"), std::string::npos) << lastError();
}

// Texel (x, y) of slice s of the 2x2 array: no two bytes alike.
std::array<std::uint8_t, 4> arrayTexel(UINT s, UINT x, UINT y) {
    const UINT base = s * 60 + (y * 2 + x) * 12;
    return {std::uint8_t(base + 1), std::uint8_t(base + 2), std::uint8_t(base + 3), std::uint8_t(base + 4)};
}

TEST(D3D11TypelessViews, ATypelessArrayIsReadAndDrawnInAnotherMemberSliceBySlice) {
    Device d;
    constexpr UINT kSlices = 3;
    std::vector<std::array<std::uint8_t, 4>> texels;
    for (UINT s = 0; s < kSlices; ++s)
        for (UINT i = 0; i < 4; ++i) texels.push_back(arrayTexel(s, i % 2, i / 2));
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    for (UINT s = 0; s < kSlices; ++s) data.push_back({&texels[s * 4], 8, 0});
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = 1;
    desc.ArraySize = kSlices;
    desc.Format = DXGI_FORMAT_R8G8B8A8_TYPELESS;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, data.data(), t.GetAddressOf()), S_OK) << lastError();

    // Slices 1 and 2 as integers: pixel (x, y) of a 4x2 target reads texel (x % 2, y) of view slice x / 2.
    D3D11_SHADER_RESOURCE_VIEW_DESC srv;
    srv.Format = DXGI_FORMAT_R8G8B8A8_UINT;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    srv.Texture2DArray = {0, 1, 1, 2};
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), &srv, view.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> got = drawWithTexture(d, std::string(kFullScreen) + R"(
Texture2DArray<uint4> T : register(t0);
float4 ps(float4 pos : SV_Position) : SV_Target { uint2 p = uint2(pos.xy); return float4(T.Load(int4(p.x % 2, p.y, p.x / 2, 0))); }
)",
                                                   view.Get(), 4, 2);
    ASSERT_EQ(got.size(), 8u);
    for (UINT y = 0; y < 2; ++y)
        for (UINT x = 0; x < 4; ++x) {
            const std::array<std::uint8_t, 4> want = arrayTexel(1 + x / 2, x % 2, y);
            EXPECT_EQ(got[y * 4 + x], (Texel{float(want[0]), float(want[1]), float(want[2]), float(want[3])})) << "pixel (" << x << ", " << y << ")";
        }

    // Slice 2 drawn into as integers; slices 0 and 1 keep their bytes.
    D3D11_RENDER_TARGET_VIEW_DESC rtvDesc;
    rtvDesc.Format = DXGI_FORMAT_R8G8B8A8_UINT;
    rtvDesc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
    rtvDesc.Texture2DArray = {0, 2, 1};
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), &rtvDesc, rtv.GetAddressOf()), S_OK) << lastError();
    drawInto(d, rtv.Get(), 2, 2, "uint4 ps(float4 pos : SV_Position) : SV_Target { return uint4(200 + uint(pos.x), 210 + uint(pos.y), 7, 9); }");
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture2D> staging;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    d.context->CopyResource(staging.Get(), t.Get());
    for (UINT s = 0; s < kSlices; ++s) {
        D3D11_MAPPED_SUBRESOURCE mapped;
        ASSERT_EQ(d.context->Map(staging.Get(), s, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
        for (UINT y = 0; y < 2; ++y)
            for (UINT x = 0; x < 2; ++x) {
                const std::uint8_t* b = static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch + x * 4;
                const std::array<std::uint8_t, 4> want =
                    s == 2 ? std::array<std::uint8_t, 4>{std::uint8_t(200 + x), std::uint8_t(210 + y), 7, 9} : arrayTexel(s, x, y);
                EXPECT_EQ((std::array<std::uint8_t, 4>{b[0], b[1], b[2], b[3]}), want) << "slice " << s << " texel (" << x << ", " << y << ")";
            }
        d.context->Unmap(staging.Get(), s);
    }
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// Face f of cube c of a typeless cube (array): the bytes (40c + 20f + 30, 60, 200 - 10f, 255).
std::uint32_t cubeFace(UINT c, UINT f) { return 0xff000000u | (200u - 10u * f) << 16 | 60u << 8 | (40u * c + 20u * f + 30u); }

// `cubes` cubes of R8G8B8A8_TYPELESS, 1x1 faces of cubeFace's bytes.
ComPtr<ID3D11Texture2D> typelessCubes(Device& d, UINT cubes, std::vector<std::uint32_t>& texels) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 1;
    desc.MipLevels = 1;
    desc.ArraySize = 6 * cubes;
    desc.Format = DXGI_FORMAT_R8G8B8A8_TYPELESS;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    texels.clear();
    for (UINT c = 0; c < cubes; ++c)
        for (UINT f = 0; f < 6; ++f) texels.push_back(cubeFace(c, f));
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    for (std::uint32_t& t : texels) data.push_back({&t, 4, 0});
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, data.data(), t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// Pixel i samples face i % 6 of cube i / 6 (a TextureCube reads cube 0 only).
std::string cubeSampler(bool array) {
    return std::string(kFullScreen) + (array ? "TextureCubeArray" : "TextureCube") + R"( Faces : register(t0);
SamplerState Point : register(s0);
float4 ps(float4 pos : SV_Position) : SV_Target {
    const float3 axes[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1), float3(0, 0, -1) };
    uint i = uint(pos.x);
    return Faces.SampleLevel(Point, )" + (array ? "float4(axes[i % 6], i / 6)" : "axes[i % 6]") + R"(, 0);
})";
}

void expectSrgbFaces(const std::vector<Texel>& got, UINT cubes, const char* what) {
    ASSERT_EQ(got.size(), std::size_t(6 * cubes)) << what;
    for (UINT i = 0; i < 6 * cubes; ++i) {
        const std::uint32_t bytes = cubeFace(i / 6, i % 6);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[i][c], srgbToLinear(float((bytes >> (8 * c)) & 0xff) / 255.0f), 2e-3f) << what << ": cube " << i / 6 << " face " << i % 6 << " channel " << c;
        EXPECT_NEAR(got[i][3], 1.0f, 1e-6f) << what;
    }
}

// Typeless cubes and cube arrays read as R8G8B8A8_UNORM_SRGB: TEXTURECUBE views of a cube and of
// a cube array's first cube, and a TEXTURECUBEARRAY view of both cubes, decode each face's bytes.
TEST(D3D11TypelessViews, TypelessCubesAndCubeArraysAreReadInAnotherMember) {
    Device d;
    D3D11_SAMPLER_DESC point;
    point.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> sampler;
    ASSERT_EQ(d.device->CreateSamplerState(&point, sampler.GetAddressOf()), S_OK) << lastError();
    std::vector<std::uint32_t> texels;
    D3D11_SHADER_RESOURCE_VIEW_DESC srv;
    srv.Format = DXGI_FORMAT_R8G8B8A8_UNORM_SRGB;
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBE;
    srv.TextureCube = {0, 1};
    ComPtr<ID3D11Texture2D> cube = typelessCubes(d, 1, texels);
    ASSERT_TRUE(cube);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(cube.Get(), &srv, view.GetAddressOf()), S_OK) << lastError();
    expectSrgbFaces(drawWithTexture(d, cubeSampler(false), view.Get(), 6, 1, sampler.Get()), 1, "a cube");

    ComPtr<ID3D11Texture2D> cubes = typelessCubes(d, 2, texels);
    ASSERT_TRUE(cubes);
    ASSERT_EQ(d.device->CreateShaderResourceView(cubes.Get(), &srv, view.ReleaseAndGetAddressOf()), S_OK) << lastError();
    expectSrgbFaces(drawWithTexture(d, cubeSampler(false), view.Get(), 6, 1, sampler.Get()), 1, "a cube array's first cube");
    srv.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBEARRAY;
    srv.TextureCubeArray = {0, 1, 0, 2};
    ASSERT_EQ(d.device->CreateShaderResourceView(cubes.Get(), &srv, view.ReleaseAndGetAddressOf()), S_OK) << lastError();
    expectSrgbFaces(drawWithTexture(d, cubeSampler(true), view.Get(), 12, 1, sampler.Get()), 2, "a cube array");
}

}  // namespace
}  // namespace d3d11test
