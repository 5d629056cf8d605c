// TextureProcessor::TextureFormat (XNA's TextureProcessorOutputFormat): NoChange keeps a DXT1/DXT5
// .dds's blocks as stored, DxtCompressed block-compresses images (Dxt1 without fractional alpha,
// Dxt5 with it), Color (the default) decodes as before. Expectations come from the files the test
// writes and from BC1/BC3 decoders written here from D3D's block-compression rules (not the
// runtime's dds_image.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "fxport/graphics.h"
#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/texture_processor.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) b[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
}

// A legacy DDS header (128 bytes) with a FourCC, `levels` mip levels, optionally a cube map.
std::vector<std::uint8_t> ddsHeader(int width, int height, int levels, const char* fourCC, bool cube = false) {
    std::vector<std::uint8_t> h(128, 0);
    h[0] = 'D', h[1] = 'D', h[2] = 'S', h[3] = ' ';
    put32(h, 4, 124);
    put32(h, 8, 0x1007 | (levels > 1 ? 0x20000 : 0));
    put32(h, 12, std::uint32_t(height));
    put32(h, 16, std::uint32_t(width));
    put32(h, 28, std::uint32_t(levels));
    put32(h, 76, 32);
    put32(h, 80, 0x4);
    for (int k = 0; k < 4; ++k) h[84 + std::size_t(k)] = std::uint8_t(fourCC[k]);
    put32(h, 108, cube ? 0x401008 : 0x1000);
    if (cube) put32(h, 112, 0xFE00);
    return h;
}

// --- BC1 / BC3 as D3D defines them ---------------------------------------------------------------
// Endpoints are RGB565 widened by bit replication. BC1: c0 > c1 gives c2 = (2 c0 + c1) / 3 and
// c3 = (c0 + 2 c1) / 3; otherwise c2 = (c0 + c1) / 2 and c3 transparent black. BC3: a0 > a1 gives
// six interpolated alphas ((7 - k) a0 + k a1) / 7; otherwise four ((5 - k) a0 + k a1) / 5, then 0
// and 255; its colour half always uses the four-colour rule. Texel i (row-major) takes index i.

std::array<int, 3> widen(unsigned c) {
    const unsigned r = c >> 11, g = (c >> 5) & 63, b = c & 31;
    return {int(r << 3 | r >> 2), int(g << 2 | g >> 4), int(b << 3 | b >> 2)};
}

std::array<Color, 16> colourHalf(const std::uint8_t* block, bool bc1) {
    const unsigned c0 = unsigned(block[0] | block[1] << 8), c1 = unsigned(block[2] | block[3] << 8);
    const auto a = widen(c0), b = widen(c1);
    Color palette[4] = {Color(a[0], a[1], a[2], 255), Color(b[0], b[1], b[2], 255), {}, {}};
    if (c0 > c1 || !bc1) {
        palette[2] = Color((2 * a[0] + b[0] + 1) / 3, (2 * a[1] + b[1] + 1) / 3, (2 * a[2] + b[2] + 1) / 3, 255);
        palette[3] = Color((a[0] + 2 * b[0] + 1) / 3, (a[1] + 2 * b[1] + 1) / 3, (a[2] + 2 * b[2] + 1) / 3, 255);
    } else {
        palette[2] = Color((a[0] + b[0] + 1) / 2, (a[1] + b[1] + 1) / 2, (a[2] + b[2] + 1) / 2, 255);
        palette[3] = Color(0, 0, 0, 0);
    }
    const std::uint32_t bits = std::uint32_t(block[4] | block[5] << 8 | block[6] << 16) | std::uint32_t(block[7]) << 24;
    std::array<Color, 16> out;
    for (int i = 0; i < 16; ++i) out[std::size_t(i)] = palette[(bits >> (2 * i)) & 3];
    return out;
}

