// BuildSpriteFont: a TrueType/OpenType font rasterised with stb_truetype (Debian's libstb) into one
// glyph atlas with XNA's per-glyph metrics (the rules are in sprite_font_import.h).
#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fxport/framework/sprite_font_import.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/sprite_font.h"
#include "fxport/graphics/texture.h"
#include "fxport/platform/file_reading.h"
#include "glyph_atlas.h"

namespace fxport {

namespace {

std::vector<unsigned char> readFile(const std::string& path) {
    platform::FileBytes file = platform::readUntrustedFile(path);
    if (!file.ok()) throw ArgumentError("SpriteFont: cannot read the font file: " + file.error);
    return std::move(file.bytes);
}

std::uint32_t bigEndian32(const std::vector<unsigned char>& b, std::size_t at) {
    return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 | b[at + 3];
}

// stb_truetype trusts the file: the table directory's offsets and lengths are read unchecked, so
// a truncated or damaged font makes it read past the buffer. Every table the directory lists
// must lie inside the file (and the directory itself), before stbtt_InitFont sees it.
bool tablesInsideFile(const std::vector<unsigned char>& bytes, std::size_t offset) {
    if (offset + 12 > bytes.size()) return false;
    const std::size_t tables = std::size_t(bytes[offset + 4]) << 8 | bytes[offset + 5];
    if (offset + 12 + tables * 16 > bytes.size()) return false;
    for (std::size_t t = 0; t < tables; ++t) {
        const std::size_t record = offset + 12 + t * 16;
        const std::uint64_t start = bigEndian32(bytes, record + 8), length = bigEndian32(bytes, record + 12);
        if (start + length > bytes.size()) return false;
    }
    return true;
}

std::string describe(char32_t c) {
    char text[16];
    std::snprintf(text, sizeof text, "U+%04X", unsigned(c));
    return text;
}

}  // namespace

std::unique_ptr<SpriteFont> BuildSpriteFont(GraphicsDevice& device, const std::string& fontFile,
                                            const FontDescription& description) {
    const std::vector<unsigned char> bytes = readFile(fontFile);
    const int offset = bytes.size() >= 12 ? stbtt_GetFontOffsetForIndex(bytes.data(), 0) : -1;
    stbtt_fontinfo font;
    if (offset < 0 || !tablesInsideFile(bytes, std::size_t(offset)) || !stbtt_InitFont(&font, bytes.data(), offset))
        throw ArgumentError("SpriteFont: '" + fontFile + "' is not a TrueType/OpenType font stb_truetype can read");
    if (!(description.Size > 0) || description.Size > 1000)
        throw ArgumentError("SpriteFont: Size " + std::to_string(description.Size) + " for '" + fontFile +
                            "' must be in (0, 1000] points");

    // XNA's processor renders Size points at 96 dpi.
    const float scale = stbtt_ScaleForMappingEmToPixels(&font, description.Size * 96.0f / 72.0f);
    int ascent = 0, descent = 0, lineGap = 0;
    stbtt_GetFontVMetrics(&font, &ascent, &descent, &lineGap);
    const int lineSpacing = int(std::lround(double(ascent - descent + lineGap) * scale));
    const int baseline = int(std::lround(double(ascent) * scale));

    GlyphAtlasBuilder atlas;
    std::vector<char32_t> missing;
    for (const auto& [first, last] : description.CharacterRegions) {
        for (char32_t c = first; c <= last; ++c) {
            const int glyph = stbtt_FindGlyphIndex(&font, int(c));
            if (glyph == 0) {
                missing.push_back(c);
                if (c == last) break;
                continue;
            }
            int advance = 0, leftSideBearing = 0;
            stbtt_GetGlyphHMetrics(&font, glyph, &advance, &leftSideBearing);
            int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            stbtt_GetGlyphBitmapBox(&font, glyph, scale, scale, &x0, &y0, &x1, &y1);
            const int width = std::max(0, x1 - x0), height = std::max(0, y1 - y0);
            std::vector<unsigned char> coverage(std::size_t(width) * std::size_t(height));
            if (width > 0 && height > 0)
                stbtt_MakeGlyphBitmap(&font, coverage.data(), width, height, width, scale, scale, glyph);
            const float advancePixels = float(advance) * scale;
            AtlasGlyph g;
            g.character = c;
            g.width = width;
            g.height = height;
            g.coverage = std::move(coverage);
            if (description.UseKerning) {
                g.cropping = Rectangle(0, baseline + y0, width, lineSpacing);
                g.kerning = Vector3(float(x0), float(width), advancePixels - float(x0) - float(width));
            } else {
                g.cropping = Rectangle(x0, baseline + y0, width, lineSpacing);
                g.kerning = Vector3(0.0f, advancePixels, 0.0f);
            }
            atlas.add(std::move(g));
            if (c == last) break;  // char32_t cannot pass U+10FFFF's successor check otherwise
        }
    }
    if (!missing.empty()) {
        std::string list;
        for (std::size_t i = 0; i < missing.size() && i < 8; ++i) list += (i ? ", " : "") + describe(missing[i]);
        if (missing.size() > 8) list += ", ...";
        std::fprintf(stderr, "fxport: warning: %s has no glyph for %zu requested character(s) (%s); they are left out\n",
                     fontFile.c_str(), missing.size(), list.c_str());
    }
    if (atlas.empty()) throw ArgumentError("SpriteFont: '" + fontFile + "' has none of the requested characters");
    return atlas.build(device, fontFile, lineSpacing, description.Spacing, description.DefaultCharacter);
}

}  // namespace fxport
