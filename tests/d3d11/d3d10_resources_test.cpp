// The D3D10 spellings of the Rastertek DX10 tutorials' buffer, query and texture calls
// (fxport/d3d10.h): ID3D10Buffer::Map(WRITE_DISCARD)/Unmap on a dynamic vertex buffer (read back
// through a staging buffer mapped READ the D3D10 way); ID3D10Query's own Begin/End/GetData for an
// occlusion query (the samples of a 2 x 4 rectangle, counted on the CPU) and for pipeline
// statistics (D3D10's eight counters); ID3D10Device::SetPredication skipping a clear; and
// D3DX10CreateShaderResourceViewFromFile on a BMP written here, its texels and mip count compared
// with the file's (and D3DX10's full chain).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/d3d10.h"

namespace d3d10test {
namespace {

using namespace fxport::d3d10;

struct D3D10Resources : ::testing::Test {
    ComPtr<ID3D10Device> device;
    void SetUp() override {
        ASSERT_EQ(D3D10CreateDevice(nullptr, D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0, D3D10_SDK_VERSION, device.GetAddressOf()), S_OK)
            << GetLastErrorMessage();
    }
    ComPtr<ID3D10Buffer> buffer(UINT bytes, D3D10_USAGE usage, UINT bind, UINT cpu) {
        D3D10_BUFFER_DESC desc;
        desc.ByteWidth = bytes;
        desc.Usage = usage;
        desc.BindFlags = bind;
        desc.CPUAccessFlags = cpu;
        ComPtr<ID3D10Buffer> b;
        EXPECT_EQ(device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), S_OK) << GetLastErrorMessage();
        return b;
    }
    // An 8 x 8 RGBA8 render target bound with a viewport over it, and a vertex shader drawing
    // x in [-1, -0.5] (pixels 0..1) by y in [0, 1] (rows 0..3): 8 pixel centres.
    ComPtr<ID3D10Texture2D> bindTarget(ComPtr<ID3D10RenderTargetView>& rtv) {
        D3D10_TEXTURE2D_DESC td;
        td.Width = td.Height = 8;
        td.MipLevels = td.ArraySize = 1;
        td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
        td.BindFlags = D3D10_BIND_RENDER_TARGET;
        ComPtr<ID3D10Texture2D> t;
        EXPECT_EQ(device->CreateTexture2D(&td, nullptr, t.GetAddressOf()), S_OK) << GetLastErrorMessage();
        EXPECT_EQ(device->CreateRenderTargetView(t.Get(), nullptr, rtv.GetAddressOf()), S_OK) << GetLastErrorMessage();
        device->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        D3D10_VIEWPORT viewport;
        viewport.Width = viewport.Height = 8;
        device->RSSetViewports(1, &viewport);
        const char* text = R"(
static const float2 kCorners[6] = { float2(-1, 1), float2(-0.5, 1), float2(-0.5, 0), float2(-1, 1), float2(-0.5, 0), float2(-1, 0) };
float4 vs(uint id : SV_VertexID) : SV_Position { return float4(kCorners[id], 0, 1); }
float4 ps() : SV_Target { return 1; }
)";
        ComPtr<ID3DBlob> v, p;
        EXPECT_EQ(D3DCompile(text, std::strlen(text), "rect.hlsl", nullptr, nullptr, "vs", "vs_4_0", 0, 0, v.GetAddressOf(), nullptr), S_OK);
        EXPECT_EQ(D3DCompile(text, std::strlen(text), "rect.hlsl", nullptr, nullptr, "ps", "ps_4_0", 0, 0, p.GetAddressOf(), nullptr), S_OK);
        if (!v || !p) return t;
        ComPtr<ID3D10VertexShader> vs;
        ComPtr<ID3D10PixelShader> ps;
        EXPECT_EQ(device->CreateVertexShader(v->GetBufferPointer(), v->GetBufferSize(), vs.GetAddressOf()), S_OK) << GetLastErrorMessage();
        EXPECT_EQ(device->CreatePixelShader(p->GetBufferPointer(), p->GetBufferSize(), ps.GetAddressOf()), S_OK) << GetLastErrorMessage();
        device->VSSetShader(vs.Get());
        device->PSSetShader(ps.Get());
        device->IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        return t;
    }
    template <class T>
    HRESULT wait(ID3D10Query* q, T& out) {
        HRESULT hr = S_FALSE;
        for (int i = 0; i < 1000000 && hr == S_FALSE; ++i) hr = q->GetData(&out, sizeof out, 0);
        return hr;
    }
};

