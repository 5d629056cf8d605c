// .dds textures (Texture2D::FromFile, Content.Load<Texture2D>): BC1/BC2/BC3 blocks decoded as D3D's
// block-compression rules define them (expectations worked out here from those rules), mip levels
// as stored, uncompressed files through their channel masks, and bad files refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "device/dds_image.h"
#include "fxport/graphics.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
}

// A DDS header (128 bytes) for width x height with `levels` mip levels; `fourCC` or masks.
std::vector<std::uint8_t> header(int width, int height, int levels, const char* fourCC, std::uint32_t bits = 0,
                                 std::uint32_t r = 0, std::uint32_t g = 0, std::uint32_t b = 0, std::uint32_t a = 0) {
    std::vector<std::uint8_t> h(128, 0);
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
        put32(h, 80, 0x40 | (a ? 0x1 : 0));
        put32(h, 88, bits), put32(h, 92, r), put32(h, 96, g), put32(h, 100, b), put32(h, 104, a);
    }
    put32(h, 108, 0x1000);
    return h;
}

// c0 = pure red (0xF800), c1 = pure blue (0x001F): c0 > c1, the four-colour mode; each row's
// texels use indices 0, 1, 2, 3.
const std::uint8_t kRedBlueBlock[8] = {0x00, 0xF8, 0x1F, 0x00, 0xE4, 0xE4, 0xE4, 0xE4};

TEST(DdsBlocks, Bc1FourColourModeInterpolatesThirds) {
    Color texels[16];
    detail::decodeBc1Block(kRedBlueBlock, texels);
    const Color expected[4] = {Color(255, 0, 0, 255), Color(0, 0, 255, 255), Color(170, 0, 85, 255), Color(85, 0, 170, 255)};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(texels[i], expected[i % 4]) << "texel " << i;
}

TEST(DdsBlocks, Bc1ThreeColourModeHasHalfwayAndTransparentBlack) {
    const std::uint8_t block[8] = {0x1F, 0x00, 0x00, 0xF8, 0xE4, 0xE4, 0xE4, 0xE4};  // c0 = blue <= c1 = red
    Color texels[16];
    detail::decodeBc1Block(block, texels);
    const Color expected[4] = {Color(0, 0, 255, 255), Color(255, 0, 0, 255), Color(128, 0, 128, 255), Color(0, 0, 0, 0)};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(texels[i], expected[i % 4]) << "texel " << i;
}

// DdsContent::Stored: each legacy pixel format as the DXGI format DirectXTK's loader maps it to
// (DXGI_FORMAT numbers from dxgiformat.h), the bytes as stored, the level sizes of the layout.
TEST(DdsStored, LegacyFormatsMapToDxgiAndKeepTheirBytes) {
    struct Case {
        const char* fourCC;
        std::uint32_t code, bits, r, g, b, a, flags, dxgi, bytes4x4;
    };
    const Case cases[] = {
        {"DXT1", 0, 0, 0, 0, 0, 0, 0, 71, 8},      {"DXT3", 0, 0, 0, 0, 0, 0, 0, 74, 16},       {"DXT5", 0, 0, 0, 0, 0, 0, 0, 77, 16},
        {"ATI1", 0, 0, 0, 0, 0, 0, 0, 80, 8},      {"BC4S", 0, 0, 0, 0, 0, 0, 0, 81, 8},        {"ATI2", 0, 0, 0, 0, 0, 0, 0, 83, 16},
        {"BC5S", 0, 0, 0, 0, 0, 0, 0, 84, 16},     {nullptr, 113, 0, 0, 0, 0, 0, 0, 10, 128},  {nullptr, 116, 0, 0, 0, 0, 0, 0, 2, 256},
        {nullptr, 111, 0, 0, 0, 0, 0, 0, 54, 32},  {nullptr, 0, 32, 0xFF, 0xFF00, 0xFF0000, 0xFF000000u, 0x41, 28, 64},
        {nullptr, 0, 32, 0xFF0000, 0xFF00, 0xFF, 0, 0x40, 88, 64},  {nullptr, 0, 32, 0x3FF00000, 0xFFC00, 0x3FF, 0xC0000000u, 0x41, 24, 64},
        {nullptr, 0, 16, 0xF800, 0x7E0, 0x1F, 0, 0x40, 85, 32},     {nullptr, 0, 8, 0xFF, 0, 0, 0, 0x20000, 61, 16},
        {nullptr, 0, 8, 0, 0, 0, 0xFF, 0x2, 65, 16},
    };
    for (const Case& c : cases) {
        std::vector<std::uint8_t> file = header(4, 4, 1, c.fourCC, c.bits, c.r, c.g, c.b, c.a);
        if (!c.fourCC && c.code) put32(file, 80, 0x4), put32(file, 84, c.code);
        if (!c.fourCC && !c.code) put32(file, 80, c.flags);
        for (std::uint32_t i = 0; i < c.bytes4x4; ++i) file.push_back(std::uint8_t(i * 3 + 1));
        const detail::DdsImage image = detail::decodeDds(file, "case.dds", detail::DdsContent::Stored);
        EXPECT_EQ(image.dxgiFormat, c.dxgi) << (c.fourCC ? c.fourCC : std::to_string(c.code + c.bits));
        ASSERT_EQ(image.stored.size(), 1u);
        EXPECT_EQ(image.stored[0], std::vector<std::uint8_t>(file.end() - std::ptrdiff_t(c.bytes4x4), file.end()));
    }
}

