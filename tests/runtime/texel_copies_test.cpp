// Texel-copy reductions (runtime/graphics/src/texel_copies.cpp): SpriteBatch batches of 1:1 texel
// copies under a Min or Max blend run as one compute dispatch. Each case is drawn on a device with
// compute passes off (the fragment stage blends every sprite) and on one with them on; the two
// images must be byte-identical, and both must equal the reduction computed here on the CPU from
// the texels and XNA's placement rule (texel (i, j) of the source rectangle lands on pixel
// (x + i, y + j) of the destination), never from the code under test. Batches that are not texel
// copies, or whose state a dispatch cannot honour, must be drawn as usual (and still be right).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "fxport/graphics.h"
#include "fxport/graphics/sprite_batch.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

constexpr int kTexelW = 40, kTexelH = 30;

struct Device {
    explicit Device(bool compute) {
        PresentationParameters p;
        p.BackBufferWidth = 64;
        p.BackBufferHeight = 32;
        p.Optimizations.ComputePasses = compute;
        device = std::make_unique<GraphicsDevice>(p);
        batch = std::make_unique<SpriteBatch>(*device);
    }
    ComputePassStatistics statistics() const { return device->computePassStatistics(); }
    std::unique_ptr<GraphicsDevice> device;
    std::unique_ptr<SpriteBatch> batch;
};

// A case: the texture's texels (raw bytes, texelBytes each), the target's size and clear, and
// what is drawn between Begin and End.
struct Case {
    SurfaceFormat format = SurfaceFormat::HdrBlendable;
    int texelBytes = 8;
    std::vector<std::uint8_t> texels;
    int targetW = kTexelW, targetH = 1;
    Vector4 clear{1, 1, 1, 1};
    std::function<void(Device&, Texture2D&)> draw;
};

struct Outcome {
    std::vector<std::uint8_t> image;
    ComputePassStatistics statistics;
};

Outcome render(const Case& c, bool compute) {
    Device d(compute);
    Texture2D texture(*d.device, kTexelW, kTexelH, false, c.format);
    texture.SetData(c.texels);
    RenderTarget2D target(*d.device, c.targetW, c.targetH, false, c.format, DepthFormat::None);
    d.device->SetRenderTarget(target);
    d.device->Clear(ClearOptions::Target, c.clear, 1.0f, 0);
    c.draw(d, texture);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    Outcome out;
    out.image.resize(std::size_t(c.targetW) * std::size_t(c.targetH) * std::size_t(c.texelBytes));
    target.getData(0, out.image.data(), out.image.size());
    out.statistics = d.statistics();
    return out;
}

// Renders `c` both ways; expects the images byte-identical to each other and to `expected`, and
// `dispatches` dispatches on the compute device. Returns the compute device's statistics.
ComputePassStatistics bothWays(const Case& c, const std::vector<std::uint8_t>& expected, long dispatches) {
    Outcome fragment = render(c, false), compute = render(c, true);
    EXPECT_EQ(fragment.statistics.dispatched, 0);
    EXPECT_EQ(compute.statistics.dispatched, dispatches);
    EXPECT_TRUE(fragment.image == compute.image) << "the dispatch's pixels differ from the fragment stage's";
    if (expected.empty()) return compute.statistics;  // no exact CPU reference (linear sampling)
    std::size_t wrong = 0, first = expected.size();
    for (std::size_t i = 0; i < expected.size() && i < fragment.image.size(); ++i)
        if (fragment.image[i] != expected[i]) ++wrong, first = std::min(first, i);
    EXPECT_EQ(fragment.image.size(), expected.size());
    EXPECT_EQ(wrong, 0u) << "fragment stage vs CPU reduction, first wrong byte " << first;
    return compute.statistics;
}

