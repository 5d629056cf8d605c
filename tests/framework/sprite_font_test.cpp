// SpriteFont from real font files (runtime/framework sprite_font_import.h): sizes measured against
// stb_truetype metrics computed here in double, glyph pixels against stb_truetype's own glyph bitmap
// placed where XNA places it (pen + A + cropping.X, cropping.Y) and sampled bilinearly on the CPU,
// a BMFont written by the test, and .spritefont descriptions (FontName through fontconfig).
// The TrueType font is DejaVu Sans from Debian's fonts-dejavu-core.
#include <stb_truetype.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/framework.h"
#include "fxport/framework/sprite_font_import.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

GraphicsDevice& device() {
    static GraphicsDevice d(PresentationParameters{});
    return d;
}

// stb_truetype's view of the font, in double, independent of the importer.
struct Reference {
    std::vector<unsigned char> bytes;
    stbtt_fontinfo font{};
    double scale = 0;
    int lineSpacing = 0, baseline = 0;

    explicit Reference(double sizePoints) {
        std::ifstream in(kDejaVu, std::ios::binary | std::ios::ate);
        bytes.resize(std::size_t(in.tellg()));
        in.seekg(0);
        in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
        EXPECT_TRUE(stbtt_InitFont(&font, bytes.data(), 0));
        // 1 / unitsPerEm from stb (float), made exact: unitsPerEm is an integer.
        const double unitsPerEm = std::round(1.0 / double(stbtt_ScaleForMappingEmToPixels(&font, 1.0f)));
        scale = sizePoints * 96.0 / 72.0 / unitsPerEm;
        int ascent = 0, descent = 0, gap = 0;
        stbtt_GetFontVMetrics(&font, &ascent, &descent, &gap);
        lineSpacing = int(std::lround((ascent - descent + gap) * scale));
        baseline = int(std::lround(ascent * scale));
    }
    double advance(char c) const {
        int a = 0, lsb = 0;
        stbtt_GetCodepointHMetrics(&font, c, &a, &lsb);
        return a * scale;
    }
    int left(char c) const {
        int x0, y0, x1, y1;
        stbtt_GetCodepointBitmapBox(&font, c, float(scale), float(scale), &x0, &y0, &x1, &y1);
        return x0;
    }
    // XNA's MeasureString width of one line: the first glyph's A clamped at 0, then A+B+C per glyph
    // (= its advance), Spacing between glyphs.
    double lineWidth(const std::string& line, double spacing) const {
        double width = 0;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const double a = left(line[i]);
            width += (i == 0 ? std::max(a, 0.0) - a : spacing) + advance(line[i]);
        }
        return width;
    }
};

TEST(SpriteFontImport, TrueTypeMeasuresAsXnaWithStbMetrics) {
    FontDescription description;
    description.Size = 14;
    auto font = BuildSpriteFont(device(), kDejaVu, description);
    const Reference ref(14);
    EXPECT_EQ(font->LineSpacing, ref.lineSpacing);
    EXPECT_EQ(font->Characters().size(), std::size_t('~' - ' ' + 1));
    for (const std::string text : {"Hello, World", "j", "AVAVA", "fxport 0.1"}) {
        const Vector2 size = font->MeasureString(text);
        EXPECT_NEAR(size.X, ref.lineWidth(text, 0), 1e-3) << text;
        EXPECT_EQ(size.Y, float(ref.lineSpacing)) << text;
    }
    // Lines: the widest line, LineSpacing per line.
    const Vector2 two = font->MeasureString("Hi\nWorld!!\n");
    EXPECT_NEAR(two.X, std::max(ref.lineWidth("Hi", 0), ref.lineWidth("World!!", 0)), 1e-3);
    EXPECT_EQ(two.Y, float(3 * ref.lineSpacing));
    // Spacing between characters, not after the last one.
    font->Spacing = 2.5f;
    EXPECT_NEAR(font->MeasureString("Hello").X, ref.lineWidth("Hello", 2.5), 1e-3);
}

