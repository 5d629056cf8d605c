// SpriteBatch and SpriteFont, rendered headless (OSMesa) into small render targets and checked
// pixel by pixel against placements computed here from XNA's rules (never from the code under test):
// a sprite at Rectangle(x, y, w, h) covers pixels x..x+w-1, y..y+h-1 and texel (i, j) lands on
// pixel (x+i, y+j); flips, rotation, scale, source rectangles, tint, premultiplied blending,
// batching counts, sort orders, custom pixel-shader-only effects, text layout and misuse errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/sprite_font.h"

#ifdef FXPORT_LSAN_SUPPRESSIONS
// Sanitizer builds: suppress what Mesa keeps until exit (lsan.supp lists Mesa and fontconfig only).
// LSAN_OPTIONS in the environment still takes precedence.
extern "C" const char* __lsan_default_options() {
    return "suppressions=" FXPORT_LSAN_SUPPRESSIONS ":print_suppressions=0";
}
#endif

namespace fxport {
namespace {

std::string str(Color c) {
    std::ostringstream out;
    out << "(" << int(c.R) << "," << int(c.G) << "," << int(c.B) << "," << int(c.A) << ")";
    return out.str();
}

bool near(Color a, Color b, int tolerance) {
    return std::abs(int(a.R) - int(b.R)) <= tolerance && std::abs(int(a.G) - int(b.G)) <= tolerance &&
           std::abs(int(a.B) - int(b.B)) <= tolerance && std::abs(int(a.A) - int(b.A)) <= tolerance;
}

// A w x h image, row-major, top row first (as render targets come back).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;
    Color at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Compares every pixel with `expected(x, y)`; lists the first mismatches and the whole picture.
::testing::AssertionResult matches(const Image& image, const std::function<Color(int, int)>& expected,
                                   int tolerance = 0) {
    std::ostringstream failures;
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Color want = expected(x, y);
            const Color got = image.at(x, y);
            if (!near(got, want, tolerance)) {
                if (count < 12) {
                    failures << "\n  pixel (" << x << "," << y << "): got " << str(got) << ", expected " << str(want);
                }
                ++count;
            }
        }
    }
    if (count == 0) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << count << " pixel(s) differ (tolerance " << tolerance << "):"
                                         << failures.str();
}

// The 4x5 test texture: every texel a different opaque colour.
constexpr int kTexW = 4;
constexpr int kTexH = 5;
Color texel(int i, int j) { return Color(30 + 50 * i, 20 + 45 * j, 100 + 10 * i + 25 * j, 255); }

const Color kBackground(10, 20, 30, 255);

class SpriteBatchTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        PresentationParameters parameters;
        parameters.BackBufferWidth = 64;
        parameters.BackBufferHeight = 64;
        device_ = std::make_unique<GraphicsDevice>(parameters);
    }
    static void TearDownTestSuite() { device_.reset(); }

    void SetUp() override { batch = std::make_unique<SpriteBatch>(*device_); }
    void TearDown() override { batch.reset(); }

    static GraphicsDevice& device() { return *device_; }

    static std::unique_ptr<Texture2D> makeTexture(int w, int h, const std::function<Color(int, int)>& fill) {
        auto texture = std::make_unique<Texture2D>(device(), w, h, false, SurfaceFormat::Color);
        std::vector<Color> data(std::size_t(w) * std::size_t(h));
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                data[std::size_t(j) * std::size_t(w) + std::size_t(i)] = fill(i, j);
            }
        }
        texture->SetData(data);
        return texture;
    }
    static std::unique_ptr<Texture2D> makeTestTexture() { return makeTexture(kTexW, kTexH, texel); }

    // Clears a w x h Color target to `clear`, runs `draw`, reads the target back. The target is
    // handed out through `keepTarget` when given, else destroyed.
    static Image render(int w, int h, Color clear, const std::function<void()>& draw,
                        std::unique_ptr<RenderTarget2D>* keepTarget = nullptr) {
        auto target = std::make_unique<RenderTarget2D>(device(), w, h, false, SurfaceFormat::Color);
        device().SetRenderTarget(*target);
        device().Clear(clear);
        draw();
        device().SetRenderTarget(nullptr);
        Image image{w, h, target->GetData<Color>()};
        if (keepTarget != nullptr) {
            *keepTarget = std::move(target);
        }
        return image;
    }

    // Expected image of one unrotated sprite: inside `area`, `inside(i, j)` of the texel offsets.
    static std::function<Color(int, int)> spriteAt(Rectangle area, std::function<Color(int, int)> inside,
                                                   Color outside = kBackground) {
        return [=](int x, int y) { return area.Contains(x, y) ? inside(x - area.X, y - area.Y) : outside; };
    }

    static std::unique_ptr<GraphicsDevice> device_;
    std::unique_ptr<SpriteBatch> batch;
};

