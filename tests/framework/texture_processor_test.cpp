// fxport::TextureProcessor (XNA's content-pipeline texture processing) and ContentManager applying
// it: every expectation is XNA's rule computed here by hand (colour key, round(v * a / 255),
// bilinear at texel centres, 2x2 rounded averages), never the processor's own output.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

TEST(TextureProcessor, DefaultsAreXnasKeyMagentaAndPremultiplyNoMipsNoResize) {
    TextureProcessor p;
    EXPECT_TRUE(p.ColorKeyEnabled);
    EXPECT_TRUE(p.ColorKeyColor == Color(255, 0, 255, 255));
    EXPECT_TRUE(p.PremultiplyAlpha);
    EXPECT_FALSE(p.GenerateMipmaps);
    EXPECT_FALSE(p.ResizeToPowerOfTwo);
}

TEST(TextureProcessor, KeysOutExactMagentaOnlyThenPremultipliesWithRounding) {
    // magenta -> transparent black; near-magenta and magenta with another alpha stay (then premultiplied).
    std::vector<Color> in = {Color(255, 0, 255, 255), Color(254, 0, 255, 255), Color(255, 0, 255, 128),
                             Color(200, 100, 51, 128), Color(1, 128, 255, 1)};
    TextureProcessor::Output out = TextureProcessor().Process(in, 5, 1);
    ASSERT_EQ(out.levels.size(), 1u);
    const std::vector<Color>& o = out.levels[0];
    EXPECT_TRUE(o[0] == Color(0, 0, 0, 0));
    EXPECT_TRUE(o[1] == Color(254, 0, 255, 255));
    EXPECT_TRUE(o[2] == Color(128, 0, 128, 128));       // 255*128/255 = 128
    EXPECT_TRUE(o[3] == Color(100, 50, 26, 128));        // 100.39 -> 100, 50.2 -> 50, 25.6 -> 26
    EXPECT_TRUE(o[4] == Color(0, 1, 1, 1));              // 0.0039 -> 0, 0.502 -> 1, 1 -> 1
}

TEST(TextureProcessor, NoneLeavesPixelsAsTheFileHasThem) {
    std::vector<Color> in = {Color(255, 0, 255, 255), Color(200, 100, 51, 128)};
    TextureProcessor::Output out = TextureProcessor::None().Process(in, 2, 1);
    EXPECT_TRUE(out.levels[0] == in);
}

TEST(TextureProcessor, MipChainIsRounded2x2AveragesDownToOneTexel) {
    TextureProcessor p = TextureProcessor::None();
    p.GenerateMipmaps = true;
    std::vector<Color> in = {Color(0, 0, 0, 255), Color(255, 0, 0, 255), Color(0, 0, 0, 255), Color(0, 0, 0, 255),
                             Color(0, 0, 0, 255), Color(0, 0, 0, 255), Color(0, 0, 0, 255), Color(0, 0, 0, 255)};  // 4x2
    TextureProcessor::Output out = p.Process(in, 4, 2);
    ASSERT_EQ(out.levels.size(), 3u);  // 4x2, 2x1, 1x1
    ASSERT_EQ(out.levels[1].size(), 2u);
    EXPECT_TRUE(out.levels[1][0] == Color(64, 0, 0, 255));  // (255 + 2) / 4 = 64
    EXPECT_TRUE(out.levels[1][1] == Color(0, 0, 0, 255));
    ASSERT_EQ(out.levels[2].size(), 1u);
    EXPECT_TRUE(out.levels[2][0] == Color(32, 0, 0, 255));  // a 2x1 level: (64 + 64 + 0 + 0 + 2) / 4
}

TEST(TextureProcessor, ResizesToPowersOfTwoBilinearlyAtTexelCentres) {
    TextureProcessor p = TextureProcessor::None();
    p.ResizeToPowerOfTwo = true;
    std::vector<Color> in = {Color(0, 0, 0, 255), Color(90, 0, 0, 255), Color(180, 0, 0, 255)};  // 3x1 -> 4x1
    TextureProcessor::Output out = p.Process(in, 3, 1);
    ASSERT_EQ(out.width, 4);
    ASSERT_EQ(out.height, 1);
    // destination x maps to source (x + 0.5) * 3 / 4 - 0.5: -0.125 (clamped 0), 0.625, 1.375, 2.125 (clamped)
    const int expected[4] = {0, 56, 124, 180};  // 0; 90*0.625 = 56.25; 90 + 90*0.375 = 123.75; 180
    for (int x = 0; x < 4; ++x) EXPECT_EQ(int(out.levels[0][std::size_t(x)].R), expected[x]) << x;
}

TEST(TextureProcessor, RefusesAPixelCountThatIsNotTheSize) {
    EXPECT_THROW(TextureProcessor().Process(std::vector<Color>(5), 2, 2), ArgumentError);
}

