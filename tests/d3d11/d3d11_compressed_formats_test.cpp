// Block-compressed textures (BC1-BC7) and the D3D10+ formats added with them, through the D3D11
// front end: texels sampled by a shader against a BC1 decoder written here from D3D's block rules
// (endpoints exact, interpolated colours within the rounding D3D leaves to the hardware), a BC7
// block whose endpoints are equal (every texel exact), blocks read back byte for byte through
// staging copies and UpdateSubresource, R11G11B10_FLOAT render targets against a CPU packing, the
// answers of CheckFormatSupport / CheckMultisampleQualityLevels / CheckFeatureSupport, and the uses
// D3D refuses for compressed textures.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

using Texel = std::array<float, 4>;

// Draws every texel of `view` (width x height) into a float target and reads the target back.
std::vector<Texel> loadEveryTexel(Device& d, ID3D11ShaderResourceView* view, UINT width, UINT height) {
    return drawWithTexture(d, kTexelLoadShader, view, width, height);
}

ComPtr<ID3D11Texture2D> makeCompressed(Device& d, DXGI_FORMAT format, UINT width, UINT height, const std::vector<std::uint8_t>& blocks,
                                       UINT rowPitch, D3D11_USAGE usage = D3D11_USAGE_DEFAULT) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = format;
    desc.Usage = usage;
    desc.BindFlags = usage == D3D11_USAGE_STAGING ? 0u : UINT(D3D11_BIND_SHADER_RESOURCE);
    desc.CPUAccessFlags = usage == D3D11_USAGE_STAGING ? UINT(D3D11_CPU_ACCESS_READ | D3D11_CPU_ACCESS_WRITE) : 0u;
    D3D11_SUBRESOURCE_DATA data{blocks.data(), rowPitch, 0};
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, blocks.empty() ? nullptr : &data, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

// --- a BC1 decoder from D3D's rules: 5:6:5 endpoints widened by bit replication; c0 > c1 gives
// four colours (thirds), otherwise three (the halfway point) and transparent black.
Texel rgb565(std::uint16_t c) {
    const int r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    return {float((r << 3) | (r >> 2)) / 255.0f, float((g << 2) | (g >> 4)) / 255.0f, float((b << 3) | (b >> 2)) / 255.0f, 1.0f};
}

std::array<Texel, 16> decodeBc1(const std::uint8_t* block) {
    const std::uint16_t c0 = std::uint16_t(block[0] | block[1] << 8), c1 = std::uint16_t(block[2] | block[3] << 8);
    const Texel a = rgb565(c0), b = rgb565(c1);
    std::array<Texel, 4> palette{a, b, {}, {0, 0, 0, 0}};
    for (int k = 0; k < 3; ++k) {
        if (c0 > c1) {
            palette[2][std::size_t(k)] = (2 * a[std::size_t(k)] + b[std::size_t(k)]) / 3;
            palette[3][std::size_t(k)] = (a[std::size_t(k)] + 2 * b[std::size_t(k)]) / 3;
        } else {
            palette[2][std::size_t(k)] = (a[std::size_t(k)] + b[std::size_t(k)]) / 2;
        }
    }
    palette[2][3] = 1;
    if (c0 > c1) palette[3][3] = 1;
    std::array<Texel, 16> out;
    for (int i = 0; i < 16; ++i) out[std::size_t(i)] = palette[(block[4 + i / 4] >> (2 * (i % 4))) & 3];
    return out;
}

// Four BC1 blocks (an 8x8 texture): both colour modes, every index.
std::vector<std::uint8_t> fourBc1Blocks() {
    return {
        0x00, 0xF8, 0x1F, 0x00, 0xE4, 0xE4, 0xE4, 0xE4,  // red > blue: four colours, indices 0 1 2 3 per row
        0xE0, 0x07, 0xFF, 0xFF, 0x1B, 0x1B, 0x1B, 0x1B,  // green < white: three colours + transparent black
        0x10, 0x84, 0x08, 0x42, 0x00, 0x55, 0xAA, 0xFF,  // greys, a row per index
        0xFF, 0xFF, 0x00, 0x00, 0x39, 0x93, 0x4E, 0xC6,  // white > black, mixed indices
    };
}

