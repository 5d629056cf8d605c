// B8G8R8X8 textures (the fourth byte unused: alpha reads 1) and typeless colour textures read
// through shader-resource views of another format of their family (UNORM and SRGB of B8G8R8X8,
// R8G8B8A8 and BC1/BC3; UNORM and SNORM of BC4/BC5): every texel loaded by a shader and compared
// with the CPU's decoding of the same bytes (sRGB to linear: D3D's formula).
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Texel = std::array<float, 4>;

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

void expectTexels(const std::vector<Texel>& got, const std::vector<Texel>& want, float tolerance, const char* what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[i][c], want[i][c], tolerance) << what << ": texel " << i << " channel " << c;
}

// Four texels as B, G, R, X bytes; X is 0 or 0x55, never what alpha reads.
const std::uint8_t kBgrx[16] = {0x10, 0x80, 0xf0, 0x00, 0xff, 0x00, 0x40, 0x55, 0x33, 0x66, 0x99, 0x00, 0x00, 0xc0, 0x20, 0x55};

// (r, g, b, 1) of kBgrx, decoded linearly or from sRGB.
std::vector<Texel> bgrxTexels(bool srgb) {
    std::vector<Texel> out;
    auto channel = [srgb](std::uint8_t v) { return srgb ? srgbToLinear(float(v) / 255.0f) : float(v) / 255.0f; };
    for (int i = 0; i < 4; ++i) out.push_back({channel(kBgrx[4 * i + 2]), channel(kBgrx[4 * i + 1]), channel(kBgrx[4 * i]), 1.0f});
    return out;
}

TEST(D3D11TypelessFormats, B8G8R8X8ReadsAlphaAsOne) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_B8G8R8X8_UNORM, 2, 2, D3D11_BIND_SHADER_RESOURCE, kBgrx, 8);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    expectTexels(drawWithTexture(d, kTexelLoadShader, view.Get(), 2, 2), bgrxTexels(false), 0.5f / 255.0f, "B8G8R8X8_UNORM");
}

TEST(D3D11TypelessFormats, B8G8R8X8SrgbDecodes) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_B8G8R8X8_UNORM_SRGB, 2, 2, D3D11_BIND_SHADER_RESOURCE, kBgrx, 8);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    expectTexels(drawWithTexture(d, kTexelLoadShader, view.Get(), 2, 2), bgrxTexels(true), 2e-3f, "B8G8R8X8_UNORM_SRGB");
}

TEST(D3D11TypelessFormats, B8G8R8X8TypelessIsReadAsUnormAndSrgb) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_B8G8R8X8_TYPELESS, 2, 2, D3D11_BIND_SHADER_RESOURCE, kBgrx, 8);
    ASSERT_TRUE(t);
    ComPtr<ID3D11ShaderResourceView> linear = viewAs(d, t.Get(), DXGI_FORMAT_B8G8R8X8_UNORM);
    ComPtr<ID3D11ShaderResourceView> srgb = viewAs(d, t.Get(), DXGI_FORMAT_B8G8R8X8_UNORM_SRGB);
    ASSERT_TRUE(linear && srgb);
    expectTexels(drawWithTexture(d, kTexelLoadShader, linear.Get(), 2, 2), bgrxTexels(false), 0.5f / 255.0f, "UNORM view");
    expectTexels(drawWithTexture(d, kTexelLoadShader, srgb.Get(), 2, 2), bgrxTexels(true), 2e-3f, "SRGB view");
}