class TextureProcessorContent : public ::testing::Test {
protected:
    static GraphicsDevice& device() {
        static GraphicsDevice d(PresentationParameters{});
        return d;
    }
    void SetUp() override {
        root = fs::temp_directory_path() / ("fxport-texproc-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root);
        Texture2D texture(device(), 2, 1, false, SurfaceFormat::Color);
        const Color texels[2] = {Color(255, 0, 255, 255), Color(200, 100, 51, 128)};
        texture.SetData(texels, 2);
        texture.SaveAsPng((root / "Sprite.png").string());
    }
    void TearDown() override { fs::remove_all(root); }
    fs::path root;
};

TEST_F(TextureProcessorContent, ContentLoadAppliesXnasDefaultsAndPerAssetSettings) {
    ContentManager content(device(), root.string());
    Color texels[2];
    content.Load<Texture2D>("Sprite")->GetData(texels, 2);
    EXPECT_TRUE(texels[0] == Color(0, 0, 0, 0));
    EXPECT_TRUE(texels[1] == Color(100, 50, 26, 128));
    EXPECT_THROW(content.SetTextureProcessor("Sprite", TextureProcessor::None()), InvalidOperation);

    ContentManager raw(device(), root.string());
    raw.SetTextureProcessor("Sprite", TextureProcessor::None());
    raw.Load<Texture2D>("Sprite")->GetData(texels, 2);
    EXPECT_TRUE(texels[0] == Color(255, 0, 255, 255));
    EXPECT_TRUE(texels[1] == Color(200, 100, 51, 128));

    ContentManager mips(device(), root.string());
    mips.textureProcessor.GenerateMipmaps = true;
    EXPECT_EQ(mips.Load<Texture2D>("Sprite")->LevelCount(), 2);
}

// The per-asset processor carries XNA's TextureFormat: NoChange keeps a DXT1 .dds's blocks (a
// texture and a cube map), DxtCompressed refuses the 2x1 sprite naming the asset (4x4 blocks), and
// the default (Color) decodes. The block bytes are the file's own; the sizes are D3D's BC1 layout.
TEST_F(TextureProcessorContent, PerAssetTextureFormat) {
    auto header = [](bool cube) {
        std::vector<std::uint8_t> h(128, 0);
        auto put = [&](std::size_t at, std::uint32_t v) {
            for (int k = 0; k < 4; ++k) h[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
        };
        h[0] = 'D', h[1] = 'D', h[2] = 'S', h[3] = ' ';
        put(4, 124), put(8, 0x1007), put(12, 4), put(16, 4), put(28, 1), put(76, 32), put(80, 0x4);
        h[84] = 'D', h[85] = 'X', h[86] = 'T', h[87] = '1';
        put(108, cube ? 0x1008 : 0x1000);
        if (cube) put(112, 0xFE00);
        return h;
    };
    const std::vector<std::uint8_t> block = {0x00, 0xF8, 0x1F, 0x00, 0xE4, 0x1B, 0x4E, 0xB1};  // red, blue, four-colour mode
    for (bool cube : {false, true}) {
        std::vector<std::uint8_t> file = header(cube);
        for (int face = 0; face < (cube ? 6 : 1); ++face) file.insert(file.end(), block.begin(), block.end());
        std::ofstream(root / (cube ? "Sky.dds" : "Wall.dds"), std::ios::binary)
            .write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
    }
    TextureProcessor noChange;
    noChange.TextureFormat = TextureProcessorOutputFormat::NoChange;
    ContentManager content(device(), root.string());
    content.SetTextureProcessor("Wall", noChange);
    content.SetTextureProcessor("Sky", noChange);
    Texture2D* wall = content.Load<Texture2D>("Wall");
    EXPECT_EQ(wall->Format(), SurfaceFormat::Dxt1);
    EXPECT_EQ(wall->GetData<std::uint8_t>(), block);
    TextureCube* sky = content.Load<TextureCube>("Sky");
    EXPECT_EQ(sky->Format(), SurfaceFormat::Dxt1);
    std::vector<std::uint8_t> face(8);
    sky->GetData(CubeMapFace::NegativeZ, face.data(), face.size());
    EXPECT_EQ(face, block);
    EXPECT_THROW(content.SetTextureProcessor("Sky", TextureProcessor()), InvalidOperation);

    ContentManager decoded(device(), root.string());
    EXPECT_EQ(decoded.Load<Texture2D>("Wall")->Format(), SurfaceFormat::Color);
    EXPECT_EQ(decoded.Load<TextureCube>("Sky")->Format(), SurfaceFormat::Color);

    TextureProcessor dxt;
    dxt.TextureFormat = TextureProcessorOutputFormat::DxtCompressed;
    decoded.SetTextureProcessor("Sprite", dxt);
    try {
        decoded.Load<Texture2D>("Sprite");
        ADD_FAILURE() << "a 2x1 image compressed";
    } catch (const ContentLoadException& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("Load<Texture2D>(\"Sprite\")"), std::string::npos) << what;
        EXPECT_NE(what.find("multiples of 4"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace fxport
