// refract(i, n, eta) with a vector eta (`float4 eta`): fxc takes its first component, as it
// truncates any vector to a scalar parameter (vkd3d's refract pins the values, eta.x alone deciding
// the total reflection). glslang has only a scalar eta ("no matching overloaded function"). The
// argument becomes `(eta).x` where its type is evidently a vector (expression_types.h); a
// one-row or one-column matrix eta stays, refused by fxc and glslang alike.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> refractVectorEta(const EffectSyntax& syntax);

}  // namespace fxport::xlate