TEST(SpriteFontImport, TrueTypeGlyphPixelsLandWhereXnaPlacesThem) {
    FontDescription description;
    description.Size = 12;
    auto font = BuildSpriteFont(device(), kDejaVu, description);
    const Reference ref(12);
    const std::string text = "Hd1g";
    const Vector2 position(3.0f, 2.0f);
    const int width = 64, height = 24;

    RenderTarget2D target(device(), width, height, false, SurfaceFormat::Color, DepthFormat::None);
    device().SetRenderTarget(&target);
    device().Clear(Color::Transparent);
    SpriteBatch batch(device());
    batch.Begin();
    batch.DrawString(*font, text, position, Color::White);
    batch.End();
    device().SetRenderTarget(nullptr);
    std::vector<Color> got(std::size_t(width) * height);
    target.GetData(got.data(), got.size());
    if (const char* folder = std::getenv("FXPORT_TEST_OUTPUT")) target.SaveAsPng(std::string(folder) + "/truetype_glyphs.png");

    // Expected coverage: each glyph's stb bitmap at (position.X + pen + A, position.Y + baseline +
    // y0), sampled bilinearly at pixel centres (zero outside the bitmap), premultiplied white
    // composed over transparent black in drawing order.
    std::vector<double> expected(std::size_t(width) * height, 0.0);
    double pen = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        int x0, y0, x1, y1;
        stbtt_GetCodepointBitmapBox(&ref.font, c, float(ref.scale), float(ref.scale), &x0, &y0, &x1, &y1);
        const int w = x1 - x0, h = y1 - y0;
        std::vector<unsigned char> bitmap(std::size_t(w) * h);
        stbtt_MakeCodepointBitmap(&ref.font, bitmap.data(), w, h, w, float(ref.scale), float(ref.scale), c);
        pen += i == 0 ? std::max(0, x0) : x0;
        const double left = position.X + pen, top = position.Y + ref.baseline + y0;
        auto texel = [&](int u, int v) {
            return u < 0 || v < 0 || u >= w || v >= h ? 0.0 : bitmap[std::size_t(v) * w + u] / 255.0;
        };
        for (int py = 0; py < height; ++py) {
            for (int px = 0; px < width; ++px) {
                // Only pixels whose centre lies inside the glyph's quad are drawn.
                const double cu = px + 0.5 - left, cv = py + 0.5 - top;
                if (cu < 0 || cv < 0 || cu >= w || cv >= h) continue;
                const double u = cu - 0.5, v = cv - 0.5;
                const int u0 = int(std::floor(u)), v0 = int(std::floor(v));
                const double fu = u - u0, fv = v - v0;
                const double a = (1 - fu) * (1 - fv) * texel(u0, v0) + fu * (1 - fv) * texel(u0 + 1, v0) +
                                 (1 - fu) * fv * texel(u0, v0 + 1) + fu * fv * texel(u0 + 1, v0 + 1);
                double& d = expected[std::size_t(py) * width + px];
                d = a + d * (1 - a);
            }
        }
        pen += ref.advance(c) - x0;
    }
    auto differences = [&](int shift) {
        int count = 0;
        for (int py = 0; py < height; ++py)
            for (int px = 0; px < width; ++px) {
                const int sx = px - shift;
                const double want = sx < 0 || sx >= width ? 0.0 : expected[std::size_t(py) * width + sx] * 255.0;
                const Color g = got[std::size_t(py) * width + px];
                if (std::abs(g.A - want) > 2.5 || std::abs(g.R - want) > 2.5) {
                    if (shift == 0 && count < 10)
                        ADD_FAILURE() << "pixel (" << px << "," << py << "): got " << int(g.A) << ", expected " << want;
                    ++count;
                }
            }
        return count;
    };
    double ink = 0;
    for (double e : expected) ink += e;
    EXPECT_GT(ink, 20.0);  // the string covers pixels
    EXPECT_EQ(differences(0), 0);
    EXPECT_GT(differences(1), 20);  // a one-pixel shift fails
}

TEST(SpriteFontImport, CharactersTheFontLacksAreLeftOutAndDefaultCharacterStandsIn) {
    FontDescription description;
    description.CharacterRegions = {{U'a', U'c'}, {U'\uE000', U'\uE001'}};  // private use: not in DejaVu Sans
    description.DefaultCharacter = U'b';
    auto font = BuildSpriteFont(device(), kDejaVu, description);
    EXPECT_EQ(font->Characters().size(), 3u);
    EXPECT_FLOAT_EQ(font->MeasureString("zz").X, font->MeasureString("bb").X);
    font->DefaultCharacter.reset();
    EXPECT_THROW(font->MeasureString("z"), ArgumentError);
}

