// Color: XNA's 32-bit colour, one byte per channel in memory order R, G, B, A (4 bytes), so
// PackedValue() == R | G << 8 | B << 16 | A << 24 ("ABGR" read as a hex number) and a Color array
// uploads as GL_RGBA / GL_UNSIGNED_BYTE. Colours are premultiplied-alpha by XNA 4 convention; use
// FromNonPremultiplied for straight alpha.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "fxport/math/vector3.h"
#include "fxport/math/vector4.h"

namespace fxport {

struct Color {
    std::uint8_t R = 0;
    std::uint8_t G = 0;
    std::uint8_t B = 0;
    std::uint8_t A = 0;

    // Transparent black (all zero), as C#'s default(Color).
    constexpr Color() = default;

    // Integer channels 0..255, clamped; alpha defaults to opaque. A template so that, as in C#,
    // a call mixing ints and floats — Color(1.0f, 0.5f, 0, 1) — picks the float constructor.
    template <std::integral I1, std::integral I2, std::integral I3, std::integral I4 = int>
    constexpr Color(I1 r, I2 g, I3 b, I4 a = 255)
        : R(clampToByte(r)), G(clampToByte(g)), B(clampToByte(b)), A(clampToByte(a)) {}

    // Float channels 0..1: scaled by 255, clamped, rounded to nearest with ties to even (what
    // XNA's Math.Round does), NaN to 0. So 0.5f becomes 128 (127.5 rounds to the even 128).
    Color(float r, float g, float b, float a = 1.0f)
        : R(unitToByte(r)), G(unitToByte(g)), B(unitToByte(b)), A(unitToByte(a)) {}
    explicit Color(Vector3 vector) : Color(vector.X, vector.Y, vector.Z, 1.0f) {}
    explicit Color(Vector4 vector) : Color(vector.X, vector.Y, vector.Z, vector.W) {}

    constexpr std::uint32_t PackedValue() const {
        return static_cast<std::uint32_t>(R) | static_cast<std::uint32_t>(G) << 8 |
               static_cast<std::uint32_t>(B) << 16 | static_cast<std::uint32_t>(A) << 24;
    }
    constexpr void setPackedValue(std::uint32_t value) {
        R = static_cast<std::uint8_t>(value);
        G = static_cast<std::uint8_t>(value >> 8);
        B = static_cast<std::uint8_t>(value >> 16);
        A = static_cast<std::uint8_t>(value >> 24);
    }

    // Channels / 255.
    Vector3 ToVector3() const { return {R / 255.0f, G / 255.0f, B / 255.0f}; }
    Vector4 ToVector4() const { return {R / 255.0f, G / 255.0f, B / 255.0f, A / 255.0f}; }

    // Every channel, alpha included, times scale — in XNA's 16.16 fixed point: the scale is
    // truncated to a multiple of 1/65536 (clamped to [0, 255.99]), each product truncated and
    // clamped to 255. Color::White * 0.5f == (127, 127, 127, 127).
    static Color Multiply(Color value, float scale);
    // value1 + (value2 - value1) * amount per channel, amount clamped to [0, 1], in XNA's fixed
    // point (amount rounded to a multiple of 1/65536, the product's fraction dropped towards -inf).
    static Color Lerp(Color value1, Color value2, float amount);
    // From straight (non-premultiplied) alpha: the colour channels times alpha.
    static Color FromNonPremultiplied(Vector4 vector);
    static Color FromNonPremultiplied(int r, int g, int b, int a);

    friend constexpr bool operator==(const Color&, const Color&) = default;