TEST_F(D3D10Resources, BufferMapWritesAndReads) {
    ComPtr<ID3D10Buffer> dynamic = buffer(16, D3D10_USAGE_DYNAMIC, D3D10_BIND_VERTEX_BUFFER, D3D10_CPU_ACCESS_WRITE);
    ComPtr<ID3D10Buffer> staging = buffer(16, D3D10_USAGE_STAGING, 0, D3D10_CPU_ACCESS_READ);
    ASSERT_TRUE(dynamic && staging);
    void* data = nullptr;
    ASSERT_EQ(dynamic->Map(D3D10_MAP_WRITE_DISCARD, 0, &data), S_OK) << GetLastErrorMessage();
    ASSERT_NE(data, nullptr);
    const float values[4] = {1.5f, -2, 3.25f, 1e6f};
    std::memcpy(data, values, sizeof values);
    dynamic->Unmap();
    device->CopyResource(staging.Get(), dynamic.Get());
    ASSERT_EQ(staging->Map(D3D10_MAP_READ, 0, &data), S_OK) << GetLastErrorMessage();
    EXPECT_EQ(std::memcmp(data, values, sizeof values), 0);
    staging->Unmap();
    // D3D's rules hold: READ of a dynamic buffer is refused, naming the usage.
    EXPECT_EQ(dynamic->Map(D3D10_MAP_READ, 0, &data), E_INVALIDARG);
    EXPECT_EQ(data, nullptr);
    EXPECT_EQ(dynamic->Map(D3D10_MAP_WRITE_DISCARD, 0, nullptr), E_INVALIDARG);
}

TEST_F(D3D10Resources, QueriesBeginEndAndGetDataOnThemselves) {
    ComPtr<ID3D10RenderTargetView> rtv;
    ComPtr<ID3D10Texture2D> target = bindTarget(rtv);
    D3D10_QUERY_DESC desc;
    desc.Query = D3D10_QUERY_OCCLUSION;
    ComPtr<ID3D10Query> occlusion;
    ASSERT_EQ(device->CreateQuery(&desc, occlusion.GetAddressOf()), S_OK) << GetLastErrorMessage();
    EXPECT_EQ(occlusion->GetDataSize(), sizeof(UINT64));
    occlusion->Begin();
    device->Draw(6, 0);
    occlusion->End();
    UINT64 samples = 0;
    ASSERT_EQ(wait(occlusion.Get(), samples), S_OK) << GetLastErrorMessage();
    EXPECT_EQ(samples, 2u * 4u);  // pixel centres x 0.5, 1.5 and y 0.5 .. 3.5

    desc.Query = D3D10_QUERY_PIPELINE_STATISTICS;
    ComPtr<ID3D10Query> statistics;
    const HRESULT made = device->CreateQuery(&desc, statistics.GetAddressOf());
    if (made == E_NOTIMPL) {  // only a driver without the extension may refuse, and the message must say so
        EXPECT_NE(std::string(GetLastErrorMessage()).find("GL_ARB_pipeline_statistics_query"), std::string::npos)
            << GetLastErrorMessage();
        GTEST_SKIP() << GetLastErrorMessage();
    }
    ASSERT_EQ(made, S_OK) << GetLastErrorMessage();
    EXPECT_EQ(statistics->GetDataSize(), sizeof(D3D10_QUERY_DATA_PIPELINE_STATISTICS));
    statistics->Begin();
    device->Draw(6, 0);
    statistics->End();
    D3D10_QUERY_DATA_PIPELINE_STATISTICS s;
    ASSERT_EQ(wait(statistics.Get(), s), S_OK) << GetLastErrorMessage();
    EXPECT_EQ(s.IAVertices, 6u);
    EXPECT_EQ(s.IAPrimitives, 2u);
    EXPECT_GE(s.PSInvocations, 8u);  // the 8 pixels, and whatever helper lanes the GPU counts
    EXPECT_EQ(s.GSInvocations, 0u);
}