std::unique_ptr<GraphicsDevice> SpriteBatchTest::device_;

// --- (1) placement -------------------------------------------------------------------------------

TEST_F(SpriteBatchTest, DestinationRectangleIsPixelExactWithPointSampling) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), texel)));
}

TEST_F(SpriteBatchTest, PositionIsPixelExactWithPointSampling) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Vector2(3, 2), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), texel)));
}

// Default Begin(): AlphaBlend + LinearClamp. An opaque sprite at scale 1 samples texel centres
// exactly, so linear filtering gives the texels too (off by half a pixel it would average them).
TEST_F(SpriteBatchTest, DefaultBeginSamplesTexelCentresWithLinearFiltering) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin();
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), texel), 1));
}

TEST_F(SpriteBatchTest, TransformMatrixMovesSprites) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr, nullptr,
                     Matrix::CreateTranslation(2, 1, 0));
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(5, 3, 4, 5), texel)));
}

// Sprite coordinates are relative to the viewport, as in XNA.
TEST_F(SpriteBatchTest, SpritesAreRelativeToTheViewport) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        device().Viewport = Viewport(4, 2, 8, 6);
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Rectangle(0, 0, 4, 5), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(4, 2, 4, 5), texel)));
}

// --- (2) source rectangles, scale, origin, rotation ------------------------------------------------

TEST_F(SpriteBatchTest, SourceRectangleSelectsTexels) {
    auto texture = makeTestTexture();
    const Rectangle source(1, 2, 2, 3);
    auto expected = spriteAt(Rectangle(5, 4, 2, 3), [](int i, int j) { return texel(1 + i, 2 + j); });
    const Image byRectangle = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Rectangle(5, 4, 2, 3), source, Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(byRectangle, expected));
    const Image byPosition = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Vector2(5, 4), &source, Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(byPosition, expected));
}

TEST_F(SpriteBatchTest, ScaleRepeatsEachTexel) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Vector2(3, 2), nullptr, Color::White, 0.0f, Vector2::Zero, 2.0f, SpriteEffects::None, 0);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 8, 10), [](int x, int y) { return texel(x / 2, y / 2); })));
}

TEST_F(SpriteBatchTest, OriginIsSubtractedFromThePosition) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Vector2(5, 4), nullptr, Color::White, 0.0f, Vector2(2, 2), 1.0f, SpriteEffects::None, 0);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), texel)));
}

// Rotation by +90 degrees turns clockwise on screen (y down): the offset (dx, dy) from the position
// goes to (-dy, dx), so texel (i, j) lands on pixel (X - 1 - j, Y + i).
TEST_F(SpriteBatchTest, RotationIsClockwiseOnScreen) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Vector2(8, 2), nullptr, Color::White, MathHelper::PiOver2, Vector2::Zero, 1.0f,
                    SpriteEffects::None, 0);
        batch->End();
    });
    EXPECT_TRUE(matches(image, [](int x, int y) {
        const int i = y - 2;
        const int j = 7 - x;
        return (i >= 0 && i < kTexW && j >= 0 && j < kTexH) ? texel(i, j) : kBackground;
    }));
}

