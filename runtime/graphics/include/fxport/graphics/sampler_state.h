// SamplerState: an immutable description with XNA's names and presets.
#pragma once

#include <cstdint>

#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/math.h"

namespace fxport {

enum class TextureFilter : std::uint8_t {
    Linear, Point, Anisotropic, LinearMipPoint, PointMipLinear,
    MinLinearMagPointMipLinear, MinLinearMagPointMipPoint, MinPointMagLinearMipLinear, MinPointMagLinearMipPoint,
};
enum class TextureAddressMode : std::uint8_t { Wrap, Clamp, Mirror, Border };

struct SamplerState {
    TextureFilter Filter = TextureFilter::Linear;
    TextureAddressMode AddressU = TextureAddressMode::Wrap;
    TextureAddressMode AddressV = TextureAddressMode::Wrap;
    TextureAddressMode AddressW = TextureAddressMode::Wrap;
    int MaxAnisotropy = 4;
    int MaxMipLevel = 0;               // the most detailed mip level used
    float MipMapLevelOfDetailBias = 0;
    // fxport additions for what D3D9 effects can say and XNA's enum cannot:
    Vector4 BorderColor = Vector4(0, 0, 0, 0);  // D3D9 BORDERCOLOR (XNA has no Border mode colour)
    bool UseMipMaps = true;                      // false = D3D9 MIPFILTER = NONE (sample level MaxMipLevel only)
    // D3D10 SamplerComparisonState: SampleCmp returns the filtered result of `reference
    // ComparisonFunction texel` (0 or 1 per texel, then weighted as the filter says). Set by an
    // effect's comparison sampler at Apply(); needs a SurfaceFormat::Depth32 texture.
    bool UseComparison = false;
    CompareFunction ComparisonFunction = CompareFunction::Never;

    bool operator==(const SamplerState&) const = default;

    static const SamplerState AnisotropicClamp;
    static const SamplerState AnisotropicWrap;
    static const SamplerState LinearClamp;
    static const SamplerState LinearWrap;
    static const SamplerState PointClamp;
    static const SamplerState PointWrap;
};

}  // namespace fxport