std::array<Color, 16> bc3Block(const std::uint8_t* block) {
    std::array<Color, 16> out = colourHalf(block + 8, false);
    int alpha[8] = {block[0], block[1]};
    if (alpha[0] > alpha[1]) {
        for (int k = 1; k < 7; ++k) alpha[k + 1] = ((7 - k) * alpha[0] + k * alpha[1] + 3) / 7;
    } else {
        for (int k = 1; k < 5; ++k) alpha[k + 1] = ((5 - k) * alpha[0] + k * alpha[1] + 2) / 5;
        alpha[6] = 0, alpha[7] = 255;
    }
    std::uint64_t bits = 0;
    for (int k = 0; k < 6; ++k) bits |= std::uint64_t(block[2 + k]) << (8 * k);
    for (int i = 0; i < 16; ++i) out[std::size_t(i)].A = std::uint8_t(alpha[(bits >> (3 * i)) & 7]);
    return out;
}

// A w x h level of BC1 (8-byte) or BC3 (16-byte) blocks decoded to texels.
std::vector<Color> decode(bool bc1, const std::vector<std::uint8_t>& blocks, int w, int h) {
    std::vector<Color> texels(std::size_t(w) * std::size_t(h));
    const std::size_t size = bc1 ? 8 : 16;
    const int bw = (w + 3) / 4;
    EXPECT_EQ(blocks.size(), std::size_t(bw) * std::size_t((h + 3) / 4) * size);
    for (int by = 0; by < (h + 3) / 4; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const std::uint8_t* at = blocks.data() + (std::size_t(by) * std::size_t(bw) + std::size_t(bx)) * size;
            const std::array<Color, 16> block = bc1 ? colourHalf(at, true) : bc3Block(at);
            for (int y = 0; y < 4 && by * 4 + y < h; ++y)
                for (int x = 0; x < 4 && bx * 4 + x < w; ++x)
                    texels[std::size_t(by * 4 + y) * std::size_t(w) + std::size_t(bx * 4 + x)] = block[std::size_t(y * 4 + x)];
        }
    return texels;
}

int maxChannelDifference(Color a, Color b) {
    return std::max({std::abs(a.R - b.R), std::abs(a.G - b.G), std::abs(a.B - b.B), std::abs(a.A - b.A)});
}

// Pseudo-random but fixed block bytes; BC1 blocks alternate between the two colour modes.
std::vector<std::uint8_t> blocksFor(bool bc1, int count, std::uint32_t seed) {
    std::vector<std::uint8_t> out;
    std::uint32_t x = seed;
    auto next = [&] { return x = x * 1664525u + 1013904223u, std::uint8_t(x >> 24); };
    for (int k = 0; k < count; ++k) {
        std::uint8_t block[16];
        for (std::uint8_t& b : block) b = next();
        std::uint8_t* colours = bc1 ? block : block + 8;
        unsigned c0 = unsigned(colours[0] | colours[1] << 8), c1 = unsigned(colours[2] | colours[3] << 8);
        if (bc1 && (k % 2 == 1) == (c0 > c1)) std::swap(c0, c1);  // odd blocks: three-colour mode
        colours[0] = std::uint8_t(c0), colours[1] = std::uint8_t(c0 >> 8), colours[2] = std::uint8_t(c1), colours[3] = std::uint8_t(c1 >> 8);
        out.insert(out.end(), block, block + (bc1 ? 8 : 16));
    }
    return out;
}