TEST(D3D11CompressedFormats, Bc1TexelsAreDecodedAsD3DDecodesThem) {
    Device d;
    const std::vector<std::uint8_t> blocks = fourBc1Blocks();
    ComPtr<ID3D11Texture2D> texture = makeCompressed(d, DXGI_FORMAT_BC1_UNORM, 8, 8, blocks, 16);  // a row of two 8-byte blocks
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    const std::vector<Texel> got = loadEveryTexel(d, view.Get(), 8, 8);
    ASSERT_EQ(got.size(), 64u);
    for (int block = 0; block < 4; ++block) {
        const std::array<Texel, 16> expected = decodeBc1(&blocks[std::size_t(block) * 8]);
        for (int i = 0; i < 16; ++i) {
            const int x = (block % 2) * 4 + i % 4, y = (block / 2) * 4 + i / 4;
            const int index = (blocks[std::size_t(block) * 8 + 4 + std::size_t(i / 4)] >> (2 * (i % 4))) & 3;
            // Endpoints are exact; how precisely the interpolated colours are computed is the
            // hardware's (NVIDIA's H200 gives 175/255 for the exact third's 170/255: 5/255 off).
            const float tolerance = index < 2 ? 0.5f / 255 : 6.0f / 255;
            for (int k = 0; k < 4; ++k)
                EXPECT_NEAR(got[std::size_t(y * 8 + x)][std::size_t(k)], expected[std::size_t(i)][std::size_t(k)], tolerance)
                    << "block " << block << " texel " << i << " channel " << k;
        }
    }
}

// Little-endian bit writer for a BC7 block.
struct Bits {
    std::array<std::uint8_t, 16> bytes{};
    int at = 0;
    void put(unsigned value, int count) {
        for (int k = 0; k < count; ++k, ++at)
            if ((value >> k) & 1u) bytes[std::size_t(at / 8)] |= std::uint8_t(1u << (at % 8));
    }
};

TEST(D3D11CompressedFormats, Bc7BlockWithEqualEndpointsReadsItsEndpointEverywhere) {
    Device d;
    UINT support = 0;
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_BC7_UNORM, &support), S_OK) << lastError();
    ASSERT_TRUE(support & D3D11_FORMAT_SUPPORT_SHADER_SAMPLE);
    // Mode 6 (bit 6 set after six zeros): RGBA endpoints of 7 bits plus a shared p-bit each, then 63
    // index bits. Equal endpoints make every index give the endpoint: (value << 1) | p.
    Bits b;
    b.put(1u << 6, 7);
    for (unsigned v : {100u, 100u, 50u, 50u, 20u, 20u, 127u, 127u}) b.put(v, 7);
    b.put(1, 1), b.put(1, 1);
    b.put(0x5A5A5A5Au, 32), b.put(0x1234567u, 31);
    std::vector<std::uint8_t> blocks(b.bytes.begin(), b.bytes.end());
    ComPtr<ID3D11Texture2D> texture = makeCompressed(d, DXGI_FORMAT_BC7_UNORM, 4, 4, blocks, 16);
    ComPtr<ID3D11ShaderResourceView> view;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    for (const Texel& t : loadEveryTexel(d, view.Get(), 4, 4)) {
        EXPECT_NEAR(t[0], 201.0f / 255, 1e-6f);
        EXPECT_NEAR(t[1], 101.0f / 255, 1e-6f);
        EXPECT_NEAR(t[2], 41.0f / 255, 1e-6f);
        EXPECT_NEAR(t[3], 1.0f, 1e-6f);
    }
}

// Reads level 0 of a compressed texture back as D3D code does: a staging copy, Map READ, RowPitch bytes per row of blocks.
std::vector<std::uint8_t> readBlocks(Device& d, ID3D11Texture2D* texture, DXGI_FORMAT format, UINT width, UINT height, UINT& rowPitch) {
    ComPtr<ID3D11Texture2D> staging = makeCompressed(d, format, width, height, {}, 0, D3D11_USAGE_STAGING);
    d.context->CopyResource(staging.Get(), texture);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    rowPitch = mapped.RowPitch;
    std::vector<std::uint8_t> out(std::size_t(mapped.DepthPitch));
    std::memcpy(out.data(), mapped.pData, out.size());
    d.context->Unmap(staging.Get(), 0);
    return out;
}