// --- (3) flips -------------------------------------------------------------------------------------

TEST_F(SpriteBatchTest, FlipsMirrorTheTexture) {
    auto texture = makeTestTexture();
    const Rectangle area(3, 2, 4, 5);
    auto drawFlipped = [&](SpriteEffects effects) {
        return render(16, 12, kBackground, [&] {
            batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
            batch->Draw(*texture, area, nullptr, Color::White, 0.0f, Vector2::Zero, effects, 0.0f);
            batch->End();
        });
    };
    EXPECT_TRUE(matches(drawFlipped(SpriteEffects::FlipHorizontally),
                        spriteAt(area, [](int i, int j) { return texel(kTexW - 1 - i, j); })));
    EXPECT_TRUE(matches(drawFlipped(SpriteEffects::FlipVertically),
                        spriteAt(area, [](int i, int j) { return texel(i, kTexH - 1 - j); })));
    EXPECT_TRUE(matches(drawFlipped(SpriteEffects::FlipHorizontally | SpriteEffects::FlipVertically),
                        spriteAt(area, [](int i, int j) { return texel(kTexW - 1 - i, kTexH - 1 - j); })));
}

// --- (4) tint --------------------------------------------------------------------------------------

TEST_F(SpriteBatchTest, ColourTintMultipliesTexels) {
    auto white = makeTexture(kTexW, kTexH, [](int, int) { return Color::White; });
    auto texture = makeTestTexture();
    const Color tint(255, 128, 0);
    const Image onWhite = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*white, Rectangle(3, 2, 4, 5), tint);
        batch->End();
    });
    EXPECT_TRUE(matches(onWhite, spriteAt(Rectangle(3, 2, 4, 5), [&](int, int) { return tint; }), 1));

    const Image onTexels = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), tint);
        batch->End();
    });
    auto times = [](int a, int b) { return int(std::lround(a * b / 255.0)); };
    EXPECT_TRUE(matches(onTexels, spriteAt(Rectangle(3, 2, 4, 5), [&](int i, int j) {
                            const Color t = texel(i, j);
                            return Color(times(t.R, tint.R), times(t.G, tint.G), times(t.B, tint.B),
                                         times(t.A, tint.A));
                        }),
                        1));
}

// --- (5) blending ----------------------------------------------------------------------------------

// BlendState::AlphaBlend is premultiplied: result = src + dst * (1 - src.a).
TEST_F(SpriteBatchTest, AlphaBlendIsPremultiplied) {
    const Color source(128, 0, 0, 128);  // 50% red, premultiplied
    const Color background(0, 60, 200, 255);
    auto texture = makeTexture(kTexW, kTexH, [&](int, int) { return source; });
    const Image image = render(16, 12, background, [&] {
        batch->Begin();  // AlphaBlend
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->End();
    });
    const double inverseAlpha = 1.0 - source.A / 255.0;
    auto blend = [&](int s, int d) { return int(std::lround(s + d * inverseAlpha)); };
    const Color blended(blend(source.R, background.R), blend(source.G, background.G), blend(source.B, background.B),
                        blend(source.A, background.A));
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), [&](int, int) { return blended; }, background), 1));
}

// --- (6) batching and sorting ----------------------------------------------------------------------

TEST_F(SpriteBatchTest, HundredSpritesOfOneTextureAreOneDrawCall) {
    auto texture = makeTestTexture();
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        for (int y = 0; y < 10; ++y) {
            for (int x = 0; x < 10; ++x) {
                batch->Draw(*texture, Rectangle(x, y, 1, 1), Rectangle(x % kTexW, y % kTexH, 1, 1), Color::White);
            }
        }
        batch->End();
    });
    EXPECT_EQ(batch->drawCallsLastEnd(), 1);
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(0, 0, 10, 10),
                                        [](int x, int y) { return texel(x % kTexW, y % kTexH); })));
}

