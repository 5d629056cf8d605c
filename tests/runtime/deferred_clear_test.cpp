// Clears that wait until needed (runtime/graphics/src/pending_clear.cpp): the pixels are those of
// executing every clear at once, and the statistics show what was saved. Each case runs on a
// device that defers and on one that does not (DeviceOptimizations::DeferClears), and the
// pixels of the two are compared with the value the clears and draws must give.
#include <gtest/gtest.h>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::runtimeFixture;

struct Device {
    explicit Device(bool defer, bool honourDiscards = true, bool dropCovered = true) {
        PresentationParameters p;
        p.BackBufferWidth = 8;
        p.BackBufferHeight = 4;
        p.Optimizations.DeferClears = defer;
        p.Optimizations.HonourDiscards = honourDiscards;
        p.Optimizations.DropCoveredClears = dropCovered;
        p.Optimizations.LazyDepthStorage = defer;  // immediate: every clear as written, on buffers made with their targets
        device = std::make_unique<GraphicsDevice>(p);
        effect = std::make_unique<Effect>(*device, runtimeFixture("Conventions.fx"));
        effect->CurrentTechnique = effect->Techniques["SolidColor"];
        device->BlendState = BlendState::Opaque;
        device->RasterizerState = RasterizerState::CullNone;
    }
    void draw(Vector4 color, const DepthStencilState& depth, float z = 0.5f) {
        effect->Parameters["Color"].SetValue(color);
        device->DepthStencilState = depth;
        effect->CurrentTechnique->Passes[0].Apply();
        drawQuad(*device, z);
    }
    std::unique_ptr<GraphicsDevice> device;
    std::unique_ptr<Effect> effect;
};

std::vector<float> pixel(const std::vector<float>& texels, int index) {
    return {texels[std::size_t(index) * 4], texels[std::size_t(index) * 4 + 1], texels[std::size_t(index) * 4 + 2],
            texels[std::size_t(index) * 4 + 3]};
}

// The bind clear of a DiscardContents target followed by the port's own Clear: one colour clear
// reaches GL, and a target nothing draws into with depth never has its depth cleared.
TEST(DeferredClears, ClearAfterBindReplacesTheBindClear) {
    for (bool defer : {true, false}) {
        SCOPED_TRACE(defer ? "deferred" : "immediate");
        Device d(defer);
        RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        ClearStatistics before = d.device->clearStatistics();
        d.device->SetRenderTarget(target);
        d.device->Clear(Color(0, 0, 255, 255));
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> texels = readFloats(target);
        for (int i = 0; i < 32; ++i) EXPECT_EQ(pixel(texels, i), (std::vector<float>{0, 0, 1, 1})) << "texel " << i;
        ClearStatistics after = d.device->clearStatistics();
        // Asked: binding the target (colour, depth, stencil), the port's Clear (the same), binding
        // the back buffer again (XNA clears a DiscardContents back buffer too).
        EXPECT_EQ(after.requested - before.requested, 9);
        if (defer) {
            // Sent to GL: the back buffer's pending colour when it was left, and the Clear's colour
            // when the target was left; the back buffer's new bind clear is still pending.
            EXPECT_EQ(after.executed - before.executed, 2);
            EXPECT_EQ(after.replaced - before.replaced, 3);  // the target's bind clear, by the Clear
            EXPECT_EQ(after.dropped - before.dropped, 4);   // depth+stencil of the back buffer, then of the target
        } else {
            EXPECT_EQ(after.executed - before.executed, 9);
            EXPECT_EQ(after.replaced + after.dropped, 0);
        }
    }
}

// A depth-tested draw after the bind sees the depth clear: the far quad drawn second loses to the
// near one only if depth was cleared to 1 first and written by the near one.
TEST(DeferredClears, DepthTestedDrawSeesThePendingDepthClear) {
    for (bool defer : {true, false}) {
        SCOPED_TRACE(defer ? "deferred" : "immediate");
        Device d(defer);
        RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        d.draw(Vector4(1, 0, 0, 1), DepthStencilState::None);      // colour only: depth stays pending
        d.draw(Vector4(0, 1, 0, 1), DepthStencilState::Default, 0.25f);  // needs depth = 1 to pass
        d.draw(Vector4(0, 0, 1, 1), DepthStencilState::Default, 0.75f);  // behind: rejected
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> texels = readFloats(target);
        for (int i = 0; i < 32; ++i) EXPECT_EQ(pixel(texels, i), (std::vector<float>{0, 1, 0, 1})) << "texel " << i;
    }
}

