#include "lighting2d/scene_sprites.h"

#include <vector>

namespace _2DLightingSystem {

using fxport::Color;

namespace {

std::unique_ptr<fxport::Texture2D> MakeTexture(fxport::GraphicsDevice& device, int w, int h,
                                               Color (*texel)(int x, int y, int w, int h)) {
    std::vector<Color> data(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) data[std::size_t(y) * std::size_t(w) + std::size_t(x)] = texel(x, y, w, h);
    auto texture = std::make_unique<fxport::Texture2D>(device, w, h);
    texture->SetData(data);
    return texture;
}

}  // namespace

SceneSprites MakeSceneSprites(fxport::GraphicsDevice& device) {
    SceneSprites s;
    s.background = MakeTexture(device, 256, 256, [](int x, int y, int, int) {
        const bool tile = ((x / 32) + (y / 32)) % 2 == 0;
        const bool grout = x % 32 == 0 || y % 32 == 0;
        const int v = grout ? 90 : (tile ? 200 : 170);
        return Color(v, v - 10 + (x % 7), v - 30 + (y % 5), 255);
    });
    s.box = MakeTexture(device, 64, 64, [](int x, int y, int w, int h) {
        const bool edge = x < 4 || y < 4 || x >= w - 4 || y >= h - 4;
        return edge ? Color(60, 40, 20, 255) : Color(150, 100, 50, 255);
    });
    s.disc = MakeTexture(device, 64, 64, [](int x, int y, int w, int h) {
        const float dx = x + 0.5f - w / 2.f, dy = y + 0.5f - h / 2.f;
        return dx * dx + dy * dy < (w / 2.f) * (w / 2.f) ? Color(70, 110, 70, 255) : Color::Transparent;
    });
    s.bar = MakeTexture(device, 32, 96, [](int x, int y, int, int h) {
        return (x < 12 || y >= h - 12) ? Color(120, 120, 140, 255) : Color::Transparent;
    });
    return s;
}

}  // namespace _2DLightingSystem
