// Texture files through D3DX11 (D3DX11CreateShaderResourceViewFromFile, D3DX11CreateTextureFromFile),
// D3DX10 and DirectXTK (CreateDDSTextureFromFile, CreateWICTextureFromFile), on DDS and PNG files
// written here: a DDS keeps its stored format, levels, faces and slices (descriptions checked, blocks
// read back byte for byte, texels sampled against block decoders written here from D3D's rules);
// a PNG becomes R8G8B8A8_UNORM with D3DX's box-filtered chain (averages computed here); bad files
// are refused with a message naming them, never a crash (every truncation of a file tried).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "d3d11_test_support.h"
#include "device/image_io.h"
#include "fxport/d3d10.h"

namespace d3d11test {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
using Texel = std::array<float, 4>;

void put32(Bytes& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
}

// A DDS header for width x height with `levels` levels: a FourCC (DXT1, DX10 ...) or, with
// fourCC null, 32-bit A8R8G8B8 masks.
Bytes ddsHeader(int width, int height, int levels, const char* fourCC) {
    Bytes h(128, 0);
    h[0] = 'D', h[1] = 'D', h[2] = 'S', h[3] = ' ';
    put32(h, 4, 124);
    put32(h, 8, 0x1007 | (levels > 1 ? 0x20000 : 0));
    put32(h, 12, std::uint32_t(height));
    put32(h, 16, std::uint32_t(width));
    put32(h, 28, std::uint32_t(levels));
    put32(h, 76, 32);
    if (fourCC) {
        put32(h, 80, 0x4);
        for (int k = 0; k < 4; ++k) h[84 + std::size_t(k)] = std::uint8_t(fourCC[k]);
    } else {
        put32(h, 80, 0x41);
        put32(h, 88, 32), put32(h, 92, 0xFF0000), put32(h, 96, 0xFF00), put32(h, 100, 0xFF), put32(h, 104, 0xFF000000u);
    }
    put32(h, 108, 0x1000);
    return h;
}

// The same with a DX10 header: `dxgi`, resource dimension (3: 2D, 4: 3D), misc flags, array size.
Bytes dx10Header(int width, int height, int levels, std::uint32_t dxgi, std::uint32_t dimension = 3, std::uint32_t misc = 0,
                 std::uint32_t arraySize = 1, std::uint32_t misc2 = 0) {
    Bytes h = ddsHeader(width, height, levels, "DX10");
    h.resize(148, 0);
    put32(h, 128, dxgi), put32(h, 132, dimension), put32(h, 136, misc), put32(h, 140, arraySize), put32(h, 144, misc2);
    return h;
}

void append(Bytes& file, const Bytes& more) { file.insert(file.end(), more.begin(), more.end()); }

struct TextureFiles : ::testing::Test {
    Device d;
    fs::path folder;
    void SetUp() override {
        folder = fs::temp_directory_path() / ("fxport-texfile-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(folder);
    }
    void TearDown() override { fs::remove_all(folder); }
    std::string write(const std::string& name, const Bytes& bytes) {
        const std::string path = (folder / name).string();
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return path;
    }
    ComPtr<ID3D11ShaderResourceView> view(const std::string& path) {
        ComPtr<ID3D11ShaderResourceView> srv;
        HRESULT reported = E_FAIL;
        EXPECT_EQ(D3DX11CreateShaderResourceViewFromFile(d.device.Get(), path.c_str(), nullptr, nullptr, srv.GetAddressOf(), &reported), S_OK)
            << lastError();
        EXPECT_EQ(reported, S_OK);
        return srv;
    }
    static ComPtr<ID3D11Texture2D> texture2D(ID3D11ShaderResourceView* srv) {
        ComPtr<ID3D11Resource> resource;
        if (srv) srv->GetResource(resource.GetAddressOf());
        return ComPtr<ID3D11Texture2D>(dynamic_cast<ID3D11Texture2D*>(resource.Get()));
    }
    // Level `level` of `texture` as stored: a staging copy of the whole texture, that level mapped
    // READ, `rows` rows of `rowBytes` (rows of 4x4 blocks for BC formats).
    Bytes readLevel(ID3D11Texture2D* texture, UINT level, std::size_t rowBytes, std::size_t rows) {
        D3D11_TEXTURE2D_DESC desc;
        texture->GetDesc(&desc);
        desc.Usage = D3D11_USAGE_STAGING;
        desc.BindFlags = 0;
        desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
        desc.MiscFlags = 0;
        ComPtr<ID3D11Texture2D> staging;
        EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
        Bytes out(rowBytes * rows, 0);
        if (!staging) return out;
        d.context->CopyResource(staging.Get(), texture);
        D3D11_MAPPED_SUBRESOURCE mapped;
        EXPECT_EQ(d.context->Map(staging.Get(), level, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
        if (!mapped.pData) return out;
        for (std::size_t y = 0; y < rows; ++y) std::memcpy(&out[y * rowBytes], static_cast<const std::uint8_t*>(mapped.pData) + y * mapped.RowPitch, rowBytes);
        d.context->Unmap(staging.Get(), level);
        return out;
    }
    std::vector<Texel> draw(const char* source, ID3D11ShaderResourceView* srv, UINT width, UINT height);
};

// Draws pixel shader `ps` of `source` reading t0 through a point sampler into a width x height
// float target and reads it back.
std::vector<Texel> TextureFiles::draw(const char* source, ID3D11ShaderResourceView* srv, UINT width, UINT height) {
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    sd.AddressU = sd.AddressV = sd.AddressW = D3D11_TEXTURE_ADDRESS_CLAMP;
    ComPtr<ID3D11SamplerState> sampler;
    EXPECT_EQ(d.device->CreateSamplerState(&sd, sampler.GetAddressOf()), S_OK) << lastError();
    return drawWithTexture(d, source, srv, width, height, sampler.Get());
}

// --- block decoders from D3D's rules, written apart from the runtime's: BC1's 5:6:5 endpoints
// widened by bit replication, c0 > c1 giving thirds, otherwise the halfway colour and transparent
// black; BC3's alpha endpoints with 6 (a0 > a1) or 4 interpolated values plus 0 and 255.
Texel widen565(unsigned c) {
    const unsigned r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    return {float(r << 3 | r >> 2) / 255, float(g << 2 | g >> 4) / 255, float(b << 3 | b >> 2) / 255, 1};
}

std::array<Texel, 16> decodeColours(const std::uint8_t* block, bool threeColourAllowed) {
    const unsigned c0 = unsigned(block[0] | block[1] << 8), c1 = unsigned(block[2] | block[3] << 8);
    const Texel a = widen565(c0), b = widen565(c1);
    std::array<Texel, 4> palette{a, b, a, b};
    const bool three = threeColourAllowed && c0 <= c1;
    for (std::size_t k = 0; k < 3; ++k) {
        palette[2][k] = three ? (a[k] + b[k]) / 2 : (2 * a[k] + b[k]) / 3;
        palette[3][k] = three ? 0 : (a[k] + 2 * b[k]) / 3;
    }
    if (three) palette[3][3] = 0;
    std::array<Texel, 16> out;
    for (int i = 0; i < 16; ++i) out[std::size_t(i)] = palette[(block[4 + i / 4] >> (2 * (i % 4))) & 3];
    return out;
}

std::array<Texel, 16> decodeBc3(const std::uint8_t* block) {
    std::array<Texel, 16> out = decodeColours(block + 8, false);
    const float a0 = block[0], a1 = block[1];
    float alpha[8] = {a0, a1};
    const int steps = a0 > a1 ? 7 : 5;
    for (int i = 1; i < steps; ++i) alpha[i + 1] = ((float(steps - i) * a0) + float(i) * a1) / float(steps);
    if (steps == 5) alpha[6] = 0, alpha[7] = 255;
    std::uint64_t bits = 0;
    for (int k = 0; k < 6; ++k) bits |= std::uint64_t(block[2 + k]) << (8 * k);
    for (int i = 0; i < 16; ++i) out[std::size_t(i)][3] = alpha[(bits >> (3 * i)) & 7] / 255;
    return out;
}

// The tolerance is the hardware's precision of interpolated palette entries (NVIDIA's H200 decodes
// an exact third, 170/255, as 175/255); the blocks themselves are compared byte for byte elsewhere.
void expectTexels(const std::vector<Texel>& got, const std::array<Texel, 16>& expected, int width, int x0) {
    for (int i = 0; i < 16; ++i)
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(got[std::size_t((i / 4) * width + x0 + i % 4)][k], expected[std::size_t(i)][k], 6.0f / 255) << "texel " << i << " channel " << k;
}

// Four BC1 blocks: red > blue (four colours), green < white (three colours + transparent black).
const Bytes kBc1Level0 = {0x00, 0xF8, 0x1F, 0x00, 0xE4, 0xE4, 0xE4, 0xE4, 0xE0, 0x07, 0xFF, 0xFF, 0x1B, 0x1B, 0x1B, 0x1B,
                          0x10, 0x84, 0x08, 0x42, 0x00, 0x55, 0xAA, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x39, 0x93, 0x4E, 0xC6};
const Bytes kBc1Level1 = {0x1F, 0x00, 0xE0, 0x07, 0x1B, 0xE4, 0x4E, 0xB1};
const Bytes kBc1Level2 = {0x00, 0xF8, 0x00, 0xF8, 0x00, 0x00, 0x00, 0x00};
const Bytes kBc1Level3 = {0xE0, 0x07, 0xE0, 0x07, 0x00, 0x00, 0x00, 0x00};

Bytes bc1MipChainFile() {
    Bytes file = ddsHeader(8, 8, 4, "DXT1");
    for (const Bytes* level : {&kBc1Level0, &kBc1Level1, &kBc1Level2, &kBc1Level3}) append(file, *level);
    return file;
}

TEST_F(TextureFiles, Bc1DdsKeepsItsBlocksAndLevels) {
    const std::string path = write("bc1.dds", bc1MipChainFile());
    ComPtr<ID3D11ShaderResourceView> srv = view(path);
    ComPtr<ID3D11Texture2D> texture = texture2D(srv.Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_BC1_UNORM);
    EXPECT_EQ(desc.Width, 8u);
    EXPECT_EQ(desc.MipLevels, 4u);
    EXPECT_EQ(desc.ArraySize, 1u);
    EXPECT_EQ(desc.MiscFlags, 0u);
    EXPECT_EQ(desc.BindFlags, UINT(D3D11_BIND_SHADER_RESOURCE));
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    srv->GetDesc(&sd);
    EXPECT_EQ(sd.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE2D);
    EXPECT_EQ(readLevel(texture.Get(), 0, 16, 2), kBc1Level0);
    EXPECT_EQ(readLevel(texture.Get(), 1, 8, 1), kBc1Level1);
    EXPECT_EQ(readLevel(texture.Get(), 3, 8, 1), kBc1Level3);
    const std::vector<Texel> got = draw(kTexelLoadShader, srv.Get(), 8, 8);
    ASSERT_EQ(got.size(), 64u);
    for (int block = 0; block < 4; ++block) {
        SCOPED_TRACE("block " + std::to_string(block));
        std::vector<Texel> region;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) region.push_back(got[std::size_t(((block / 2) * 4 + y) * 8 + (block % 2) * 4 + x)]);
        expectTexels(region, decodeColours(&kBc1Level0[std::size_t(block) * 8], true), 4, 0);
    }
}

TEST_F(TextureFiles, Bc3AndSrgbBc7KeepTheirFormats) {
    const Bytes block = {0xF0, 0x10, 0x88, 0x46, 0x3A, 0x9C, 0x2B, 0x71, 0x00, 0xF8, 0xE0, 0x07, 0x1B, 0xE4, 0x4E, 0xB1};
    Bytes file = ddsHeader(4, 4, 1, "DXT5");
    append(file, block);
    ComPtr<ID3D11ShaderResourceView> srv = view(write("bc3.dds", file));
    ComPtr<ID3D11Texture2D> texture = texture2D(srv.Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_BC3_UNORM);
    EXPECT_EQ(desc.MipLevels, 1u);
    expectTexels(draw(kTexelLoadShader, srv.Get(), 4, 4), decodeBc3(block.data()), 4, 0);

    Bytes bc7 = dx10Header(8, 4, 1, DXGI_FORMAT_BC7_UNORM_SRGB);
    append(bc7, Bytes(32, 0x40));
    ComPtr<ID3D11Resource> resource;
    ASSERT_EQ(D3DX11CreateTextureFromFile(d.device.Get(), write("bc7.dds", bc7).c_str(), nullptr, nullptr, resource.GetAddressOf(), nullptr), S_OK)
        << lastError();
    ComPtr<ID3D11Texture2D> bc7Texture(dynamic_cast<ID3D11Texture2D*>(resource.Get()));
    ASSERT_TRUE(bc7Texture);
    bc7Texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_BC7_UNORM_SRGB);
    EXPECT_EQ(readLevel(bc7Texture.Get(), 0, 32, 1), Bytes(32, 0x40));
}

// D3DX9 wrote A16B16G16R16F as FourCC 113: the texels stay half floats.
TEST_F(TextureFiles, HalfFloatDdsStaysHalfFloat) {
    Bytes file = ddsHeader(2, 2, 1, nullptr);
    put32(file, 80, 0x4), put32(file, 84, 113);
    Bytes texels;
    for (std::uint16_t h : {0x3C00, 0x4000, 0xBC00, 0x3800, 0x0000, 0x7BFF, 0x3555, 0x3C00, 0x4200, 0x4400, 0x4500, 0x4600, 0xC000, 0x3400, 0x2E66, 0x3C00})
        texels.push_back(std::uint8_t(h & 0xFF)), texels.push_back(std::uint8_t(h >> 8));
    append(file, texels);
    ComPtr<ID3D11Texture2D> texture = texture2D(view(write("rgba16f.dds", file)).Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_R16G16B16A16_FLOAT);
    EXPECT_EQ(readLevel(texture.Get(), 0, 16, 2), texels);
}

// A DX10 cube of 2x2 R8G8B8A8 faces with two levels, each face one colour: a TEXTURECUBE view whose
// six axis directions sample the six faces.
TEST_F(TextureFiles, CubeDdsIsViewedAsACube) {
    Bytes file = dx10Header(2, 2, 2, DXGI_FORMAT_R8G8B8A8_UNORM, 3, D3D11_RESOURCE_MISC_TEXTURECUBE);
    const std::uint8_t colours[6][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}, {0, 255, 255, 255}, {255, 0, 255, 128}};
    for (const auto& colour : colours)
        for (int texel = 0; texel < 5; ++texel) file.insert(file.end(), colour, colour + 4);  // 2x2, then 1x1
    ComPtr<ID3D11ShaderResourceView> srv = view(write("cube.dds", file));
    ASSERT_TRUE(srv);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    srv->GetDesc(&sd);
    EXPECT_EQ(sd.ViewDimension, D3D11_SRV_DIMENSION_TEXTURECUBE);
    ComPtr<ID3D11Texture2D> texture = texture2D(srv.Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.ArraySize, 6u);
    EXPECT_EQ(desc.MipLevels, 2u);
    EXPECT_EQ(desc.MiscFlags, UINT(D3D11_RESOURCE_MISC_TEXTURECUBE));
    const char* source = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
TextureCube cube : register(t0);
SamplerState s : register(s0);
float4 ps(float4 p : SV_Position) : SV_Target {
    const float3 axes[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1), float3(0, 0, -1) };
    return cube.SampleLevel(s, axes[uint(p.x)], 0);
}
)";
    const std::vector<Texel> got = draw(source, srv.Get(), 6, 1);
    ASSERT_EQ(got.size(), 6u);
    for (std::size_t face = 0; face < 6; ++face)
        for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(got[face][k], colours[face][k] / 255.0f, 0.5f / 255) << "face " << face << " channel " << k;
}