class DxtTextureFormat : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        PresentationParameters parameters;
        parameters.BackBufferWidth = 16;
        parameters.BackBufferHeight = 16;
        device_ = std::make_unique<GraphicsDevice>(parameters);
    }
    static void TearDownTestSuite() { device_.reset(); }
    static GraphicsDevice& device() { return *device_; }

    void SetUp() override {
        dir = fs::temp_directory_path() / ("fxport-dxt-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string write(const std::string& name, const std::vector<std::uint8_t>& bytes) {
        std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return (dir / name).string();
    }
    std::string writePng(const std::string& name, int w, int h, const std::vector<Color>& texels) {
        Texture2D source(device(), w, h, false, SurfaceFormat::Color);
        source.SetData(texels);
        source.SaveAsPng((dir / name).string());
        return (dir / name).string();
    }

    // `texture` drawn into a w x h Color target with point sampling and no blending: at the
    // texture's size that is level 0, at half its size level 1 (one texel per pixel either way).
    static std::vector<Color> drawn(Texture2D& texture, int w, int h) {
        RenderTarget2D target(device(), w, h, false, SurfaceFormat::Color, DepthFormat::None);
        device().SetRenderTarget(target);
        device().Clear(Color(1, 2, 3, 4));
        SpriteBatch batch(device());
        batch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch.Draw(texture, Rectangle(0, 0, w, h), Color::White);
        batch.End();
        device().SetRenderTarget(nullptr);
        return target.GetData<Color>();
    }

    static std::vector<std::uint8_t> levelBytes(const Texture2D& texture, int level) {
        const int w = std::max(1, texture.Width() >> level), h = std::max(1, texture.Height() >> level);
        std::vector<std::uint8_t> bytes(regionBytes(texture.Format(), w, h));
        texture.getData(level, bytes.data(), bytes.size());
        return bytes;
    }

    static std::unique_ptr<GraphicsDevice> device_;
    fs::path dir;
};

std::unique_ptr<GraphicsDevice> DxtTextureFormat::device_;

TEST(TextureProcessorFormat, DefaultIsXnasColor) {
    EXPECT_EQ(TextureProcessor().TextureFormat, TextureProcessorOutputFormat::Color);
    EXPECT_EQ(TextureProcessor::None().TextureFormat, TextureProcessorOutputFormat::Color);
}

// An 8x8 DXT1 and DXT5 file with two levels (4 blocks, then 1): under NoChange the texture holds
// the file's blocks, level by level, and samples as the blocks decode (draw at 8x8 for level 0,
// at 4x4 for level 1). The default processor (Color, magenta keyed, premultiplied) decodes instead.
TEST_F(DxtTextureFormat, NoChangeKeepsDxt1AndDxt5BlocksAsStored) {
    for (bool bc1 : {true, false}) {
        SCOPED_TRACE(bc1 ? "DXT1" : "DXT5");
        const std::vector<std::uint8_t> level0 = blocksFor(bc1, 4, bc1 ? 7u : 11u), level1 = blocksFor(bc1, 1, bc1 ? 5u : 3u);
        std::vector<std::uint8_t> file = ddsHeader(8, 8, 2, bc1 ? "DXT1" : "DXT5");
        file.insert(file.end(), level0.begin(), level0.end());
        file.insert(file.end(), level1.begin(), level1.end());
        const std::string path = write(bc1 ? "one.dds" : "five.dds", file);

        TextureProcessor noChange;
        noChange.TextureFormat = TextureProcessorOutputFormat::NoChange;
        auto texture = noChange.Load(device(), path);
        EXPECT_EQ(texture->Format(), bc1 ? SurfaceFormat::Dxt1 : SurfaceFormat::Dxt5);
        ASSERT_EQ(texture->LevelCount(), 4);  // the stored two; 2x2 and 1x1 completed from level 1
        EXPECT_EQ(levelBytes(*texture, 0), level0);
        EXPECT_EQ(levelBytes(*texture, 1), level1);

        // Sampled texels: the blocks decoded here, within 6: how precisely interpolated palette
        // entries are computed is left to the hardware (llvmpipe is within 1; NVIDIA's H200 decodes
        // BC1's one-third point 5 off, as the D3D11 compressed-format tests measured).
        constexpr int kTolerance = 6;
        const std::vector<Color> expected0 = decode(bc1, level0, 8, 8), expected1 = decode(bc1, level1, 4, 4);
        const std::vector<Color> got0 = drawn(*texture, 8, 8), got1 = drawn(*texture, 4, 4);
        int transparent = 0;
        for (std::size_t i = 0; i < got0.size(); ++i) {
            EXPECT_LE(maxChannelDifference(got0[i], expected0[i]), kTolerance) << "level 0 texel " << i;
            transparent += expected0[i].A == 0;
        }
        for (std::size_t i = 0; i < got1.size(); ++i) EXPECT_LE(maxChannelDifference(got1[i], expected1[i]), kTolerance) << "level 1 texel " << i;
        if (bc1) {
            EXPECT_GT(transparent, 0) << "no BC1 block used its transparent black";
        }

        // The default (Color) decodes the same file: texels equal the blocks decoded here.
        auto colour = TextureProcessor().Load(device(), path);
        EXPECT_EQ(colour->Format(), SurfaceFormat::Color);
        std::vector<Color> texels(64);
        colour->GetData(texels.data(), texels.size());
        EXPECT_EQ(texels, expected0);
        // Texture2D::FromFile, like XNA's FromStream, never returns a compressed texture.
        EXPECT_EQ(Texture2D::FromFile(device(), path)->Format(), SurfaceFormat::Color);
    }
}