TEST_F(D3D10Resources, SetPredicationSkipsAClear) {
    ComPtr<ID3D10RenderTargetView> rtv;
    ComPtr<ID3D10Texture2D> target = bindTarget(rtv);
    D3D10_QUERY_DESC desc;
    desc.Query = D3D10_QUERY_OCCLUSION_PREDICATE;
    ComPtr<ID3D10Predicate> predicate;
    ASSERT_EQ(device->CreatePredicate(&desc, predicate.GetAddressOf()), S_OK) << GetLastErrorMessage();
    predicate->Begin();
    device->Draw(6, 0);  // some samples pass: the predicate's data is TRUE
    predicate->End();
    const FLOAT red[4] = {1, 0, 0, 1};
    device->SetPredication(predicate.Get(), TRUE);
    device->ClearRenderTargetView(rtv.Get(), red);  // skipped
    ComPtr<ID3D10Predicate> got;
    BOOL value = FALSE;
    device->GetPredication(got.GetAddressOf(), &value);
    EXPECT_EQ(got.Get(), predicate.Get());
    EXPECT_EQ(value, TRUE);
    device->SetPredication(nullptr, FALSE);
    // Pixel (7, 7) was never drawn: still 0 unless the clear ran.
    D3D10_TEXTURE2D_DESC sd;
    target->GetDesc(&sd);
    sd.Usage = D3D10_USAGE_STAGING;
    sd.BindFlags = 0;
    sd.CPUAccessFlags = D3D10_CPU_ACCESS_READ;
    ComPtr<ID3D10Texture2D> staging;
    ASSERT_EQ(device->CreateTexture2D(&sd, nullptr, staging.GetAddressOf()), S_OK) << GetLastErrorMessage();
    device->CopyResource(staging.Get(), target.Get());
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(device->GetD3D11Context()->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    std::uint32_t last = 0;
    std::memcpy(&last, static_cast<const std::uint8_t*>(mapped.pData) + 7 * mapped.RowPitch + 7 * 4, 4);
    device->GetD3D11Context()->Unmap(staging.Get(), 0);
    EXPECT_EQ(last, 0u);
}

// A 32-bit BMP (BITMAPINFOHEADER, bottom-up rows, BGRA bytes) of `texels` (RGBA, top row first).
void writeBmp(const std::string& path, int w, int h, const std::vector<std::uint32_t>& texels) {
    std::vector<std::uint8_t> f(54 + std::size_t(w * h * 4), 0);
    auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) f[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
    };
    f[0] = 'B', f[1] = 'M';
    put32(2, std::uint32_t(f.size()));
    put32(10, 54);
    put32(14, 40);
    put32(18, std::uint32_t(w));
    put32(22, std::uint32_t(h));
    f[26] = 1, f[28] = 32;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint32_t c = texels[std::size_t((h - 1 - y) * w + x)];  // file rows bottom-up
            std::uint8_t* p = &f[54 + std::size_t((y * w + x) * 4)];
            p[0] = std::uint8_t(c >> 16), p[1] = std::uint8_t(c >> 8), p[2] = std::uint8_t(c), p[3] = std::uint8_t(c >> 24);
        }
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(f.data()), std::streamsize(f.size()));
}

TEST_F(D3D10Resources, D3DX10LoadsATextureFileWithAFullMipChain) {
    const std::vector<std::uint32_t> texels = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xffffffffu,
                                               0xff000000u, 0xff808080u, 0xff204060u, 0xff0a0b0cu};  // RGBA, 4 x 2
    const std::string path = (std::filesystem::temp_directory_path() / "fxport_d3dx10_texture.bmp").string();
    writeBmp(path, 4, 2, texels);
    ComPtr<ID3D10ShaderResourceView> srv;
    HRESULT reported = E_FAIL;
    ASSERT_EQ(D3DX10CreateShaderResourceViewFromFile(device.Get(), path.c_str(), nullptr, nullptr, srv.GetAddressOf(), &reported), S_OK)
        << GetLastErrorMessage();
    EXPECT_EQ(reported, S_OK);
    ComPtr<ID3D11Resource> resource;
    srv->GetResource(resource.GetAddressOf());
    auto* texture = dynamic_cast<ID3D10Texture2D*>(resource.Get());
    ASSERT_NE(texture, nullptr);
    D3D10_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Width, 4u);
    EXPECT_EQ(desc.Height, 2u);
    EXPECT_EQ(desc.MipLevels, 3u);  // 4x2, 2x1, 1x1
    EXPECT_EQ(desc.Format, DXGI_FORMAT_R8G8B8A8_UNORM);
    desc.MipLevels = 1;
    desc.Usage = D3D10_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D10_CPU_ACCESS_READ;
    ComPtr<ID3D10Texture2D> staging;
    ASSERT_EQ(device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << GetLastErrorMessage();
    device->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, texture, 0, nullptr);
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(device->GetD3D11Context()->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            std::uint32_t got = 0;
            std::memcpy(&got, static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch + x * 4, 4);
            EXPECT_EQ(got, texels[std::size_t(y * 4 + x)]) << "texel " << x << "," << y;
        }
    device->GetD3D11Context()->Unmap(staging.Get(), 0);
    std::remove(path.c_str());

    EXPECT_EQ(D3DX10CreateShaderResourceViewFromFile(device.Get(), L"no/such/file.png", nullptr, nullptr, srv.GetAddressOf(), &reported),
              E_INVALIDARG);
    EXPECT_EQ(reported, E_INVALIDARG);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("no/such/file.png"), std::string::npos) << GetLastErrorMessage();
}

