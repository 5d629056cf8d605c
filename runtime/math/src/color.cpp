// Color arithmetic in XNA's 16.16 fixed point, so blended and scaled colours match XNA's bytes.
#include "fxport/math/color.h"

#include <cstdint>

namespace fxport {

namespace {

std::uint8_t channel(std::uint32_t value) { return static_cast<std::uint8_t>(value > 255 ? 255 : value); }

}  // namespace

Color Color::Multiply(Color value, float scale) {
    const float fixed = scale * 65536.0f;
    // Truncated towards zero and clamped to [0, 0xFFFFFF] (a scale below 256), as XNA.
    const std::uint32_t s = fixed >= 0.0f ? (fixed <= 16777215.0f ? static_cast<std::uint32_t>(fixed)
                                                                  : 16777215u)
                                          : 0u;
    Color result;
    result.R = channel((value.R * s) >> 16);
    result.G = channel((value.G * s) >> 16);
    result.B = channel((value.B * s) >> 16);
    result.A = channel((value.A * s) >> 16);
    return result;
}

Color Color::Lerp(Color value1, Color value2, float amount) {
    // amount in [0, 1] becomes a 16.16 weight, rounded like Color(float) rounds a channel.
    const float clamped = MathHelper::Clamp(amount, 0.0f, 1.0f);
    const float scaled = clamped * 65536.0f;
    float whole = std::floor(scaled);
    const float fraction = scaled - whole;
    if (fraction > 0.5f || (fraction == 0.5f && std::fmod(whole, 2.0f) != 0.0f)) {
        whole += 1.0f;
    }
    const int weight = static_cast<int>(whole);
    // (to - from) * weight may be negative: >> on a negative int rounds towards -inf (C++20,
    // and C#), which keeps the result between the two channels.
    const auto blend = [weight](std::uint8_t from, std::uint8_t to) {
        return static_cast<std::uint8_t>(from + (((to - from) * weight) >> 16));
    };
    return Color(blend(value1.R, value2.R), blend(value1.G, value2.G), blend(value1.B, value2.B),
                 blend(value1.A, value2.A));
}

Color Color::FromNonPremultiplied(Vector4 vector) {
    return Color(vector.X * vector.W, vector.Y * vector.W, vector.Z * vector.W, vector.W);
}

Color Color::FromNonPremultiplied(int r, int g, int b, int a) {
    // Integer products divided by 255 (truncating), then clamped, as XNA.
    const long long alpha = a;
    return Color(r * alpha / 255, g * alpha / 255, b * alpha / 255, a);
}

}  // namespace fxport
