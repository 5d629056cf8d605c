// SpriteFont: XNA 4's bitmap font (a texture of glyphs plus per-glyph metrics), drawn with
// SpriteBatch::DrawString. Fonts from files (TrueType, BMFont, XNA .spritefont descriptions) come from
// ContentManager::Load<SpriteFont> / fxport/framework/sprite_font_import.h; createDebugFont makes a
// small built-in one (8x8 pixel glyphs of printable ASCII, the public-domain font8x8 / IBM PC BIOS
// shapes) for on-screen debug text, as the tutorials' "DefaultFont" is used.
//
//   auto font = SpriteFont::createDebugFont(device);
//   Vector2 size = font->MeasureString("Distance Scale: 1.5");
//   spriteBatch.DrawString(*font, "Distance Scale: 1.5", Vector2(0, 148), Color::Blue);
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "fxport/graphics/sprite_batch.h"
#include "fxport/math.h"

namespace fxport {

class GraphicsDevice;
class Texture2D;

class SpriteFont {
public:
    // XNA's SpriteFont data, one entry per character in each vector (the order of `characters`; it
    // need not be sorted). glyphBounds: where the glyph is in the texture; cropping: where the glyph
    // image sits in its character cell (X, Y offset; Width = advance used when mirroring); kerning:
    // (left bearing, glyph width, right bearing) in pixels — the pen advances by their sum. Throws
    // ArgumentError when the vectors differ in length or a character appears twice.
    SpriteFont(std::unique_ptr<Texture2D> texture, std::vector<Rectangle> glyphBounds, std::vector<Rectangle> cropping,
               std::vector<char32_t> characters, int lineSpacing, float spacing, std::vector<Vector3> kerning,
               std::optional<char32_t> defaultCharacter);
    ~SpriteFont();
    SpriteFont(const SpriteFont&) = delete;
    SpriteFont& operator=(const SpriteFont&) = delete;

    // The built-in debug font: characters 32..126, 8x8 pixel glyphs, monospaced 8 pixels per
    // character, LineSpacing 10, Spacing 0, DefaultCharacter '?'. Its texture is SurfaceFormat::Color,
    // white glyphs with alpha (premultiplied: transparent texels are (0,0,0,0)).
    static std::unique_ptr<SpriteFont> createDebugFont(fxport::GraphicsDevice& device);

    // Width of the longest line and height of all lines (LineSpacing each; the last line at least as
    // high as its tallest character cell, cropping.Height), in pixels at scale 1, as XNA measures.
    // (0, 0) for an empty string.
    Vector2 MeasureString(std::string_view text) const;

    // XNA properties: public and settable, as in XNA.
    int LineSpacing = 0;       // pixels from one line's top to the next
    float Spacing = 0;         // extra pixels between characters
    std::optional<char32_t> DefaultCharacter;  // drawn for characters the font lacks
    const std::vector<char32_t>& Characters() const { return characters_; }

    // fxport internals, used by SpriteBatch::DrawString.
    Texture2D& texture() const { return *texture_; }
    // Index of the glyph drawn for `character` (DefaultCharacter's when absent). Throws ArgumentError
    // when neither exists.
    int glyphIndex(char32_t character) const;
    // XNA's SpriteFont.InternalDraw: queues one sprite per glyph.
    void draw(SpriteBatch& spriteBatch, std::string_view text, Vector2 position, Color color, float rotation,
              Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth) const;

private:
    std::unique_ptr<Texture2D> texture_;
    std::vector<Rectangle> glyphs_;
    std::vector<Rectangle> cropping_;
    std::vector<char32_t> characters_;
    std::vector<Vector3> kerning_;
    std::vector<std::pair<char32_t, int>> lookup_;  // sorted by character
};

}  // namespace fxport
