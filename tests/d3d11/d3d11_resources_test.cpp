// Buffers, textures and views: creation with initial data, the descriptions D3D rejects
// (E_INVALIDARG naming field and value), Map (WRITE_DISCARD on dynamic buffers, READ on staging),
// UpdateSubresource (whole and boxed), CopyResource, and read-back the way D3D code does it.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

struct ResourcesTest : ::testing::Test {
    Device d;
};

TEST_F(ResourcesTest, BufferInitialDataUpdateSubresourceAndCopyReadBack) {
    std::vector<std::uint8_t> bytes(64);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::uint8_t(i * 3 + 1);
    ComPtr<ID3D11Buffer> b = makeBuffer(d, bytes.data(), 64, D3D11_BIND_VERTEX_BUFFER);
    EXPECT_EQ(readBufferBytes(d, b.Get()), bytes);
    // A boxed update changes bytes [8, 12) only.
    const std::uint8_t patch[4] = {200, 201, 202, 203};
    D3D11_BOX box;
    box.left = 8;
    box.right = 12;
    d.context->UpdateSubresource(b.Get(), 0, &box, patch, 0, 0);
    EXPECT_EQ(lastError(), "");
    std::memcpy(&bytes[8], patch, 4);
    EXPECT_EQ(readBufferBytes(d, b.Get()), bytes);
    // Buffer to buffer on the GPU.
    ComPtr<ID3D11Buffer> copy = makeBuffer(d, nullptr, 64, D3D11_BIND_INDEX_BUFFER);
    d.context->CopyResource(copy.Get(), b.Get());
    EXPECT_EQ(readBufferBytes(d, copy.Get()), bytes);
}

TEST_F(ResourcesTest, DynamicBufferWriteDiscardReachesTheGpu) {
    D3D11_BUFFER_DESC dynamic;
    dynamic.ByteWidth = 32;
    dynamic.Usage = D3D11_USAGE_DYNAMIC;
    dynamic.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    dynamic.CPUAccessFlags = D3D11_CPU_ACCESS_WRITE;
    ComPtr<ID3D11Buffer> cb;
    ASSERT_EQ(d.device->CreateBuffer(&dynamic, nullptr, cb.GetAddressOf()), S_OK) << lastError();
    for (int round = 0; round < 2; ++round) {
        D3D11_MAPPED_SUBRESOURCE m;
        ASSERT_EQ(d.context->Map(cb.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &m), S_OK) << lastError();
        EXPECT_EQ(m.RowPitch, 32u);
        float values[8];
        for (int i = 0; i < 8; ++i) values[i] = float(round * 10 + i) + 0.5f;
        std::memcpy(m.pData, values, sizeof values);
        d.context->Unmap(cb.Get(), 0);
        // A constant buffer cannot be a copy source into staging on D3D either way: read it through
        // a DEFAULT copy.
        ComPtr<ID3D11Buffer> copy = makeBuffer(d, nullptr, 32, D3D11_BIND_CONSTANT_BUFFER);
        d.context->CopyResource(copy.Get(), cb.Get());
        std::vector<std::uint8_t> got = readBufferBytes(d, copy.Get());
        EXPECT_EQ(std::memcmp(got.data(), values, sizeof values), 0) << "round " << round;
    }
    // Map rules: READ on a dynamic buffer, Map of a DEFAULT buffer, a second Map.
    D3D11_MAPPED_SUBRESOURCE m;
    EXPECT_EQ(d.context->Map(cb.Get(), 0, D3D11_MAP_READ, 0, &m), E_INVALIDARG);
    ComPtr<ID3D11Buffer> plain = makeBuffer(d, nullptr, 16, D3D11_BIND_VERTEX_BUFFER);
    EXPECT_EQ(d.context->Map(plain.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &m), E_INVALIDARG);
    EXPECT_NE(lastError().find("Usage = 0"), std::string::npos) << lastError();
    ASSERT_EQ(d.context->Map(cb.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &m), S_OK);
    EXPECT_EQ(d.context->Map(cb.Get(), 0, D3D11_MAP_WRITE_DISCARD, 0, &m), E_INVALIDARG);
    d.context->Unmap(cb.Get(), 0);
}

