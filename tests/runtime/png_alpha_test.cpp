// PNGs people open: the frame (SaveBackBufferAsPng) is saved as a screen shows it, alpha ignored
// (written 255, as XNA's window ignores it); RenderTarget2D::SaveAsPng keeps alpha, as XNA's does.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::testDevice;

// Alpha 0 in the left half, 128 in the right half of whatever is bound, copied texel for texel by
// SpriteBatch with BlendState::Opaque (alpha reaches the target unblended).
Color patternAt(int x, int width) { return x < width / 2 ? Color(200, 100, 50, 0) : Color(20, 40, 60, 128); }

void drawPattern(GraphicsDevice& device, int width, int height) {
    std::vector<Color> texels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) texels.push_back(patternAt(x, width));
    Texture2D pattern(device, width, height);
    pattern.SetData(texels);
    SpriteBatch batch(device);
    batch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp);
    batch.Draw(pattern, Vector2(0, 0), Color::White);
    batch.End();
}

std::vector<Color> readPng(GraphicsDevice& device, const std::string& path) {
    return Texture2D::FromFile(device, path)->GetData<Color>();
}

TEST(PngAlpha, BackBufferIsSavedOpaqueWithItsColours) {
    GraphicsDevice& device = testDevice();
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    const int w = device.PresentationParameters().BackBufferWidth, h = device.PresentationParameters().BackBufferHeight;
    drawPattern(device, w, h);
    std::vector<Color> inMemory = device.GetBackBufferData();
    ASSERT_EQ(inMemory[0].A, 0);  // the back buffer itself does hold alpha 0 ...
    std::string path = ::testing::TempDir() + "/fxport_frame_alpha.png";
    device.SaveBackBufferAsPng(path);
    std::vector<Color> saved = readPng(device, path);
    ASSERT_EQ(saved.size(), std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Color expected = patternAt(x, w);
            expected.A = 255;  // ... the PNG does not
            ASSERT_EQ(saved[std::size_t(y * w + x)], expected) << "pixel " << x << "," << y;
        }
}

TEST(PngAlpha, RenderTargetKeepsAlpha) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D target(device, 6, 3, false, SurfaceFormat::Color, DepthFormat::None);
    device.SetRenderTarget(target);
    drawPattern(device, 6, 3);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::string path = ::testing::TempDir() + "/fxport_target_alpha.png";
    target.SaveAsPng(path);
    std::vector<Color> saved = readPng(device, path);
    ASSERT_EQ(saved.size(), 18u);
    for (int i = 0; i < 18; ++i) {
        EXPECT_EQ(saved[std::size_t(i)], patternAt(i % 6, 6)) << "pixel " << i % 6 << "," << i / 6;
    }
}

}  // namespace
}  // namespace fxport