// A clear of part of the target (a smaller viewport) executes at once after what is pending.
TEST(DeferredClears, ViewportClearAfterPendingWholeClear) {
    for (bool defer : {true, false}) {
        SCOPED_TRACE(defer ? "deferred" : "immediate");
        Device d(defer);
        RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4);
        d.device->SetRenderTarget(target);
        d.device->Clear(Color(255, 0, 0, 255));
        d.device->Viewport = Viewport(2, 1, 3, 2);
        d.device->Clear(Color(0, 255, 0, 255));
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> texels = readFloats(target);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                bool inside = x >= 2 && x < 5 && y >= 1 && y < 3;
                EXPECT_EQ(pixel(texels, y * 8 + x), (std::vector<float>{inside ? 0.f : 1.f, inside ? 1.f : 0.f, 0, 1}))
                    << x << "," << y;
            }
    }
}

// PreserveContents: a depth clear nobody used is still executed when the target is left, since the
// next binding keeps the buffer: a later depth-tested draw behind 0.5 must fail against the
// cleared-and-then-written value.
TEST(DeferredClears, PreserveContentsKeepsDepthClears) {
    for (bool defer : {true, false}) {
        SCOPED_TRACE(defer ? "deferred" : "immediate");
        Device d(defer);
        RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8, 0,
                              RenderTargetUsage::PreserveContents);
        d.device->SetRenderTarget(target);
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0, 0, 0, 1), 0.5f, 0);
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        d.device->SetRenderTarget(target);
        d.draw(Vector4(1, 1, 1, 1), DepthStencilState::Default, 0.75f);  // behind the cleared 0.5: rejected
        d.draw(Vector4(1, 0, 1, 1), DepthStencilState::Default, 0.25f);  // in front: drawn
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> texels = readFloats(target);
        for (int i = 0; i < 32; ++i) EXPECT_EQ(pixel(texels, i), (std::vector<float>{1, 0, 1, 1})) << "texel " << i;
    }
}

// Reading the bound back buffer sees a pending clear.
TEST(DeferredClears, BackBufferReadSeesPendingClear) {
    Device d(true);
    d.device->Clear(Color(10, 20, 30, 255));
    std::vector<Color> pixels = d.device->GetBackBufferData();
    ASSERT_EQ(pixels.size(), 32u);
    for (const Color& c : pixels) EXPECT_TRUE(c.R == 10 && c.G == 20 && c.B == 30 && c.A == 255);
}

// DiscardContents before a full-target quad: the bind clear's colour never reaches GL (counted as
// discarded), the depth clear still does for the depth-tested draw, and the pixels are the quad's
// -- the same as with discards not honoured (every clear sent).
TEST(DeferredClears, DiscardContentsDropsThePendingColourClear) {
    for (bool honour : {true, false}) {
        SCOPED_TRACE(honour ? "honoured" : "not honoured");
        Device d(true, honour);
        RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        ClearStatistics before = d.device->clearStatistics();
        d.device->DiscardContents(ClearOptions::Target);
        d.draw(Vector4(0.25f, 0.5f, 0.75f, 1), DepthStencilState::Default);  // tests and writes depth: needs its clear
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> texels = readFloats(target);
        for (int i = 0; i < 32; ++i) EXPECT_EQ(pixel(texels, i), (std::vector<float>{0.25f, 0.5f, 0.75f, 1})) << "texel " << i;
        ClearStatistics after = d.device->clearStatistics();
        EXPECT_EQ(after.discarded - before.discarded, honour ? 1 : 0);
        // Sent: depth+stencil (one call, two channels) before the draw, and colour too unless discarded.
        EXPECT_EQ(after.executed - before.executed, honour ? 2 : 3);
    }
}