// A 24-bit RGB file has no DXGI format: Stored mode decodes it (dxgiFormat 0); a BC4 file does not
// decode to RGBA8, so XNA's Decoded read refuses it by name.
TEST(DdsStored, FormatsWithoutDxgiDecodeAndOpaqueOnesRefuseDecoding) {
    std::vector<std::uint8_t> rgb = header(1, 1, 1, nullptr, 24, 0xFF0000, 0xFF00, 0xFF);
    rgb.insert(rgb.end(), {10, 20, 30});
    const detail::DdsImage image = detail::decodeDds(rgb, "rgb.dds", detail::DdsContent::Stored);
    EXPECT_EQ(image.dxgiFormat, 0u);
    ASSERT_EQ(image.levels.size(), 1u);
    EXPECT_EQ(image.levels[0][0], Color(30, 20, 10, 255));
    std::vector<std::uint8_t> bc4 = header(4, 4, 1, "ATI1");
    bc4.resize(bc4.size() + 8, 0);
    try {
        detail::decodeDds(bc4, "bc4.dds");
        ADD_FAILURE() << "decoded";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("bc4.dds: DXGI format 80 does not decode"), std::string::npos) << e.what();
    }
}

TEST(DdsBlocks, Bc2ExplicitAndBc3InterpolatedAlpha) {
    std::uint8_t bc2[16] = {0x10, 0x32, 0x54, 0x76, 0x98, 0xBA, 0xDC, 0xFE};  // texel i: alpha nibble i
    std::copy(kRedBlueBlock, kRedBlueBlock + 8, bc2 + 8);
    Color texels[16];
    detail::decodeBc2Block(bc2, texels);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(texels[i].A, i * 17) << "texel " << i;
    EXPECT_EQ(texels[2], Color(170, 0, 85, 34));  // BC2's colours never use the three-colour mode

    // a0 = 255 > a1 = 0: eight alphas, a2..a7 = ((7 - k) * a0 + k * a1) / 7. Texel i takes index i % 8.
    std::uint8_t bc3[16] = {255, 0};
    std::uint64_t bits = 0;
    for (int i = 0; i < 16; ++i) bits |= std::uint64_t(i % 8) << (3 * i);
    for (int k = 0; k < 6; ++k) bc3[2 + k] = std::uint8_t(bits >> (8 * k));
    std::copy(kRedBlueBlock, kRedBlueBlock + 8, bc3 + 8);
    detail::decodeBc3Block(bc3, texels);
    const int alphas[8] = {255, 0, 219, 182, 146, 109, 73, 36};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(texels[i].A, alphas[i % 8]) << "texel " << i;
    // a0 <= a1: six alphas plus 0 and 255.
    bc3[0] = 0, bc3[1] = 255;
    detail::decodeBc3Block(bc3, texels);
    const int six[8] = {0, 255, 51, 102, 153, 204, 0, 255};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(texels[i].A, six[i % 8]) << "texel " << i;
}

