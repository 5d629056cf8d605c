// GlyphAtlasBuilder: shelf packing of glyph images into one Color texture for a SpriteFont.
#include "glyph_atlas.h"

#include <algorithm>
#include <numeric>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/texture.h"

namespace fxport {

std::unique_ptr<SpriteFont> GlyphAtlasBuilder::build(GraphicsDevice& device, const std::string& name, int lineSpacing,
                                                     float spacing, std::optional<char32_t> defaultCharacter) {
    // Cells are the glyph plus one transparent texel on every side.
    long long area = 0;
    int widest = 1;
    for (const AtlasGlyph& g : glyphs_) {
        area += (long long)(g.width + 2) * (g.height + 2);
        widest = std::max(widest, g.width + 2);
    }
    int width = 64;
    while ((long long)width * width < area && width < 8192) width *= 2;
    while (width < widest) width *= 2;

    std::vector<std::size_t> order(glyphs_.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return glyphs_[a].height > glyphs_[b].height; });
    int x = 0, y = 0, rowHeight = 0;
    for (std::size_t i : order) {
        AtlasGlyph& g = glyphs_[i];
        if (x + g.width + 2 > width) {
            x = 0;
            y += rowHeight;
            rowHeight = 0;
        }
        g.bounds = Rectangle(x + 1, y + 1, g.width, g.height);
        x += g.width + 2;
        rowHeight = std::max(rowHeight, g.height + 2);
    }
    const int height = std::max(1, y + rowHeight);
    if (width > 16384 || height > 16384)
        throw ArgumentError("SpriteFont '" + name + "': the glyphs need a " + std::to_string(width) + "x" +
                            std::to_string(height) + " atlas; ask for fewer characters or a smaller Size");

    std::vector<Color> texels(std::size_t(width) * std::size_t(height), Color::Transparent);
    std::vector<Rectangle> bounds, cropping;
    std::vector<char32_t> characters;
    std::vector<Vector3> kerning;
    for (const AtlasGlyph& g : glyphs_) {
        for (int row = 0; row < g.height; ++row) {
            for (int column = 0; column < g.width; ++column) {
                const std::size_t source = std::size_t(row) * std::size_t(g.width) + std::size_t(column);
                Color texel;
                if (g.rgba.empty()) {
                    const unsigned char a = g.coverage[source];
                    texel = Color(a, a, a, a);  // white, premultiplied
                } else {
                    texel = g.rgba[source];
                }
                texels[std::size_t(g.bounds.Y + row) * std::size_t(width) + std::size_t(g.bounds.X + column)] = texel;
            }
        }
        bounds.push_back(g.bounds);
        cropping.push_back(g.cropping);
        characters.push_back(g.character);
        kerning.push_back(g.kerning);
    }
    auto texture = std::make_unique<Texture2D>(device, width, height, false, SurfaceFormat::Color);
    texture->Name = name;
    texture->SetData(texels);
    return std::make_unique<SpriteFont>(std::move(texture), std::move(bounds), std::move(cropping),
                                        std::move(characters), lineSpacing, spacing, std::move(kerning),
                                        defaultCharacter);
}

}  // namespace fxport