// A SpriteBatch sprite that covers the whole target, opaque, through SpriteBatch's own shaders:
// the pending colour clear is dropped (ClearStatistics::covered) and the pixels are the sprite's,
// as with every clear executed or with DropCoveredClears off. One texel short, alpha-blended, or a viewport smaller than the
// target: the clear runs, and the uncovered texels keep its colour (XNA's DiscardColor).
TEST(DeferredClears, SpriteCoveringTheTargetDropsThePendingColourClear) {
    struct Case {
        const char* name;
        Rectangle destination;
        const BlendState* blend;
        bool smallViewport;
        bool dropped;
    };
    const Case cases[] = {
        {"covers", Rectangle(0, 0, 8, 4), &BlendState::Opaque, false, true},
        {"beyond the edges", Rectangle(-2, -1, 12, 6), &BlendState::Opaque, false, true},
        {"one column short", Rectangle(0, 0, 7, 4), &BlendState::Opaque, false, false},
        {"alpha-blended", Rectangle(0, 0, 8, 4), &BlendState::AlphaBlend, false, false},
        {"viewport smaller than the target", Rectangle(0, 0, 8, 4), &BlendState::Opaque, true, false},
    };
    const Color sprite(10, 200, 30, 255);
    for (const Case& c : cases) {
        std::vector<Color> images[3];
        for (int mode = 0; mode < 3; ++mode) {
            const bool defer = mode < 2, drop = mode == 0;
            SCOPED_TRACE(std::string(c.name) + (mode == 0 ? ", dropping" : mode == 1 ? ", not dropping" : ", immediate"));
            Device d(defer, true, drop);
            RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Color, DepthFormat::None);
            Texture2D white(*d.device, 1, 1);
            white.SetData(std::vector<Color>{Color::White});
            SpriteBatch batch(*d.device);
            d.device->SetRenderTarget(target);
            if (c.smallViewport) d.device->Viewport = Viewport(0, 0, 6, 4);
            ClearStatistics before = d.device->clearStatistics();
            batch.Begin(SpriteSortMode::Deferred, *c.blend);
            batch.Draw(white, c.destination, sprite);
            batch.End();
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            images[mode].resize(32);
            target.GetData(images[mode].data(), 32);
            ClearStatistics after = d.device->clearStatistics();
            EXPECT_EQ(after.covered - before.covered, drop && c.dropped ? 1 : 0);
            const std::vector<Color>& texels = images[mode];
            for (int i = 0; i < 32; ++i) {
                const bool inside = (i % 8) < (c.smallViewport ? 6 : c.destination.X + c.destination.Width);
                const Color expected = inside ? sprite : d.device->DiscardColor;
                if (c.blend == &BlendState::Opaque) {
                    EXPECT_TRUE(texels[std::size_t(i)] == expected) << "texel " << i;
                }
            }
        }
        EXPECT_TRUE(images[0] == images[1] && images[0] == images[2]) << c.name << ": the three ways differ";
    }
}