TEST(SpriteFontImport, NotAFontIsAnErrorNamingTheFile) {
    const fs::path bad = fs::temp_directory_path() / ("fxport-notafont-" + std::to_string(::getpid()) + ".ttf");
    std::ofstream(bad) << "plain text, not a font";
    try {
        BuildSpriteFont(device(), bad.string(), FontDescription{});
        ADD_FAILURE() << "text loaded as a font";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
    fs::remove(bad);
}

class FontFiles : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("fxport-fonts-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root);
    }
    void TearDown() override { fs::remove_all(root); }
    void write(const std::string& name, const std::string& text) { std::ofstream(root / name) << text; }
    fs::path root;
};

// A BMFont written here: two glyphs on a 8x4 page with known texels.
TEST_F(FontFiles, BMFontLoadsMeasuresAndDrawsItsTexels) {
    // Page: 'A' at (0,0) 3x4 (texel alpha 40*(x+1)+10*y), 'B' at (4,0) 2x2 opaque.
    Texture2D page(device(), 8, 4, false, SurfaceFormat::Color);
    std::vector<Color> texels(32, Color::Transparent);
    auto alphaA = [](int x, int y) { return 40 * (x + 1) + 10 * y; };
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 3; ++x) texels[std::size_t(y * 8 + x)] = Color(255, 255, 255, alphaA(x, y));
    for (int y = 0; y < 2; ++y)
        for (int x = 4; x < 6; ++x) texels[std::size_t(y * 8 + x)] = Color(255, 255, 255, 255);
    page.SetData(texels);
    page.SaveAsPng((root / "tiny_0.png").string());
    write("Tiny.fnt",
          "info face=\"Tiny\" size=8 bold=0 italic=0 charset=\"\" unicode=1 padding=0,0,0,0 spacing=1,1\n"
          "common lineHeight=7 base=5 scaleW=8 scaleH=4 pages=1 packed=0\n"
          "page id=0 file=\"tiny_0.png\"\n"
          "chars count=2\n"
          "char id=65 x=0 y=0 width=3 height=4 xoffset=1 yoffset=2 xadvance=5 page=0 chnl=15\n"
          "char id=66 x=4 y=0 width=2 height=2 xoffset=0 yoffset=1 xadvance=3 page=0 chnl=15\n");
    ContentManager content(device(), root.string());
    SpriteFont* font = content.Load<SpriteFont>("Tiny");
    EXPECT_EQ(font->LineSpacing, 7);
    // "AB": A's A-width 1 (first glyph, kept), 1+3+1 = 5, then B 0+2+1 = 3.
    EXPECT_TRUE(font->MeasureString("AB") == Vector2(8, 7));
    EXPECT_TRUE(font->MeasureString("BA\nA") == Vector2(8, 14));

    RenderTarget2D target(device(), 16, 12, false, SurfaceFormat::Color, DepthFormat::None);
    device().SetRenderTarget(&target);
    device().Clear(Color::Transparent);
    SpriteBatch batch(device());
    batch.Begin();
    batch.DrawString(*font, "AB", Vector2(2, 1), Color::White);
    batch.End();
    device().SetRenderTarget(nullptr);
    std::vector<Color> got(16 * 12);
    target.GetData(got.data(), got.size());
    // A at (2 + 1, 1 + 2), B at (2 + 5 + 0, 1 + 1); premultiplied page texels.
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 16; ++x) {
            int want = 0;
            if (x >= 3 && x < 6 && y >= 3 && y < 7) want = alphaA(x - 3, y - 3);
            if (x >= 7 && x < 9 && y >= 2 && y < 4) want = 255;
            const Color g = got[std::size_t(y * 16 + x)];
            // Linear filtering at texel centres: llvmpipe's 8-bit filter weights leak up to 1/256 of
            // each neighbour (2 LSB next to an opaque texel).
            EXPECT_NEAR(g.A, want, 2) << "(" << x << "," << y << ")";
            EXPECT_NEAR(g.R, want, 2) << "(" << x << "," << y << ")";
        }
    }
}