TEST_F(SpriteBatchTest, DrawCallsFollowTextureRunsAndSortMode) {
    auto a = makeTexture(1, 1, [](int, int) { return Color::Red; });
    auto b = makeTexture(1, 1, [](int, int) { return Color::Blue; });
    auto drawAlternating = [&](SpriteSortMode mode) {
        return render(16, 12, kBackground, [&] {
            batch->Begin(mode, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
            for (int k = 0; k < 10; ++k) {
                batch->Draw(k % 2 == 0 ? *a : *b, Rectangle(k, 0, 1, 1), Color::White);
            }
            batch->End();
        });
    };
    auto expected = [](int x, int y) {
        return (y == 0 && x < 10) ? (x % 2 == 0 ? Color::Red : Color::Blue) : kBackground;
    };

    EXPECT_TRUE(matches(drawAlternating(SpriteSortMode::Deferred), expected));
    EXPECT_EQ(batch->drawCallsLastEnd(), 10) << "Deferred: one draw per run of the same texture";
    EXPECT_TRUE(matches(drawAlternating(SpriteSortMode::Texture), expected));
    EXPECT_EQ(batch->drawCallsLastEnd(), 2) << "Texture: grouped by texture";
    EXPECT_TRUE(matches(drawAlternating(SpriteSortMode::Immediate), expected));
    EXPECT_EQ(batch->drawCallsLastEnd(), 10) << "Immediate: one draw per sprite";

    render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Immediate, BlendState::Opaque);
        for (int k = 0; k < 3; ++k) {
            batch->Draw(*a, Rectangle(k, 0, 1, 1), Color::White);
        }
        batch->End();
    });
    EXPECT_EQ(batch->drawCallsLastEnd(), 3) << "Immediate draws each sprite, even with one texture";

    batch->Begin();
    batch->End();
    EXPECT_EQ(batch->drawCallsLastEnd(), 0);
}

TEST_F(SpriteBatchTest, LargeBatchesAreSplit) {
    auto texture = makeTexture(1, 1, [](int, int) { return Color::White; });
    const int count = SpriteBatch::kMaxBatchSize + 100;
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        for (int k = 0; k < count; ++k) {
            batch->Draw(*texture, Rectangle(k % 16, (k / 16) % 12, 1, 1), Color::White);
        }
        batch->End();
    });
    EXPECT_EQ(batch->drawCallsLastEnd(), 2);
    EXPECT_TRUE(matches(image, [](int, int) { return Color::White; }));
}