TEST(D3D11TypelessFormats, B8G8R8X8RenderTargetBlendsWithDestinationAlphaOne) {
    // Destination alpha of an X format is 1: src * DEST_ALPHA keeps the source whole.
    Device d;
    ComPtr<ID3D11Texture2D> target = makeFormatTexture(d, DXGI_FORMAT_B8G8R8X8_UNORM, 2, 2, D3D11_BIND_RENDER_TARGET, nullptr, 0);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const float clear[4] = {0, 0, 0, 0};  // alpha 0 would be stored by a format with alpha
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    D3D11_BLEND_DESC bd;
    bd.RenderTarget[0].BlendEnable = TRUE;
    bd.RenderTarget[0].SrcBlend = D3D11_BLEND_DEST_ALPHA;
    bd.RenderTarget[0].DestBlend = D3D11_BLEND_ZERO;
    ComPtr<ID3D11BlendState> blend;
    ASSERT_EQ(d.device->CreateBlendState(&bd, blend.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetBlendState(blend.Get(), nullptr, 0xffffffffu);
    const char* source = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
float4 ps() : SV_Target { return float4(0.2, 0.4, 0.6, 0.5); }
)";
    ComPtr<ID3DBlob> vsCode = compile(source, "vs", "vs_5_0"), psCode = compile(source, "ps", "ps_5_0");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = 2;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");
    const std::vector<std::uint8_t> bytes = readTexelBytes(d, target.Get(), 4);
    ASSERT_EQ(bytes.size(), 16u);
    for (int i = 0; i < 4; ++i) {  // B, G, R of (0.2, 0.4, 0.6) * 1
        EXPECT_NEAR(bytes[std::size_t(4 * i)], 153, 1) << "texel " << i;
        EXPECT_NEAR(bytes[std::size_t(4 * i + 1)], 102, 1) << "texel " << i;
        EXPECT_NEAR(bytes[std::size_t(4 * i + 2)], 51, 1) << "texel " << i;
    }
}

TEST(D3D11TypelessFormats, R8G8B8A8TypelessIsReadAsUnormSrgbAndSnorm) {
    Device d;
    const std::uint8_t rgba[8] = {0x20, 0x90, 0xe0, 0xff, 0x7f, 0x81, 0x00, 0x40};
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R8G8B8A8_TYPELESS, 2, 1, D3D11_BIND_SHADER_RESOURCE, rgba, 8);
    ASSERT_TRUE(t);
    std::vector<Texel> unorm, srgb, snorm;
    for (int i = 0; i < 2; ++i) {
        Texel u, s, n;
        for (int c = 0; c < 4; ++c) {
            const std::uint8_t v = rgba[4 * i + c];
            u[std::size_t(c)] = float(v) / 255.0f;
            s[std::size_t(c)] = c == 3 ? u[std::size_t(c)] : srgbToLinear(u[std::size_t(c)]);  // alpha stays linear
            n[std::size_t(c)] = std::max(float(std::int8_t(v)) / 127.0f, -1.0f);
        }
        unorm.push_back(u), srgb.push_back(s), snorm.push_back(n);
    }
    expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UNORM).Get(), 2, 1), unorm, 0.5f / 255.0f, "UNORM");
    expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_UNORM_SRGB).Get(), 2, 1), srgb, 2e-3f, "SRGB");
    expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), DXGI_FORMAT_R8G8B8A8_SNORM).Get(), 2, 1), snorm, 0.5f / 127.0f, "SNORM");
}

// One 4x4 BC1 block of a single colour: both endpoints c, every index 0 (D3D: every texel is c0).
std::vector<std::uint8_t> bc1Solid(std::uint16_t c) {
    return {std::uint8_t(c & 0xff), std::uint8_t(c >> 8), std::uint8_t(c & 0xff), std::uint8_t(c >> 8), 0, 0, 0, 0};
}
// c's 5:6:5 channels widened by bit replication (D3D's endpoint rule, exact).
Texel rgb565(std::uint16_t c, bool srgb) {
    const int r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    Texel t{float((r << 3) | (r >> 2)) / 255.0f, float((g << 2) | (g >> 4)) / 255.0f, float((b << 3) | (b >> 2)) / 255.0f, 1.0f};
    if (srgb)
        for (int k = 0; k < 3; ++k) t[std::size_t(k)] = srgbToLinear(t[std::size_t(k)]);
    return t;
}

TEST(D3D11TypelessFormats, Bc1AndBc3TypelessAreReadAsUnormAndSrgb) {
    const std::uint16_t colour = (20 << 11) | (45 << 5) | 9;
    std::vector<std::uint8_t> bc3 = {0xff, 0xff, 0, 0, 0, 0, 0, 0};  // alpha endpoints 255, indices 0: alpha 1
    const std::vector<std::uint8_t> bc1 = bc1Solid(colour);
    bc3.insert(bc3.end(), bc1.begin(), bc1.end());
    for (auto [typeless, unorm, srgb, blocks] :
         {std::tuple{DXGI_FORMAT_BC1_TYPELESS, DXGI_FORMAT_BC1_UNORM, DXGI_FORMAT_BC1_UNORM_SRGB, bc1},
          std::tuple{DXGI_FORMAT_BC3_TYPELESS, DXGI_FORMAT_BC3_UNORM, DXGI_FORMAT_BC3_UNORM_SRGB, bc3}}) {
        Device d;
        ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, typeless, 4, 4, D3D11_BIND_SHADER_RESOURCE, blocks.data(), UINT(blocks.size()));
        ASSERT_TRUE(t);
        expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), unorm).Get(), 4, 4), std::vector<Texel>(16, rgb565(colour, false)), 1e-6f,
                     "UNORM view");
        expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), srgb).Get(), 4, 4), std::vector<Texel>(16, rgb565(colour, true)), 2e-3f,
                     "SRGB view");
    }
}

