// TextureFilter <-> (min, mag, mip) linear/point parts.
#include "device/sampler_filter.h"

namespace fxport {

FilterParts splitFilter(TextureFilter f) {
    switch (f) {
    case TextureFilter::Linear: return {true, true, true, false};
    case TextureFilter::Anisotropic: return {true, true, true, true};
    case TextureFilter::Point: return {false, false, false, false};
    case TextureFilter::LinearMipPoint: return {true, true, false, false};
    case TextureFilter::PointMipLinear: return {false, false, true, false};
    case TextureFilter::MinLinearMagPointMipLinear: return {true, false, true, false};
    case TextureFilter::MinLinearMagPointMipPoint: return {true, false, false, false};
    case TextureFilter::MinPointMagLinearMipLinear: return {false, true, true, false};
    case TextureFilter::MinPointMagLinearMipPoint: return {false, true, false, false};
    }
    return {};
}

TextureFilter joinFilter(const FilterParts& p) {
    if (p.anisotropic) return TextureFilter::Anisotropic;
    if (p.minLinear && p.magLinear) return p.mipLinear ? TextureFilter::Linear : TextureFilter::LinearMipPoint;
    if (!p.minLinear && !p.magLinear) return p.mipLinear ? TextureFilter::PointMipLinear : TextureFilter::Point;
    if (p.minLinear) return p.mipLinear ? TextureFilter::MinLinearMagPointMipLinear : TextureFilter::MinLinearMagPointMipPoint;
    return p.mipLinear ? TextureFilter::MinPointMagLinearMipLinear : TextureFilter::MinPointMagLinearMipPoint;
}

}  // namespace fxport