TEST_F(TextureFiles, VolumeDdsIsATexture3D) {
    Bytes file = ddsHeader(4, 2, 1, nullptr);
    put32(file, 8, 0x801007);  // DDSD_DEPTH
    put32(file, 24, 3);
    put32(file, 112, 0x200000);  // DDSCAPS2_VOLUME
    append(file, Bytes(4 * 2 * 3 * 4, 0x7F));
    ComPtr<ID3D11Resource> resource;
    ASSERT_EQ(D3DX11CreateTextureFromFile(d.device.Get(), write("volume.dds", file).c_str(), nullptr, nullptr, resource.GetAddressOf(), nullptr), S_OK)
        << lastError();
    D3D11_RESOURCE_DIMENSION type = D3D11_RESOURCE_DIMENSION_UNKNOWN;
    resource->GetType(&type);
    EXPECT_EQ(type, D3D11_RESOURCE_DIMENSION_TEXTURE3D);
    auto* volume = dynamic_cast<ID3D11Texture3D*>(resource.Get());
    ASSERT_NE(volume, nullptr);
    D3D11_TEXTURE3D_DESC desc;
    volume->GetDesc(&desc);
    EXPECT_EQ(desc.Width, 4u);
    EXPECT_EQ(desc.Height, 2u);
    EXPECT_EQ(desc.Depth, 3u);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_B8G8R8A8_UNORM);  // A8R8G8B8's bytes are B, G, R, A
}