// Colour keying does not reach a compressed file's blocks (MonoGame's processor returns compressed
// input as it is): a DXT1 block of pure magenta stays magenta under NoChange with keying on.
TEST_F(DxtTextureFormat, NoChangeDoesNotKeyOrPremultiplyBlocks) {
    std::vector<std::uint8_t> file = ddsHeader(4, 4, 1, "DXT1");
    const std::uint8_t magenta[8] = {0x1F, 0xF8, 0x00, 0x00, 0, 0, 0, 0};  // c0 = 0xF81F > c1: four-colour, all index 0
    file.insert(file.end(), magenta, magenta + 8);
    TextureProcessor noChange;
    noChange.TextureFormat = TextureProcessorOutputFormat::NoChange;
    ASSERT_TRUE(noChange.ColorKeyEnabled && noChange.PremultiplyAlpha);
    auto texture = noChange.Load(device(), write("magenta.dds", file));
    EXPECT_EQ(levelBytes(*texture, 0), std::vector<std::uint8_t>(magenta, magenta + 8));
    for (const Color& c : drawn(*texture, 4, 4)) EXPECT_EQ(c, Color(255, 0, 255, 255));
}

// A DXT1 cube map under NoChange stays Dxt1, each face's blocks as stored.
TEST_F(DxtTextureFormat, NoChangeKeepsACubesBlocks) {
    std::vector<std::uint8_t> file = ddsHeader(4, 4, 1, "DXT1", true);
    const std::vector<std::uint8_t> faces = blocksFor(true, 6, 23u);
    file.insert(file.end(), faces.begin(), faces.end());
    const std::string path = write("sky.dds", file);
    TextureProcessor noChange;
    noChange.TextureFormat = TextureProcessorOutputFormat::NoChange;
    auto cube = noChange.LoadCube(device(), path);
    EXPECT_EQ(cube->Format(), SurfaceFormat::Dxt1);
    for (int face = 0; face < 6; ++face) {
        std::vector<std::uint8_t> got(8);
        cube->GetData(CubeMapFace(face), got.data(), got.size());
        EXPECT_EQ(got, std::vector<std::uint8_t>(faces.begin() + face * 8, faces.begin() + face * 8 + 8)) << "face " << face;
    }
    EXPECT_EQ(TextureProcessor().LoadCube(device(), path)->Format(), SurfaceFormat::Color);
}