// layerDepth 0 is the front: BackToFront draws the largest depth first, FrontToBack the smallest,
// so with overlapping opaque sprites (no depth buffer) the one drawn last shows.
TEST_F(SpriteBatchTest, DepthSortModesOrderOverlappingSprites) {
    auto red = makeTexture(1, 1, [](int, int) { return Color::Red; });
    auto blue = makeTexture(1, 1, [](int, int) { return Color::Blue; });
    auto drawOverlapping = [&](SpriteSortMode mode) {
        const Image image = render(16, 12, kBackground, [&] {
            batch->Begin(mode, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
            batch->Draw(*red, Rectangle(2, 2, 4, 4), nullptr, Color::White, 0, Vector2::Zero, SpriteEffects::None,
                        0.2f);
            batch->Draw(*blue, Rectangle(4, 4, 4, 4), nullptr, Color::White, 0, Vector2::Zero, SpriteEffects::None,
                        0.8f);
            batch->End();
        });
        return image.at(5, 5);
    };
    EXPECT_EQ(str(drawOverlapping(SpriteSortMode::BackToFront)), str(Color::Red)) << "front (0.2) drawn last";
    EXPECT_EQ(str(drawOverlapping(SpriteSortMode::FrontToBack)), str(Color::Blue)) << "back (0.8) drawn last";
    EXPECT_EQ(str(drawOverlapping(SpriteSortMode::Deferred)), str(Color::Blue)) << "Draw order";
}

// --- (7) custom effect -----------------------------------------------------------------------------

TEST_F(SpriteBatchTest, PixelShaderOnlyEffectRunsWithSpriteBatchVertexShader) {
    auto texture = makeTestTexture();
    Effect redChannel(device(), FXPORT_RUNTIME_FIXTURES "/SpriteRedChannel.fx");
    const Image image = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr,
                     redChannel);
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(image, spriteAt(Rectangle(3, 2, 4, 5), [](int i, int j) {
                            return Color(int(texel(i, j).R), 0, 0, 255);
                        })));

    // Two textures: the effect is applied again for the second batch; afterwards a plain batch
    // gets SpriteBatch's own pixel shader back.
    auto white = makeTexture(2, 2, [](int, int) { return Color::White; });
    const Image two = render(16, 12, kBackground, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr,
                     &redChannel);
        batch->Draw(*texture, Rectangle(3, 2, 4, 5), Color::White);
        batch->Draw(*white, Rectangle(10, 2, 2, 2), Color::White);
        batch->End();
        EXPECT_EQ(batch->drawCallsLastEnd(), 2);
        batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        batch->Draw(*white, Rectangle(13, 2, 2, 2), Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(two, [](int x, int y) {
        if (Rectangle(3, 2, 4, 5).Contains(x, y)) {
            return Color(int(texel(x - 3, y - 2).R), 0, 0, 255);
        }
        if (Rectangle(10, 2, 2, 2).Contains(x, y)) {
            return Color::Red;
        }
        if (Rectangle(13, 2, 2, 2).Contains(x, y)) {
            return Color::White;
        }
        return kBackground;
    }));
}

// --- states ------------------------------------------------------------------------------------------

TEST_F(SpriteBatchTest, NullStatesMeanXnaDefaultsAndEndSetsThem) {
    device().BlendState = BlendState::Additive;
    device().SamplerStates[0] = SamplerState::PointWrap;
    device().DepthStencilState = DepthStencilState::Default;
    device().RasterizerState = RasterizerState::CullNone;
    batch->Begin(SpriteSortMode::Deferred, nullptr, nullptr, nullptr, nullptr, nullptr);
    batch->End();  // XNA sets the states even for an empty batch
    EXPECT_TRUE(device().BlendState == BlendState::AlphaBlend);
    EXPECT_TRUE(device().SamplerStates[0] == SamplerState::LinearClamp);
    EXPECT_TRUE(device().DepthStencilState == DepthStencilState::None);
    EXPECT_TRUE(device().RasterizerState == RasterizerState::CullCounterClockwise);

    batch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, DepthStencilState::DepthRead,
                 RasterizerState::CullNone);
    batch->End();
    EXPECT_TRUE(device().BlendState == BlendState::Opaque);
    EXPECT_TRUE(device().SamplerStates[0] == SamplerState::PointClamp);
    EXPECT_TRUE(device().DepthStencilState == DepthStencilState::DepthRead);
    EXPECT_TRUE(device().RasterizerState == RasterizerState::CullNone);
}

// --- (8) text ----------------------------------------------------------------------------------------

// Rows of two debug-font glyphs, typed here from font8x8 independently of the library's table
// (bit 0 = leftmost pixel, first byte = top row).
constexpr std::uint8_t kGlyphH[8] = {0x33, 0x33, 0x33, 0x3F, 0x33, 0x33, 0x33, 0x00};
constexpr std::uint8_t kGlyphF[8] = {0x1C, 0x36, 0x06, 0x0F, 0x06, 0x06, 0x0F, 0x00};