// Positive halves no greater than 1 (0x0000..0x3C00): their order is their bits' order, so the
// reference reduces the bit patterns. The clear is 1.0 (0x3C00) where the case clears to white.
std::vector<std::uint8_t> randomHalves(unsigned seed) {
    std::mt19937 random(seed);
    std::vector<std::uint8_t> bytes(std::size_t(kTexelW) * kTexelH * 8);
    for (std::size_t i = 0; i < bytes.size(); i += 2) {
        const std::uint16_t h = std::uint16_t(random() % 0x3C01u);
        bytes[i] = std::uint8_t(h & 0xFF), bytes[i + 1] = std::uint8_t(h >> 8);
    }
    return bytes;
}

std::uint16_t halfAt(const std::vector<std::uint8_t>& bytes, std::size_t index) {
    return std::uint16_t(bytes[index * 2] | (bytes[index * 2 + 1] << 8));
}

void setHalf(std::vector<std::uint8_t>& bytes, std::size_t index, std::uint16_t h) {
    bytes[index * 2] = std::uint8_t(h & 0xFF), bytes[index * 2 + 1] = std::uint8_t(h >> 8);
}

BlendState reductionBlend(BlendFunction color, BlendFunction alpha) {
    BlendState b;
    b.ColorBlendFunction = color, b.AlphaBlendFunction = alpha;
    b.ColorSourceBlend = b.ColorDestinationBlend = b.AlphaSourceBlend = b.AlphaDestinationBlend = Blend::One;
    return b;
}

// lighting2d's occlusion map: every row of the texture onto one row, Min, from a white clear.
TEST(TexelCopies, MinOfEveryRowOntoOneRow) {
    Case c;
    c.texels = randomHalves(1);
    c.draw = [](Device& d, Texture2D& texture) {
        d.batch->Begin(SpriteSortMode::Deferred, reductionBlend(BlendFunction::Min, BlendFunction::Min), SamplerState::PointClamp,
                       nullptr, nullptr);
        for (int row = 0; row < kTexelH; ++row)
            d.batch->Draw(texture, Rectangle(0, 0, kTexelW, 1), Rectangle(0, row, kTexelW, 1), Color::White);
        d.batch->End();
    };
    std::vector<std::uint8_t> expected(std::size_t(kTexelW) * 8);
    for (int x = 0; x < kTexelW; ++x)
        for (int ch = 0; ch < 4; ++ch) {
            std::uint16_t m = 0x3C00;
            for (int row = 0; row < kTexelH; ++row) m = std::min(m, halfAt(c.texels, std::size_t(row * kTexelW + x) * 4 + ch));
            setHalf(expected, std::size_t(x) * 4 + ch, m);
        }
    ComputePassStatistics s = bothWays(c, expected, 1);
    EXPECT_TRUE(s.fellBack.empty());
}