TEST(D3D11CompressedFormats, BlocksReadBackAsWrittenThroughInitialDataAndUpdateSubresource) {
    Device d;
    // Initial data with a padded pitch (24 bytes for a 16-byte row of blocks).
    const std::vector<std::uint8_t> blocks = fourBc1Blocks();
    std::vector<std::uint8_t> padded(48, 0xEE);
    for (int row = 0; row < 2; ++row) std::memcpy(&padded[std::size_t(row) * 24], &blocks[std::size_t(row) * 16], 16);
    ComPtr<ID3D11Texture2D> texture = makeCompressed(d, DXGI_FORMAT_BC1_UNORM, 8, 8, padded, 24);
    UINT rowPitch = 0;
    EXPECT_EQ(readBlocks(d, texture.Get(), DXGI_FORMAT_BC1_UNORM, 8, 8, rowPitch), blocks);
    EXPECT_EQ(rowPitch, 16u);
    // One block replaced: the box (4, 4)-(8, 8) is the bottom-right block.
    const std::uint8_t replacement[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    D3D11_BOX box{4, 4, 0, 8, 8, 1};
    d.context->UpdateSubresource(texture.Get(), 0, &box, replacement, 8, 0);
    EXPECT_EQ(lastError(), "");
    std::vector<std::uint8_t> expected = blocks;
    std::memcpy(&expected[24], replacement, 8);
    EXPECT_EQ(readBlocks(d, texture.Get(), DXGI_FORMAT_BC1_UNORM, 8, 8, rowPitch), expected);
    // BC3 and BC5 (16-byte blocks) round-trip too.
    for (DXGI_FORMAT format : {DXGI_FORMAT_BC3_UNORM, DXGI_FORMAT_BC5_UNORM, DXGI_FORMAT_BC7_UNORM}) {
        std::vector<std::uint8_t> wide(64);
        for (std::size_t i = 0; i < wide.size(); ++i) wide[i] = std::uint8_t(i * 37 + 11);
        if (format == DXGI_FORMAT_BC7_UNORM)
            for (std::size_t i = 0; i < wide.size(); i += 16) wide[i] = 0x40;  // mode 6: every bit pattern after it is valid
        ComPtr<ID3D11Texture2D> t = makeCompressed(d, format, 8, 8, wide, 32);
        EXPECT_EQ(readBlocks(d, t.Get(), format, 8, 8, rowPitch), wide) << int(format);
        EXPECT_EQ(rowPitch, 32u) << int(format);
    }
}

// An unsigned small float's bits for a power of two 2^e (mantissa 0): the biased exponent (bias 15).
std::uint32_t smallFloatPowerOfTwo(float value, int mantissaBits) {
    int exponent = 0;
    std::frexp(value, &exponent);  // value = 0.5 * 2^exponent
    return std::uint32_t(exponent - 1 + 15) << mantissaBits;
}

TEST(D3D11CompressedFormats, R11G11B10FloatTargetHoldsPackedSmallFloats) {
    Device d;
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R11G11B10_FLOAT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET | D3D11_BIND_SHADER_RESOURCE;
    ComPtr<ID3D11Texture2D> target;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    const float colour[4] = {1.0f, 0.5f, 4.0f, 1.0f};
    d.context->ClearRenderTargetView(rtv.Get(), colour);
    const std::uint32_t expected = smallFloatPowerOfTwo(1.0f, 6) | smallFloatPowerOfTwo(0.5f, 6) << 11 | smallFloatPowerOfTwo(4.0f, 5) << 22;
    for (std::uint32_t bits : readTexels<std::uint32_t>(d, target.Get())) EXPECT_EQ(bits, expected);
}

TEST(D3D11CompressedFormats, FormatSupportAnswersMatchWhatCreateTexture2DMakes) {
    Device d;
    UINT bits = 0;
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_R8G8B8A8_UNORM, &bits), S_OK);
    for (UINT want : {D3D11_FORMAT_SUPPORT_TEXTURE2D, D3D11_FORMAT_SUPPORT_RENDER_TARGET, D3D11_FORMAT_SUPPORT_SHADER_SAMPLE,
                      D3D11_FORMAT_SUPPORT_BLENDABLE, D3D11_FORMAT_SUPPORT_IA_VERTEX_BUFFER})
        EXPECT_TRUE(bits & want) << want;
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_BC1_UNORM, &bits), S_OK);
    EXPECT_TRUE(bits & D3D11_FORMAT_SUPPORT_SHADER_SAMPLE);
    EXPECT_FALSE(bits & D3D11_FORMAT_SUPPORT_RENDER_TARGET);
    EXPECT_FALSE(bits & D3D11_FORMAT_SUPPORT_MIP_AUTOGEN);
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_D24_UNORM_S8_UINT, &bits), S_OK);
    EXPECT_TRUE(bits & D3D11_FORMAT_SUPPORT_DEPTH_STENCIL);
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_R16_UINT, &bits), S_OK);
    EXPECT_TRUE(bits & D3D11_FORMAT_SUPPORT_IA_INDEX_BUFFER);
    ASSERT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT_R11G11B10_FLOAT, &bits), S_OK);
    EXPECT_TRUE(bits & D3D11_FORMAT_SUPPORT_RENDER_TARGET);
    EXPECT_EQ(d.device->CheckFormatSupport(DXGI_FORMAT(200), &bits), E_FAIL);
    EXPECT_EQ(bits, 0u);

    UINT levels = 7;
    ASSERT_EQ(d.device->CheckMultisampleQualityLevels(DXGI_FORMAT_R8G8B8A8_UNORM, 4, &levels), S_OK);
    EXPECT_EQ(levels, 1u);
    ASSERT_EQ(d.device->CheckMultisampleQualityLevels(DXGI_FORMAT_BC1_UNORM, 4, &levels), S_OK);
    EXPECT_EQ(levels, 0u);
    ASSERT_EQ(d.device->CheckMultisampleQualityLevels(DXGI_FORMAT_BC1_UNORM, 1, &levels), S_OK);
    EXPECT_EQ(levels, 1u);
    EXPECT_EQ(d.device->CheckMultisampleQualityLevels(DXGI_FORMAT_R8G8B8A8_UNORM, 3, &levels), E_FAIL);

    D3D11_FEATURE_DATA_THREADING threading{TRUE, TRUE};
    ASSERT_EQ(d.device->CheckFeatureSupport(D3D11_FEATURE_THREADING, &threading, sizeof threading), S_OK);
    EXPECT_EQ(threading.DriverCommandLists, FALSE);
    D3D11_FEATURE_DATA_FORMAT_SUPPORT format{DXGI_FORMAT_BC3_UNORM, 0};
    ASSERT_EQ(d.device->CheckFeatureSupport(D3D11_FEATURE_FORMAT_SUPPORT, &format, sizeof format), S_OK);
    EXPECT_TRUE(format.OutFormatSupport & D3D11_FORMAT_SUPPORT_TEXTURE2D);
    EXPECT_EQ(d.device->CheckFeatureSupport(D3D11_FEATURE_DOUBLES, &threading, sizeof threading), E_INVALIDARG);
    EXPECT_NE(lastError().find("D3D11_FEATURE_DOUBLES needs a 4-byte structure"), std::string::npos) << lastError();
}

TEST(D3D11CompressedFormats, UsesD3DRefusesAreRefusedNamingTheField) {
    Device d;
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 8;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_BC3_UNORM;
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("block-compressed textures are only sampled"), std::string::npos) << lastError();
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), E_INVALIDARG);
    desc.MiscFlags = 0;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    // A box off the 4x4 grid.
    const std::uint8_t block[16] = {};
    D3D11_BOX box{2, 0, 0, 6, 4, 1};
    d.context->UpdateSubresource(t.Get(), 0, &box, block, 16, 0);
    EXPECT_NE(lastError().find("not on the 4x4 block grid"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
