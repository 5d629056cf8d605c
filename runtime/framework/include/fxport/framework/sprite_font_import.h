// Building SpriteFonts from font files, what ContentManager::Load<SpriteFont> does (usable without a
// ContentManager). The glyph metrics follow XNA's SpriteFont model (sprite_font.h):
//
//  * TrueType/OpenType (stb_truetype): the em is Size points at 96 dpi (Size * 96/72 pixels), as
//    XNA's font processor renders. LineSpacing = round((ascent - descent + lineGap) * scale) from the
//    hhea table; per glyph its antialiased bitmap (8-bit coverage, white, premultiplied alpha) in one
//    atlas with a transparent texel around each glyph; kerning (A, B, C) = (bitmap left x, bitmap
//    width, advance - A - B) so the pen advances by the font's advance; cropping = (0, baseline +
//    bitmap top, B, LineSpacing) with the baseline at round(ascent * scale) below the line top.
//    UseKerning = false: kerning (0, advance, 0) and the bitmap's left x moves into cropping.X (the
//    same pen advance; a glyph that starts a line is not pulled left by a negative A). XNA 4's
//    SpriteFont has no pair kerning; a font's kern pairs are not applied.
//  * BMFont (.fnt, text format; AngelCode's tool and its clones): LineSpacing = lineHeight; per char
//    glyph = (x, y, width, height) on its page, cropping = (0, yoffset, width, lineHeight), kerning =
//    (xoffset, width, xadvance - xoffset - width); pages stacked into one texture; the page PNGs
//    premultiplied. Kerning pairs are ignored with a warning (no place for them in XNA's SpriteFont).
//  * .spritefont (XNA's XML font description): FontName (a .ttf/.otf beside the file named so, else
//    fontconfig's best match for the family and Style; a substitute is reported on stderr), Size,
//    Spacing, UseKerning, Style (Regular, Bold, Italic, "Bold, Italic"), DefaultCharacter,
//    CharacterRegions.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fxport {

class GraphicsDevice;
class SpriteFont;

enum class FontDescriptionStyle { Regular, Bold, Italic, BoldItalic };

// XNA's FontDescription (the .spritefont fields). The defaults are XNA's new-SpriteFont template's.
struct FontDescription {
    std::string FontName;         // family name, or a font file
    float Size = 14;              // points, at 96 dpi
    float Spacing = 0;            // SpriteFont.Spacing
    bool UseKerning = true;       // per-glyph A/C widths from the font's metrics
    FontDescriptionStyle Style = FontDescriptionStyle::Regular;
    std::optional<char32_t> DefaultCharacter;
    std::vector<std::pair<char32_t, char32_t>> CharacterRegions{{U' ', U'~'}};  // inclusive
};

// A SpriteFont from a TrueType/OpenType file with the description's size, spacing and characters
// (FontName is not used: the file is given). Characters the font lacks are left out, with one
// warning on stderr listing them. Throws ArgumentError naming the file when it is not a font.
std::unique_ptr<SpriteFont> BuildSpriteFont(GraphicsDevice& device, const std::string& fontFile,
                                            const FontDescription& description);
// A SpriteFont from a BMFont text .fnt file and its page images. Errors name the file and line.
std::unique_ptr<SpriteFont> LoadBMFont(GraphicsDevice& device, const std::string& fntFile);
// Reads an XNA .spritefont XML description. Errors name the file and line.
FontDescription ReadFontDescription(const std::string& spritefontFile);
// The font file a description's FontName and Style resolve to (see above), next to `besideFile`'s
// folder first. Throws ArgumentError when nothing matches.
std::string FindFontFile(const FontDescription& description, const std::string& besideFile);

}  // namespace fxport