// D3D10's spellings of array textures and their views reach the D3D11 device's arrays.
TEST_F(D3D10Resources, ArrayTexturesTakeD3D10sViewDimensions) {
    D3D10_TEXTURE2D_DESC td;
    td.Width = td.Height = 4;
    td.MipLevels = 1;
    td.ArraySize = 4;
    td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    td.BindFlags = D3D10_BIND_SHADER_RESOURCE | D3D10_BIND_RENDER_TARGET;
    ComPtr<ID3D10Texture2D> t;
    ASSERT_EQ(device->CreateTexture2D(&td, nullptr, t.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_SHADER_RESOURCE_VIEW_DESC srv;
    srv.ViewDimension = D3D10_SRV_DIMENSION_TEXTURE2DARRAY;
    srv.Texture2DArray = D3D10_TEX2D_ARRAY_SRV{0, 1, 2, 2};
    ComPtr<ID3D10ShaderResourceView> view;
    EXPECT_EQ(device->CreateShaderResourceView(t.Get(), &srv, view.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_RENDER_TARGET_VIEW_DESC rtv;
    rtv.ViewDimension = D3D10_RTV_DIMENSION_TEXTURE2DARRAY;
    rtv.Texture2DArray = D3D10_TEX2D_ARRAY_RTV{0, 4, 1};
    ComPtr<ID3D10RenderTargetView> target;
    EXPECT_EQ(device->CreateRenderTargetView(t.Get(), &rtv, target.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("FirstArraySlice + ArraySize = 4 + 1 (the texture has 4 slices)"), std::string::npos)
        << GetLastErrorMessage();
}

// ID3D10Device::CreateTexture1D is D3D11's: a 1D array, a TEXTURE1DARRAY view of part of its
// slices, and a slice range past its end refused with the field.
TEST_F(D3D10Resources, OneDimensionalTexturesTakeD3D10sViewDimensions) {
    D3D10_TEXTURE1D_DESC td;
    td.Width = 8;
    td.MipLevels = 0;
    td.ArraySize = 3;
    td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    td.BindFlags = D3D10_BIND_SHADER_RESOURCE;
    ComPtr<ID3D10Texture1D> t;
    ASSERT_EQ(device->CreateTexture1D(&td, nullptr, t.GetAddressOf()), S_OK) << GetLastErrorMessage();
    t->GetDesc(&td);
    EXPECT_EQ(td.MipLevels, 4u);
    D3D10_SHADER_RESOURCE_VIEW_DESC srv;
    srv.ViewDimension = D3D10_SRV_DIMENSION_TEXTURE1DARRAY;
    srv.Texture1DArray = D3D10_TEX1D_ARRAY_SRV{1, 2, 1, 2};
    ComPtr<ID3D10ShaderResourceView> view;
    EXPECT_EQ(device->CreateShaderResourceView(t.Get(), &srv, view.GetAddressOf()), S_OK) << GetLastErrorMessage();
    srv.Texture1DArray = D3D10_TEX1D_ARRAY_SRV{0, 1, 2, 2};
    EXPECT_EQ(device->CreateShaderResourceView(t.Get(), &srv, view.ReleaseAndGetAddressOf()), E_INVALIDARG);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("Texture1DArray.FirstArraySlice + ArraySize = 2 + 2 (the texture has 3 slices)"), std::string::npos)
        << GetLastErrorMessage();
}

}  // namespace
}  // namespace d3d10test
