// Cube arrays: CreateTexture2D with MISC_TEXTURECUBE and ArraySize 6N, read by HLSL's
// TextureCubeArray through a D3D11_SRV_DIMENSION_TEXTURECUBEARRAY view (GL's cube map array view
// of the texture's layers). Each face of each cube is one colour; pixel i samples face i % 6 of
// cube i / 6 along the face's axis and must read that face's colour. A TEXTURECUBE view of a cube
// array reads its first cube through HLSL's TextureCube.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* const kCubes = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
TextureCubeArray tex : register(t0);
SamplerState smp : register(s0);
float4 ps(float4 p : SV_Position) : SV_Target {
    const float3 axes[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1), float3(0, 0, -1) };
    uint i = uint(p.x);
    return tex.SampleLevel(smp, float4(axes[i % 6], float(i / 6)), 0);
}
)";

constexpr UINT kCubeCount = 3;

// Face f of cube c (D3D's face order: +X, -X, +Y, -Y, +Z, -Z) is grey level 10 * (6c + f) + 5.
std::uint32_t faceColour(UINT slice) {
    const std::uint32_t v = 10 * slice + 5;
    return 0xff000000u | v << 16 | v << 8 | v;
}

ComPtr<ID3D11Texture2D> makeCubeArray(Device& d) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 1;
    desc.MipLevels = 1;
    desc.ArraySize = 6 * kCubeCount;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    std::vector<std::uint32_t> texels(desc.ArraySize);
    std::vector<D3D11_SUBRESOURCE_DATA> data(desc.ArraySize);
    for (UINT s = 0; s < desc.ArraySize; ++s) {
        texels[s] = faceColour(s);
        data[s] = {&texels[s], 4, 0};
    }
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, data.data(), t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// What pixel i of a draw through `view` reads, as RGBA floats.
void expectFaces(const std::vector<std::array<float, 4>>& got, UINT firstFace, UINT cubes) {
    ASSERT_EQ(got.size(), std::size_t(6 * cubes));
    for (UINT i = 0; i < 6 * cubes; ++i) {
        const float want = float(faceColour(firstFace + i) & 0xff) / 255.0f;
        EXPECT_NEAR(got[i][0], want, 1e-6f) << "cube " << i / 6 << " face " << i % 6;
        EXPECT_NEAR(got[i][3], 1.0f, 1e-6f);
    }
}

TEST(D3D11CubeArray, EveryFaceOfEveryCubeIsSampled) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeCubeArray(d);
    ASSERT_TRUE(t);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    view->GetDesc(&desc);
    EXPECT_EQ(desc.ViewDimension, D3D11_SRV_DIMENSION_TEXTURECUBEARRAY);
    EXPECT_EQ(desc.TextureCubeArray.NumCubes, kCubeCount);
    expectFaces(drawWithTexture(d, kCubes, view.Get(), 6 * kCubeCount, 1), 0, kCubeCount);
}

TEST(D3D11CubeArray, AViewOfSomeCubesStartsAtItsFirstFace) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeCubeArray(d);
    ASSERT_TRUE(t);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBEARRAY;
    desc.TextureCubeArray = {0, 1, 6, 2};  // cubes 1 and 2
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), S_OK) << lastError();
    expectFaces(drawWithTexture(d, kCubes, view.Get(), 12, 1), 6, 2);
}

TEST(D3D11CubeArray, FacesAreAlsoA2DArrayAndBadRangesAreRefused) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeCubeArray(d);
    ASSERT_TRUE(t);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    desc.Texture2DArray = {0, 1, 0, 6 * kCubeCount};
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), S_OK) << lastError();
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBEARRAY;
    desc.TextureCubeArray = {0, 1, 12, 2};  // past the third cube
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("NumCubes 2"), std::string::npos) << lastError();
}

// D3D11_TEX_CUBE_SRV names levels only: a TEXTURECUBE view of a cube array is its first cube.
TEST(D3D11CubeArray, ATextureCubeViewOfACubeArrayReadsItsFirstCube) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeCubeArray(d);
    ASSERT_TRUE(t);
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBE;
    desc.TextureCube = {0, UINT(-1)};
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC got;
    view->GetDesc(&got);
    EXPECT_EQ(got.ViewDimension, D3D11_SRV_DIMENSION_TEXTURECUBE);
    EXPECT_EQ(got.TextureCube.MipLevels, 1u);
    const char* const oneCube = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
TextureCube tex : register(t0);
SamplerState smp : register(s0);
float4 ps(float4 p : SV_Position) : SV_Target {
    const float3 axes[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1), float3(0, 0, -1) };
    return tex.SampleLevel(smp, axes[uint(p.x)], 0);
}
)";
    expectFaces(drawWithTexture(d, oneCube, view.Get(), 6, 1), 0, 1);
    desc.TextureCube = {1, 1};
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("TextureCube = {MostDetailedMip 1, MipLevels 1} (the texture has 1 levels)"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