TEST_F(SpriteBatchTest, DebugFontMetrics) {
    auto font = SpriteFont::createDebugFont(device());
    EXPECT_EQ(font->LineSpacing, 10);
    EXPECT_EQ(font->Spacing, 0.0f);
    EXPECT_EQ(font->Characters().size(), 95u);
    EXPECT_TRUE(font->MeasureString("") == Vector2(0, 0));
    EXPECT_TRUE(font->MeasureString("abc") == Vector2(24, 10));
    EXPECT_TRUE(font->MeasureString("Hi!\nfx") == Vector2(24, 20));
    EXPECT_TRUE(font->MeasureString("a\r\nbcd\n") == Vector2(24, 30));
    font->Spacing = 2;
    EXPECT_TRUE(font->MeasureString("abc") == Vector2(28, 10));
}

TEST_F(SpriteBatchTest, DrawStringPlacesGlyphsInsideTheMeasuredBox) {
    auto font = SpriteFont::createDebugFont(device());
    const std::string text = "Hi!\nfx";
    const Vector2 position(2, 3);
    const Vector2 size = font->MeasureString(text);
    const Rectangle box(int(position.X), int(position.Y), int(size.X), int(size.Y));
    const Image image = render(40, 28, Color::Transparent, [&] {
        batch->Begin();
        batch->DrawString(*font, text, position, Color::White);
        batch->End();
    });

    int inside = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Color c = image.at(x, y);
            if (box.Contains(x, y)) {
                inside += c.A != 0 ? 1 : 0;
            } else {
                EXPECT_EQ(str(c), str(Color::Transparent)) << "outside the measured box at (" << x << "," << y << ")";
            }
        }
    }
    EXPECT_GT(inside, 20);
    // First glyph of each line, pixel by pixel: right side up, not mirrored, newline LineSpacing
    // down. Exact with point sampling. With Begin()'s LinearClamp, within 3/255: fxport's D3D9
    // pixel-centre emulation shifts geometry by half a pixel less 1/256 down the rows (the
    // viewport's origin, draw_state.cpp applyViewport), so texel centres are missed by 1/256 texel, which llvmpipe's 8-bit
    // filter weights turn into up to 2/255 at a 0/255 glyph edge.
    const Image pointSampled = render(40, 28, Color::Transparent, [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend, SamplerState::PointClamp, nullptr, nullptr);
        batch->DrawString(*font, text, position, Color::White);
        batch->End();
    });
    auto expectGlyph = [&](const Image& picture, int tolerance, const std::uint8_t (&rows)[8], int left, int top,
                           const char* name) {
        for (int r = 0; r < 8; ++r) {
            for (int b = 0; b < 8; ++b) {
                const Color want = ((rows[r] >> b) & 1) ? Color::White : Color::Transparent;
                EXPECT_TRUE(near(picture.at(left + b, top + r), want, tolerance))
                    << name << " row " << r << " column " << b << ": got " << str(picture.at(left + b, top + r))
                    << " (tolerance " << tolerance << ")";
            }
        }
    };
    expectGlyph(pointSampled, 0, kGlyphH, 2, 3, "'H'");
    expectGlyph(pointSampled, 0, kGlyphF, 2, 13, "'f'");
    expectGlyph(image, 3, kGlyphH, 2, 3, "'H'");
    expectGlyph(image, 3, kGlyphF, 2, 13, "'f'");

    // Characters the font lacks draw as DefaultCharacter '?'; UTF-8 is one character per code point.
    const Image unknown = render(40, 28, Color::Transparent, [&] {
        batch->Begin();
        batch->DrawString(*font, "\xC3\xA9x", position, Color::White);  // "éx"
        batch->End();
    });
    const Image question = render(40, 28, Color::Transparent, [&] {
        batch->Begin();
        batch->DrawString(*font, "?x", position, Color::White);
        batch->End();
    });
    EXPECT_TRUE(matches(unknown, [&](int x, int y) { return question.at(x, y); }));
    font->DefaultCharacter.reset();
    batch->Begin();
    EXPECT_THROW(batch->DrawString(*font, "\xC3\xA9", position, Color::White), ArgumentError);
    batch->End();
}