// DxtCompressed on PNGs (16x8 gradients along x, so each 4x4 block's colours lie on one line, as BC1's
// palette is): an opaque image becomes Dxt1, one with fractional alpha Dxt5. Bound on the decoded
// texels, per channel: 8 for colour (a 5-bit endpoint channel is one of 32 levels 8.2 apart, so
// quantising it alone may move it 4; the interpolated palette entries round again) and 4 for BC3
// alpha (8-bit endpoints, six interpolated steps of at most 10 across a block here, halved, plus
// rounding). The processor's other steps are off (None()) so the source is the oracle.
TEST_F(DxtTextureFormat, DxtCompressedPicksDxt1OrDxt5AndStaysNearTheSource) {
    const int w = 16, h = 8;
    for (bool withAlpha : {false, true}) {
        SCOPED_TRACE(withAlpha ? "alpha" : "opaque");
        std::vector<Color> source;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                source.push_back(Color(20 + 14 * x, 200 - 12 * x, 60 + 3 * x + 20 * (y / 4), withAlpha ? 40 + 10 * x + 3 * y : 255));
        const std::string path = writePng(withAlpha ? "alpha.png" : "opaque.png", w, h, source);
        TextureProcessor dxt = TextureProcessor::None();
        dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
        auto texture = dxt.Load(device(), path);
        ASSERT_EQ(texture->Format(), withAlpha ? SurfaceFormat::Dxt5 : SurfaceFormat::Dxt1);
        ASSERT_EQ(texture->Width(), w);
        const std::vector<Color> decoded = decode(!withAlpha, levelBytes(*texture, 0), w, h);
        for (std::size_t i = 0; i < source.size(); ++i) {
            const Color s = source[i], d = decoded[i];
            EXPECT_LE(std::max({std::abs(s.R - d.R), std::abs(s.G - d.G), std::abs(s.B - d.B)}), 8) << "texel " << i;
            EXPECT_LE(std::abs(s.A - d.A), withAlpha ? 4 : 0) << "texel " << i;
        }
    }
}

// XNA's rule is about fractional alpha: alpha only 0 or 255 (here magenta keyed out by the default
// processor) is Dxt1, its keyed texels BC1's transparent black; mip levels are compressed too.
TEST_F(DxtTextureFormat, DxtCompressedKeyedImageIsDxt1WithTransparentBlack) {
    const int w = 8, h = 8;
    std::vector<Color> source;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) source.push_back((x + y) % 5 == 0 ? Color(255, 0, 255, 255) : Color(30 + 20 * x, 90, 200 - 20 * x, 255));
    const std::string path = writePng("keyed.png", w, h, source);
    TextureProcessor dxt;  // XNA's defaults: magenta keyed, premultiplied
    dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
    dxt.GenerateMipmaps = true;
    auto texture = dxt.Load(device(), path);
    ASSERT_EQ(texture->Format(), SurfaceFormat::Dxt5) << "mip averages of keyed texels have fractional alpha";

    dxt.GenerateMipmaps = false;
    texture = dxt.Load(device(), path);
    ASSERT_EQ(texture->Format(), SurfaceFormat::Dxt1);
    const std::vector<Color> decoded = decode(true, levelBytes(*texture, 0), w, h);
    for (std::size_t i = 0; i < source.size(); ++i) {
        if (source[i] == Color(255, 0, 255, 255)) {
            EXPECT_EQ(decoded[i], Color(0, 0, 0, 0)) << "texel " << i;
        } else {
            EXPECT_EQ(decoded[i].A, 255) << "texel " << i;
            EXPECT_LE(maxChannelDifference(decoded[i], source[i]), 16) << "texel " << i;  // three-colour mode: one midpoint only
        }
    }
}