class DdsTexture : public ::testing::Test {
protected:
    static GraphicsDevice& device() {
        static GraphicsDevice d(PresentationParameters{});
        return d;
    }
    void SetUp() override {
        dir = fs::temp_directory_path() / ("fxport-dds-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::vector<std::uint8_t>& bytes) {
        std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return (dir / name).string();
    }
    fs::path dir;
};

// 8x8 DXT1 with its four levels: level l is made of blocks of one solid colour (index 0 only).
TEST_F(DdsTexture, Dxt1MipChainLoadsLevelByLevel) {
    std::vector<std::uint8_t> file = header(8, 8, 4, "DXT1");
    const std::uint16_t colours[4] = {0xF800, 0x07E0, 0x001F, 0xFFFF};  // red, green, blue, white
    const Color expected[4] = {Color(255, 0, 0, 255), Color(0, 255, 0, 255), Color(0, 0, 255, 255), Color(255, 255, 255, 255)};
    for (int level = 0; level < 4; ++level) {
        const int blocks = std::max(1, (8 >> level) / 4) * std::max(1, (8 >> level) / 4);
        for (int k = 0; k < blocks; ++k) {
            // c0 = the colour, c1 = 0: four-colour mode (c0 > c1), every index 0.
            const std::uint8_t block[8] = {std::uint8_t(colours[level]), std::uint8_t(colours[level] >> 8), 0, 0, 0, 0, 0, 0};
            file.insert(file.end(), block, block + 8);
        }
    }
    const auto texture = Texture2D::FromFile(device(), write("chain.dds", file));
    EXPECT_EQ(texture->Width(), 8);
    EXPECT_EQ(texture->Height(), 8);
    ASSERT_EQ(texture->LevelCount(), 4);
    for (int level = 0; level < 4; ++level) {
        const int side = 8 >> level;
        std::vector<Color> texels(std::size_t(side * side));
        texture->getData(level, texels.data(), texels.size() * sizeof(Color));
        for (const Color& c : texels) EXPECT_EQ(c, expected[level]) << "level " << level;
    }
}

// A8R8G8B8 (bytes B, G, R, A in memory) and R5G6B5, read through their masks.
TEST_F(DdsTexture, UncompressedFilesFollowTheirChannelMasks) {
    std::vector<std::uint8_t> argb = header(2, 1, 1, nullptr, 32, 0xFF0000, 0xFF00, 0xFF, 0xFF000000u);
    for (std::uint8_t byte : {10, 20, 30, 40, 50, 60, 70, 80}) argb.push_back(byte);
    const auto a = Texture2D::FromFile(device(), write("argb.dds", argb));
    std::vector<Color> texels(2);
    a->GetData(texels.data(), 2);
    EXPECT_EQ(texels[0], Color(30, 20, 10, 40));
    EXPECT_EQ(texels[1], Color(70, 60, 50, 80));

    std::vector<std::uint8_t> rgb565 = header(1, 1, 1, nullptr, 16, 0xF800, 0x07E0, 0x001F);
    rgb565.push_back(0x10), rgb565.push_back(0x84);  // 0x8410: r 16, g 32, b 16
    const auto b = Texture2D::FromFile(device(), write("565.dds", rgb565));
    Color texel;
    b->GetData(&texel, 1);
    EXPECT_EQ(texel, Color(132, 130, 132, 255));  // 16 * 255 / 31, 32 * 255 / 63, rounded; opaque without an alpha mask
}

TEST_F(DdsTexture, BadFilesAreRefusedNamingTheFile) {
    auto expectRefused = [&](const std::string& path, const std::string& words) {
        try {
            Texture2D::FromFile(device(), path);
            ADD_FAILURE() << path << " loaded";
        } catch (const ArgumentError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(path), std::string::npos) << what;
            EXPECT_NE(what.find(words), std::string::npos) << what;
        }
    };
    std::vector<std::uint8_t> truncated = header(8, 8, 1, "DXT5");
    truncated.resize(truncated.size() + 20);  // four blocks need 64 bytes
    expectRefused(write("truncated.dds", truncated), "truncated");
    expectRefused(write("png.dds", {0x89, 'P', 'N', 'G'}), "not a DDS file");
    std::vector<std::uint8_t> huge = header(1 << 20, 1 << 20, 1, "DXT1");
    expectRefused(write("huge.dds", huge), "is not a size fxport loads");
    std::vector<std::uint8_t> volume = header(4, 4, 1, "DXT1");
    put32(volume, 112, 0x200000);
    expectRefused(write("volume.dds", volume), "volume texture");
    expectRefused(write("atc.dds", header(4, 4, 1, "ATC ")), "compression 'ATC ' is not one fxport reads");
}