TEST_F(ResourcesTest, InvalidBufferDescriptionsAreNamed) {
    D3D11_BUFFER_DESC desc;
    ComPtr<ID3D11Buffer> b;
    desc.ByteWidth = 0;
    desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ByteWidth = 0"), std::string::npos) << lastError();
    desc.ByteWidth = 20;
    desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ByteWidth = 20"), std::string::npos) << lastError();
    desc.ByteWidth = 32;
    desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER | D3D11_BIND_VERTEX_BUFFER;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("BindFlags = 5"), std::string::npos) << lastError();
    desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    desc.Usage = D3D11_USAGE_DYNAMIC;
    desc.CPUAccessFlags = 0;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("CPUAccessFlags = 0"), std::string::npos) << lastError();
    desc.Usage = D3D11_USAGE_IMMUTABLE;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("IMMUTABLE"), std::string::npos) << lastError();
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("BindFlags = 1"), std::string::npos) << lastError();
    desc.Usage = D3D11_USAGE(7);
    desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Usage = 7"), std::string::npos) << lastError();
    EXPECT_FALSE(b);
}

TEST_F(ResourcesTest, TextureInitialDataWithPaddedPitchAndBoxedUpdateReadBack) {
    // 3x2 texels given with a 16-byte row pitch (3 texels = 12 bytes + 4 padding).
    const std::uint32_t rows[2][4] = {{0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xdeadbeefu}, {0x80402010u, 0x01020304u, 0xffffffffu, 0xdeadbeefu}};
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = 3;
    desc.Height = 2;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    D3D11_SUBRESOURCE_DATA data;
    data.pSysMem = rows;
    data.SysMemPitch = 16;
    ComPtr<ID3D11Texture2D> t;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, &data, t.GetAddressOf()), S_OK) << lastError();
    auto pixels = readPixels(d, t.Get());
    auto texel = [](std::uint32_t v) { return std::array<std::uint8_t, 4>{std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)}; };
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) EXPECT_EQ(pixels[std::size_t(y * 3 + x)], texel(rows[y][x])) << x << "," << y;
    // UpdateSubresource of the 2x1 box at (1,1).
    const std::uint32_t patch[2] = {0x11223344u, 0x55667788u};
    D3D11_BOX box;
    box.left = 1, box.top = 1, box.right = 3, box.bottom = 2;
    d.context->UpdateSubresource(t.Get(), 0, &box, patch, 8, 0);
    EXPECT_EQ(lastError(), "");
    pixels = readPixels(d, t.Get());
    EXPECT_EQ(pixels[0], texel(rows[0][0]));
    EXPECT_EQ(pixels[3], texel(rows[1][0]));
    EXPECT_EQ(pixels[4], texel(patch[0]));
    EXPECT_EQ(pixels[5], texel(patch[1]));
}