// Writes a PNG for a person to look at when FXPORT_TEST_OUTPUT names a folder.
TEST_F(SpriteBatchTest, DrawStringPictureForInspection) {
    auto font = SpriteFont::createDebugFont(device());
    const std::string text =
        "fxport debug font 8x8\n !\"#$%&'()*+,-./0123456789:;<=>?\n@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_\n"
        "`abcdefghijklmnopqrstuvwxyz{|}~\nSample Radius: 0.25";
    const Vector2 size = font->MeasureString(text);
    std::unique_ptr<RenderTarget2D> target;
    const Image image = render(int(size.X) * 2 + 8, int(size.Y) * 2 + 8, Color(40, 40, 60, 255), [&] {
        batch->Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend, SamplerState::PointClamp, nullptr, nullptr);
        batch->DrawString(*font, text, Vector2(4, 4), Color::Yellow, 0.0f, Vector2::Zero, 2.0f, SpriteEffects::None, 0);
        batch->End();
    }, &target);
    int lit = 0;
    for (const Color& c : image.pixels) {
        lit += (c.R > 200 && c.G > 200 && c.B < 100) ? 1 : 0;
    }
    EXPECT_GT(lit, 500);
    if (const char* folder = std::getenv("FXPORT_TEST_OUTPUT")) {
        target->SaveAsPng(std::string(folder) + "/sprite_batch_debug_font.png");
    }
}

// --- (9) misuse --------------------------------------------------------------------------------------

template <class F>
std::string invalidOperationMessage(F&& f) {
    try {
        f();
    } catch (const InvalidOperation& error) {
        return error.what();
    }
    return "(no InvalidOperation thrown)";
}

TEST_F(SpriteBatchTest, MisuseThrowsInvalidOperation) {
    auto texture = makeTestTexture();
    auto font = SpriteFont::createDebugFont(device());
    EXPECT_NE(invalidOperationMessage([&] { batch->Draw(*texture, Vector2(0, 0), Color::White); }).find("Begin"),
              std::string::npos);
    EXPECT_NE(
        invalidOperationMessage([&] { batch->DrawString(*font, "x", Vector2(0, 0), Color::White); }).find("Begin"),
        std::string::npos);
    EXPECT_NE(invalidOperationMessage([&] { batch->End(); }).find("Begin"), std::string::npos);
    batch->Begin();
    EXPECT_NE(invalidOperationMessage([&] { batch->Begin(); }).find("End"), std::string::npos);
    batch->End();
    // Still usable afterwards.
    batch->Begin();
    batch->Draw(*texture, Vector2(0, 0), Color::White);
    batch->End();
    EXPECT_EQ(batch->drawCallsLastEnd(), 1);
}

// --- resources ---------------------------------------------------------------------------------------

TEST_F(SpriteBatchTest, LeavesNoGpuObjectsBehind) {
    auto drawSomeText = [&](SpriteBatch& spriteBatch) {
        auto font = SpriteFont::createDebugFont(device());
        render(16, 12, kBackground, [&] {
            spriteBatch.Begin();
            spriteBatch.DrawString(*font, "ok", Vector2(1, 1), Color::White);
            spriteBatch.End();
        });
    };
    // First use of the device makes objects it keeps for every later draw (streaming buffers,
    // vertex arrays, its internal constant buffer); count after that.
    drawSomeText(*batch);
    batch.reset();
    const GpuObjectCounts before = device().liveGpuObjects();
    {
        SpriteBatch spriteBatch(device());
        drawSomeText(spriteBatch);
    }
    const GpuObjectCounts after = device().liveGpuObjects();
    EXPECT_EQ(after.textures, before.textures);
    EXPECT_EQ(after.buffers, before.buffers);
    EXPECT_EQ(after.programs, before.programs);
    EXPECT_EQ(after.pipelines, before.pipelines);
    EXPECT_EQ(after.framebuffers, before.framebuffers);
    EXPECT_EQ(after.vertexArrays, before.vertexArrays);
    EXPECT_EQ(after.total(), before.total());
}

}  // namespace
}  // namespace fxport