TEST_F(FontFiles, BMFontErrorsNameFileAndLine) {
    write("Broken.fnt", "info face=\"x\"\ncommon lineHeight=7 base=5 scaleW=8 scaleH=4 pages=1\nchar id=65 x=zero\n");
    try {
        LoadBMFont(device(), (root / "Broken.fnt").string());
        ADD_FAILURE() << "broken .fnt loaded";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("Broken.fnt(3)"), std::string::npos) << e.what();
    }
}

TEST_F(FontFiles, SpriteFontDescriptionThroughFontconfig) {
    write("Hud.spritefont",
          "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
          "<XnaContent xmlns:Graphics=\"Microsoft.Xna.Framework.Content.Pipeline.Graphics\">\n"
          "  <Asset Type=\"Graphics:FontDescription\">\n"
          "    <!-- <FontName>Not This</FontName> -->\n"
          "    <FontName>DejaVu Sans</FontName>\n"
          "    <Size>10</Size>\n"
          "    <Spacing>1</Spacing>\n"
          "    <UseKerning>true</UseKerning>\n"
          "    <Style>Regular</Style>\n"
          "    <DefaultCharacter>*</DefaultCharacter>\n"
          "    <CharacterRegions>\n"
          "      <CharacterRegion><Start>&#32;</Start><End>&#126;</End></CharacterRegion>\n"
          "      <CharacterRegion><Start>&#xE9;</Start><End>&#233;</End></CharacterRegion>\n"
          "    </CharacterRegions>\n"
          "  </Asset>\n"
          "</XnaContent>\n");
    const FontDescription d = ReadFontDescription((root / "Hud.spritefont").string());
    EXPECT_EQ(d.FontName, "DejaVu Sans");
    EXPECT_EQ(d.Size, 10.0f);
    ASSERT_EQ(d.CharacterRegions.size(), 2u);
    EXPECT_EQ(d.CharacterRegions[1], std::make_pair(U'\u00E9', U'\u00E9'));
    ContentManager content(device(), root.string());
    SpriteFont* font = content.Load<SpriteFont>("Hud");
    const Reference ref(10);  // fontconfig's DejaVu Sans is the same file
    EXPECT_EQ(font->LineSpacing, ref.lineSpacing);
    EXPECT_EQ(font->Spacing, 1.0f);
    EXPECT_EQ(font->DefaultCharacter, std::optional<char32_t>(U'*'));
    EXPECT_EQ(font->Characters().size(), 96u);
    EXPECT_NEAR(font->MeasureString("Hud").X, ref.lineWidth("Hud", 1.0), 1e-3);
}

TEST_F(FontFiles, SpriteFontDescriptionErrorsNameFileAndLine) {
    write("Bad.spritefont", "<XnaContent>\n<Asset>\n<FontName>DejaVu Sans</FontName>\n<Size>big</Size>\n</Asset></XnaContent>\n");
    try {
        ReadFontDescription((root / "Bad.spritefont").string());
        ADD_FAILURE() << "bad Size accepted";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("Bad.spritefont(4)"), std::string::npos) << e.what();
    }
    ContentManager content(device(), root.string());
    try {
        content.Load<SpriteFont>("Bad");
        ADD_FAILURE() << "bad .spritefont loaded";
    } catch (const ContentLoadException& e) {
        EXPECT_NE(std::string(e.what()).find("Load<SpriteFont>(\"Bad\")"), std::string::npos) << e.what();
    }
}

TEST_F(FontFiles, BareTrueTypeAssetUsesTheTemplateDefaults) {
    fs::copy_file(kDejaVu, root / "Body.ttf");
    ContentManager content(device(), root.string());
    SpriteFont* font = content.Load<SpriteFont>("Body");
    EXPECT_EQ(font->LineSpacing, Reference(14).lineSpacing);
    EXPECT_EQ(font->Characters().size(), std::size_t('~' - ' ' + 1));
    EXPECT_EQ(content.Load<SpriteFont>("Body"), font);
}

}  // namespace
}  // namespace fxport