TEST_F(ResourcesTest, ClearRenderTargetViewFillsTheTexture) {
    ComPtr<ID3D11Texture2D> t = makeTexture(d, 4, 4, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const FLOAT colour[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    d.context->ClearRenderTargetView(rtv.Get(), colour);
    for (const auto& p : readPixels(d, t.Get())) EXPECT_EQ(p, (std::array<std::uint8_t, 4>{64, 128, 191, 255}));
}

TEST_F(ResourcesTest, InvalidTextureDescriptionsAndViewsAreNamed) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = 8;
    desc.Height = 8;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> t;
    auto rejected = [&](HRESULT expected, D3D11_TEXTURE2D_DESC bad, const char* text) {
        EXPECT_EQ(d.device->CreateTexture2D(&bad, nullptr, t.GetAddressOf()), expected) << text;
        EXPECT_NE(lastError().find(text), std::string::npos) << lastError();
    };
    D3D11_TEXTURE2D_DESC bad = desc;
    bad.Width = 0;
    rejected(E_INVALIDARG, bad, "Width x Height = 0 x 8");
    bad = desc;
    bad.ArraySize = 0;
    rejected(E_INVALIDARG, bad, "ArraySize = 0");
    bad = desc;
    bad.MipLevels = 5;
    rejected(E_INVALIDARG, bad, "MipLevels = 5");
    bad = desc;
    bad.SampleDesc.Count = 0;
    rejected(E_INVALIDARG, bad, "SampleDesc.Count = 0");
    bad = desc;
    bad.Format = DXGI_FORMAT_UNKNOWN;
    rejected(E_INVALIDARG, bad, "Format = DXGI_FORMAT_UNKNOWN");
    bad = desc;
    bad.Usage = D3D11_USAGE_IMMUTABLE;
    rejected(E_INVALIDARG, bad, "IMMUTABLE without pInitialData");
    bad = desc;
    bad.ArraySize = 9;  // cube arrays are made (d3d11_cube_array_test.cpp), 6 faces a cube
    bad.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
    rejected(E_INVALIDARG, bad, "ArraySize = 9");

    // Views need the matching bind flag.
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(t.Get(), nullptr, rtv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_BIND_RENDER_TARGET"), std::string::npos) << lastError();
    ComPtr<ID3D11DepthStencilView> dsv;
    EXPECT_EQ(d.device->CreateDepthStencilView(t.Get(), nullptr, dsv.GetAddressOf()), E_INVALIDARG);
    ComPtr<ID3D11ShaderResourceView> srv;
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    sd.ViewDimension = D3D11_SRV_DIMENSION_UNKNOWN;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &sd, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("ViewDimension = 0"), std::string::npos) << lastError();
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, srv.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Resource> resource;
    srv->GetResource(resource.GetAddressOf());
    EXPECT_EQ(resource.Get(), static_cast<ID3D11Resource*>(t.Get()));
}

TEST_F(ResourcesTest, ReferenceCountsFollowD3D) {
    ComPtr<ID3D11Texture2D> t = makeTexture(d, 2, 2, D3D11_BIND_SHADER_RESOURCE);
    EXPECT_EQ(t->AddRef(), 2u);
    EXPECT_EQ(t->Release(), 1u);
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, srv.GetAddressOf()), S_OK);
    EXPECT_EQ(t->AddRef(), 3u);  // the view holds its texture
    t->Release();
    ComPtr<ID3D11Device> fromChild;
    t->GetDevice(fromChild.GetAddressOf());
    EXPECT_EQ(fromChild.Get(), d.device.Get());
}

}  // namespace
}  // namespace d3d11test

namespace d3d11test {
namespace {

// D3D11CreateDeviceAndSwapChain: a headless swap chain whose back buffer is a render target of the
// description's size and format, drawn into (cleared) and read back; invalid descriptions name the field.
TEST(D3D11SwapChain, BackBufferIsARenderTargetOfTheDescribedSize) {
    DXGI_SWAP_CHAIN_DESC sd;
    sd.BufferCount = 1;
    sd.BufferDesc.Width = 8;
    sd.BufferDesc.Height = 4;
    sd.BufferDesc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    sd.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
    Device d;  // for readPixels' context
    d.device.Reset();
    d.context.Reset();
    ComPtr<IDXGISwapChain> swapChain;
    ASSERT_EQ(D3D11CreateDeviceAndSwapChain(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, &sd,
                                            swapChain.GetAddressOf(), d.device.GetAddressOf(), nullptr, d.context.GetAddressOf()),
              S_OK)
        << lastError();
    ComPtr<ID3D11Texture2D> backBuffer;
    ASSERT_EQ(swapChain->GetBuffer(0, IID_ID3D11Texture2D, reinterpret_cast<void**>(backBuffer.GetAddressOf())), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC desc;
    backBuffer->GetDesc(&desc);
    EXPECT_EQ(desc.Width, 8u);
    EXPECT_EQ(desc.Height, 4u);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(backBuffer.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const FLOAT color[4] = {1, 0.2f, 0, 1};  // 0.2 * 255 = 51 exactly
    d.context->ClearRenderTargetView(rtv.Get(), color);
    EXPECT_EQ(swapChain->Present(1, 0), S_OK);
    EXPECT_EQ(swapChain->PresentCount(), 1u);
    for (const auto& p : readPixels(d, backBuffer.Get())) {
        EXPECT_EQ(p[0], 255);
        EXPECT_EQ(p[1], 51);
        EXPECT_EQ(p[2], 0);
    }
    sd.BufferDesc.Width = 0;
    ComPtr<IDXGISwapChain> none;
    ComPtr<ID3D11Device> other;
    EXPECT_EQ(D3D11CreateDeviceAndSwapChain(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION, &sd, none.GetAddressOf(),
                                            other.GetAddressOf(), nullptr, nullptr),
              E_INVALIDARG);
    EXPECT_NE(lastError().find("BufferDesc.Width x Height = 0 x 4"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