// Mip levels under DxtCompressed: each level compressed, its texels near the 2x2 averages of the
// level above (the processor's rounded means; the bound of level 0).
TEST_F(DxtTextureFormat, DxtCompressedMipLevelsAreCompressed) {
    const int w = 8, h = 8;
    std::vector<Color> source;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) source.push_back(Color(10 + 30 * x, 50, 100, 255));
    TextureProcessor dxt = TextureProcessor::None();
    dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
    dxt.GenerateMipmaps = true;
    auto texture = dxt.Load(device(), writePng("ramp.png", w, h, source));
    ASSERT_EQ(texture->Format(), SurfaceFormat::Dxt1);
    ASSERT_EQ(texture->LevelCount(), 4);
    const std::vector<Color> level1 = decode(true, levelBytes(*texture, 1), 4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const int r = (10 + 30 * (2 * x) + 10 + 30 * (2 * x + 1) + 1) / 2;
            EXPECT_LE(maxChannelDifference(level1[std::size_t(y * 4 + x)], Color(r, 50, 100, 255)), 8) << x << "," << y;
        }
    EXPECT_EQ(levelBytes(*texture, 3).size(), 8u);  // 1x1: one block
}

// DxtCompressed on .dds files: a DXT5 file keeps its blocks as stored (no second compression); an
// uncompressed A8R8G8B8 file is compressed from its texels (opaque: Dxt1, within the BC1 bound).
TEST_F(DxtTextureFormat, DxtCompressedKeepsDxtFilesAndCompressesUncompressedOnes) {
    TextureProcessor dxt;
    dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
    std::vector<std::uint8_t> five = ddsHeader(4, 4, 1, "DXT5");
    const std::vector<std::uint8_t> block = blocksFor(false, 1, 19u);
    five.insert(five.end(), block.begin(), block.end());
    auto kept = dxt.Load(device(), write("five.dds", five));
    EXPECT_EQ(kept->Format(), SurfaceFormat::Dxt5);
    EXPECT_EQ(levelBytes(*kept, 0), block);

    std::vector<std::uint8_t> argb = ddsHeader(4, 4, 1, "DXT1");
    put32(argb, 80, 0x41), put32(argb, 84, 0), put32(argb, 88, 32);  // DDPF_RGB | DDPF_ALPHAPIXELS, 32 bits
    put32(argb, 92, 0xFF0000), put32(argb, 96, 0xFF00), put32(argb, 100, 0xFF), put32(argb, 104, 0xFF000000u);
    std::vector<Color> source;
    for (int i = 0; i < 16; ++i) {
        source.push_back(Color(40 + 50 * (i % 4), 120, 220 - 50 * (i % 4), 255));
        for (std::uint8_t byte : {source.back().B, source.back().G, source.back().R, source.back().A}) argb.push_back(byte);
    }
    auto compressed = dxt.Load(device(), write("argb.dds", argb));
    ASSERT_EQ(compressed->Format(), SurfaceFormat::Dxt1);
    const std::vector<Color> decoded = decode(true, levelBytes(*compressed, 0), 4, 4);
    for (std::size_t i = 0; i < 16; ++i) EXPECT_LE(maxChannelDifference(decoded[i], source[i]), 8) << "texel " << i;
}

// A size that is not a multiple of 4 cannot be block-compressed: refused, naming the file and size.
TEST_F(DxtTextureFormat, DxtCompressedRefusesSizesNotMultiplesOfFour) {
    const std::string path = writePng("odd.png", 6, 4, std::vector<Color>(24, Color(10, 20, 30, 255)));
    TextureProcessor dxt;
    dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
    try {
        dxt.Load(device(), path);
        ADD_FAILURE() << "6x4 compressed";
    } catch (const ArgumentError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find("multiples of 4"), std::string::npos) << what;
        EXPECT_NE(what.find("6x4"), std::string::npos) << what;
    }
    dxt.ResizeToPowerOfTwo = true;  // 8x4: compresses
    EXPECT_EQ(dxt.Load(device(), path)->Format(), SurfaceFormat::Dxt1);
    // NoChange on an image: Color, as XNA's importer gives Color bitmaps.
    dxt.TextureFormat = TextureProcessorOutputFormat::NoChange;
    EXPECT_EQ(dxt.Load(device(), path)->Format(), SurfaceFormat::Color);
}

}  // namespace
}  // namespace fxport