// Max on an 8-bit target; sprites partly off the target, a viewport offset, a scissor rectangle,
// green masked off, colour and alpha reduced the other way round; sprites from several source
// rectangles overlapping in places.
TEST(TexelCopies, MaxMinOnAColorTargetWithViewportScissorAndMask) {
    Case c;
    c.format = SurfaceFormat::Color;
    c.texelBytes = 4;
    std::mt19937 random(2);
    c.texels.resize(std::size_t(kTexelW) * kTexelH * 4);
    for (auto& b : c.texels) b = std::uint8_t(random());
    c.targetW = 36, c.targetH = 20;
    c.clear = Vector4(0.2f, 0.4f, 0.6f, 0.8f);
    const Viewport viewport(3, 2, 30, 16);
    const Rectangle scissor(5, 1, 24, 14);
    struct Sprite {
        Rectangle destination, source;
    };
    std::vector<Sprite> sprites;
    for (int i = 0; i < 12; ++i) {
        const int w = 18 + i % 5, h = 10 + i % 4;
        sprites.push_back({Rectangle(-2 + i, -1 + i / 2, w, h), Rectangle(i, i / 2, w, h)});
    }
    BlendState blend = reductionBlend(BlendFunction::Max, BlendFunction::Min);
    blend.ColorWriteChannels = ColorWriteChannels::Red | ColorWriteChannels::Blue | ColorWriteChannels::Alpha;
    RasterizerState scissored = RasterizerState::CullCounterClockwise;
    scissored.ScissorTestEnable = true;
    c.draw = [&](Device& d, Texture2D& texture) {
        d.device->Viewport = viewport;
        d.device->ScissorRectangle = scissor;
        d.batch->Begin(SpriteSortMode::Deferred, blend, SamplerState::PointWrap, nullptr, scissored);
        for (const Sprite& s : sprites) d.batch->Draw(texture, s.destination, s.source, Color::White);
        d.batch->End();
    };
    const std::uint8_t clear[4] = {51, 102, 153, 204};
    std::vector<std::uint8_t> expected(std::size_t(c.targetW) * c.targetH * 4);
    for (int y = 0; y < c.targetH; ++y)
        for (int x = 0; x < c.targetW; ++x) {
            std::uint8_t* px = &expected[std::size_t(y * c.targetW + x) * 4];
            std::copy(clear, clear + 4, px);
            const bool visible = x >= viewport.X && x < viewport.X + viewport.Width && y >= viewport.Y &&
                                 y < viewport.Y + viewport.Height && x >= scissor.X && x < scissor.X + scissor.Width &&
                                 y >= scissor.Y && y < scissor.Y + scissor.Height;
            if (!visible) continue;
            for (const Sprite& s : sprites) {
                const int i = x - viewport.X - s.destination.X, j = y - viewport.Y - s.destination.Y;
                if (i < 0 || j < 0 || i >= s.destination.Width || j >= s.destination.Height) continue;
                const std::uint8_t* t = &c.texels[std::size_t((s.source.Y + j) * kTexelW + s.source.X + i) * 4];
                px[0] = std::max(px[0], t[0]);
                px[2] = std::max(px[2], t[2]);
                px[3] = std::min(px[3], t[3]);
            }
        }
    ComputePassStatistics s = bothWays(c, expected, 1);
    EXPECT_TRUE(s.fellBack.empty());
}

