// BlendState: an immutable description (a value) with XNA's names and presets. The device compares
// it field by field with what GL has and changes only what differs.
#pragma once

#include <cstdint>

#include "fxport/math.h"

namespace fxport {

enum class Blend : std::uint8_t {
    One, Zero, SourceColor, InverseSourceColor, SourceAlpha, InverseSourceAlpha,
    DestinationColor, InverseDestinationColor, DestinationAlpha, InverseDestinationAlpha,
    BlendFactor, InverseBlendFactor, SourceAlphaSaturation,
};
// Min and Max ignore the blend factors, as in D3D and GL.
enum class BlendFunction : std::uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

enum class ColorWriteChannels : std::uint8_t { None = 0, Red = 1, Green = 2, Blue = 4, Alpha = 8, All = 15 };
constexpr ColorWriteChannels operator|(ColorWriteChannels a, ColorWriteChannels b) {
    return ColorWriteChannels(std::uint8_t(a) | std::uint8_t(b));
}

struct BlendState {
    BlendFunction AlphaBlendFunction = BlendFunction::Add;
    Blend AlphaDestinationBlend = Blend::Zero;
    Blend AlphaSourceBlend = Blend::One;
    BlendFunction ColorBlendFunction = BlendFunction::Add;
    Blend ColorDestinationBlend = Blend::Zero;
    Blend ColorSourceBlend = Blend::One;
    // Render target 0's mask is named like its type, as in XNA; hence the qualified type names.
    fxport::ColorWriteChannels ColorWriteChannels = fxport::ColorWriteChannels::All;
    fxport::ColorWriteChannels ColorWriteChannels1 = fxport::ColorWriteChannels::All;
    fxport::ColorWriteChannels ColorWriteChannels2 = fxport::ColorWriteChannels::All;
    fxport::ColorWriteChannels ColorWriteChannels3 = fxport::ColorWriteChannels::All;
    Color BlendFactor = Color(255, 255, 255, 255);
    int MultiSampleMask = -1;

    // True unless the state is "One, Zero, Add" for colour and alpha (blending can be switched off).
    bool blendingEnabled() const;
    bool operator==(const BlendState&) const = default;

    static const BlendState Additive;          // src*alpha + dst
    static const BlendState AlphaBlend;        // premultiplied: src + dst*(1-srcAlpha)
    static const BlendState NonPremultiplied;  // src*srcAlpha + dst*(1-srcAlpha)
    static const BlendState Opaque;            // src
};

}  // namespace fxport
