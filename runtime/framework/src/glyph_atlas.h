// GlyphAtlasBuilder: packs glyph images (8-bit coverage or RGBA) into one texture, a transparent
// texel around each so linear filtering at any scale cannot bleed, and makes the SpriteFont.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport {

class GraphicsDevice;
class SpriteFont;

struct AtlasGlyph {
    char32_t character = 0;
    int width = 0, height = 0;
    std::vector<unsigned char> coverage;  // width*height coverage (white glyph), or empty when `rgba` is used
    std::vector<Color> rgba;              // width*height premultiplied texels
    Rectangle cropping;
    Vector3 kerning;
    Rectangle bounds;  // set by build(): where the glyph landed in the texture
};

class GlyphAtlasBuilder {
public:
    void add(AtlasGlyph glyph) { glyphs_.push_back(std::move(glyph)); }
    bool empty() const { return glyphs_.empty(); }
    // Packs the glyphs in rows (tallest first) into a power-of-two-wide texture and makes the font.
    std::unique_ptr<SpriteFont> build(GraphicsDevice& device, const std::string& name, int lineSpacing, float spacing,
                                      std::optional<char32_t> defaultCharacter);

private:
    std::vector<AtlasGlyph> glyphs_;
};

}  // namespace fxport