// A DX10 array of two 2x2 R8G8B8A8 items, each with its own bytes: a TEXTURE2DARRAY view, each
// slice read back as stored.
TEST_F(TextureFiles, ArrayDdsKeepsEveryItem) {
    Bytes file = dx10Header(2, 2, 1, DXGI_FORMAT_R8G8B8A8_UNORM, 3, 0, 2);
    Bytes items[2];
    for (std::size_t i = 0; i < 16; ++i) items[0].push_back(std::uint8_t(i * 7)), items[1].push_back(std::uint8_t(255 - i * 5));
    append(file, items[0]);
    append(file, items[1]);
    ComPtr<ID3D11ShaderResourceView> srv = view(write("array.dds", file));
    ASSERT_TRUE(srv);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    srv->GetDesc(&sd);
    EXPECT_EQ(sd.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE2DARRAY);
    ComPtr<ID3D11Texture2D> texture = texture2D(srv.Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.ArraySize, 2u);
    EXPECT_EQ(desc.MipLevels, 1u);
    EXPECT_EQ(readLevel(texture.Get(), 0, 8, 2), items[0]);
    EXPECT_EQ(readLevel(texture.Get(), 1, 8, 2), items[1]);  // subresource 1: item 1's level 0
}

// A DX10 TEXTURE1D array of two 4-texel R8G8B8A8 rows with two levels (4 and 2 texels): an
// ID3D11Texture1D under a TEXTURE1DARRAY view, each subresource read back as stored.
TEST_F(TextureFiles, OneDimensionalDdsKeepsItsRowsAndLevels) {
    Bytes file = dx10Header(4, 1, 2, DXGI_FORMAT_R8G8B8A8_UNORM, 2, 0, 2);
    Bytes rows[4];  // item 0 level 0, item 0 level 1, item 1 level 0, item 1 level 1
    for (std::size_t r = 0; r < 4; ++r) {
        for (std::size_t i = 0; i < (r % 2 ? 8u : 16u); ++i) rows[r].push_back(std::uint8_t(r * 50 + i * 3));
        append(file, rows[r]);
    }
    ComPtr<ID3D11ShaderResourceView> srv = view(write("line.dds", file));
    ASSERT_TRUE(srv);
    D3D11_SHADER_RESOURCE_VIEW_DESC sd;
    srv->GetDesc(&sd);
    EXPECT_EQ(sd.ViewDimension, D3D11_SRV_DIMENSION_TEXTURE1DARRAY);
    ComPtr<ID3D11Resource> resource;
    srv->GetResource(resource.GetAddressOf());
    D3D11_RESOURCE_DIMENSION dimension = D3D11_RESOURCE_DIMENSION_UNKNOWN;
    resource->GetType(&dimension);
    ASSERT_EQ(dimension, D3D11_RESOURCE_DIMENSION_TEXTURE1D);
    auto* line = static_cast<ID3D11Texture1D*>(resource.Get());
    D3D11_TEXTURE1D_DESC desc;
    line->GetDesc(&desc);
    EXPECT_EQ(desc.Width, 4u);
    EXPECT_EQ(desc.ArraySize, 2u);
    EXPECT_EQ(desc.MipLevels, 2u);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture1D> staging;
    ASSERT_EQ(d.device->CreateTexture1D(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    d.context->CopyResource(staging.Get(), line);
    for (UINT sub = 0; sub < 4; ++sub) {
        D3D11_MAPPED_SUBRESOURCE mapped;
        ASSERT_EQ(d.context->Map(staging.Get(), sub, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
        const auto* bytes = static_cast<const std::uint8_t*>(mapped.pData);
        EXPECT_EQ(Bytes(bytes, bytes + rows[sub].size()), rows[sub]) << "subresource " << sub;
        d.context->Unmap(staging.Get(), sub);
    }
}

// A DXT1 file with 2 of 4 levels: fxport's textures have 1 level or the full chain, so the texels are
// decoded and the chain completed (as Texture2D::FromFile does); a BC7 one is refused by name.
TEST_F(TextureFiles, PartialChainsDecodeOrAreRefused) {
    Bytes file = ddsHeader(8, 8, 2, "DXT1");
    append(file, kBc1Level0);
    append(file, kBc1Level1);
    ComPtr<ID3D11Texture2D> texture = texture2D(view(write("partial.tex", file)).Get());  // known by its magic, not its name
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(desc.MipLevels, 4u);
    Bytes bc7 = dx10Header(8, 8, 2, DXGI_FORMAT_BC7_UNORM);
    append(bc7, Bytes(64 + 16, 0));
    const std::string path = write("partial-bc7.dds", bc7);
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(D3DX11CreateShaderResourceViewFromFile(d.device.Get(), path.c_str(), nullptr, nullptr, srv.GetAddressOf(), nullptr), E_NOTIMPL);
    EXPECT_NE(lastError().find(path), std::string::npos) << lastError();
    EXPECT_NE(lastError().find("2 of 4 mip levels"), std::string::npos) << lastError();
}

// A 4x2 PNG: D3DX's full chain of 2x2 box averages; DirectXTK's WIC loader one level without a
// context, the chain with one.
TEST_F(TextureFiles, PngGetsD3DXsMipChain) {
    const std::vector<std::array<std::uint8_t, 4>> pixels = {{10, 20, 30, 255}, {50, 60, 70, 255}, {200, 0, 100, 0},  {0, 0, 0, 255},
                                                             {30, 40, 50, 255}, {70, 80, 91, 255}, {100, 100, 100, 0}, {255, 255, 255, 255}};
    const std::string path = (folder / "image.png").string();
    fxport::detail::savePng(path, 4, 2, pixels.front().data());
    ComPtr<ID3D11Texture2D> texture = texture2D(view(path).Get());
    ASSERT_TRUE(texture);
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(desc.MipLevels, 3u);  // 4x2, 2x1, 1x1
    Bytes level0;
    for (const auto& p : pixels) level0.insert(level0.end(), p.begin(), p.end());
    EXPECT_EQ(readLevel(texture.Get(), 0, 16, 2), level0);
    Bytes level1;
    for (int x = 0; x < 2; ++x)
        for (std::size_t k = 0; k < 4; ++k) {
            const int sum = pixels[std::size_t(2 * x)][k] + pixels[std::size_t(2 * x + 1)][k] + pixels[std::size_t(4 + 2 * x)][k] + pixels[std::size_t(5 + 2 * x)][k];
            level1.push_back(std::uint8_t((sum + 2) / 4));
        }
    EXPECT_EQ(readLevel(texture.Get(), 1, 8, 1), level1);

    ComPtr<ID3D11Resource> one, chain;
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(CreateWICTextureFromFile(d.device.Get(), path.c_str(), one.GetAddressOf(), srv.GetAddressOf()), S_OK) << lastError();
    dynamic_cast<ID3D11Texture2D*>(one.Get())->GetDesc(&desc);
    EXPECT_EQ(desc.MipLevels, 1u);
    ASSERT_TRUE(srv);
    const std::wstring wide(path.begin(), path.end());
    ASSERT_EQ(CreateWICTextureFromFile(d.device.Get(), d.context.Get(), wide.c_str(), chain.GetAddressOf(), nullptr), S_OK) << lastError();
    dynamic_cast<ID3D11Texture2D*>(chain.Get())->GetDesc(&desc);
    EXPECT_EQ(desc.MipLevels, 3u);
}

TEST_F(TextureFiles, DirectXTkDdsLoaderAndD3DX10ShareTheLoader) {
    const std::string path = write("bc1.dds", bc1MipChainFile());
    const std::wstring wide(path.begin(), path.end());
    ComPtr<ID3D11Resource> texture;
    ComPtr<ID3D11ShaderResourceView> srv;
    DDS_ALPHA_MODE alpha = DDS_ALPHA_MODE_CUSTOM;
    ASSERT_EQ(CreateDDSTextureFromFile(d.device.Get(), wide.c_str(), texture.GetAddressOf(), srv.GetAddressOf(), 0, &alpha), S_OK) << lastError();
    EXPECT_EQ(alpha, DDS_ALPHA_MODE_UNKNOWN);
    D3D11_TEXTURE2D_DESC desc;
    dynamic_cast<ID3D11Texture2D*>(texture.Get())->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_BC1_UNORM);
    EXPECT_EQ(desc.MipLevels, 4u);
    Bytes premultiplied = dx10Header(4, 4, 1, DXGI_FORMAT_BC3_UNORM, 3, 0, 1, 2);
    append(premultiplied, Bytes(16, 0));
    ASSERT_EQ(CreateDDSTextureFromFile(d.device.Get(), write("pm.dds", premultiplied).c_str(), nullptr, srv.GetAddressOf(), 0, &alpha), S_OK)
        << lastError();
    EXPECT_EQ(alpha, DDS_ALPHA_MODE_PREMULTIPLIED);

    ComPtr<fxport::d3d10::ID3D10Device> device10;
    ASSERT_EQ(fxport::d3d10::D3D10CreateDevice(nullptr, fxport::d3d10::D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0, fxport::d3d10::D3D10_SDK_VERSION,
                                               device10.GetAddressOf()),
              S_OK);
    ComPtr<ID3D11ShaderResourceView> srv10;
    ASSERT_EQ(fxport::d3d10::D3DX10CreateShaderResourceViewFromFile(device10.Get(), path.c_str(), nullptr, nullptr, srv10.GetAddressOf(), nullptr), S_OK)
        << lastError();
    texture2D(srv10.Get())->GetDesc(&desc);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_BC1_UNORM);
}

TEST_F(TextureFiles, BadFilesAreRefusedByName) {
    auto refused = [&](const std::string& path, HRESULT expected, const std::string& words) {
        ComPtr<ID3D11ShaderResourceView> srv;
        HRESULT reported = S_OK;
        EXPECT_EQ(D3DX11CreateShaderResourceViewFromFile(d.device.Get(), path.c_str(), nullptr, nullptr, srv.GetAddressOf(), &reported), expected) << path;
        EXPECT_EQ(reported, expected);
        EXPECT_FALSE(srv);
        EXPECT_NE(lastError().find(path), std::string::npos) << lastError();
        EXPECT_NE(lastError().find(words), std::string::npos) << lastError();
    };
    Bytes truncated = ddsHeader(8, 8, 1, "DXT1");
    append(truncated, Bytes(20, 0));
    refused(write("truncated.dds", truncated), E_INVALIDARG, "truncated");
    Bytes huge = dx10Header(16384, 16384, 1, DXGI_FORMAT_R32G32B32A32_FLOAT, 3, 0, 2048);  // 8 TiB claimed
    refused(write("huge.dds", huge), E_INVALIDARG, "truncated");
    refused(write("unknown.dds", dx10Header(4, 4, 1, 200)), E_INVALIDARG, "DXGI format 200");
    refused(write("buffer.dds", dx10Header(4, 4, 1, DXGI_FORMAT_BC1_UNORM, 1)), E_INVALIDARG, "resource dimension 1");
    Bytes partialCube = ddsHeader(4, 4, 1, "DXT1");
    put32(partialCube, 112, 0x200 | 0x400);
    refused(write("partial-cube.dds", partialCube), E_INVALIDARG, "six faces");
    Bytes tallLine = dx10Header(4, 2, 1, DXGI_FORMAT_R8G8B8A8_UNORM, 2);
    append(tallLine, Bytes(32, 0));
    refused(write("tall-line.dds", tallLine), E_INVALIDARG, "a 1D texture of height 2");
    refused((folder / "missing.png").string(), E_INVALIDARG, "missing.png");

    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(CreateDDSTextureFromFile(d.device.Get(), write("not.dds", {'P', 'N', 'G', '!'}).c_str(), nullptr, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("not a DDS file"), std::string::npos) << lastError();
    EXPECT_EQ(CreateWICTextureFromFile(d.device.Get(), write("bc1.dds", bc1MipChainFile()).c_str(), nullptr, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("is a DDS file"), std::string::npos) << lastError();
    int info = 0;
    EXPECT_EQ(D3DX11CreateShaderResourceViewFromFile(d.device.Get(), "x.png", reinterpret_cast<D3DX11_IMAGE_LOAD_INFO*>(&info), nullptr,
                                                     srv.GetAddressOf(), nullptr),
              E_NOTIMPL);
}

// Every prefix of a valid file (a cube with levels) is refused, none crashes or loads.
TEST_F(TextureFiles, EveryTruncationIsRefused) {
    Bytes file = dx10Header(2, 2, 2, DXGI_FORMAT_R8G8B8A8_UNORM, 3, D3D11_RESOURCE_MISC_TEXTURECUBE);
    append(file, Bytes(6 * 5 * 4, 0x55));
    for (std::size_t length = 0; length < file.size(); length += (length < 160 ? 1 : 7)) {
        const std::string path = write("cut.dds", Bytes(file.begin(), file.begin() + std::ptrdiff_t(length)));
        ComPtr<ID3D11Resource> resource;
        const HRESULT hr = D3DX11CreateTextureFromFile(d.device.Get(), path.c_str(), nullptr, nullptr, resource.GetAddressOf(), nullptr);
        EXPECT_TRUE(FAILED(hr)) << length << " bytes";
        EXPECT_FALSE(resource) << length << " bytes";
    }
}

}  // namespace
}  // namespace d3d11test
