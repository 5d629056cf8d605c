// CopyResource of the textures D3D11 copies whole beyond plain 2D colour ones: a cube texture
// (every face; each face one colour, read back by sampling the face's centre direction in a
// compute shader) and a typeless depth texture (R32_TYPELESS, DSV + SRV: cleared through its DSV,
// copied, and the copy read through its R32_FLOAT view by Load). A depth buffer without a shader
// view is E_NOTIMPL naming it.
#include <array>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// Runs `source`'s cs over one group with `srv` at t0, a point sampler at s0 and `count` float4s at u0.
std::vector<std::array<float, 4>> readThrough(Device& d, const char* source, ID3D11ShaderResourceView* srv, UINT count) {
    ComPtr<ID3DBlob> code = compile(source, "cs", "cs_5_0");
    if (!code) return {};
    ComPtr<ID3D11ComputeShader> cs;
    EXPECT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Buffer> out = makeBuffer(d, nullptr, count * 16, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 16);
    ComPtr<ID3D11UnorderedAccessView> uav;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(out.Get(), nullptr, uav.GetAddressOf()), S_OK) << lastError();
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> sampler;
    EXPECT_EQ(d.device->CreateSamplerState(&sd, sampler.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetShaderResources(0, 1, &srv);
    d.context->CSSetSamplers(0, 1, sampler.GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(0, 1, uav.GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    EXPECT_EQ(lastError(), "");
    return readBuffer<std::array<float, 4>>(d, out.Get());
}

ComPtr<ID3D11Texture2D> makeCube(Device& d, const std::array<std::uint32_t, 6>* faceColours) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = 1;
    desc.ArraySize = 6;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    std::vector<std::vector<std::uint32_t>> texels;
    std::vector<D3D11_SUBRESOURCE_DATA> init(6);
    for (int f = 0; f < 6 && faceColours; ++f) {
        texels.emplace_back(4, (*faceColours)[std::size_t(f)]);
        init[std::size_t(f)].pSysMem = texels.back().data();
        init[std::size_t(f)].SysMemPitch = 8;
    }
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, faceColours ? init.data() : nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

TEST(D3D11Copy, CubeTexturesCopyEveryFace) {
    Device d;
    const std::array<std::uint32_t, 6> colours = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xff00ffffu, 0xffff00ffu, 0xffffff00u};
    ComPtr<ID3D11Texture2D> source = makeCube(d, &colours), copy = makeCube(d, nullptr);
    ASSERT_TRUE(source && copy);
    d.context->CopyResource(copy.Get(), source.Get());
    ASSERT_EQ(lastError(), "");
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(copy.Get(), nullptr, srv.GetAddressOf()), S_OK) << lastError();
    const auto got = readThrough(d, R"(
TextureCube<float4> Cube : register(t0);
SamplerState Point : register(s0);
RWStructuredBuffer<float4> Out : register(u0);
static const float3 kFaces[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1), float3(0, 0, -1) };
[numthreads(6, 1, 1)]
void cs(uint i : SV_GroupIndex) { Out[i] = Cube.SampleLevel(Point, kFaces[i], 0); }
)",
                                 srv.Get(), 6);
    ASSERT_EQ(got.size(), 6u);
    for (std::size_t f = 0; f < 6; ++f)  // D3D's face order: +X, -X, +Y, -Y, +Z, -Z
        for (int c = 0; c < 4; ++c)
            EXPECT_FLOAT_EQ(got[f][std::size_t(c)], float((colours[f] >> (8 * c)) & 0xff) / 255.0f) << "face " << f << " channel " << c;
}

ComPtr<ID3D11Texture2D> makeDepth(Device& d, UINT bind) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 4;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = bind & D3D11_BIND_SHADER_RESOURCE ? DXGI_FORMAT_R32_TYPELESS : DXGI_FORMAT_D24_UNORM_S8_UINT;
    desc.BindFlags = bind;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

TEST(D3D11Copy, TypelessDepthTexturesCopyTheirDepth) {
    Device d;
    const UINT bind = D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> source = makeDepth(d, bind), copy = makeDepth(d, bind);
    ASSERT_TRUE(source && copy);
    D3D11_DEPTH_STENCIL_VIEW_DESC dd;
    dd.Format = DXGI_FORMAT_D32_FLOAT;
    dd.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateDepthStencilView(source.Get(), &dd, dsv.GetAddressOf()), S_OK) << lastError();
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH, 0.375f, 0);
    d.context->CopyResource(copy.Get(), source.Get());
    ASSERT_EQ(lastError(), "");
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.Format = DXGI_FORMAT_R32_FLOAT;
    sd.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    sd.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(copy.Get(), &sd, srv.GetAddressOf()), S_OK) << lastError();
    const auto got = readThrough(d, R"(
Texture2D<float> Depth : register(t0);
RWStructuredBuffer<float4> Out : register(u0);
[numthreads(4, 4, 1)]
void cs(uint3 p : SV_GroupThreadID, uint i : SV_GroupIndex) { Out[i] = Depth.Load(int3(p.xy, 0)); }
)",
                                 srv.Get(), 16);
    ASSERT_EQ(got.size(), 16u);
    for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(got[i][0], 0.375f) << "texel " << i;

    ComPtr<ID3D11Texture2D> plain = makeDepth(d, D3D11_BIND_DEPTH_STENCIL), plainCopy = makeDepth(d, D3D11_BIND_DEPTH_STENCIL);
    d.context->CopyResource(plainCopy.Get(), plain.Get());
    EXPECT_NE(lastError().find("CopyResource: a depth-stencil texture without BIND_SHADER_RESOURCE"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