// A blend onto the zero clear executed for the draw, on an 8-bit target, with source factor One
// and Add, Subtract or Max is a write: the same bytes as blending (ClearStatistics::blendsAsWrites;
// with compute passes on the draw may then run as a dispatch). A second draw blends onto the
// first draw's pixels as usual. Other blends, a non-zero clear or a float target are not touched.
// Each case runs with DropCoveredClears on (the fold) and off (every blend drawn as written).
TEST(DeferredClears, BlendOntoTheZeroClearIsAWrite) {
    auto blend = [](Blend source, Blend destination, BlendFunction function) {
        BlendState b;
        b.ColorSourceBlend = b.AlphaSourceBlend = source;
        b.ColorDestinationBlend = b.AlphaDestinationBlend = destination;
        b.ColorBlendFunction = b.AlphaBlendFunction = function;
        return b;
    };
    struct Case {
        const char* name;
        BlendState blend;
        Vector4 clear;
        SurfaceFormat format;
        bool folds;
    };
    const Case cases[] = {
        {"One/One Add", blend(Blend::One, Blend::One, BlendFunction::Add), Vector4(0, 0, 0, 0), SurfaceFormat::Color, true},
        {"premultiplied AlphaBlend", BlendState::AlphaBlend, Vector4(0, 0, 0, 0), SurfaceFormat::Color, true},
        {"Max", blend(Blend::One, Blend::One, BlendFunction::Max), Vector4(0, 0, 0, 0), SurfaceFormat::Color, true},
        {"Subtract", blend(Blend::One, Blend::InverseSourceColor, BlendFunction::Subtract), Vector4(0, 0, 0, 0), SurfaceFormat::Color, true},
        {"Rgba64", blend(Blend::One, Blend::One, BlendFunction::Add), Vector4(0, 0, 0, 0), SurfaceFormat::Rgba64, true},
        {"Additive (source alpha)", BlendState::Additive, Vector4(0, 0, 0, 0), SurfaceFormat::Color, false},
        {"Min", blend(Blend::One, Blend::One, BlendFunction::Min), Vector4(0, 0, 0, 0), SurfaceFormat::Color, false},
        {"ReverseSubtract", blend(Blend::One, Blend::One, BlendFunction::ReverseSubtract), Vector4(0, 0, 0, 0), SurfaceFormat::Color, false},
        {"a clear that is not zero", blend(Blend::One, Blend::One, BlendFunction::Add), Vector4(0, 0, 0, 1.0f / 255), SurfaceFormat::Color, false},
        {"a float target", blend(Blend::One, Blend::One, BlendFunction::Add), Vector4(0, 0, 0, 0), SurfaceFormat::Vector4, false},
    };
    // Multiples of 51/255: no value rounds from a tie (GPUs differ there), blended in fixed point or float.
    const Vector4 first(0.2f, 0.4f, 0.8f, 0.6f), second(0.4f, 0.2f, 0.4f, 0.2f);
    for (const Case& c : cases) {
        std::vector<std::uint8_t> images[2];
        std::vector<float> colors;  // the folded Color image, as floats
        for (bool fold : {true, false}) {
            SCOPED_TRACE(std::string(c.name) + (fold ? ", folded" : ", blended"));
            Device d(true, true, fold);
            RenderTarget2D target(*d.device, 8, 4, false, c.format, DepthFormat::None);
            d.device->SetRenderTarget(target);
            d.device->Clear(ClearOptions::Target, c.clear, 1.0f, 0);
            d.device->BlendState = c.blend;
            const ClearStatistics before = d.device->clearStatistics();
            d.draw(first, DepthStencilState::None);
            const ClearStatistics between = d.device->clearStatistics();
            d.draw(second, DepthStencilState::None);
            const ClearStatistics after = d.device->clearStatistics();
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            EXPECT_EQ(between.blendsAsWrites - before.blendsAsWrites, fold && c.folds ? 1 : 0);
            EXPECT_EQ(after.blendsAsWrites - between.blendsAsWrites, 0);  // the second draw blends onto the first
            std::vector<std::uint8_t>& bytes = images[fold ? 0 : 1];
            const std::size_t texelBytes = c.format == SurfaceFormat::Color ? 4 : c.format == SurfaceFormat::Rgba64 ? 8 : 16;
            bytes.resize(32 * texelBytes);
            target.getData(0, bytes.data(), bytes.size());
            if (fold && c.format == SurfaceFormat::Color) colors = readFloats(target);
        }
        EXPECT_EQ(images[0], images[1]) << c.name << ": the fold changed the pixels";
        if (c.name == std::string("One/One Add")) {  // the second draw added onto the first
            const std::vector<float> expected = {153 / 255.0f, 153 / 255.0f, 1.0f, 204 / 255.0f};  // 51 + 102, 102 + 51, 204 + 102 saturated, 153 + 51
            for (int i = 0; i < 32; ++i) EXPECT_EQ(pixel(colors, i), expected) << "texel " << i;
        }
    }
}

}  // namespace
}  // namespace fxport