// BC1 as D3D defines it, written again here (not dds_image.cpp's): 5:6:5 endpoints widened by bit
// replication; c0 > c1 gives c2 = (2 c0 + c1) / 3, c3 = (c0 + 2 c1) / 3; otherwise c2 = (c0 + c1) / 2
// and c3 transparent black. Texel i of the block (row-major) takes index bits 2i..2i+1.
std::vector<Color> cpuBc1(const std::uint8_t* block) {
    const unsigned c0 = unsigned(block[0] | block[1] << 8), c1 = unsigned(block[2] | block[3] << 8);
    auto widen = [](unsigned c) {
        const unsigned r = c >> 11, g = (c >> 5) & 63, b = c & 31;
        return std::array<int, 3>{int(r << 3 | r >> 2), int(g << 2 | g >> 4), int(b << 3 | b >> 2)};
    };
    const auto a = widen(c0), b = widen(c1);
    Color palette[4] = {Color(a[0], a[1], a[2], 255), Color(b[0], b[1], b[2], 255), {}, {}};
    if (c0 > c1) {
        palette[2] = Color((2 * a[0] + b[0] + 1) / 3, (2 * a[1] + b[1] + 1) / 3, (2 * a[2] + b[2] + 1) / 3, 255);
        palette[3] = Color((a[0] + 2 * b[0] + 1) / 3, (a[1] + 2 * b[1] + 1) / 3, (a[2] + 2 * b[2] + 1) / 3, 255);
    } else {
        palette[2] = Color((a[0] + b[0] + 1) / 2, (a[1] + b[1] + 1) / 2, (a[2] + b[2] + 1) / 2, 255);
        palette[3] = Color(0, 0, 0, 0);
    }
    const std::uint32_t bits = std::uint32_t(block[4] | block[5] << 8 | block[6] << 16) | std::uint32_t(block[7]) << 24;
    std::vector<Color> out;
    for (int i = 0; i < 16; ++i) out.push_back(palette[(bits >> (2 * i)) & 3]);
    return out;
}