TEST(D3D11TypelessFormats, Bc4AndBc5TypelessAreReadAsUnormAndSnorm) {
    // Both endpoints 0x40, indices 0: every texel's channel is 0x40 (UNORM 64/255, SNORM 64/127).
    const std::vector<std::uint8_t> bc4 = {0x40, 0x40, 0, 0, 0, 0, 0, 0};
    std::vector<std::uint8_t> bc5 = bc4;
    bc5.insert(bc5.end(), bc4.begin(), bc4.end());
    for (auto [typeless, unorm, snorm, blocks, channels] :
         {std::tuple{DXGI_FORMAT_BC4_TYPELESS, DXGI_FORMAT_BC4_UNORM, DXGI_FORMAT_BC4_SNORM, bc4, 1},
          std::tuple{DXGI_FORMAT_BC5_TYPELESS, DXGI_FORMAT_BC5_UNORM, DXGI_FORMAT_BC5_SNORM, bc5, 2}}) {
        Device d;
        ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, typeless, 4, 4, D3D11_BIND_SHADER_RESOURCE, blocks.data(), UINT(blocks.size()));
        ASSERT_TRUE(t);
        const Texel u = {64.0f / 255.0f, channels > 1 ? 64.0f / 255.0f : 0.0f, 0, 1}, s = {64.0f / 127.0f, channels > 1 ? 64.0f / 127.0f : 0.0f, 0, 1};
        expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), unorm).Get(), 4, 4), std::vector<Texel>(16, u), 1e-3f, "UNORM view");
        expectTexels(drawWithTexture(d, kTexelLoadShader, viewAs(d, t.Get(), snorm).Get(), 4, 4), std::vector<Texel>(16, s), 1e-2f, "SNORM view");
    }
}

TEST(D3D11TypelessFormats, ViewsOutsideTheFamilyOrWithoutAFormatAreRefused) {
    Device d;
    const std::vector<std::uint8_t> blocks = bc1Solid(0x1234);
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_BC1_TYPELESS, 4, 4, D3D11_BIND_SHADER_RESOURCE, blocks.data(), 8);
    ASSERT_TRUE(t);
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("typeless"), std::string::npos) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_BC3_UNORM;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipLevels = 1;
    EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), &desc, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("DXGI_FORMAT_BC3_UNORM"), std::string::npos) << lastError();
    // A typed texture keeps its own format (D3D casts only typeless ones).
    ComPtr<ID3D11Texture2D> typed = makeFormatTexture(d, DXGI_FORMAT_B8G8R8X8_UNORM, 2, 2, D3D11_BIND_SHADER_RESOURCE, kBgrx, 8);
    desc.Format = DXGI_FORMAT_B8G8R8X8_UNORM_SRGB;
    EXPECT_NE(d.device->CreateShaderResourceView(typed.Get(), &desc, view.GetAddressOf()), S_OK);
}

TEST(D3D11TypelessFormats, RenderTargetViewsWriteTheStoredFormat) {
    Device d;
    ComPtr<ID3D11Texture2D> t = makeFormatTexture(d, DXGI_FORMAT_R8G8B8A8_TYPELESS, 2, 2, D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE, nullptr, 0);
    ASSERT_TRUE(t);
    D3D11_RENDER_TARGET_VIEW_DESC desc;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(t.Get(), &desc, rtv.GetAddressOf()), S_OK) << lastError();
    const float colour[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    d.context->ClearRenderTargetView(rtv.Get(), colour);
    const std::vector<std::uint8_t> bytes = readTexelBytes(d, t.Get(), 4);
    ASSERT_EQ(bytes.size(), 16u);
    EXPECT_NEAR(bytes[0], 64, 1);
    EXPECT_NEAR(bytes[1], 128, 1);
    EXPECT_NEAR(bytes[2], 191, 1);
}

}  // namespace
}  // namespace d3d11test