    // XNA's named colours (the .NET/X11 web colours), the ones tutorials use.
    static const Color Transparent;       // (0, 0, 0, 0)
    static const Color TransparentBlack;  // (0, 0, 0, 0)
    static const Color Black;
    static const Color White;
    static const Color Red;
    static const Color Green;  // (0, 128, 0): the web "green", not (0, 255, 0) which is Lime
    static const Color Lime;
    static const Color Blue;
    static const Color Yellow;
    static const Color Cyan;
    static const Color Magenta;
    static const Color Orange;
    static const Color Purple;
    static const Color Gray;  // (128, 128, 128), darker than DarkGray (169, 169, 169), as in .NET
    static const Color DarkGray;
    static const Color LightGray;
    static const Color DimGray;
    static const Color Silver;
    static const Color CornflowerBlue;
    static const Color ForestGreen;
    static const Color Crimson;
    static const Color Honeydew;
    static const Color Navy;
    static const Color DarkBlue;
    static const Color SkyBlue;
    static const Color DarkGreen;
    static const Color DarkRed;
    static const Color Brown;
    static const Color Gold;
    static const Color Pink;
    static const Color Beige;
    static const Color Wheat;
    static const Color SandyBrown;

private:
    template <std::integral I>
    static constexpr std::uint8_t clampToByte(I value) {
        if (std::cmp_less(value, 0)) {
            return 0;
        }
        if (std::cmp_greater(value, 255)) {
            return 255;
        }
        return static_cast<std::uint8_t>(value);
    }
    static std::uint8_t unitToByte(float value) {
        const float scaled = value * 255.0f;
        if (!(scaled > 0.0f)) {  // also NaN
            return 0;
        }
        if (scaled >= 255.0f) {
            return 255;
        }
        float whole = std::floor(scaled);
        const float fraction = scaled - whole;
        if (fraction > 0.5f || (fraction == 0.5f && std::fmod(whole, 2.0f) != 0.0f)) {
            whole += 1.0f;
        }
        return static_cast<std::uint8_t>(whole);
    }
};

inline constexpr Color Color::Transparent{0, 0, 0, 0};
inline constexpr Color Color::TransparentBlack{0, 0, 0, 0};
inline constexpr Color Color::Black{0, 0, 0};
inline constexpr Color Color::White{255, 255, 255};
inline constexpr Color Color::Red{255, 0, 0};
inline constexpr Color Color::Green{0, 128, 0};
inline constexpr Color Color::Lime{0, 255, 0};
inline constexpr Color Color::Blue{0, 0, 255};
inline constexpr Color Color::Yellow{255, 255, 0};
inline constexpr Color Color::Cyan{0, 255, 255};
inline constexpr Color Color::Magenta{255, 0, 255};
inline constexpr Color Color::Orange{255, 165, 0};
inline constexpr Color Color::Purple{128, 0, 128};
inline constexpr Color Color::Gray{128, 128, 128};
inline constexpr Color Color::DarkGray{169, 169, 169};
inline constexpr Color Color::LightGray{211, 211, 211};
inline constexpr Color Color::DimGray{105, 105, 105};
inline constexpr Color Color::Silver{192, 192, 192};
inline constexpr Color Color::CornflowerBlue{100, 149, 237};
inline constexpr Color Color::ForestGreen{34, 139, 34};
inline constexpr Color Color::Crimson{220, 20, 60};
inline constexpr Color Color::Honeydew{240, 255, 240};
inline constexpr Color Color::Navy{0, 0, 128};
inline constexpr Color Color::DarkBlue{0, 0, 139};
inline constexpr Color Color::SkyBlue{135, 206, 235};
inline constexpr Color Color::DarkGreen{0, 100, 0};
inline constexpr Color Color::DarkRed{139, 0, 0};
inline constexpr Color Color::Brown{165, 42, 42};
inline constexpr Color Color::Gold{255, 215, 0};
inline constexpr Color Color::Pink{255, 192, 203};
inline constexpr Color Color::Beige{245, 245, 220};
inline constexpr Color Color::Wheat{245, 222, 179};
inline constexpr Color Color::SandyBrown{244, 164, 96};

inline Color operator*(Color value, float scale) { return Color::Multiply(value, scale); }
inline Color operator*(float scale, Color value) { return Color::Multiply(value, scale); }

static_assert(sizeof(Color) == 4 && std::is_standard_layout_v<Color> &&
              std::is_trivially_copyable_v<Color>);

}  // namespace fxport