// A 4x4 DXT1 cube map with two levels per face (4x4, then 2x2 stored as one block): every face a
// different block, faces 1, 3 and 5 in the three-colour mode (with transparent texels). Each face's
// level 0 must be its block decoded; level 1 the block's top-left 2x2.
TEST_F(DdsTexture, Dxt1CubeMapLoadsEveryFaceAndLevel) {
    std::vector<std::uint8_t> file = header(4, 4, 2, "DXT1");
    put32(file, 108, 0x401008);  // complex, mipmaps, texture
    put32(file, 112, 0xFE00);    // cube map, all six faces
    std::vector<std::array<std::uint8_t, 8>> blocks;
    for (int face = 0; face < 6; ++face) {
        for (int level = 0; level < 2; ++level) {
            const std::uint16_t hi = std::uint16_t(0x1234 * (face + 1) + 0x0841 * level), lo = std::uint16_t(0x8421 >> face);
            const std::uint16_t c0 = face % 2 ? std::min(hi, lo) : std::max(hi, lo), c1 = face % 2 ? std::max(hi, lo) : std::min(hi, lo);
            const std::uint32_t bits = 0x1B1B6CE4u * std::uint32_t(face * 2 + level + 3);
            blocks.push_back({std::uint8_t(c0), std::uint8_t(c0 >> 8), std::uint8_t(c1), std::uint8_t(c1 >> 8), std::uint8_t(bits),
                              std::uint8_t(bits >> 8), std::uint8_t(bits >> 16), std::uint8_t(bits >> 24)});
            file.insert(file.end(), blocks.back().begin(), blocks.back().end());
        }
    }
    const auto cube = TextureCube::FromFile(device(), write("sky.dds", file));
    EXPECT_EQ(cube->Size(), 4);
    ASSERT_EQ(cube->LevelCount(), 3);  // the stored two, and 1x1 made from level 1
    int transparent = 0;
    for (int face = 0; face < 6; ++face) {
        const std::vector<Color> level0 = cpuBc1(blocks[std::size_t(face * 2)].data());
        const std::vector<Color> level1 = cpuBc1(blocks[std::size_t(face * 2 + 1)].data());
        std::vector<Color> got(16);
        cube->GetData(CubeMapFace(face), 0, got.data(), got.size());
        EXPECT_EQ(got, level0) << "face " << face << " level 0";
        for (const Color& c : level0) transparent += c.A == 0;
        got.resize(4);
        cube->GetData(CubeMapFace(face), 1, got.data(), got.size());
        EXPECT_EQ(got, (std::vector<Color>{level1[0], level1[1], level1[4], level1[5]})) << "face " << face << " level 1";
    }
    EXPECT_GT(transparent, 0) << "no face used BC1's transparent black";
    std::vector<std::uint8_t> flat = header(4, 4, 1, "DXT1");
    flat.resize(flat.size() + 8, 0);
    EXPECT_THROW(TextureCube::FromFile(device(), write("flat.dds", flat)), ArgumentError);
}


// A volume DDS (DDSCAPS2_VOLUME, DDSD_DEPTH): each level's slices follow each other, front to back.
std::vector<std::uint8_t> volumeHeader(int width, int height, int depth, int levels, const char* fourCC, std::uint32_t bits = 0,
                                       std::uint32_t r = 0, std::uint32_t g = 0, std::uint32_t b = 0, std::uint32_t a = 0) {
    std::vector<std::uint8_t> h = header(width, height, levels, fourCC, bits, r, g, b, a);
    put32(h, 8, 0x801007 | (levels > 1 ? 0x20000 : 0));
    put32(h, 24, std::uint32_t(depth));
    put32(h, 112, 0x200000);
    return h;
}

// 4x2x3 A8R8G8B8 with two levels stored (24 texels, then 2x1x1): every texel distinct, read back
// exactly; the third level (1x1x1) is the rounded mean of level 1's two texels.
TEST_F(DdsTexture, VolumeLoadsAsTexture3DLevelByLevel) {
    std::vector<std::uint8_t> file = volumeHeader(4, 2, 3, 2, nullptr, 32, 0xFF0000, 0xFF00, 0xFF, 0xFF000000u);
    std::vector<Color> level0, level1;
    for (int i = 0; i < 24; ++i) {
        const Color c(std::uint8_t(10 * i), std::uint8_t(255 - 7 * i), std::uint8_t(i * i % 256), std::uint8_t(100 + i));
        level0.push_back(c);
        for (std::uint8_t byte : {c.B, c.G, c.R, c.A}) file.push_back(byte);  // slice z = i / 8, row (i / 4) % 2, column i % 4
    }
    level1 = {Color(1, 2, 3, 4), Color(200, 100, 50, 254)};
    for (const Color& c : level1)
        for (std::uint8_t byte : {c.B, c.G, c.R, c.A}) file.push_back(byte);
    const auto volume = Texture3D::FromFile(device(), write("volume.dds", file));
    EXPECT_EQ(volume->Width(), 4);
    EXPECT_EQ(volume->Height(), 2);
    EXPECT_EQ(volume->Depth(), 3);
    ASSERT_EQ(volume->LevelCount(), 3);
    std::vector<Color> got(24);
    volume->getData(0, got.data(), got.size() * sizeof(Color));
    EXPECT_EQ(got, level0);
    got.resize(2);
    volume->getData(1, got.data(), got.size() * sizeof(Color));
    EXPECT_EQ(got, level1);
    got.resize(1);
    volume->getData(2, got.data(), got.size() * sizeof(Color));
    EXPECT_EQ(got[0], Color(101, 51, 27, 129));  // (1 + 200 + 1) / 2, (2 + 100 + 1) / 2, (3 + 50 + 1) / 2, (4 + 254 + 1) / 2
}

