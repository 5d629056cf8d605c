// INTERNAL: XNA's TextureFilter as its three parts (minification, magnification, mip), and back.
// The one place that knows how the nine filters split: the GL sampler objects and the effect's
// sampler_state merge (D3D9 sets MinFilter/MagFilter/MipFilter one by one) both use it.
#pragma once

#include "fxport/graphics/sampler_state.h"

namespace fxport {

struct FilterParts {
    bool minLinear = true;
    bool magLinear = true;
    bool mipLinear = true;
    bool anisotropic = false;  // implies linear min and mag (XNA's Anisotropic has a linear mip)
};

FilterParts splitFilter(TextureFilter filter);
TextureFilter joinFilter(const FilterParts& parts);

}  // namespace fxport