// Batches that are not texel copies are drawn by the fragment stage (and the fall-back is right);
// a texel-copy batch whose state the dispatch cannot honour says why.
TEST(TexelCopies, WhatIsNotAReductionOfTexelCopiesIsDrawnAsUsual) {
    const std::vector<std::uint8_t> texels = randomHalves(3);
    auto rowsWith = [&](Color tint, const SamplerState& sampler, SpriteEffects effects) {
        Case c;
        c.texels = texels;
        c.draw = [=](Device& d, Texture2D& texture) {
            d.batch->Begin(SpriteSortMode::Deferred, reductionBlend(BlendFunction::Min, BlendFunction::Min), sampler, nullptr,
                           nullptr);
            for (int row = 0; row < kTexelH; ++row)
                d.batch->Draw(texture, Rectangle(0, 0, kTexelW, 1), Rectangle(0, row, kTexelW, 1), tint, 0.0f, Vector2::Zero,
                              effects, 0.0f);
            d.batch->End();
        };
        return c;
    };
    // The reference for the untinted, unflipped rows (the fall-backs below must still draw it).
    std::vector<std::uint8_t> expected(std::size_t(kTexelW) * 8);
    for (int x = 0; x < kTexelW; ++x)
        for (int ch = 0; ch < 4; ++ch) {
            std::uint16_t m = 0x3C00;
            for (int row = 0; row < kTexelH; ++row) m = std::min(m, halfAt(texels, std::size_t(row * kTexelW + x) * 4 + ch));
            setHalf(expected, std::size_t(x) * 4 + ch, m);
        }
    {
        // D3D9's pixel centres carry a 1/256-pixel bias (the port's half-pixel offset), so a linear
        // sample takes 1/256 of a neighbour: no exact reference; both ways must still agree.
        SCOPED_TRACE("linear sampling: refused with its reason");
        ComputePassStatistics s = bothWays(rowsWith(Color::White, SamplerState::LinearClamp, SpriteEffects::None), {}, 0);
        EXPECT_EQ(s.fellBack["texel copies: not Point sampling"], 1);
    }
    {
        SCOPED_TRACE("a tint: not texel copies");
        Outcome fragment = render(rowsWith(Color(128, 255, 255, 255), SamplerState::PointClamp, SpriteEffects::None), false);
        Outcome compute = render(rowsWith(Color(128, 255, 255, 255), SamplerState::PointClamp, SpriteEffects::None), true);
        EXPECT_EQ(compute.statistics.dispatched, 0);
        EXPECT_TRUE(fragment.image == compute.image);
    }
    {
        SCOPED_TRACE("flipped: not texel copies");
        Outcome compute = render(rowsWith(Color::White, SamplerState::PointClamp, SpriteEffects::FlipHorizontally), true);
        EXPECT_EQ(compute.statistics.dispatched, 0);
    }
    {
        SCOPED_TRACE("a target of another format: refused with its reason");
        Case c = rowsWith(Color::White, SamplerState::PointClamp, SpriteEffects::None);
        Device d(true);
        Texture2D texture(*d.device, kTexelW, kTexelH, false, c.format);
        texture.SetData(c.texels);
        RenderTarget2D target(*d.device, kTexelW, 1, false, SurfaceFormat::Vector4, DepthFormat::None);
        d.device->SetRenderTarget(target);
        d.device->Clear(ClearOptions::Target, Vector4(1, 1, 1, 1), 1.0f, 0);
        c.draw(d, texture);
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        EXPECT_EQ(d.statistics().dispatched, 0);
        EXPECT_EQ(d.statistics().fellBack["texel copies: the texture's format is not the target's"], 1);
        std::vector<float> image(std::size_t(kTexelW) * 4);
        target.GetData(image.data(), image.size());
        // Half to float is exact: the fragment stage's Min of the halves, as floats.
        auto halfToFloat = [](std::uint16_t h) {
            const int exponent = (h >> 10) & 31, mantissa = h & 1023;
            return exponent == 0 ? std::ldexp(float(mantissa), -24) : std::ldexp(float(mantissa | 1024), exponent - 25);
        };
        for (int i = 0; i < kTexelW * 4; ++i) EXPECT_EQ(image[std::size_t(i)], halfToFloat(halfAt(expected, std::size_t(i)))) << i;
    }
}

// Sprites scattered over the target overlap too little for every invocation to test every sprite.
TEST(TexelCopies, ScatteredSpritesAreDrawnAsUsual) {
    Case c;
    c.texels = randomHalves(4);
    c.targetW = 64, c.targetH = 32;
    c.clear = Vector4(0, 0, 0, 0);
    c.draw = [](Device& d, Texture2D& texture) {
        d.batch->Begin(SpriteSortMode::Deferred, reductionBlend(BlendFunction::Max, BlendFunction::Max), SamplerState::PointClamp,
                       nullptr, nullptr);
        for (int i = 0; i < 16; ++i)
            d.batch->Draw(texture, Rectangle((i % 8) * 8, (i / 8) * 16, 2, 2), Rectangle(i, i, 2, 2), Color::White);
        d.batch->End();
    };
    std::vector<std::uint8_t> expected(std::size_t(c.targetW) * c.targetH * 8, 0);
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int ch = 0; ch < 4; ++ch) {
                    const std::size_t pixel = std::size_t(((i / 8) * 16 + j) * c.targetW + (i % 8) * 8 + k);
                    setHalf(expected, pixel * 4 + ch, halfAt(c.texels, std::size_t((i + j) * kTexelW + i + k) * 4 + ch));
                }
    ComputePassStatistics s = bothWays(c, expected, 0);
    EXPECT_EQ(s.fellBack["texel copies: sprites overlap too little"], 1);
}

}  // namespace
}  // namespace fxport

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    unsetenv("FXPORT_COMPUTE_PASSES");  // each device here says itself whether it uses compute passes
    return RUN_ALL_TESTS();
}
