// SpriteFont: glyph lookup, XNA's MeasureString and text layout, and the built-in debug font.
#include "fxport/graphics/sprite_font.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/texture.h"

namespace fxport {

namespace {

constexpr char32_t kReplacementCharacter = 0xFFFD;

// Next code point of UTF-8 text; a malformed or truncated sequence yields U+FFFD and skips one byte.
char32_t nextCodePoint(std::string_view text, std::size_t& i) {
    const auto lead = static_cast<unsigned char>(text[i++]);
    if (lead < 0x80) {
        return lead;
    }
    int length = 0;
    char32_t value = 0;
    if ((lead & 0xE0) == 0xC0) {
        length = 1;
        value = lead & 0x1F;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 2;
        value = lead & 0x0F;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 3;
        value = lead & 0x07;
    } else {
        return kReplacementCharacter;
    }
    if (i + std::size_t(length) > text.size()) {
        return kReplacementCharacter;
    }
    for (int k = 0; k < length; ++k) {
        const auto continuation = static_cast<unsigned char>(text[i + std::size_t(k)]);
        if ((continuation & 0xC0) != 0x80) {
            return kReplacementCharacter;
        }
        value = (value << 6) | (continuation & 0x3F);
    }
    i += std::size_t(length);
    return value;
}

std::string describeCharacter(char32_t c) {
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", unsigned(c));
    if (c >= 0x20 && c < 0x7F) {
        return std::string("'") + char(c) + "' (" + code + ")";
    }
    return code;
}

// The debug font's glyphs, characters 0x20..0x7E (see debug_font_data.inc for their origin).
constexpr std::uint8_t kDebugGlyphs[][8] = {
#include "debug_font_data.inc"
};
constexpr int kDebugFirstCharacter = 0x20;
constexpr int kDebugGlyphCount = int(sizeof kDebugGlyphs / sizeof kDebugGlyphs[0]);
static_assert(kDebugGlyphCount == 0x7F - 0x20, "printable ASCII");
constexpr int kDebugGlyphSize = 8;
constexpr int kDebugCell = kDebugGlyphSize + 2;  // one transparent texel around each glyph, so
                                                 // linear filtering at any scale cannot bleed
constexpr int kDebugColumns = 16;
constexpr int kDebugRows = (kDebugGlyphCount + kDebugColumns - 1) / kDebugColumns;
constexpr int kDebugLineSpacing = 10;

}  // namespace

SpriteFont::SpriteFont(std::unique_ptr<Texture2D> texture, std::vector<Rectangle> glyphBounds,
                       std::vector<Rectangle> cropping, std::vector<char32_t> characters, int lineSpacing,
                       float spacing, std::vector<Vector3> kerning, std::optional<char32_t> defaultCharacter)
    : LineSpacing(lineSpacing),
      Spacing(spacing),
      DefaultCharacter(defaultCharacter),
      texture_(std::move(texture)),
      glyphs_(std::move(glyphBounds)),
      cropping_(std::move(cropping)),
      characters_(std::move(characters)),
      kerning_(std::move(kerning)) {
    if (!texture_) {
        throw ArgumentError("SpriteFont: no texture");
    }
    if (glyphs_.size() != characters_.size() || cropping_.size() != characters_.size() ||
        kerning_.size() != characters_.size()) {
        throw ArgumentError("SpriteFont: " + std::to_string(characters_.size()) + " characters but " +
                            std::to_string(glyphs_.size()) + " glyph rectangles, " + std::to_string(cropping_.size()) +
                            " cropping rectangles and " + std::to_string(kerning_.size()) + " kerning entries");
    }
    lookup_.reserve(characters_.size());
    for (std::size_t i = 0; i < characters_.size(); ++i) {
        lookup_.emplace_back(characters_[i], int(i));
    }
    std::sort(lookup_.begin(), lookup_.end());
    const auto duplicate = std::adjacent_find(lookup_.begin(), lookup_.end(),
                                              [](const auto& a, const auto& b) { return a.first == b.first; });
    if (duplicate != lookup_.end()) {
        throw ArgumentError("SpriteFont: the character " + describeCharacter(duplicate->first) + " appears twice");
    }
}

SpriteFont::~SpriteFont() = default;

std::unique_ptr<SpriteFont> SpriteFont::createDebugFont(fxport::GraphicsDevice& device) {
    const int width = kDebugColumns * kDebugCell;
    const int height = kDebugRows * kDebugCell;
    std::vector<Color> texels(std::size_t(width) * std::size_t(height), Color::Transparent);
    std::vector<Rectangle> glyphs;
    std::vector<Rectangle> cropping;
    std::vector<char32_t> characters;
    std::vector<Vector3> kerning;
    for (int index = 0; index < kDebugGlyphCount; ++index) {
        const int left = (index % kDebugColumns) * kDebugCell + 1;
        const int top = (index / kDebugColumns) * kDebugCell + 1;
        for (int row = 0; row < kDebugGlyphSize; ++row) {
            for (int column = 0; column < kDebugGlyphSize; ++column) {
                if ((kDebugGlyphs[index][row] >> column) & 1) {  // bit 0 = leftmost pixel
                    texels[std::size_t(top + row) * std::size_t(width) + std::size_t(left + column)] = Color::White;
                }
            }
        }
        glyphs.emplace_back(left, top, kDebugGlyphSize, kDebugGlyphSize);
        cropping.emplace_back(0, 0, kDebugGlyphSize, kDebugGlyphSize);
        characters.push_back(char32_t(kDebugFirstCharacter + index));
        kerning.emplace_back(0.0f, float(kDebugGlyphSize), 0.0f);
    }
    auto texture = std::make_unique<Texture2D>(device, width, height, false, SurfaceFormat::Color);
    texture->Name = "DebugFont";
    texture->SetData(texels);
    return std::make_unique<SpriteFont>(std::move(texture), std::move(glyphs), std::move(cropping),
                                        std::move(characters), kDebugLineSpacing, 0.0f, std::move(kerning), U'?');
}

int SpriteFont::glyphIndex(char32_t character) const {
    auto find = [this](char32_t c) {
        const auto it = std::lower_bound(
            lookup_.begin(), lookup_.end(), c,
            [](const std::pair<char32_t, int>& entry, char32_t key) { return entry.first < key; });
        return it != lookup_.end() && it->first == c ? it->second : -1;
    };
    int index = find(character);
    if (index < 0 && DefaultCharacter) {
        index = find(*DefaultCharacter);
        if (index < 0) {
            throw ArgumentError("SpriteFont: the character " + describeCharacter(character) +
                                " is not in the font, nor is its DefaultCharacter " +
                                describeCharacter(*DefaultCharacter));
        }
    }
    if (index < 0) {
        throw ArgumentError("SpriteFont: the character " + describeCharacter(character) +
                            " is not in the font and the font has no DefaultCharacter");
    }
    return index;
}

Vector2 SpriteFont::MeasureString(std::string_view text) const {
    if (text.empty()) {
        return Vector2::Zero;
    }
    float width = 0.0f;
    float lineWidth = 0.0f;
    float height = float(LineSpacing);  // every line but the last
    float lastLineHeight = float(LineSpacing);
    bool firstInLine = true;
    for (std::size_t i = 0; i < text.size();) {
        const char32_t c = nextCodePoint(text, i);
        if (c == U'\r') {
            continue;
        }
        if (c == U'\n') {
            width = std::max(width, lineWidth);
            lineWidth = 0.0f;
            height += float(LineSpacing);
            lastLineHeight = float(LineSpacing);
            firstInLine = true;
            continue;
        }
        const int index = glyphIndex(c);
        Vector3 k = kerning_[std::size_t(index)];
        if (firstInLine) {
            k.X = std::max(k.X, 0.0f);
        } else {
            lineWidth += Spacing;
        }
        lineWidth += k.X + k.Y + k.Z;
        lastLineHeight = std::max(lastLineHeight, float(cropping_[std::size_t(index)].Height));
        firstInLine = false;
    }
    width = std::max(width, lineWidth);
    return Vector2(width, height - float(LineSpacing) + lastLineHeight);
}

// XNA's SpriteFont.InternalDraw: a pen moves along each line (right to left when mirrored); each
// glyph is placed relative to the text block, scaled, offset by -origin and rotated about the
// block's position, then drawn as one sprite with the same rotation, scale and effects.
void SpriteFont::draw(SpriteBatch& spriteBatch, std::string_view text, Vector2 position, Color color, float rotation,
                      Vector2 origin, Vector2 scale, SpriteEffects effects, float layerDepth) const {
    const Matrix transform = Matrix::CreateTranslation(-origin.X * scale.X, -origin.Y * scale.Y, 0.0f) *
                             Matrix::CreateRotationZ(rotation);
    const bool flipX = (effects & SpriteEffects::FlipHorizontally) != SpriteEffects::None;
    const bool flipY = (effects & SpriteEffects::FlipVertically) != SpriteEffects::None;
    const float direction = flipX ? -1.0f : 1.0f;
    Vector2 measured;
    if (flipX || flipY) {
        measured = MeasureString(text);
    }
    const float lineStart = flipX ? measured.X * scale.X : 0.0f;
    Vector2 pen(lineStart, flipY ? (measured.Y - float(LineSpacing)) * scale.Y : 0.0f);
    bool firstInLine = true;
    for (std::size_t i = 0; i < text.size();) {
        const char32_t c = nextCodePoint(text, i);
        if (c == U'\r') {
            continue;
        }
        if (c == U'\n') {
            firstInLine = true;
            pen.X = lineStart;
            pen.Y += (flipY ? -1.0f : 1.0f) * float(LineSpacing) * scale.Y;
            continue;
        }
        const auto index = std::size_t(glyphIndex(c));
        Vector3 k = kerning_[index];
        if (firstInLine) {
            k.X = std::max(k.X, 0.0f);
        } else {
            pen.X += Spacing * scale.X * direction;
        }
        pen.X += k.X * scale.X * direction;
        const Rectangle& glyph = glyphs_[index];
        Rectangle cell = cropping_[index];
        if (flipY) {
            cell.Y = LineSpacing - glyph.Height - cell.Y;
        }
        if (flipX) {
            cell.X -= cell.Width;
        }
        Vector2 offset(pen.X + float(cell.X) * scale.X, pen.Y + float(cell.Y) * scale.Y);
        offset = Vector2::Transform(offset, transform);
        spriteBatch.Draw(*texture_, position + offset, glyph, color, rotation, Vector2::Zero, scale, effects,
                         layerDepth);
        firstInLine = false;
        pen.X += (k.Y + k.Z) * scale.X * direction;
    }
}

}  // namespace fxport