// 4x4x2 DXT1: one block per slice, the second in the three-colour mode.
TEST_F(DdsTexture, Dxt1VolumeDecodesEverySlice) {
    std::vector<std::uint8_t> file = volumeHeader(4, 4, 2, 1, "DXT1");
    const std::uint8_t slices[2][8] = {{0x00, 0xF8, 0x1F, 0x00, 0xE4, 0x1B, 0x4E, 0xB1}, {0x1F, 0x00, 0x00, 0xF8, 0x1B, 0xE4, 0xB1, 0x4E}};
    std::vector<Color> expected;
    for (const auto& block : slices) {
        file.insert(file.end(), block, block + 8);
        const std::vector<Color> decoded = cpuBc1(block);
        expected.insert(expected.end(), decoded.begin(), decoded.end());
    }
    const auto volume = Texture3D::FromFile(device(), write("dxt1-volume.dds", file));
    ASSERT_EQ(volume->Depth(), 2);
    std::vector<Color> got(32);
    volume->GetData(got.data(), got.size());
    EXPECT_EQ(got, expected);
}

TEST_F(DdsTexture, VolumesAndFlatTexturesAreLoadedByTheirOwnClass) {
    std::vector<std::uint8_t> volume = volumeHeader(4, 4, 2, 1, "DXT1");
    volume.resize(volume.size() + 8, 0);  // slice 1's block is missing
    const std::string truncated = write("truncated-volume.dds", volume);
    try {
        Texture3D::FromFile(device(), truncated);
        ADD_FAILURE() << "loaded";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("level 0 slice 1 needs 8 bytes"), std::string::npos) << e.what();
    }
    volume.resize(volume.size() + 8, 0);
    const std::string whole = write("volume.dds", volume);
    try {
        Texture2D::FromFile(device(), whole);
        ADD_FAILURE() << "loaded";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("load it as Texture3D"), std::string::npos) << e.what();
    }
    std::vector<std::uint8_t> flat = header(4, 4, 1, "DXT1");
    flat.resize(flat.size() + 8, 0);
    try {
        Texture3D::FromFile(device(), write("flat.dds", flat));
        ADD_FAILURE() << "loaded";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("not a volume texture (a 2D texture; load it as Texture2D)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fxport

namespace fxport {
namespace {

// XNA's Dxt formats hold blocks: SetData/GetData exchange them as they are (GL stores them
// compressed); a region must lie on the 4x4 grid; they are never render targets.
TEST_F(DdsTexture, DxtTextureHoldsItsBlocksAsSet) {
    GraphicsDevice& d = device();
    Texture2D texture(d, 8, 4, false, SurfaceFormat::Dxt5);
    std::vector<std::uint8_t> blocks(32);
    for (std::size_t i = 0; i < blocks.size(); ++i) blocks[i] = std::uint8_t(i * 29 + 3);
    texture.SetData(blocks);
    EXPECT_EQ(texture.GetData<std::uint8_t>(), blocks);
    // The second block alone (texels 4..7 of the four rows).
    const std::vector<std::uint8_t> second(16, 0x42);
    const Rectangle right(4, 0, 4, 4);
    texture.SetData(0, &right, second.data(), second.size());
    std::copy(second.begin(), second.end(), blocks.begin() + 16);
    EXPECT_EQ(texture.GetData<std::uint8_t>(), blocks);
    const Rectangle offGrid(2, 0, 4, 4);
    EXPECT_THROW(texture.SetData(0, &offGrid, second.data(), second.size()), ArgumentError);
    try {
        texture.SetData(blocks.data(), 31);
        ADD_FAILURE() << "31 bytes for two 16-byte blocks accepted";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("needs 32 bytes"), std::string::npos) << e.what();
    }
    EXPECT_THROW(RenderTarget2D(d, 8, 8, false, SurfaceFormat::Dxt1, DepthFormat::None), ArgumentError);
}

}  // namespace
}  // namespace fxport
